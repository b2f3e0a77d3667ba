// Phase 1 (read): characters, line ends, words and block types (docs/semantics.md §1-§2).
// Every expectation is worked out by hand from the rules, never copied from the reader's output.
#include <gtest/gtest.h>

#include <algorithm>

#include <string>
#include <vector>

#include "essi/read.hpp"
#include "essi/pipeline.hpp"
#include "test_util.hpp"

using namespace essi;
using namespace essi_test;

namespace {

Tape rd(std::string_view text, const Profile& p = Profile{}) { return read_tape(text, p); }

std::vector<std::int32_t> words_of(const Tape& t, std::size_t i) {
    auto w = t.words(i);
    return {w.begin(), w.end()};
}

// The blocks that are not Comment / Percent / EndMark (what the program executes).
std::vector<Block> program_blocks(const Tape& t) {
    std::vector<Block> out;
    for (const auto& b : t.blocks())
        if (b.kind == BlockKind::Function || b.kind == BlockKind::FunctionValue || b.kind == BlockKind::Motion)
            out.push_back(b);
    return out;
}

}  // namespace

// ---------------------------------------------------------------- line ends

TEST(ReadLineEnds, CrLf) {
    const std::string src = "7\r\n+100+0\r\n8\r\n64\r\n";
    Tape t = rd(src);
    ASSERT_EQ(t.size(), 4u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(0).line, 1u);
    EXPECT_EQ(t.block(1).line, 2u);
    EXPECT_EQ(t.block(2).line, 3u);
    EXPECT_EQ(t.block(3).line, 4u);
    // offsets: "7" 0, "\r\n" 1-2, "+100+0" 3..8, "\r\n" 9-10, "8" 11, "\r\n", "64" 14
    EXPECT_EQ(t.block(0).offset, 0u);
    EXPECT_EQ(t.block(1).offset, 3u);
    EXPECT_EQ(t.block(2).offset, 11u);
    EXPECT_EQ(t.block(3).offset, 14u);
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

TEST(ReadLineEnds, EachKindCountsOneLine) {
    // 7 CRLF 8 LF 9 CR 10 LFCR 11 LF 64
    const std::string src = "7\r\n8\n9\r10\n\r11\n64";
    Tape t = rd(src);
    ASSERT_EQ(t.size(), 6u) << dump(t.diagnostics());
    const std::uint16_t codes[] = {7, 8, 9, 10, 11, 64};
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(t.block(i).kind, BlockKind::Function) << i;
        EXPECT_EQ(t.block(i).code, codes[i]) << i;
        EXPECT_EQ(t.block(i).line, i + 1) << "block " << i;
    }
}

TEST(ReadLineEnds, LfCrTape) {
    Tape t = rd("7\n\r8\n\r64\n\r");
    ASSERT_EQ(t.size(), 3u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(0).line, 1u);
    EXPECT_EQ(t.block(1).line, 2u);
    EXPECT_EQ(t.block(2).line, 3u);
}

TEST(ReadLineEnds, EmptyBlocksCountLines) {
    struct Case {
        const char* src;
        std::uint32_t line_of_8;
    };
    const Case cases[] = {
        {"7\n\n8\n64\n", 3},          // LF LF
        {"7\r\r8\r64\r", 3},          // CR CR
        {"7\r\n\r\n8\r\n64\r\n", 3},  // CRLF CRLF
        {"7\n\r\n\r8\n\r64\n\r", 3},  // LFCR LFCR
        {"7\r\n\n8\n64\n", 3},        // CRLF LF
        {"7\n\r\r8\r64\r", 3},        // LFCR CR
        {"7\n\n\n\n8\n64\n", 5},      // four LF
        {"7\r\n\r\n\r\n8\r\n64\r\n", 4},
    };
    for (const auto& c : cases) {
        Tape t = rd(c.src);
        ASSERT_EQ(t.size(), 3u) << "tape: " << ::testing::PrintToString(std::string(c.src));
        EXPECT_EQ(t.block(1).code, 8);
        EXPECT_EQ(t.block(1).line, c.line_of_8) << ::testing::PrintToString(std::string(c.src));
        EXPECT_EQ(t.block(2).line, c.line_of_8 + 1) << ::testing::PrintToString(std::string(c.src));
    }
}

