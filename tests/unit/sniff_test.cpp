// "Is this a tape?" (essi/sniff.hpp): the rule the CLI uses to pick files of a folder and the viewer to tell
// what a file that draws nothing is.
#include <gtest/gtest.h>

#include <string>

#include "essi/sniff.hpp"

namespace {

using essi::looks_binary;
using essi::looks_like_essi;

TEST(Sniff, TapesAndOtherFiles) {
    EXPECT_TRUE(
        looks_like_essi("%\r\n3\r\nPART 12 - any text\r\n4\r\n39+3000\r\n+100+200\r\n7\r\n-100\r\n8\r\n63\r\n"));
    EXPECT_TRUE(looks_like_essi("\xEF\xBB\xBF+100+200\n-50+0\n64\n"));
    EXPECT_TRUE(looks_like_essi("+100+200\n+5+5 \n+1x\n0\n/\n"));  // one bad line of five is still a tape
    EXPECT_FALSE(looks_like_essi("# README\nSome text\n"));
    EXPECT_FALSE(looks_like_essi("{\"a\": 1}\n"));
    EXPECT_FALSE(looks_like_essi("1 fn 39 value=30 tools=-\n2 fn 29 tools=-\n"));  // a trace
    EXPECT_FALSE(looks_like_essi("123\n"));                                        // one line says nothing
    EXPECT_FALSE(looks_like_essi(std::string("+1+2\n\0\n+3+4\n", 12)));
    EXPECT_FALSE(looks_like_essi(""));
}

TEST(Sniff, BinaryBytes) {
    EXPECT_TRUE(looks_binary(std::string("+1+2\n\0", 6)));        // a NUL anywhere in the head
    EXPECT_FALSE(looks_binary("+100+200\r\n\t7\x0b\x0c\n63\n"));  // tab, VT, FF are text
    std::string mostly_text(100, '+');
    mostly_text[10] = '\x01';  // 1 control byte in 100
    EXPECT_FALSE(looks_binary(mostly_text));
    for (int k = 0; k < 5; ++k) mostly_text[20 + k] = '\x1b';  // 6 in 100: more than 1 in 20
    EXPECT_TRUE(looks_binary(mostly_text));
    EXPECT_FALSE(looks_like_essi(mostly_text + "\n+1+1\n"));
    EXPECT_FALSE(looks_binary(""));
    // Only the head counts: a NUL after kBinarySniffBytes does not make a tape binary.
    std::string late(essi::kBinarySniffBytes, '7');
    late += std::string(1, '\0');
    EXPECT_FALSE(looks_binary(late));
}

}  // namespace

// What cannot be a tape, by the core's rule (the viewer keeps the open tape then): nothing, a picture, an archive, a
// PDF, binary data; text is left to the reader, whatever it holds.
TEST(Sniff, NotATapeSaysWhatTheFileIs) {
    using essi::Lang;
    const auto said = [](std::string_view bytes) { return essi::not_a_tape(bytes).text(Lang::En); };
    EXPECT_EQ(said(""), "the file is empty");
    EXPECT_EQ(said(std::string("\x89PNG\r\n\x1A\n\0\0\0\rIHDR", 16)), "it is a PNG picture");
    EXPECT_EQ(said("\xFF\xD8\xFF\xE0\x00\x10JFIF"), "it is a JPEG picture");
    EXPECT_EQ(said("GIF89a\x01\x00"), "it is a GIF picture");
    EXPECT_EQ(said(std::string("PK\x03\x04\x14\0\0\0", 8)), "it is a ZIP archive");
    EXPECT_EQ(said(std::string("\x1F\x8B\x08\0", 4)), "it is a gzip archive");
    EXPECT_EQ(said("%PDF-1.7\n%\xE2\xE3\xCF\xD3\n"), "it is a PDF document");
    EXPECT_EQ(said(std::string("+100\0+200\n", 10)), "it is a binary file (a tape is text: + - digits and line ends)");
    EXPECT_EQ(essi::not_a_tape("%\n+100+0\n").msg, essi::Msg::None);
    EXPECT_EQ(essi::not_a_tape("Hello, a letter\n").msg, essi::Msg::None);  // (text: its diagnostics say it)
    EXPECT_EQ(essi::not_a_tape("\n").msg, essi::Msg::None);
    EXPECT_EQ(essi::not_a_tape("%PDF-1.7").text(Lang::De), "es ist ein PDF-Dokument");
}
