// Comments written in UTF-8 or GB 18030 / GBK: detected per tape and decoded to UTF-8 (essi/text_encoding.hpp).
#include <gtest/gtest.h>

#include <string>

#include "essi/text_encoding.hpp"

using essi::TextEncoding;

namespace {
// "切割" (cut) and "零件 A1" (part A1) in GBK / GB 18030, and the same in UTF-8.
const std::string kGbCut = "\xC7\xD0\xB8\xEE";
const std::string kGbPart = "\xC1\xE3\xBC\xFE A1";
const std::string kUtf8Cut = "\xE5\x88\x87\xE5\x89\xB2";
}  // namespace

TEST(TextEncoding, DetectsUtf8AndGb18030PerTape) {
    EXPECT_EQ(essi::detect_text_encoding("3\n+100+0\n4\n"), TextEncoding::Utf8);  // ASCII: either
    EXPECT_EQ(essi::detect_text_encoding("3\n" + kUtf8Cut + "\n4\n7\n"), TextEncoding::Utf8);
    EXPECT_EQ(essi::detect_text_encoding("3\n" + kGbCut + "\n" + kGbPart + "\n4\n7\n"), TextEncoding::Gb18030);
    // A four-byte GB 18030 character (U+00E4, "ä": 81 30 8A 31).
    EXPECT_EQ(essi::detect_text_encoding("3\nK\x81\x30\x8A\x31se\n4\n"), TextEncoding::Gb18030);
    // Bytes that are neither: UTF-8 (and shown as \xNN).
    EXPECT_EQ(essi::detect_text_encoding("3\n\xFF\xFF\n4\n"), TextEncoding::Utf8);
}

TEST(TextEncoding, DecodesGb18030ToUtf8) {
    EXPECT_EQ(essi::decode_text(kGbCut, TextEncoding::Gb18030), kUtf8Cut);
    EXPECT_EQ(essi::decode_text(kGbPart, TextEncoding::Gb18030), "\xE9\x9B\xB6\xE4\xBB\xB6 A1");
    EXPECT_EQ(essi::decode_text("K\x81\x30\x8A\x31se", TextEncoding::Gb18030), "K\xC3\xA4se");
    // A control character and a lead byte with nothing after it: \xNN, the rest decoded.
    EXPECT_EQ(essi::decode_text("a\x01" + kGbCut + "\xC7", TextEncoding::Gb18030), "a\\x01" + kUtf8Cut + "\\xC7");
}

TEST(TextEncoding, Utf8IsShownAsItIs) {
    EXPECT_EQ(essi::decode_text(kUtf8Cut + " 7", TextEncoding::Utf8), kUtf8Cut + " 7");
    // GBK read as UTF-8: what is no UTF-8 as bytes (D0 B8 happens to be UTF-8's "и").
    EXPECT_EQ(essi::decode_text(kGbCut, TextEncoding::Utf8), "\\xC7\xD0\xB8\\xEE");
}

TEST(TextEncoding, NamesOfTheSetting) {
    EXPECT_EQ(essi::parse_text_encoding("UTF-8"), TextEncoding::Utf8);
    EXPECT_EQ(essi::parse_text_encoding("gbk"), TextEncoding::Gb18030);
    EXPECT_EQ(essi::parse_text_encoding("GB_18030"), TextEncoding::Gb18030);
    EXPECT_FALSE(essi::parse_text_encoding("latin1").has_value());
    EXPECT_EQ(essi::text_encoding_name(TextEncoding::Gb18030), "gb18030");
}

namespace {
// `text` (ASCII and "切割") in UTF-16, little-endian or big-endian, with its byte order mark.
std::string utf16(const std::u16string& text, bool big_endian) {
    std::string out = big_endian ? "\xFE\xFF" : "\xFF\xFE";
    for (const char16_t u : text) {
        const char hi = static_cast<char>(u >> 8), lo = static_cast<char>(u & 0xFF);
        out += big_endian ? std::string{hi, lo} : std::string{lo, hi};
    }
    return out;
}
}  // namespace

// A tape saved as UTF-16 with a byte order mark is read as its UTF-8 text without the mark (a character beyond the
// BMP from its surrogate pair); other bytes are the text as they are.
TEST(TapeText, Utf16WithAByteOrderMarkBecomesUtf8) {
    const std::u16string tape = u"3\r\n切割 \U0001F527\r\n4\r\n+100+0\r\n";
    const std::string want = "3\r\n" + kUtf8Cut + " \xF0\x9F\x94\xA7\r\n4\r\n+100+0\r\n";
    for (const bool big_endian : {false, true}) {
        const essi::TapeText t = essi::decode_tape_text(utf16(tape, big_endian));
        EXPECT_TRUE(t.ok());
        ASSERT_TRUE(t.decoded.has_value());
        EXPECT_EQ(*t.decoded, want);
    }
    EXPECT_EQ(*essi::decode_tape_text(utf16(u"", false)).decoded, "");
    for (const std::string plain : {"3\n+100+0\n", "\xEF\xBB\xBF+100+0\n", "", "\xFF"}) {
        const essi::TapeText t = essi::decode_tape_text(plain);
        EXPECT_TRUE(t.ok());
        EXPECT_FALSE(t.decoded.has_value()) << plain;
    }
}

// UTF-16 that is no text: the message says which order, what and where (the byte, and the line of the decoded text).
TEST(TapeText, BadUtf16SaysWhere) {
    const essi::TapeText odd = essi::decode_tape_text(utf16(u"+1\n+2\n", false) + "x");
    EXPECT_FALSE(odd.ok());
    EXPECT_FALSE(odd.decoded.has_value());
    EXPECT_EQ(odd.problem.text(essi::Lang::En),
              "the file is UTF-16 LE text with an odd number of bytes (15): its last byte, on line 3, is half a "
              "character");
    const std::u16string lone_high = u"+1\r\n+2\r\n\xD800+";
    const essi::TapeText high = essi::decode_tape_text(utf16(lone_high, true));
    EXPECT_EQ(high.problem.text(essi::Lang::En),
              "the file is UTF-16 BE text with an unpaired surrogate D800 at byte 18 (line 3): it is no character");
    const essi::TapeText low = essi::decode_tape_text(utf16(u"\xDC01", false));
    EXPECT_EQ(low.problem.text(essi::Lang::En),
              "the file is UTF-16 LE text with an unpaired surrogate DC01 at byte 2 (line 1): it is no character");
    const essi::TapeText at_end = essi::decode_tape_text(utf16(u"+1\n\xD83D", false));
    EXPECT_EQ(at_end.problem.text(essi::Lang::De),
              "die Datei ist UTF-16-LE-Text mit einem ungepaarten Surrogat D83D bei Byte 8 (Zeile 2): es ist kein "
              "Zeichen");
}
