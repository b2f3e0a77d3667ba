// Numbers of every length, at every position relative to the end of the tape: the reader parses digits
// eight bytes at a time when it can and one at a time near the end, and both must agree with the text.
#include <gtest/gtest.h>

#include <string>

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
    ASSERT_EQ(t.block(0).kind, BlockKind::Motion) << (t.diagnostics().empty() ? "" : t.diagnostics()[0].message);
    EXPECT_EQ(t.words(0)[0], 12);
    EXPECT_EQ(t.words(0)[1], -7);
}

}  // namespace