TEST(ReadLineEnds, LeadingBlockEndCharacters) {
    Tape t = rd("\r\n\r\n7\r\n64\r\n");
    ASSERT_EQ(t.size(), 2u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(0).code, 7);
    EXPECT_EQ(t.block(0).line, 3u);
    EXPECT_EQ(t.block(0).offset, 4u);
    EXPECT_EQ(t.block(1).line, 4u);
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

TEST(ReadLineEnds, NoFinalLineEnd) {
    Tape t = rd("7\n+100+0\n8\n64");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t.block(3).code, 64);
    EXPECT_EQ(t.block(3).line, 4u);
    EXPECT_TRUE(t.has_program_end());
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

// ---------------------------------------------------------------- %, / and the end

TEST(ReadMarks, PercentAtStartAndAfterEnd) {
    Tape t = rd("%\r\n7\r\n+100+0\r\n8\r\n64\r\n%\r\n");
    ASSERT_EQ(t.size(), 6u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(0).kind, BlockKind::Percent);
    EXPECT_EQ(t.block(1).kind, BlockKind::Function);
    EXPECT_EQ(t.block(1).line, 2u);
    EXPECT_EQ(t.block(4).code, 64);
    EXPECT_EQ(t.block(5).kind, BlockKind::Percent);
    EXPECT_EQ(t.block(5).line, 6u);
    EXPECT_TRUE(t.has_program_end());
    EXPECT_EQ(t.end_block(), 5u);  // first block after the 64
    // the rewind-stop % after the end is accepted: no W110, no W112, nothing at all
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

const Profile& woyda() {
    static const Profile p = *builtin_profile("woyda");
    return p;
}

TEST(ReadMarks, SlashEndsTheProgram) {
    Tape t = rd("7\n+100+0\n8\n/\n", woyda());
    ASSERT_EQ(t.size(), 4u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(3).kind, BlockKind::EndMark);
    EXPECT_EQ(t.block(3).line, 4u);
    EXPECT_TRUE(t.has_program_end());
    EXPECT_EQ(t.end_block(), 4u);
    EXPECT_FALSE(has_code(t.diagnostics(), DiagCode::W114_NoProgramEnd));
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

TEST(ReadMarks, Code63And64End) {
    for (const char* src : {"7\n8\n63\n", "7\n8\n64\n"}) {
        Tape t = rd(src, woyda());
        EXPECT_TRUE(t.has_program_end()) << src;
        EXPECT_EQ(t.end_block(), 3u) << src;
        EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
    }
}

TEST(ReadMarks, IsoEndsAt64OrTheEndOfTheData) {
    Tape t = rd("7\n8\n63\n+100+0\n");
    EXPECT_FALSE(t.has_program_end());
    EXPECT_EQ(t.end_block(), 4u);
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());  // no W114: the data ends the tape (ISO)
    EXPECT_TRUE(rd("7\n8\n64\n").has_program_end());
    // '/' is Woyda's end mark: not an ESSI character under ISO
    EXPECT_TRUE(has_code(rd("7\n8\n/\n").diagnostics(), DiagCode::E101_InvalidCharacter));
}

TEST(ReadMarks, NoEndW114) {
    Tape t = rd("7\n+100+0\n8\n", woyda());
    EXPECT_FALSE(t.has_program_end());
    EXPECT_EQ(t.end_block(), t.size());
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::W114_NoProgramEnd);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->severity, Severity::Warning);
    EXPECT_NE(essi::diagnostic_message(*d, essi::Lang::En).find("expected 63, 64 or / as the last block"),
              std::string::npos)
        << essi::diagnostic_message(*d, essi::Lang::En);
    EXPECT_FALSE(t.has_errors());
}

TEST(ReadMarks, ContentAfterEndW110) {
    Tape t = rd("7\n8\n64\n+100+0\n");
    EXPECT_TRUE(t.has_program_end());
    EXPECT_EQ(t.end_block(), 3u);
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::W110_ContentAfterEnd);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->severity, Severity::Warning);
    EXPECT_EQ(d->line, 4u);
    EXPECT_FALSE(t.has_errors());
}

