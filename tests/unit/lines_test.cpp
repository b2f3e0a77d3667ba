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
        expect_lines(t, 5);    // a pair CR LF split between two calls, an 8-byte skip past the slice
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
