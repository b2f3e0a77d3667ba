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