TEST(ReadMarks, ContentAfterSlashW110) {
    Tape t = rd("7\n8\n/\n9\n", woyda());
    EXPECT_EQ(t.end_block(), 3u);
    ASSERT_TRUE(has_code(t.diagnostics(), DiagCode::W110_ContentAfterEnd)) << dump(t.diagnostics());
    EXPECT_EQ(find_code(t.diagnostics(), DiagCode::W110_ContentAfterEnd)->line, 4u);
}

TEST(ReadMarks, MisplacedPercentW112) {
    Tape t = rd("7\n%\n8\n64\n");
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::W112_MisplacedPercent);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->line, 2u);
}

TEST(ReadMarks, MarkWithOtherCharactersE116) {
    Tape t = rd("%7\n7\n64\n");
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E116_MisplacedMark);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->line, 1u);
    EXPECT_TRUE(t.has_errors());
}

TEST(ReadMarks, EmptyTapeE113) {
    for (const char* src : {"", "\r\n\r\n", "\n"}) {
        Tape t = rd(src);
        EXPECT_TRUE(has_code(t.diagnostics(), DiagCode::E113_EmptyTape))
            << ::testing::PrintToString(std::string(src)) << dump(t.diagnostics());
        EXPECT_TRUE(t.has_errors());
    }
}

// ---------------------------------------------------------------- words and block types

TEST(ReadWords, StraightLine) {
    Tape t = rd("+300-200\n");
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t.block(0).kind, BlockKind::Motion);
    EXPECT_FALSE(t.block(0).has_code());
    EXPECT_FALSE(t.block(0).has_address());
    EXPECT_EQ(t.block(0).word_count(), 2);
    EXPECT_EQ(words_of(t, 0), (std::vector<std::int32_t>{300, -200}));
}

TEST(ReadWords, SignOnlyIsZero) {
    Tape t = rd("++200\n+100+\n+-300\n-+\n+++205++\n64\n");
    ASSERT_EQ(t.size(), 6u) << dump(t.diagnostics());
    EXPECT_EQ(words_of(t, 0), (std::vector<std::int32_t>{0, 200}));
    EXPECT_EQ(words_of(t, 1), (std::vector<std::int32_t>{100, 0}));
    EXPECT_EQ(words_of(t, 2), (std::vector<std::int32_t>{0, -300}));
    EXPECT_EQ(words_of(t, 3), (std::vector<std::int32_t>{0, 0}));
    EXPECT_EQ(t.block(4).kind, BlockKind::Motion);
    EXPECT_EQ(t.block(4).word_count(), 5);
    EXPECT_EQ(words_of(t, 4), (std::vector<std::int32_t>{0, 0, 205, 0, 0}));
    EXPECT_TRUE(t.block(4).tc_positive());
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(t.block(i).word_count(), 2) << i;
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

TEST(ReadWords, ArcBlockAndTcSign) {
    Tape t = rd("+1000+0+500+0-\n+1000+0+500+0+\n+0+0+100+0-25\n64\n");
    ASSERT_EQ(t.size(), 4u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(0).word_count(), 5);
    EXPECT_EQ(words_of(t, 0), (std::vector<std::int32_t>{1000, 0, 500, 0, 0}));
    EXPECT_FALSE(t.block(0).tc_positive());
    EXPECT_TRUE(t.block(1).tc_positive());
    // TC is a signed number whose sign is what counts
    EXPECT_EQ(t.block(2).word_count(), 5);
    EXPECT_FALSE(t.block(2).tc_positive());
}

TEST(ReadWords, ParabolaBlockAndTpSign) {
    Tape t = rd("+100+50+0+100+-\n+1+2+3+4-+\n+200+0+100+50++\n64\n");
    ASSERT_EQ(t.size(), 4u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(0).kind, BlockKind::Motion);
    EXPECT_EQ(t.block(0).word_count(), 6);
    EXPECT_EQ(words_of(t, 0), (std::vector<std::int32_t>{100, 50, 0, 100, 0, 0}));
    EXPECT_TRUE(t.block(0).tc_positive());
    EXPECT_FALSE(t.block(0).tp_positive());
    EXPECT_EQ(words_of(t, 1), (std::vector<std::int32_t>{1, 2, 3, 4, 0, 0}));
    EXPECT_FALSE(t.block(1).tc_positive());
    EXPECT_TRUE(t.block(1).tp_positive());
    EXPECT_TRUE(t.block(2).tc_positive());
    EXPECT_TRUE(t.block(2).tp_positive());
}

TEST(ReadWords, FunctionCodes) {
    Tape t = rd("0\n7\n64\n");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t.block(0).kind, BlockKind::Function);
    EXPECT_EQ(t.block(0).code, 0);
    EXPECT_TRUE(t.block(0).has_code());
    EXPECT_EQ(t.block(0).word_count(), 0);
    EXPECT_EQ(t.block(1).code, 7);
    Tape t3 = rd("115\n999\n64\n");
    EXPECT_EQ(t3.block(0).code, 115);
    EXPECT_EQ(t3.block(1).code, 999);
    EXPECT_EQ(t3.block(1).kind, BlockKind::Function);
    EXPECT_FALSE(t3.has_errors()) << dump(t3.diagnostics());
}

