// Numbers of every length, at every position relative to the end of the tape: the reader's fast path reads
// a line without looking for the end of the bytes when enough of them follow, and with that check near the
// end; both must agree with the text and with each other.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "essi/read.hpp"

namespace {

using essi::BlockKind;

TEST(ReadNumbers, EveryLengthAndEveryTail) {
    const essi::Profile profile;
    const std::string digits = "987654321";
    for (int n1 = 0; n1 <= 9; ++n1) {
        for (int n2 = 0; n2 <= 9; ++n2) {
            for (const char* tail : {"", "\n", "\r\n", "\n63\n", "\n7\n+1+2\n8\n63\n"}) {
                const std::string a = digits.substr(0, n1), b = digits.substr(9 - n2);
                const std::string line = "+" + a + "-" + b;
                SCOPED_TRACE(line + " tail " + std::to_string(std::string(tail).size()));
                const essi::Tape t = essi::read_tape(line + tail, profile);
                ASSERT_GE(t.size(), 1u);
                ASSERT_EQ(t.block(0).kind, BlockKind::Motion);
                const auto w = t.words(0);
                ASSERT_EQ(w.size(), 2u);
                EXPECT_EQ(w[0], n1 == 0 ? 0 : std::stoi(a));
                EXPECT_EQ(w[1], n2 == 0 ? 0 : -std::stoi(b));
            }
        }
    }
}

TEST(ReadNumbers, FunctionCodesAndValuesOfEveryLength) {
    const essi::Profile profile;
    for (const char* text : {"7", "39", "136", "39+1", "39+1400", "136+12000", "41+123456789"}) {
        SCOPED_TRACE(text);
        const std::string tape = std::string(text) + "\n";
        const essi::Tape t = essi::read_tape(tape, profile);
        ASSERT_EQ(t.size(), 1u);
        const std::string s(text);
        const auto plus = s.find('+');
        EXPECT_EQ(t.block(0).code, std::stoi(s.substr(0, plus)));
        if (plus != std::string::npos) {
            ASSERT_EQ(t.block(0).kind, BlockKind::FunctionValue);
            EXPECT_EQ(t.words(0)[0], std::stoi(s.substr(plus + 1)));
        } else {
            EXPECT_EQ(t.block(0).kind, BlockKind::Function);
        }
    }
}

TEST(ReadNumbers, TenDigitsAreTooMany) {
    const essi::Profile profile;
    const essi::Tape t = essi::read_tape("+1234567890+0\n63\n", profile);
    ASSERT_FALSE(t.diagnostics().empty());
    EXPECT_EQ(t.diagnostics()[0].code, essi::DiagCode::E104_NumberTooLarge);
    EXPECT_EQ(t.diagnostics()[0].line, 1u);
}

TEST(ReadNumbers, LeadingZerosKeepTheirValue) {
    const essi::Profile profile;
    const essi::Tape t = essi::read_tape("+0000000000012-007\n63\n", profile);
    ASSERT_EQ(t.block(0).kind, BlockKind::Motion)
        << (t.diagnostics().empty() ? "" : essi::diagnostic_message(t.diagnostics()[0], essi::Lang::En));
    EXPECT_EQ(t.words(0)[0], 12);
    EXPECT_EQ(t.words(0)[1], -7);
}

// The same line read far from the end of the bytes (in a batch of common lines, with no end-of-bytes test)
// and as the last line (checked at every byte): the same block, words and diagnostics, and the values the
// text says. The filler after it is long enough, and has words enough, for the reader to read in batches
// (more than 64 lines of 99 bytes, and room for 64 lines of 8 words in read_tape's exact reservation).
TEST(ReadNumbers, SameBlockFarFromAndAtTheEnd) {
    const essi::Profile profile;
    std::string filler;
    std::uint32_t filler_lines = 0;
    for (; filler.size() < 8000; filler_lines += 2) filler += "+1-2\n38\n";
    struct Case {
        const char* line;
        std::vector<std::int32_t> words;  // expected; empty with `error` for a line that is an error
        const char* error;                // expected diagnostic code name, or nullptr
    };
    const Case cases[] = {
        {"+1-2", {1, -2}, nullptr},
        {"+-", {0, 0}, nullptr},
        {"-0+0", {0, 0}, nullptr},
        {"+123456789-987654321", {123456789, -987654321}, nullptr},
        {"+0000000001+2", {1, 2}, nullptr},  // 10 characters of digits, 1 significant: the general path
        {"+1234567890+0", {}, "E104"},
        {"+10+20+5+5+", {10, 20, 5, 5, 0}, nullptr},
        {"+10+20+5+5-+", {10, 20, 5, 5, 0, 0}, nullptr},  // a parabola: TC -, TP +
        {"+1+2+3+4+5+6+7+8+9", {}, "E105"},               // more words than the fast path takes: the general path
        {"+1+2+3", {}, "E105"},
        {"7", {}, nullptr},
        {"39+1400", {1400}, nullptr},
        {"1234", {}, "E103"},
        {"+1 +2", {1, 2}, "W109"},
        {"+1x", {}, "E101"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.line);
        // The first line of a tape is read by the general path: the line under test comes second.
        const std::string far = "6\n" + std::string(c.line) + "\n" + filler + "63\n";
        const std::string at_end = "6\n" + std::string(c.line);
        const essi::Tape a = essi::read_tape(far, profile), b = essi::read_tape(at_end, profile);
        ASSERT_GE(a.size(), 2u);
        ASSERT_EQ(b.size(), 2u);
        EXPECT_EQ(a.block(1).kind, b.block(1).kind);
        EXPECT_EQ(a.block(1).code, b.block(1).code);
        EXPECT_EQ(a.block(1).packed & ~essi::Block::kProgramEnd, b.block(1).packed & ~essi::Block::kProgramEnd);
        const auto wa = a.words(1), wb = b.words(1);
        EXPECT_EQ(std::vector<std::int32_t>(wa.begin(), wa.end()), std::vector<std::int32_t>(wb.begin(), wb.end()));
        if (!c.words.empty()) {
            EXPECT_EQ(std::vector<std::int32_t>(wa.begin(), wa.end()), c.words);
        }
        const auto first_code = [](const essi::Tape& t) {
            return t.diagnostics().empty() ? std::string() : essi::code_name(t.diagnostics()[0].code);
        };
        EXPECT_EQ(first_code(a), c.error ? c.error : "");
        // Every line counted: the end code is on the line after the filler.
        EXPECT_EQ(a.block(a.size() - 1).line, 2 + filler_lines + 1);
        EXPECT_EQ(a.block(a.size() - 1).code, 63);
        // At the end the tape also lacks its end code (W114) after any error of the line.
        if (c.error) {
            EXPECT_EQ(first_code(b), c.error);
        }
    }
}

}  // namespace
