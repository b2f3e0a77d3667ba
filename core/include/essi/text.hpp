// Text that goes into a report, a terminal or a markup file: valid UTF-8 and no control characters, whatever
// bytes it was made from (a file name on Linux is any bytes but NUL and '/').
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace essi {

// The length of the valid UTF-8 character at s[i] (1-4), or 0 when the bytes there are not one (a stray
// continuation byte, an overlong form, a surrogate, beyond U+10FFFF, cut off).
[[nodiscard]] std::size_t utf8_char_length(std::string_view s, std::size_t i);
// The columns UTF-8 text takes in a terminal: 2 for each East Asian wide character (CJK, fullwidth forms), 1 for
// every other character.
[[nodiscard]] std::size_t display_width(std::string_view utf8);
[[nodiscard]] bool is_valid_utf8(std::string_view s);

// `s` as text that is safe to print anywhere: valid UTF-8 characters are kept, every other byte and every control
// character (below U+0020, and DEL) is written as \xNN. Text that is already safe comes back unchanged.
[[nodiscard]] std::string display_text(std::string_view s);

// What a message quotes of input text: all of it when it has at most `max_bytes` bytes, else its start (cut at a
// character boundary) and "...", so that a message never grows with the input.
[[nodiscard]] std::string excerpt(std::string_view text, std::size_t max_bytes);

// A number as a message writes it: up to 10 significant digits, no trailing zeros ("1400", "0.5", "3600001",
// "1e+10"): a value of a tape or a setting of a profile, as it was written.
[[nodiscard]] std::string number_text(double v);
// A number with `decimals` decimals, never "-0.000" (a value that rounds to zero is zero); "inf", "-inf" and "nan"
// for what is not a finite number.
[[nodiscard]] std::string fixed_text(double v, int decimals);
// Millimetres measured on a tape or its machine (a length, a size, a position, a distance, a tolerance), as every
// message and report writes them: kMmDecimals decimals, without the unit ("12.500", "-3.000", "0.000").
constexpr int kMmDecimals = 3;  // 1 micrometre
[[nodiscard]] std::string mm_text(double mm);
// Text for XML (JUnit, SVG): & < > " ' as entities, control characters but tab, CR and LF as '?'.
[[nodiscard]] std::string xml_escape(std::string_view s);
// A length as people read it: "1234.567 mm" below 10 m (mm_text), "184 377.775 m" (thousands apart) from 10 m on.
[[nodiscard]] std::string length_text(double mm);
// A count as people read it, the thousands apart: "58 780", "1 000 000", "999".
[[nodiscard]] std::string count_text(std::uint64_t n);

}  // namespace essi