TEST(ReadWords, FunctionCodeTooLongE103) {
    Tape t = rd("7\n1234\n64\n");
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E103_FunctionCodeTooLong);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->severity, Severity::Error);
    EXPECT_EQ(d->line, 2u);
    EXPECT_EQ(t.block(1).kind, BlockKind::Invalid);
}

TEST(ReadWords, FunctionWithValue) {
    Tape t = rd("39+1400\n41+5\n29+20\n136+12000\n64\n");
    ASSERT_EQ(t.size(), 5u) << dump(t.diagnostics());
    const std::uint16_t codes[] = {39, 41, 29, 136};
    const std::int32_t values[] = {1400, 5, 20, 12000};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(t.block(i).kind, BlockKind::FunctionValue) << i;
        EXPECT_EQ(t.block(i).code, codes[i]) << i;
        EXPECT_EQ(t.block(i).word_count(), 1) << i;
        EXPECT_FALSE(t.block(i).has_address()) << i;
        EXPECT_EQ(words_of(t, i), std::vector<std::int32_t>{values[i]}) << i;
    }
}

TEST(ReadWords, FunctionValueAfterMinusE118) {
    // The fast path (a plain line) and the general path (a trailing blank) alike; "-0" has a sign too.
    Tape t = rd("7\n41-50\n29-20 \n39-0\n41+5\n8\n64\n");
    EXPECT_EQ(count_code(t.diagnostics(), DiagCode::E118_FunctionValueSign), 3u) << dump(t.diagnostics());
    for (std::size_t i : {1u, 2u, 3u}) EXPECT_EQ(t.block(i).kind, BlockKind::Invalid) << i;
    EXPECT_EQ(t.block(4).kind, BlockKind::FunctionValue);
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E118_FunctionValueSign);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->severity, Severity::Error);
    EXPECT_EQ(d->line, 2u);
    EXPECT_EQ(d->column, 1u);
    EXPECT_NE(essi::diagnostic_message(*d, essi::Lang::En).find("41+value"), std::string::npos)
        << essi::diagnostic_message(*d, essi::Lang::En);
}

TEST(ReadWords, NegativeDwellNoLongerMakesTheTimeNegative) {
    // Before E118, 41-50 was a dwell of -50 s: the estimate went below zero.
    const essi::CheckResult r = essi::check_tape("7\n+100+0\n41-50\n8\n64\n", *builtin_profile("iso6582"));
    EXPECT_GT(r.stats.estimated_time_s, 0.0);
    EXPECT_FALSE(r.ok());
}

TEST(ReadWords, ALineOfSignsCostsNoMemoryPerSign) {
    // A line of a million '+' is one block of a million words (E105): the reader kept every word (4 bytes each,
    // and as much again reserved by read_tape), about 5 bytes of memory per byte of input.
    const std::string line(1000000, '+');
    const Tape t = rd("7\n" + line + "\n8\n64\n");
    EXPECT_EQ(count_code(t.diagnostics(), DiagCode::E105_WordCount), 1u) << dump(t.diagnostics());
    EXPECT_NE(essi::diagnostic_message(t.diagnostics().front(), essi::Lang::En).find("1000000 signed words"),
              std::string::npos);
    EXPECT_LT(t.memory_bytes(), 4096u);
    const std::string bytes = line + "+1+1\n";
    const Profile iso = *builtin_profile("iso6582");  // (the reader keeps a reference: the profile must outlive it)
    TapeReader reader(bytes, iso);                    // a chunk at a time, as a check reads
    Tape chunk;
    ASSERT_TRUE(reader.read_chunk(chunk, 100));
    EXPECT_LT(chunk.memory_bytes(), 4096u);
}

