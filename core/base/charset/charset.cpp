// The parts of essi/charset.hpp that are the same on every platform: GB 18030's four-byte characters (a table and
// arithmetic, by the standard), so that ICU and musl's iconv, which differ there, are not asked.
#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>

#include "charset_platform.hpp"
#include "essi/charset.hpp"

namespace essi {
namespace {

struct FourByteRun {
    std::uint32_t index;
    char32_t code_point;
};
constexpr FourByteRun kFourByteRuns[] = {
#include "gb18030_four_byte.inc"
};
constexpr std::uint32_t kBmpFourByteCount = 39420;          // 81 30 81 30 .. 84 31 A4 39
constexpr std::uint32_t kSupplementaryFirstIndex = 189000;  // 90 30 81 30 = U+10000
constexpr char32_t kLastCodePoint = 0x10FFFF;

}  // namespace

void append_utf8(std::string& out, char32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

std::optional<char32_t> gb18030_four_byte_code_point(std::string_view c) {
    if (c.size() != 4) return std::nullopt;
    const auto b = [&](std::size_t k) { return static_cast<std::uint32_t>(static_cast<unsigned char>(c[k])); };
    if (b(0) < 0x81 || b(0) > 0xFE || b(1) < 0x30 || b(1) > 0x39 || b(2) < 0x81 || b(2) > 0xFE || b(3) < 0x30 ||
        b(3) > 0x39)
        return std::nullopt;
    const std::uint32_t index = (((b(0) - 0x81) * 10 + (b(1) - 0x30)) * 126 + (b(2) - 0x81)) * 10 + (b(3) - 0x30);
    if (index < kBmpFourByteCount) {
        const auto run = std::prev(std::upper_bound(std::begin(kFourByteRuns), std::end(kFourByteRuns), index,
                                                    [](std::uint32_t i, const FourByteRun& r) { return i < r.index; }));
        return static_cast<char32_t>(run->code_point + (index - run->index));
    }
    if (index < kSupplementaryFirstIndex) return std::nullopt;
    const char32_t cp = 0x10000 + (index - kSupplementaryFirstIndex);
    return cp <= kLastCodePoint ? std::optional<char32_t>(cp) : std::nullopt;
}

std::optional<std::string> gb18030_char_to_utf8(std::string_view character) {
    if (character.size() == 4) {
        const std::optional<char32_t> cp = gb18030_four_byte_code_point(character);
        if (!cp) return std::nullopt;
        std::string out;
        append_utf8(out, *cp);
        return out;
    }
    return detail::gb18030_two_byte_to_utf8(character);
}

}  // namespace essi
