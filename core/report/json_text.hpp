// Pretty-printed JSON written as nlohmann::json::dump(indent) writes it, without making a JSON value: for the parts
// of a report that can be large (the parts list, the diagnostics; essi/report_json.hpp).
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "essi/report_json.hpp"

namespace essi {

// Pretty-printed JSON as nlohmann::json::dump(indent) writes it, into a buffer handed to `write` when it grows past
// kJsonFlushBytes: members are written in the order given (the caller gives them sorted by name).

class JsonText {
public:
    JsonText(int indent, int depth, const std::function<void(std::string_view)>& write)
        : step_(indent), depth_(depth), write_(write) {
        buf_.reserve(2 * kJsonFlushBytes);
    }
    ~JsonText() { flush(); }
    JsonText(const JsonText&) = delete;
    JsonText& operator=(const JsonText&) = delete;

    void flush() {
        if (!buf_.empty()) write_(buf_);
        buf_.clear();
    }
    // `{` or `[`: the first member or element goes on the next line.
    void open(char bracket) {
        buf_ += bracket;
        ++depth_;
        first_ = true;
    }
    // `}` or `]` after its members (`empty`: none were written: `{}`, `[]`).
    void close(char bracket) {
        --depth_;
        if (!first_) {
            buf_ += '\n';
            indent();
        }
        buf_ += bracket;
        first_ = false;
        if (buf_.size() >= kJsonFlushBytes) flush();
    }
    // The next member's name (in an object) ...
    void key(std::string_view name) {
        next();
        buf_ += '"';
        buf_ += name;
        buf_.append("\": ", 3);
    }
    // ... or the next element (in an array), then its value.
    void element() { next(); }
    void number(double v) {
        if (!std::isfinite(v)) {
            buf_ += "null";
            return;
        }
        char digits[64];
        char* end = nlohmann::detail::to_chars(digits, digits + sizeof digits, v);
        buf_.append(digits, end);
    }
    template <class Int>
    void integer(std::string_view name, Int v) {
        key(name);
        integer(v);
    }
    template <class Int>
    void integer(Int v) {
        char digits[24];
        const auto r = std::to_chars(digits, digits + sizeof digits, v);
        buf_.append(digits, r.ptr);
    }
    void null() { buf_ += "null"; }
    // A string as dump() writes it (nlohmann's own escaping, but for text that needs none).
    void string(std::string_view s) {
        const auto needs_escaping = [](char c) {  // (or, 0x80 and above, checking as UTF-8)
            const auto u = static_cast<unsigned char>(c);
            return u < 0x20 || u >= 0x80 || c == '"' || c == '\\';
        };
        if (std::find_if(s.begin(), s.end(), needs_escaping) != s.end()) {
            buf_ += nlohmann::json(s).dump();
            return;
        }
        buf_ += '"';
        buf_ += s;
        buf_ += '"';
    }
    void string(std::string_view name, std::string_view s) {
        key(name);
        string(s);
    }
    void boolean(bool v) { buf_ += v ? "true" : "false"; }

    // Helpers for the members of the parts list.
    void rounded(std::string_view name, double v) {
        key(name);
        number(round_for_json(v));
    }
    void rounded_or_null(std::string_view name, const std::optional<double>& v) {
        key(name);
        if (v) number(round_for_json(*v));
        else null();
    }
    void box(std::string_view name, const Box& b) {
        key(name);
        if (b.empty) {
            null();
            return;
        }
        open('{');
        rounded("max_x", b.max_x);
        rounded("max_y", b.max_y);
        rounded("min_x", b.min_x);
        rounded("min_y", b.min_y);
        close('}');
    }

private:
    void next() {
        if (!first_) buf_ += ',';
        buf_ += '\n';
        first_ = false;
        indent();
    }
    void indent() { buf_.append(static_cast<std::size_t>(step_ * depth_), ' '); }

    int step_, depth_;
    bool first_ = false;
    const std::function<void(std::string_view)>& write_;
    std::string buf_;
};

}  // namespace essi