TEST(ReadWords, HeadAddresses) {
    Tape t = rd("19\n1+100+200\n2+100+0+50+0-\n2+1+2+3+4+-\n20\n64\n");
    ASSERT_EQ(t.size(), 6u) << dump(t.diagnostics());
    EXPECT_EQ(t.block(1).kind, BlockKind::Motion);
    EXPECT_EQ(t.block(1).code, 1);
    EXPECT_TRUE(t.block(1).has_address());
    EXPECT_EQ(t.block(1).word_count(), 2);
    EXPECT_EQ(words_of(t, 1), (std::vector<std::int32_t>{100, 200}));
    EXPECT_EQ(t.block(2).code, 2);
    EXPECT_TRUE(t.block(2).has_address());
    EXPECT_EQ(t.block(2).word_count(), 5);
    EXPECT_FALSE(t.block(2).tc_positive());
    EXPECT_EQ(t.block(3).word_count(), 6);
    EXPECT_TRUE(t.block(3).tc_positive());
    EXPECT_FALSE(t.block(3).tp_positive());
    EXPECT_FALSE(t.has_errors()) << dump(t.diagnostics());
}

TEST(ReadWords, WordCountE105) {
    for (const char* line : {"+100", "+1+2+3", "+1+2+3+4", "+1+2+3+4+5+6+7"}) {
        const std::string src = std::string("7\n") + line + "\n64\n";
        Tape t = rd(src);
        const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E105_WordCount);
        ASSERT_NE(d, nullptr) << line << "\n" << dump(t.diagnostics());
        EXPECT_EQ(d->line, 2u) << line;
        EXPECT_EQ(d->severity, Severity::Error);
        EXPECT_EQ(t.block(1).kind, BlockKind::Invalid) << line;
    }
}

TEST(ReadWords, FunctionWordCountE106) {
    for (const char* line : {"7+1+2+3", "1+1+2+3+4", "2+1+2+3+4+5+6+7"}) {
        const std::string src = std::string("7\n") + line + "\n64\n";
        Tape t = rd(src);
        const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E106_FunctionWordCount);
        ASSERT_NE(d, nullptr) << line << "\n" << dump(t.diagnostics());
        EXPECT_EQ(d->line, 2u) << line;
        EXPECT_EQ(t.block(1).kind, BlockKind::Invalid) << line;
    }
}

TEST(ReadWords, NumberTooLargeE104) {
    Tape ok = rd("+999999999+0\n64\n");
    EXPECT_FALSE(has_code(ok.diagnostics(), DiagCode::E104_NumberTooLarge)) << dump(ok.diagnostics());
    ASSERT_EQ(ok.size(), 2u);
    EXPECT_EQ(words_of(ok, 0), (std::vector<std::int32_t>{999999999, 0}));
    Tape bad = rd("+1000000000+0\n64\n");
    EXPECT_TRUE(has_code(bad.diagnostics(), DiagCode::E104_NumberTooLarge)) << dump(bad.diagnostics());
}

// ---------------------------------------------------------------- 3 ... 4 ignore sections

