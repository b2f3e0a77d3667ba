// Where a key of a profile's JSON text is (key_position.hpp). The text was parsed already, so it is valid JSON: a
// scan over it finds the key without building anything, and descends only into the objects on the key's path
// (no recursion, whatever the nesting).
#include "key_position.hpp"

namespace essi::profile_detail {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

class Scanner {
public:
    explicit Scanner(std::string_view text) : t_(text) {}

    void skip_space() {
        while (i_ < t_.size() && is_space(t_[i_])) ++i_;
    }
    // A string at i_ (its opening quote): past it; its text when it holds no escape (keys of a profile do not).
    std::optional<std::string_view> string() {
        const std::size_t start = ++i_;
        bool escaped = false;
        while (i_ < t_.size() && t_[i_] != '"') {
            if (t_[i_] == '\\') {
                escaped = true;
                ++i_;
            }
            ++i_;
        }
        const std::string_view s = t_.substr(start, i_ - start);
        ++i_;
        if (escaped) return std::nullopt;
        return s;
    }
    // Past the value at i_.
    void skip_value() {
        skip_space();
        if (i_ >= t_.size()) return;
        if (t_[i_] == '"') {
            (void)string();
            return;
        }
        if (t_[i_] != '{' && t_[i_] != '[') {
            while (i_ < t_.size() && t_[i_] != ',' && t_[i_] != '}' && t_[i_] != ']' && !is_space(t_[i_])) ++i_;
            return;
        }
        std::size_t depth = 0;
        do {
            const char c = t_[i_];
            if (c == '"') {
                (void)string();
                continue;
            }
            if (c == '{' || c == '[') ++depth;
            if (c == '}' || c == ']') --depth;
            ++i_;
        } while (depth > 0 && i_ < t_.size());
    }
    // In the object at i_: where the last key `name` is named and where its value starts.
    struct Found {
        std::size_t key, value;
    };
    std::optional<Found> find_in_object(std::string_view name) {
        skip_space();
        if (i_ >= t_.size() || t_[i_] != '{') return std::nullopt;
        ++i_;
        std::optional<Found> found;
        for (;;) {
            skip_space();
            if (i_ >= t_.size() || t_[i_] == '}') break;
            if (t_[i_] == ',') {
                ++i_;
                continue;
            }
            const std::size_t key_at = i_;
            const std::optional<std::string_view> key = string();
            skip_space();
            ++i_;  // ':'
            skip_space();
            if (key && *key == name) found = Found{key_at, i_};
            skip_value();
        }
        return found;
    }
    void seek(std::size_t at) { i_ = at; }

private:
    std::string_view t_;
    std::size_t i_ = 0;
};

}  // namespace

TextPosition position_of(std::string_view text, std::size_t offset) {
    TextPosition p;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.column = 1;
        } else {
            ++p.column;
        }
    }
    return p;
}

std::optional<std::size_t> key_offset(std::string_view text, const std::vector<std::string>& path) {
    Scanner s(text);
    std::optional<std::size_t> at;
    for (const std::string& name : path) {
        const auto found = s.find_in_object(name);
        if (!found) break;
        at = found->key;
        s.seek(found->value);
    }
    return at;
}

}  // namespace essi::profile_detail
