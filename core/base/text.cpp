// Safe text for reports (essi/text.hpp).
#include "essi/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <cstdint>

namespace essi {

namespace {

bool is_continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

}  // namespace

std::size_t utf8_char_length(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    if (c < 0x80) return 1;
    std::size_t n = 0;
    std::uint32_t code = 0, min = 0;
    if ((c & 0xE0) == 0xC0) n = 2, code = c & 0x1F, min = 0x80;
    else if ((c & 0xF0) == 0xE0) n = 3, code = c & 0x0F, min = 0x800;
    else if ((c & 0xF8) == 0xF0) n = 4, code = c & 0x07, min = 0x10000;
    else return 0;
    if (i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if (!is_continuation(byte(i + k))) return 0;
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    return code < min || surrogate || code > 0x10FFFF ? 0 : n;
}

bool is_valid_utf8(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = utf8_char_length(s, i);
        if (n == 0) return false;
        i += n;
    }
    return true;
}

std::size_t display_width(std::string_view s) {
    std::size_t width = 0;
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = std::max<std::size_t>(utf8_char_length(s, i), 1);
        char32_t c = static_cast<unsigned char>(s[i]);
        if (n > 1) {
            c &= 0x3F >> (n - 1);
            for (std::size_t k = 1; k < n; ++k) c = (c << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
        }
        const bool wide = (c >= 0x1100 && c <= 0x115F) || (c >= 0x2E80 && c <= 0xA4CF) ||
                          (c >= 0xAC00 && c <= 0xD7A3) || (c >= 0xF900 && c <= 0xFAFF) ||
                          (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFF60) ||
                          (c >= 0xFFE0 && c <= 0xFFE6) || (c >= 0x20000 && c <= 0x3FFFD);
        width += wide ? 2 : 1;
        i += n;
    }
    return width;
}

std::string excerpt(std::string_view text, std::size_t max_bytes) {
    if (text.size() <= max_bytes) return std::string(text);
    std::size_t n = max_bytes;
    while (n > 0 && is_continuation(static_cast<unsigned char>(text[n]))) --n;  // not inside a UTF-8 character
    return std::string(text.substr(0, n)) + "...";
}

std::string display_text(std::string_view s) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const std::size_t n = c < 0x20 || c == 0x7F ? 0 : utf8_char_length(s, i);
        if (n == 0) {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
            ++i;
            continue;
        }
        out.append(s.substr(i, n));
        i += n;
    }
    return out;
}

std::string fixed_text(double v, int decimals) {
    if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
    char buf[400];  // (the widest double, 1e308, in full)
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    if (buf[0] == '-' && std::string_view(buf).find_first_not_of("-0.") == std::string_view::npos) return buf + 1;
    return buf;
}

std::string mm_text(double mm) { return fixed_text(mm, kMmDecimals); }

namespace {
// The digits of a whole number with the thousands apart ("184377" -> "184 377").
std::string thousands_apart(std::string_view digits) {
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
        out += digits[i];
    }
    return out;
}
}  // namespace

std::string length_text(double mm) {
    if (!(std::fabs(mm) >= 10000)) return mm_text(mm) + " mm";
    const std::string digits = mm_text(std::fabs(mm) / 1000);  // "184377.775"
    const std::size_t point = digits.find('.');
    return (mm < 0 ? "-" : "") + thousands_apart(std::string_view(digits).substr(0, point)) + digits.substr(point) +
           " m";
}

std::string count_text(std::uint64_t n) { return thousands_apart(std::to_string(n)); }

std::string xml_escape(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // XML 1.0 allows no control characters but tab, CR and LF.
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += '?';
                else out += c;
        }
    }
    return out;
}

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);  // (a value of a tape, 3600001, is not 3.6e+06)
    return buf;
}

}  // namespace essi
