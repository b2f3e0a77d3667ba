// The line-end rule and the line index (essi/lines.hpp): the same lines as the rule written out plainly, built
// whole or a few bytes at a time, and the same line numbers as the reader's blocks.
#include <gtest/gtest.h>

#include <string>

#include "../bench/nest_generator.hpp"
#include "essi/lines.hpp"
#include "essi/read.hpp"
#include "test_util.hpp"

namespace {

using essi::LineIndex;
using essi_test::split_lines;

void expect_lines(const std::string& text, std::size_t slice) {
    SCOPED_TRACE("slice " + std::to_string(slice) + ", " + std::to_string(text.size()) + " bytes");
    LineIndex index;
    std::size_t calls = 0;
    while (!index.build(text, slice)) ASSERT_LT(++calls, text.size() + 2) << "the index makes no progress";
    EXPECT_TRUE(index.done(text));
    const auto want = split_lines(text);
    ASSERT_EQ(index.line_count(), want.size());
    std::size_t signed_lines = 0;
    for (std::size_t n = 1; n <= want.size(); ++n) {
        ASSERT_EQ(index.line(text, n), want[n - 1]) << "line " << n;
        signed_lines += !want[n - 1].empty() && (want[n - 1][0] == '+' || want[n - 1][0] == '-');
    }
    EXPECT_EQ(index.signed_lines(), signed_lines);
    EXPECT_EQ(index.line(text, 0), "");
    EXPECT_EQ(index.line(text, want.size() + 1), "");
}

TEST(LineIndex, SameLinesAsTheRule) {
    const std::string tricky = essi_test::tricky_lines_text();
    for (const std::string& t : {tricky, tricky + "\n", tricky + "\r\n", std::string("\n\r\n"), std::string("7"),
                                 essi::bench::generate_nest_tape(100000, 2)}) {
        expect_lines(t, static_cast<std::size_t>(-1));
        expect_lines(t, 5);  // a pair CR LF split between two calls, an 8-byte skip past the slice
        expect_lines(t, 4096);
    }
}

TEST(LineIndex, EmptyBytesHaveNoLine) {
    LineIndex index;
    EXPECT_TRUE(index.build(""));
    EXPECT_EQ(index.line_count(), 0u);
    EXPECT_EQ(index.line("", 1), "");
}

TEST(LineIndex, LinesOfTheReadersBlocks) {
    // Every block's line number finds the block's own line, and column_of/line_text agree with the index.
    std::string text = essi_test::tricky_lines_text();
    const essi::Tape tape = essi::read_tape(text, *essi::builtin_profile("iso6582"));
    LineIndex index;
    index.build(text);
    ASSERT_GT(tape.size(), 300u);
    for (const essi::Block& b : tape.blocks()) {
        const std::string_view line = index.line(text, b.line);
        ASSERT_EQ(line, essi::line_text(text, b.offset)) << "line " << b.line;
        ASSERT_EQ(text.data() + b.offset - (essi::column_of(text, b.offset) - 1), line.data()) << "line " << b.line;
    }
}

}  // namespace

namespace {

// find_line_end against the rule written out plainly, from every position of text with tabs, control bytes,
// lines longer than eight bytes and every kind of line end.
TEST(Lines, FindLineEndIsTheFirstCrOrLf) {
    const std::string text =
        "+100+200\n\t7\r\n0123456789abcdefghij\x01\x0B\x0D\n\r\n\x0C"
        "end";
    for (std::size_t pos = 0; pos <= text.size(); ++pos) {
        std::size_t want = pos;
        while (want < text.size() && text[want] != '\n' && text[want] != '\r') ++want;
        EXPECT_EQ(essi::find_line_end(text, pos), want) << "from " << pos;
    }
    EXPECT_EQ(essi::find_line_end("", 0), 0u);
    EXPECT_EQ(essi::find_line_end("abc", 3), 3u);
    EXPECT_EQ(essi::find_line_end(std::string(100, 'x') + "\r", 0), 100u);
    EXPECT_EQ(essi::find_line_end(std::string(100, '\t'), 5), 100u);
}

TEST(Lines, FindLineStartIsAfterTheLineEndBefore) {
    const std::string text = "ab\r\ncd\nef";
    EXPECT_EQ(essi::find_line_start(text, 0), 0u);
    EXPECT_EQ(essi::find_line_start(text, 2), 0u);  // (the CR ends line 1)
    EXPECT_EQ(essi::find_line_start(text, 3), 3u);  // (the LF after it: an empty start, as line_text has it)
    EXPECT_EQ(essi::find_line_start(text, 5), 4u);
    EXPECT_EQ(essi::find_line_start(text, 9), 7u);
    EXPECT_EQ(essi::line_text(text, 5), "cd");
    EXPECT_EQ(essi::line_text(text, 8), "ef");
    EXPECT_EQ(essi::column_of(text, 8), 2u);
}

// Tapes with CR line ends only: a line's end is found without a search to the end of the bytes (an EIA tape of
// 20 000 such lines is read at once).
TEST(Lines, CrOnlyTapesReadLineByLine) {
    std::string tape = "%\r";
    for (int i = 0; i < 20000; ++i) tape += "G01 X1 Y1\r";
    tape += "M30\r";
    std::size_t lines = 0;
    for (std::size_t pos = 0; pos < tape.size(); pos = essi::find_line_end(tape, pos) + 1) ++lines;
    EXPECT_EQ(lines, 20002u);
}

}  // namespace
