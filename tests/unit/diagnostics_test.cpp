// Diagnostics: stable code names, severities by letter, a summary for every code.
#include <gtest/gtest.h>

#include <iterator>
#include <set>
#include <string>

#include "essi/diagnostics.hpp"

using namespace essi;

namespace {

// Every code the header declares (ESSI diagnostics.hpp), by number.
const int kAllNumbers[] = {101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118,
                           119, 120, 121, 122, 123, 124, 125, 126, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210,
                           211, 212, 213, 214, 215, 216, 301, 302, 303, 304, 305, 306, 307, 401, 402, 403, 501, 502,
                           503, 504, 601, 602, 603, 604, 605, 606, 607, 608, 609, 610, 611, 612, 613, 614, 615};
const std::set<int> kWarnings = {109, 110, 111, 112, 114, 124, 125, 201, 202, 204, 205, 208, 209, 210, 211, 212,
                                 213, 214, 215, 305, 501, 502, 503, 504, 601, 604, 607, 608, 609, 610, 611};
const std::set<int> kNotes = {403, 603, 612, 613, 614, 615};

}  // namespace

TEST(Diagnostics, CodeNames) {
    EXPECT_EQ(code_name(DiagCode::E301_ArcEndNotOnCircle), "E301");
    EXPECT_EQ(code_name(DiagCode::E101_InvalidCharacter), "E101");
    EXPECT_EQ(code_name(DiagCode::W109_WhitespaceSkipped), "W109");
    EXPECT_EQ(code_name(DiagCode::W201_UnknownFunction), "W201");
    EXPECT_EQ(code_name(DiagCode::W305_ParabolaDirection), "W305");
    EXPECT_EQ(code_name(DiagCode::E402_BadProfile), "E402");
}

TEST(Diagnostics, AllCodesInNumericOrder) {
    const auto codes = all_codes();
    ASSERT_EQ(codes.size(), std::size(kAllNumbers));
    for (std::size_t i = 0; i < codes.size(); ++i) EXPECT_EQ(static_cast<int>(codes[i]), kAllNumbers[i]) << i;
}

TEST(Diagnostics, SeverityByLetter) {
    for (int n : kAllNumbers) {
        const auto code = static_cast<DiagCode>(n);
        const std::string name = code_name(code);
        ASSERT_EQ(name.size(), 4u) << n;
        EXPECT_EQ(name.substr(1), std::to_string(n));
        const bool warning = kWarnings.count(n) > 0, note = kNotes.count(n) > 0;
        EXPECT_EQ(name[0], warning ? 'W' : note ? 'N' : 'E') << n;
        EXPECT_EQ(default_severity(code), warning ? Severity::Warning
                                          : note  ? Severity::Note
                                                  : Severity::Error)
            << name;
    }
}

TEST(Diagnostics, EveryCodeHasASummary) {
    std::set<std::string> seen;
    for (DiagCode c : all_codes()) {
        const std::string s(code_summary(c));
        EXPECT_FALSE(s.empty()) << code_name(c);
        EXPECT_GT(s.size(), 10u) << code_name(c) << ": " << s;
        EXPECT_TRUE(seen.insert(s).second) << "duplicate summary for " << code_name(c) << ": " << s;
    }
}

TEST(Diagnostics, SeverityNames) {
    EXPECT_EQ(severity_name(Severity::Error), "error");
    EXPECT_EQ(severity_name(Severity::Warning), "warning");
    EXPECT_EQ(severity_name(Severity::Note), "note");
}