TEST(ReadIgnore, CommentSectionKeepsAnything) {
    const std::string src =
        "3\n"
        "PART 12+34 #x \xC3\x9C\xE4\xB8\xAD\n"  // letters, +, digits, #, UTF-8 (U+00DC, U+4E2D)
        "+100+200\n"
        "64\n"
        "4\n"
        "7\n"
        "+100+0\n"
        "8\n"
        "64\n";
    Tape t = rd(src);
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
    std::vector<Block> comments;
    for (const auto& b : t.blocks())
        if (b.kind == BlockKind::Comment) comments.push_back(b);
    ASSERT_EQ(comments.size(), 3u);
    EXPECT_EQ(comments[0].line, 2u);
    EXPECT_EQ(line_text(src, comments[0].offset), "PART 12+34 #x \xC3\x9C\xE4\xB8\xAD");
    EXPECT_EQ(comments[1].line, 3u);
    EXPECT_EQ(line_text(src, comments[1].offset), "+100+200");
    EXPECT_EQ(comments[2].line, 4u);
    // the executable blocks: 7, +100+0, 8, 64 (and the 3 and 4 themselves if kept as functions)
    std::vector<Block> prog = program_blocks(t);
    std::vector<Block> motions;
    for (const auto& b : prog)
        if (b.kind == BlockKind::Motion) motions.push_back(b);
    ASSERT_EQ(motions.size(), 1u);
    EXPECT_EQ(motions[0].line, 7u);
    EXPECT_TRUE(t.has_program_end());
    // the program ends at the 64 on line 9, not at the one inside the comment
    ASSERT_GT(t.end_block(), 0u);
    EXPECT_EQ(t.block(t.end_block() - 1).line, 9u);
    EXPECT_EQ(t.end_block(), t.size());
}

TEST(ReadIgnore, PercentSlashAndGb18030InsideComment) {
    const std::string src = "3\n%\n/\n\xD6\xD0\xCE\xC4 \t= G01 X1.0\n4\n7\n8\n64\n";
    Tape t = rd(src);
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
    EXPECT_TRUE(t.has_program_end());
    EXPECT_EQ(t.block(t.end_block() - 1).line, 8u);
}

TEST(ReadIgnore, UnclosedIgnoreE107PointsAtThe3) {
    Tape t = rd("7\n8\n3\nsome text\n64\n");
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E107_UnclosedIgnore);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->severity, Severity::Error);
    EXPECT_EQ(d->line, 3u);
    EXPECT_EQ(d->column, 1u);
}

TEST(ReadIgnore, StrayIgnoreOffW111) {
    Tape t = rd("7\n4\n8\n64\n");
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::W111_StrayIgnoreOff);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->line, 2u);
    EXPECT_EQ(d->severity, Severity::Warning);
}

// ---------------------------------------------------------------- characters

TEST(ReadChars, WhitespaceSkippedW109ByDefault) {
    Tape t = rd("7 \n+100 +200\n\t8\n64\n");
    EXPECT_FALSE(t.has_errors()) << dump(t.diagnostics());
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::W109_WhitespaceSkipped, 1, 2)) << dump(t.diagnostics());
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::W109_WhitespaceSkipped, 2, 5)) << dump(t.diagnostics());
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::W109_WhitespaceSkipped, 3, 1)) << dump(t.diagnostics());
    EXPECT_EQ(find_code(t.diagnostics(), DiagCode::W109_WhitespaceSkipped)->severity, Severity::Warning);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t.block(0).kind, BlockKind::Function);
    EXPECT_EQ(t.block(0).code, 7);
    EXPECT_EQ(t.block(1).kind, BlockKind::Motion);
    EXPECT_EQ(words_of(t, 1), (std::vector<std::int32_t>{100, 200}));
    EXPECT_EQ(t.block(2).code, 8);
    EXPECT_EQ(t.block(3).code, 64);
    EXPECT_TRUE(t.has_program_end());
}

TEST(ReadChars, TrailingSpaceAfterEndCode) {
    // real tapes end with "64 "
    Tape t = rd("7\n8\n64 \n");
    EXPECT_TRUE(t.has_program_end());
    EXPECT_FALSE(t.has_errors()) << dump(t.diagnostics());
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::W109_WhitespaceSkipped, 3, 3)) << dump(t.diagnostics());
}

TEST(ReadChars, WhitespaceStrictE108) {
    Profile p;
    p.whitespace = WhitespacePolicy::Strict;
    Tape t = rd("7\n+100 +200\n64\n", p);
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::E108_WhitespaceStrict, 2, 5)) << dump(t.diagnostics());
    EXPECT_FALSE(has_code(t.diagnostics(), DiagCode::W109_WhitespaceSkipped));
    EXPECT_TRUE(t.has_errors());
}

