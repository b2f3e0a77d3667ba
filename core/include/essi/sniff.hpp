// "Is this a tape?": what the first bytes of a file say about it, for the CLI (which files of a folder to check)
// and the viewer (which files it opens, what to tell about a file that draws nothing). One rule for both.
#pragma once

#include <cstddef>
#include <string_view>

#include "essi/i18n.hpp"

namespace essi {

// Bytes from the start of a file that the sniffing looks at.
constexpr std::size_t kSniffBytes = 1024;
// Bytes looks_binary looks at.
constexpr std::size_t kBinarySniffBytes = 4096;

// True when the start of `bytes` is not text: a NUL byte, or more than one byte in 20 a control character other
// than tab, line ends, vertical tab and form feed.
[[nodiscard]] bool looks_binary(std::string_view bytes);

// True when `head` (the first kSniffBytes of a file) looks like an ESSI tape: not binary, and outside 3/4
// comment sections at least 2 non-empty lines, of which at least 80 % hold only + - 0-9 (spaces, tabs
// allowed), or are % or /, and at least one holds a digit. A UTF-8 byte order mark is skipped.
[[nodiscard]] bool looks_like_essi(std::string_view head);

// Why a file's text (decode_tape_text, essi/text_encoding.hpp) cannot be a tape, or Msg::None when it may be one:
// it is empty, it starts with the signature of a picture (PNG, JPEG, GIF), an archive (ZIP, gzip) or a PDF, or it
// looks_binary. (Text that is no tape is read and its diagnostics say so.)
[[nodiscard]] Message not_a_tape(std::string_view text);

}  // namespace essi
