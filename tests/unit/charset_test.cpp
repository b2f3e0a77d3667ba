// essi/charset.hpp: the same decoding from ICU (native) and musl's iconv (WASM), GB 18030's four-byte characters
// from the standard's table in both; the encoders natively (musl has none: nullopt under Emscripten).
#include <gtest/gtest.h>

#include <string>

#include "essi/charset.hpp"

namespace {
const std::string kUtf8Chinese = "\xE4\xB8\xAD\xE6\x96\x87";  // 中文
const std::string kGbChinese = "\xD6\xD0\xCE\xC4";            // 中文 in GB 2312 / GBK / GB 18030
}  // namespace

TEST(Charset, Gb18030CharactersToUtf8) {
    EXPECT_EQ(essi::gb18030_char_to_utf8("\xD6\xD0"), "\xE4\xB8\xAD");
    EXPECT_EQ(essi::gb18030_char_to_utf8("\x81\x30\x8A\x31"), "\xC3\xA4");          // a four-byte character: U+00E4
    EXPECT_EQ(essi::gb18030_char_to_utf8("\x84\x31\xA4\x39"), "\xEF\xBF\xBF");      // the last of the BMP: U+FFFF
    EXPECT_EQ(essi::gb18030_char_to_utf8("\x90\x30\x81\x30"), "\xF0\x90\x80\x80");  // beyond it: U+10000
    EXPECT_EQ(essi::gb18030_char_to_utf8("\xE3\x32\x9A\x35"), "\xF4\x8F\xBF\xBF");  // the last: U+10FFFF
}

TEST(Charset, FourByteCharactersByTheStandardsRuns) {
    EXPECT_EQ(essi::gb18030_four_byte_code_point("\x81\x30\x81\x30"), U'\u0080');  // the first
    EXPECT_EQ(essi::gb18030_four_byte_code_point("\x81\x30\x84\x36"), U'\u00A5');  // a new run
    EXPECT_EQ(essi::gb18030_four_byte_code_point("\x82\x35\x87\x39"), U'\u4DB6');  // after CJK Extension A
    EXPECT_EQ(essi::gb18030_four_byte_code_point("\x84\x31\xA4\x39"), U'\uFFFF');
    EXPECT_FALSE(essi::gb18030_four_byte_code_point("\xE3\x32\x9A\x36").has_value());  // past U+10FFFF
    EXPECT_FALSE(essi::gb18030_four_byte_code_point("\x81\x30\x81").has_value());
}

TEST(Charset, WhatIsNoGb18030CharacterIsRefused) {
    EXPECT_FALSE(essi::gb18030_char_to_utf8("\x84\x31\xA5\x30").has_value());  // between the BMP and U+10000
    EXPECT_FALSE(essi::gb18030_char_to_utf8("\xFF\x30").has_value());          // no lead byte
}

#if defined(__EMSCRIPTEN__)
// musl's iconv has no GB encoders: the text stays UTF-8 (essi/charset.hpp).
TEST(Charset, NoEncodersUnderEmscripten) {
    for (const char* charset : {"GB18030", "GBK", "GB2312"})
        EXPECT_FALSE(essi::utf8_to_charset(kUtf8Chinese, charset).has_value()) << charset;
}
#else
TEST(Charset, Utf8ToTheChineseCharsets) {
    EXPECT_EQ(essi::utf8_to_charset(kUtf8Chinese + " A1", "GB18030"), kGbChinese + " A1");
    EXPECT_EQ(essi::utf8_to_charset(kUtf8Chinese, "GBK"), kGbChinese);
    EXPECT_EQ(essi::utf8_to_charset(kUtf8Chinese, "GB2312"), kGbChinese);
    EXPECT_EQ(essi::utf8_to_charset("K\xC3\xA4se", "GB18030"), "K\x81\x30\x8A\x31se");
}

TEST(Charset, WhatTheCharsetLacksBecomesAQuestionMark) {
    // "ä" has no code in GB 2312; a byte that is no UTF-8 none in any charset.
    EXPECT_EQ(essi::utf8_to_charset("K\xC3\xA4se", "GB2312"), "K?se");
    EXPECT_EQ(essi::utf8_to_charset("a\xFF"
                                    "b" +
                                        kUtf8Chinese,
                                    "GB18030"),
              "a?b" + kGbChinese);
    EXPECT_EQ(essi::utf8_to_charset("", "GB18030"), "");
}
#endif

TEST(Charset, AnUnknownCharsetHasNoConverter) {
    EXPECT_FALSE(essi::utf8_to_charset("abc", "NO-SUCH-CHARSET-6582").has_value());
}
