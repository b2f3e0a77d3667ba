// The viewer's problems list (web/app/ProblemList.hpp): a code with many findings is one row, counting those the
// max_per_code cap left out; next and previous problem; a page of the list for state(); and the layout by the
// screen's width (web/app/ScreenLayout.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/ProblemList.hpp"
#include "app/ScreenLayout.hpp"
#include "essi/diagnostic_cap.hpp"
#include "essi/pipeline.hpp"
#include "essi/text.hpp"

using namespace essi;
using namespace essi::viewer;

namespace {

// A line per block that ends with a blank: one W109 a line; then an E101 (a letter) on the last line before 64.
std::string blanks_tape(int lines, bool with_error) {
    std::string t;
    for (int i = 0; i < lines; ++i) t += "+10+0 \n";
    if (with_error) t += "+10x\n";
    return t + "64\n";
}

Diagnostic at_line(DiagCode code, std::uint32_t line, Severity s = Severity::Warning) {
    return make_diagnostic(s, code, line, 1, Msg::None);
}

}  // namespace

TEST(ViewerProblems, ACodeWithManyFindingsIsOneRowCountingThoseTheCapLeftOut) {
    Profile profile;
    profile.max_per_code = 1000;
    const CheckResult r = check_tape(blanks_tape(2500, true), profile);
    ProblemList list;
    list.build(r.diagnostics);
    ASSERT_EQ(list.groups().size(), 1u);
    const ProblemGroup& g = list.groups()[0];
    EXPECT_EQ(g.code, DiagCode::W109_WhitespaceSkipped);
    EXPECT_EQ(g.total, 2500u);           // 1 000 kept and 1 500 left out
    EXPECT_EQ(g.members.size(), 1001u);  // the kept ones and the cap's summary
    EXPECT_EQ(g.severity, Severity::Warning);
    const std::vector<ProblemRow> closed = list.rows({false});
    // The group and the E101 of its own (the rows in the list's order: the group where its first finding is).
    ASSERT_EQ(closed.size(), 2u);
    EXPECT_EQ(closed[0].kind, ProblemRow::Kind::Group);
    EXPECT_EQ(closed[1].kind, ProblemRow::Kind::Diagnostic);
    EXPECT_EQ(r.diagnostics[closed[1].index].code, DiagCode::E101_InvalidCharacter);
    const std::vector<ProblemRow> open = list.rows({true});
    ASSERT_EQ(open.size(), 2u + 1001u);
    EXPECT_EQ(open[1].kind, ProblemRow::Kind::Member);
    EXPECT_EQ(r.diagnostics[open[1].index].line, 1u);
    // Every kept finding is reachable from the group, and the summary says how many more there are.
    std::size_t summaries = 0;
    for (const std::size_t m : g.members) {
        EXPECT_EQ(list.group_of(m), 0u);
        if (cap_omitted(r.diagnostics[m]) > 0) {
            ++summaries;
            EXPECT_EQ(cap_omitted(r.diagnostics[m]), 1500u);
        }
    }
    EXPECT_EQ(summaries, 1u);
    EXPECT_EQ(count_text(g.total), "2 500");
    EXPECT_EQ(count_text(58780), "58 780");
    EXPECT_EQ(count_text(1000000), "1 000 000");
    EXPECT_EQ(count_text(999), "999");
}

TEST(ViewerProblems, AFewFindingsOfACodeKeepARowEach) {
    std::vector<Diagnostic> d;
    for (std::uint32_t l = 1; l <= kGroupFindingsAbove; ++l) d.push_back(at_line(DiagCode::W109_WhitespaceSkipped, l));
    ProblemList list;
    list.build(d);
    EXPECT_TRUE(list.groups().empty());
    EXPECT_EQ(list.rows({}).size(), kGroupFindingsAbove);
    d.push_back(at_line(DiagCode::W109_WhitespaceSkipped, 9));
    list.build(d);
    ASSERT_EQ(list.groups().size(), 1u);
    EXPECT_EQ(list.groups()[0].total, kGroupFindingsAbove + 1);
    EXPECT_EQ(list.rows({}).size(), 1u);
}

TEST(ViewerProblems, NextAndPreviousGoRoundThoseWithAPlace) {
    const std::vector<Diagnostic> d = {
        at_line(DiagCode::E402_BadProfile, 0), at_line(DiagCode::E101_InvalidCharacter, 3),
        at_line(DiagCode::W109_WhitespaceSkipped, 7), at_line(DiagCode::E101_InvalidCharacter, 9)};
    constexpr std::size_t none = ProblemList::npos;
    EXPECT_EQ(step_problem(d, none, 1), 1u);  // (the first with a line: not the profile's)
    EXPECT_EQ(step_problem(d, 1, 1), 2u);
    EXPECT_EQ(step_problem(d, 3, 1), 1u);  // round, past the one without a line
    EXPECT_EQ(step_problem(d, none, -1), 3u);
    EXPECT_EQ(step_problem(d, 1, -1), 3u);
    EXPECT_EQ(step_problem(d, 2, -1), 1u);
    EXPECT_EQ(step_problem({}, none, 1), none);
    EXPECT_EQ(step_problem({at_line(DiagCode::E402_BadProfile, 0)}, none, 1), none);
}

TEST(ViewerProblems, APageOfTheListForState) {
    const ProblemPage first = problem_page(-1, -1);
    EXPECT_EQ(first.offset, 0u);
    EXPECT_EQ(first.limit, kStateProblemsPage);
    EXPECT_EQ(first.end(2501), 100u);
    EXPECT_EQ(first.end(7), 7u);
    const ProblemPage p = problem_page(2450, 100);
    EXPECT_EQ(p.end(2501), 2501u);
    EXPECT_EQ(p.end(2000), 2000u);  // (past the end: empty)
    EXPECT_EQ(problem_page(5, 0).end(100), 5u);
    EXPECT_EQ(problem_page(0, 1000000).limit, kStateProblemsMax);
}

TEST(ViewerScreenLayout, ANarrowWindowHasTheBottomSheetCollapsedToItsTabs) {
    EXPECT_TRUE(compact_layout(390));
    EXPECT_TRUE(compact_layout(699));
    EXPECT_FALSE(compact_layout(700));
    EXPECT_FALSE(compact_layout(1024));
    BottomSheet sheet;
    EXPECT_FALSE(sheet.open);
    const Rect collapsed = compact_drawing_area(390, 844, 38, sheet);
    EXPECT_EQ(collapsed.x, 0);
    EXPECT_EQ(collapsed.w, 390);
    EXPECT_EQ(collapsed.y, 38);
    EXPECT_EQ(collapsed.h, 844 - 38 - kSheetTabsHeight);
    sheet.tap(SheetTab::Statistics);
    EXPECT_TRUE(sheet.open);
    EXPECT_EQ(sheet.tab, SheetTab::Statistics);
    EXPECT_FLOAT_EQ(sheet_height(sheet, 844), 844 * kSheetOpenShare);
    EXPECT_FLOAT_EQ(compact_drawing_area(390, 844, 38, sheet).h, 844 - 38 - 844 * kSheetOpenShare);
    sheet.tap(SheetTab::Source);  // another tab: still open, on it
    EXPECT_TRUE(sheet.open);
    EXPECT_EQ(sheet.tab, SheetTab::Source);
    sheet.tap(SheetTab::Source);  // the open tab: closed
    EXPECT_FALSE(sheet.open);
    EXPECT_EQ(sheet_height(sheet, 844), kSheetTabsHeight);
    EXPECT_STREQ(sheet_tab_name(SheetTab::Inspector), "inspector");
}
