// Conversions between UTF-8 and the Chinese charsets of GB/T 22217 shops (GB 18030, GBK, GB 2312): one
// implementation per platform, chosen by CMake (core/CMakeLists.txt, ESSI_CHARSET):
//   core/base/charset/charset_icu.cpp    ICU's converters (native builds; links statically, so the static `essi`
//                                         decodes GB 18030 in an empty root, where glibc's iconv has no modules)
//   core/base/charset/charset_iconv.cpp  the C library's iconv (Emscripten's musl, which has GB 18030 built in)
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace essi {

// The UTF-8 of one well-formed GB 18030 character (2 or 4 bytes), or nullopt when the converter refuses it.
[[nodiscard]] std::optional<std::string> gb18030_char_to_utf8(std::string_view character);

// `utf8` in `charset` ("GB18030", "GBK" or "GB2312"): a character the charset has no code for, and each byte that
// is not UTF-8, becomes '?'. nullopt when the platform has no converter for `charset`.
[[nodiscard]] std::optional<std::string> utf8_to_charset(std::string_view utf8, const char* charset);

}  // namespace essi
