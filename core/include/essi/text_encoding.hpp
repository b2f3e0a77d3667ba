// The text of comments: what a 3 ... 4 ignore section (or an EIA "( ... )") holds is free text, written in the
// encoding of the CAM system that made the tape — UTF-8, or GB 18030 / GBK in Chinese yards (GB/T 22217). The
// tape does not say which: detect_text_encoding looks at every byte above ASCII, decode_text makes UTF-8 of it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "essi/i18n.hpp"

namespace essi {

enum class TextEncoding : unsigned char {
    Utf8,     // UTF-8 (ASCII is both)
    Gb18030,  // GB 18030 (a superset of GBK and GB 2312)
};

// "utf-8", "gb18030" (the names the viewer's setting and the automation API use).
[[nodiscard]] std::string_view text_encoding_name(TextEncoding e);
// "utf-8" / "utf8", "gb18030" / "gbk" / "gb2312" (any case); nullopt otherwise.
[[nodiscard]] std::optional<TextEncoding> parse_text_encoding(std::string_view name);

// The encoding of a tape's text: UTF-8 when every byte above ASCII is part of a well-formed UTF-8 character,
// else GB 18030 when they all are part of well-formed GB 18030 characters, else UTF-8 (bytes that fit neither
// are shown as \xNN). Looks at the whole tape once.
[[nodiscard]] TextEncoding detect_text_encoding(std::string_view bytes);

// `bytes` as UTF-8: as they are for Utf8 (malformed bytes as \xNN, control characters too: display_text), decoded
// by essi/charset.hpp for Gb18030 (a byte that is no GB 18030 character as \xNN).
[[nodiscard]] std::string decode_text(std::string_view bytes, TextEncoding encoding);

// A file's bytes as the text of a tape. UTF-16 with a byte order mark (FF FE: little-endian, FE FF: big-endian) is
// decoded to UTF-8 without the mark (the line and column of what is found in it are those of the decoded text);
// any other bytes are the text as they are (a UTF-8 mark too: the reader says it is there).
struct TapeText {
    std::optional<std::string> decoded;  // the UTF-8 text of UTF-16 bytes (nullopt: the bytes are the text)
    Message problem;  // UTF-16 that is no text: an odd number of bytes, an unpaired surrogate (where: byte, line)
    [[nodiscard]] bool ok() const { return problem.msg == Msg::None; }
};
[[nodiscard]] TapeText decode_tape_text(std::string_view bytes);

}  // namespace essi