TEST(ReadChars, InvalidCharacterE101) {
    const std::string src = "7\n+100X+200\n64\n";
    Tape t = rd(src);
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E101_InvalidCharacter);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->severity, Severity::Error);
    EXPECT_EQ(d->line, 2u);
    EXPECT_EQ(d->column, 5u);
    const bool names_byte = essi::diagnostic_message(*d, essi::Lang::En).find('X') != std::string::npos ||
                            essi::diagnostic_message(*d, essi::Lang::En).find("0x58") != std::string::npos ||
                            essi::diagnostic_message(*d, essi::Lang::En).find("0X58") != std::string::npos;
    EXPECT_TRUE(names_byte) << essi::diagnostic_message(*d, essi::Lang::En);
    EXPECT_TRUE(t.has_errors());
    EXPECT_EQ(t.block(1).kind, BlockKind::Invalid);
}

TEST(ReadChars, InvalidCharacterColumnsAreBytes) {
    Tape t = rd("+100+200X\n64\n");
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::E101_InvalidCharacter, 1, 9)) << dump(t.diagnostics());
    Tape t2 = rd("\r\n\r\n7\r\n+1.5+0\r\n64\r\n");
    EXPECT_TRUE(has_code_at(t2.diagnostics(), DiagCode::E101_InvalidCharacter, 4, 3)) << dump(t2.diagnostics());
}

TEST(ReadChars, Utf8BomE102) {
    Tape t = rd("\xEF\xBB\xBF%\r\n7\r\n8\r\n64\r\n");
    const Diagnostic* d = find_code(t.diagnostics(), DiagCode::E102_NonAsciiByte);
    ASSERT_NE(d, nullptr) << dump(t.diagnostics());
    EXPECT_EQ(d->severity, Severity::Error);
    EXPECT_EQ(d->line, 1u);
    EXPECT_EQ(d->column, 1u);
    EXPECT_FALSE(has_code(t.diagnostics(), DiagCode::E101_InvalidCharacter)) << dump(t.diagnostics());
}

TEST(ReadChars, NonAsciiInBlockE102) {
    Tape t = rd("7\n+100\xC3\xA4+0\n64\n");
    EXPECT_TRUE(has_code_at(t.diagnostics(), DiagCode::E102_NonAsciiByte, 2, 5)) << dump(t.diagnostics());
    EXPECT_FALSE(has_code(t.diagnostics(), DiagCode::E101_InvalidCharacter)) << dump(t.diagnostics());
}

TEST(ReadChars, BinaryGarbageNeverCrashes) {
    std::string bin;
    for (int i = 0; i < 200000; ++i) bin.push_back(static_cast<char>((i * 131 + 7) & 0xFF));
    Tape t = rd(bin);
    EXPECT_TRUE(t.has_errors());
    // reading stops after too many errors instead of reporting every byte
    EXPECT_TRUE(has_code(t.diagnostics(), DiagCode::E115_TooManyErrors));
    EXPECT_LT(t.diagnostics().size(), 100000u);
}

TEST(ReadChars, ColumnOfAndLineText) {
    const std::string src = "7\r\n+100X+0\r\n64";
    // '+' at offset 3, 'X' at offset 7
    EXPECT_EQ(column_of(src, 0), 1u);
    EXPECT_EQ(column_of(src, 3), 1u);
    EXPECT_EQ(column_of(src, 7), 5u);
    EXPECT_EQ(column_of(src, 12), 1u);  // the '6' of "64"
    EXPECT_EQ(column_of(src, 13), 2u);  // the '4' of "64"
    EXPECT_EQ(line_text(src, 7), "+100X+0");
    EXPECT_EQ(line_text(src, 0), "7");
    EXPECT_EQ(line_text(src, 12), "64");
}

// ---------------------------------------------------------------- Block packing and the word store

TEST(ReadBlock, PackedBits) {
    Block b;
    b.packed = 5;
    EXPECT_EQ(b.word_count(), 5);
    EXPECT_TRUE(b.tc_positive());
    EXPECT_TRUE(b.tp_positive());
    EXPECT_FALSE(b.has_address());
    b.packed = static_cast<std::uint8_t>(6 | Block::kTcNegative | Block::kHasAddress);
    EXPECT_EQ(b.word_count(), 6);
    EXPECT_FALSE(b.tc_positive());
    EXPECT_TRUE(b.tp_positive());
    EXPECT_TRUE(b.has_address());
    b.packed = static_cast<std::uint8_t>(6 | Block::kTpNegative);
    EXPECT_TRUE(b.tc_positive());
    EXPECT_FALSE(b.tp_positive());
    b.code = Block::kNoCode;
    EXPECT_FALSE(b.has_code());
    b.code = 0;
    EXPECT_TRUE(b.has_code());
}

