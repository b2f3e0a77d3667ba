// Comments' text encoding: detection and decoding (essi/text_encoding.hpp). The decoder is essi/charset.hpp's
// (ICU natively, iconv under Emscripten).
#include "essi/text_encoding.hpp"

#include <cctype>
#include <cstdio>

#include "essi/charset.hpp"
#include "essi/lines.hpp"
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

namespace {

// The 1-based line a character after `text` is on (the core's line-end rule: CR, LF, CR LF and LF CR end a line).
std::size_t line_at_end(std::string_view text) {
    std::size_t line = 1;
    const auto* data = reinterpret_cast<const unsigned char*>(text.data());
    const auto size = static_cast<std::uint32_t>(text.size());
    for (std::size_t end = find_line_end(text, 0); end < text.size(); end = find_line_end(text, end)) {
        ++line;
        end = past_line_end(data, static_cast<std::uint32_t>(end), size);
    }
    return line;
}

std::string hex_unit(unsigned unit) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%04X", unit);
    return buf;
}

bool is_high_surrogate(unsigned u) { return u >= 0xD800 && u <= 0xDBFF; }
bool is_low_surrogate(unsigned u) { return u >= 0xDC00 && u <= 0xDFFF; }

// UTF-16 after its byte order mark (big-endian or not) as UTF-8, or the problem with it.
TapeText decode_utf16(std::string_view bytes, bool big_endian) {
    const char* order = big_endian ? "BE" : "LE";
    TapeText t;
    std::string out;
    out.reserve(bytes.size() / 2);
    const auto unit_at = [&](std::size_t i) {
        const auto a = static_cast<unsigned char>(bytes[i]), b = static_cast<unsigned char>(bytes[i + 1]);
        return big_endian ? (unsigned{a} << 8) | b : (unsigned{b} << 8) | a;
    };
    constexpr std::size_t kMark = 2;
    std::size_t i = kMark;
    for (; i + 1 < bytes.size(); i += 2) {
        const unsigned u = unit_at(i);
        if (is_high_surrogate(u) && i + 3 < bytes.size() && is_low_surrogate(unit_at(i + 2))) {
            append_utf8(out, 0x10000 + ((u - 0xD800) << 10) + (unit_at(i + 2) - 0xDC00));
            i += 2;
        } else if (is_high_surrogate(u) || is_low_surrogate(u)) {
            t.problem = {Msg::ReadUtf16Unpaired, {order, hex_unit(u), i, line_at_end(out)}};
            return t;
        } else {
            append_utf8(out, u);
        }
    }
    if (i < bytes.size()) {
        t.problem = {Msg::ReadUtf16OddBytes, {order, bytes.size(), line_at_end(out)}};
        return t;
    }
    t.decoded = std::move(out);
    return t;
}

}  // namespace

TapeText decode_tape_text(std::string_view bytes) {
    if (bytes.starts_with("\xFF\xFE")) return decode_utf16(bytes, false);
    if (bytes.starts_with("\xFE\xFF")) return decode_utf16(bytes, true);
    return {};
}

}  // namespace essi
