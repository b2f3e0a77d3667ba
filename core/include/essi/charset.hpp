// Conversions between UTF-8 and the Chinese charsets of GB/T 22217 shops (GB 18030, GBK, GB 2312). GB 18030's
// four-byte characters are the standard's table and arithmetic (core/base/charset/charset.cpp, every build); the
// two-byte characters and the encoders come from one implementation per platform, chosen by CMake
// (core/CMakeLists.txt, ESSI_CHARSET):
//   core/base/charset/charset_icu.cpp    ICU's converters (native builds; links statically, so the static `essi`
//                                         converts in an empty root, where glibc's iconv has no modules)
//   core/base/charset/charset_iconv.cpp  the C library's iconv (Emscripten's musl: decoders only)
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace essi {

// Appends the UTF-8 of a code point (at most U+10FFFF) to `out`.
void append_utf8(std::string& out, char32_t code_point);

// The UTF-8 of one well-formed GB 18030 character (2 or 4 bytes), or nullopt when it is none.
[[nodiscard]] std::optional<std::string> gb18030_char_to_utf8(std::string_view character);

// The code point of a four-byte GB 18030 character (81 30 81 30 .. 84 31 A4 39: the rest of the BMP by the
// standard's runs; 90 30 81 30 .. E3 32 9A 35: U+10000 .. U+10FFFF), or nullopt.
[[nodiscard]] std::optional<char32_t> gb18030_four_byte_code_point(std::string_view character);

// `utf8` in `charset` ("GB18030", "GBK" or "GB2312"): a character the charset has no code for, and each byte that
// is not UTF-8, becomes '?'. nullopt when the platform has no converter for `charset` (Emscripten: none of them).
[[nodiscard]] std::optional<std::string> utf8_to_charset(std::string_view utf8, const char* charset);

}  // namespace essi