TEST(ReadBlock, PackedFromTape) {
    Tape t = rd("19\n2+100+0+50+0-\n+1+2+3+4-+\n64\n");
    ASSERT_EQ(t.size(), 4u);
    const Block& a = t.block(1);
    EXPECT_EQ(a.packed & Block::kWordCountMask, 5);
    EXPECT_NE(a.packed & Block::kTcNegative, 0);
    EXPECT_NE(a.packed & Block::kHasAddress, 0);
    const Block& p = t.block(2);
    EXPECT_EQ(p.packed & Block::kWordCountMask, 6);
    EXPECT_NE(p.packed & Block::kTcNegative, 0);
    EXPECT_EQ(p.packed & Block::kTpNegative, 0);
    EXPECT_EQ(p.packed & Block::kHasAddress, 0);
    EXPECT_EQ(p.code, Block::kNoCode);
}

TEST(ReadBlock, WordsRandomAccessAndCursorAcrossIndexStride) {
    // 300 blocks: lines with words (i, -2i), every 7th an arc, every 11th a function
    std::string src;
    std::vector<std::vector<std::int32_t>> expected;
    for (int i = 0; i < 300; ++i) {
        if (i % 11 == 0) {
            src += "7\n";
            expected.push_back({});
        } else if (i % 7 == 0) {
            src += "+" + std::to_string(i) + "+0+" + std::to_string(i) + "+0-\n";
            expected.push_back({i, 0, i, 0, 0});
        } else {
            src += "+" + std::to_string(i) + "-" + std::to_string(2 * i) + "\n";
            expected.push_back({i, -2 * i});
        }
    }
    src += "64\n";
    Tape t = rd(src);
    ASSERT_EQ(t.size(), 301u);
    for (std::size_t i : {0u, 1u, 63u, 64u, 65u, 127u, 128u, 150u, 299u})
        EXPECT_EQ(words_of(t, i), expected[i]) << "block " << i;
    Tape::WordCursor cur(t);
    for (std::size_t i = 0; i < 300; ++i) {
        auto w = cur.next(i);
        ASSERT_EQ(std::vector<std::int32_t>(w.begin(), w.end()), expected[i]) << "block " << i;
    }
    EXPECT_GT(t.memory_bytes(), 0u);
}

TEST(ReadChars, StrictWhitespaceInsideCommentIsFine) {
    Profile p;
    p.whitespace = WhitespacePolicy::Strict;
    Tape t = rd("3\nPART NO 12\t A\n4\n7\n8\n64\n", p);
    EXPECT_TRUE(t.diagnostics().empty()) << dump(t.diagnostics());
}

// read_tape reserves exactly what a tape needs (a block per line, a word per sign, and the fast path's room for
// one line's words): nothing grows while reading, whatever the last line is and whether a line end follows it.
TEST(ReadBlock, WholeTapeReservationStaysExact) {
    for (const char* tape : {"7\n+1+2\n8\n63\n", "7\n+1+2\n8\n63", "7\n+1+2\n8\n+3-4", "39+2000\n7\n+1+2\n8\n64"}) {
        SCOPED_TRACE(tape);
        const Tape t = rd(tape);
        const std::string s(tape);
        const std::size_t lines = static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')) + 1;
        const std::size_t signs =
            static_cast<std::size_t>(std::count(s.begin(), s.end(), '+') + std::count(s.begin(), s.end(), '-'));
        const std::size_t room_for_one_line = 8;  // the reader's kMaxPlainWords
        EXPECT_EQ(t.memory_bytes(), lines * sizeof(essi::Block) + (signs + room_for_one_line) * sizeof(std::int32_t) +
                                        (lines / Tape::kWordIndexStride + 1) * sizeof(std::uint32_t));
    }
}
