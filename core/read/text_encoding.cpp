// Comments' text encoding: detection and decoding (essi/text_encoding.hpp). The decoder is essi/charset.hpp's
// (ICU natively, iconv under Emscripten).
#include "essi/text_encoding.hpp"

#include <cctype>
#include <cstdio>

#include "essi/charset.hpp"
#include "essi/text.hpp"

namespace essi {
namespace {

// The length of the well-formed GB 18030 character at `i` (2 or 4 bytes), or 0.
std::size_t gb18030_char_length(std::string_view s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = b(i);
    if (lead < 0x81 || lead > 0xFE || i + 1 >= s.size()) return 0;
    const unsigned char second = b(i + 1);
    if ((second >= 0x40 && second <= 0x7E) || (second >= 0x80 && second <= 0xFE)) return 2;
    if (second < 0x30 || second > 0x39 || i + 3 >= s.size()) return 0;
    const unsigned char third = b(i + 2), fourth = b(i + 3);
    return third >= 0x81 && third <= 0xFE && fourth >= 0x30 && fourth <= 0x39 ? 4 : 0;
}

std::string hex_escape(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", c);
    return buf;
}

// GB 18030 character by character (essi/charset.hpp): a byte that starts no character the converter takes
// becomes \xNN.
std::string decode_gb18030(std::string_view bytes) {
    std::string out;
    out.reserve(bytes.size() * 3 / 2 + 8);
    std::size_t i = 0;
    while (i < bytes.size()) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c < 0x80) {
            out += c < 0x20 || c == 0x7F ? hex_escape(c) : std::string(1, static_cast<char>(c));
            ++i;
            continue;
        }
        const std::size_t n = gb18030_char_length(bytes, i);
        const std::optional<std::string> utf8 = n == 0 ? std::nullopt : gb18030_char_to_utf8(bytes.substr(i, n));
        if (!utf8) {
            out += hex_escape(c);
            ++i;
            continue;
        }
        out += *utf8;
        i += n;
    }
    return out;
}

}  // namespace

std::string_view text_encoding_name(TextEncoding e) { return e == TextEncoding::Gb18030 ? "gb18030" : "utf-8"; }

std::optional<TextEncoding> parse_text_encoding(std::string_view name) {
    std::string n;
    for (char c : name)
        if (c != '-' && c != '_') n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (n == "utf8") return TextEncoding::Utf8;
    if (n == "gb18030" || n == "gbk" || n == "gb2312" || n == "cp936") return TextEncoding::Gb18030;
    return std::nullopt;
}

namespace {
// Whether every byte above ASCII is part of a well-formed character of the encoding whose lengths `length` gives.
template <class CharLength>
bool well_formed(std::string_view bytes, CharLength length) {
    for (std::size_t i = 0; i < bytes.size();) {
        if (static_cast<unsigned char>(bytes[i]) < 0x80) {
            ++i;
            continue;
        }
        const std::size_t n = length(bytes, i);
        if (n == 0) return false;
        i += n;
    }
    return true;
}
}  // namespace

TextEncoding detect_text_encoding(std::string_view bytes) {
    if (well_formed(bytes, utf8_char_length)) return TextEncoding::Utf8;
    return well_formed(bytes, gb18030_char_length) ? TextEncoding::Gb18030 : TextEncoding::Utf8;
}

std::string decode_text(std::string_view bytes, TextEncoding encoding) {
    return encoding == TextEncoding::Gb18030 ? decode_gb18030(bytes) : display_text(bytes);
}

}  // namespace essi
