// Safe text for reports (essi/text.hpp): UTF-8 validation and \xNN for what is not printable text.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "essi/functions.hpp"
#include "essi/profile.hpp"
#include "essi/text.hpp"

namespace {

using essi::display_text;
using essi::is_valid_utf8;

TEST(Text, ValidUtf8) {
    EXPECT_TRUE(is_valid_utf8("plain ASCII"));
    EXPECT_TRUE(
        is_valid_utf8("\xC3\x9C"
                      "ber \xE4\xB8\xAD\xE6\x96\x87 \xF0\x9F\x94\xA5"));  // Ü, 中文, an emoji
    EXPECT_FALSE(is_valid_utf8("\xFF"));
    EXPECT_FALSE(is_valid_utf8("\xC3"));              // cut off
    EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));          // overlong '/'
    EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));      // a surrogate
    EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));  // beyond U+10FFFF
    EXPECT_FALSE(is_valid_utf8("\x80"));              // a stray continuation byte
}

TEST(Text, DisplayTextKeepsTextAndNamesTheRest) {
    EXPECT_EQ(display_text("tapes/PR002.esi"), "tapes/PR002.esi");
    EXPECT_EQ(display_text("Z\xC3\xBC"
                           "ge/\xE9\x92\xA2\xE6\x9D\xBF.esi"),
              "Z\xC3\xBC"
              "ge/\xE9\x92\xA2\xE6\x9D\xBF.esi");
    EXPECT_EQ(display_text("bad\xFF\xFE.esi"), "bad\\xFF\\xFE.esi");
    EXPECT_EQ(display_text("a\x1B[31m\x7F\tb\n"), "a\\x1B[31m\\x7F\\x09b\\x0A");
    EXPECT_EQ(display_text(std::string("nul\0x", 5)), "nul\\x00x");
    EXPECT_EQ(display_text("\xE4\xB8"), "\\xE4\\xB8");  // a character cut off: its bytes
    EXPECT_TRUE(is_valid_utf8(display_text("\xC0\xAF\xED\xA0\x80\x80")));
}

TEST(Text, ExcerptQuotesTheStartAtACharacterBoundary) {
    EXPECT_EQ(essi::excerpt("12345", 12), "12345");
    EXPECT_EQ(essi::excerpt("123456789012345", 12), "123456789012...");
    EXPECT_EQ(essi::excerpt("ab\xE4\xB8\xAD"
                            "cd",
                            3),
              "ab...");  // not inside the 3-byte character
    EXPECT_EQ(essi::excerpt("ab\xE4\xB8\xAD"
                            "cd",
                            5),
              "ab\xE4\xB8\xAD...");
}

}  // namespace

TEST(Text, LengthsAsPeopleReadThem) {
    EXPECT_EQ(essi::length_text(0), "0.000 mm");
    EXPECT_EQ(essi::length_text(9999.9994), "9999.999 mm");
    EXPECT_EQ(essi::length_text(10000), "10.000 m");
    EXPECT_EQ(essi::length_text(184377774.914), "184 377.775 m");
    EXPECT_EQ(essi::length_text(-1234567.5), "-1 234.568 m");
    EXPECT_EQ(essi::length_text(1e12), "1 000 000 000.000 m");
}

TEST(Text, KerfValuesSayWidthOrOffset) {
    essi::Profile p;
    p.kerf_value = essi::KerfValueMeaning::Width;
    EXPECT_EQ(essi::kerf_value_text(2, p), "kerf width 2 mm (the torch 1 mm to the side)");
    p.kerf_value = essi::KerfValueMeaning::Offset;
    EXPECT_EQ(essi::kerf_value_text(1.5, p), "kerf offset 1.5 mm (a cut 3 mm wide)");
    EXPECT_EQ(essi::kerf_offset_text(essi::KerfSide::Left, 1.5), "torch 1.500 mm to the left (a cut 3.000 mm wide)");
    // a 29 block in words: the profile's kerf, as a width (iso6582)
    const essi::Profile iso;
    EXPECT_NE(
        essi::describe_function(29, false, 0, iso).find("the profile's kerf width 2 mm (the torch 1 mm to the side)"),
        std::string::npos)
        << essi::describe_function(29, false, 0, iso);
    EXPECT_NE(essi::describe_function(30, true, 30, iso).find("kerf width 3 mm"), std::string::npos);
}

namespace {

// Millimetres in messages (mm_text): three decimals, rounded, and never a negative zero.
TEST(Text, MillimetresHaveThreeDecimals) {
    EXPECT_EQ(essi::mm_text(12.5), "12.500");
    EXPECT_EQ(essi::mm_text(-3), "-3.000");
    EXPECT_EQ(essi::mm_text(0), "0.000");
    EXPECT_EQ(essi::mm_text(1234.56789), "1234.568");
    EXPECT_EQ(essi::mm_text(0.0004), "0.000");
    EXPECT_EQ(essi::mm_text(-0.0004), "0.000");  // (not "-0.000")
    EXPECT_EQ(essi::mm_text(-0.0), "0.000");
    EXPECT_EQ(essi::mm_text(-0.0006), "-0.001");
    EXPECT_EQ(essi::mm_text(3000), "3000.000");
    EXPECT_EQ(essi::mm_text(1e12), "1000000000000.000");
    EXPECT_EQ(essi::mm_text(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(essi::mm_text(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(essi::mm_text(std::nan("")), "nan");
    EXPECT_EQ(essi::mm_text(1e308).size(), 309u + 4u);  // every digit of the widest double
}

TEST(Text, FixedTextTakesItsDecimals) {
    EXPECT_EQ(essi::fixed_text(90, 1), "90.0");
    EXPECT_EQ(essi::fixed_text(-0.04, 1), "0.0");
    EXPECT_EQ(essi::fixed_text(2.25, 0), "2");
    EXPECT_EQ(essi::fixed_text(-1.5, 2), "-1.50");
    EXPECT_EQ(essi::length_text(1234.5674), "1234.567 mm");
    EXPECT_EQ(essi::length_text(-0.0001), "0.000 mm");
    EXPECT_EQ(essi::length_text(184377775), "184 377.775 m");
}

}  // namespace
