// What each platform's converter gives essi/charset.hpp (charset_icu.cpp natively, charset_iconv.cpp under
// Emscripten): GB 18030's two-byte characters, the table of GBK and GB 2312 that the platform's library holds.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace essi::detail {

// The UTF-8 of one two-byte GB 18030 character, or nullopt when the converter refuses it.
[[nodiscard]] std::optional<std::string> gb18030_two_byte_to_utf8(std::string_view character);

}  // namespace essi::detail
