// The cut plan (essi/plan.hpp): loops and lead-ins, roles by nesting, plates, and each rule's diagnostic with its
// numbers, place and related places. Tapes are built here from absolute points in mm (incremental ESSI words in
// 0.1 mm, as a nesting program writes them).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/plan.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "../bench/nest_generator.hpp"
#include "deferred_plan.hpp"

namespace {

using essi::CheckResult;
using essi::ContourRole;
using essi::DiagCode;
using essi::Diagnostic;

class Tape {
public:
    Tape() { function("39+1000"); }
    Tape& function(const std::string& f) {
        text_ += f + "\n";
        return *this;
    }
    Tape& to(double x, double y) {
        const long long X = std::llround(x * 10), Y = std::llround(y * 10);
        text_ += word(X - x_) + word(Y - y_) + "\n";
        x_ = X;
        y_ = Y;
        return *this;
    }
    Tape& arc(double x, double y, double cx, double cy, bool ccw) {
        const long long X = std::llround(x * 10), Y = std::llround(y * 10);
        const long long CX = std::llround(cx * 10), CY = std::llround(cy * 10);
        text_ += word(X - x_) + word(Y - y_) + word(CX - x_) + word(CY - y_) + (ccw ? "+" : "-") + "\n";
        x_ = X;
        y_ = Y;
        return *this;
    }
    Tape& rapid(double x, double y) { return function("5").to(x, y).function("6"); }
    // A rectangle clockwise from the middle of its left edge, with a lead-in of `lead` mm from the left.
    Tape& part_cw(double x0, double y0, double x1, double y1, const std::string& kerf = "29", double lead = 10) {
        const double ym = (y0 + y1) / 2;
        rapid(x0 - lead, ym).function(kerf).function("7");
        to(x0, ym).to(x0, y1).to(x1, y1).to(x1, y0).to(x0, y0).to(x0, ym);
        return function("8").function("38");
    }
    // A full circle pierced at its centre, with a lead-in to it.
    Tape& hole(double cx, double cy, double r, const std::string& kerf = "29", bool ccw = true) {
        rapid(cx, cy).function(kerf).function("7").to(cx + r, cy).arc(cx + r, cy, cx, cy, ccw);
        return function("8").function("38");
    }
    // The torch back home and a programmed stop: the next plate.
    Tape& next_plate() { return rapid(0, 0).function("0"); }
    std::string end() { return rapid(0, 0).function("64").text_; }

private:
    static std::string word(long long v) { return (v < 0 ? "-" : "+") + std::to_string(v < 0 ? -v : v); }
    std::string text_;
    long long x_ = 0, y_ = 0;
};

CheckResult check(const std::string& tape, const essi::Profile& profile = essi::Profile{}) {
    return essi::check_tape(tape, profile);
}

// The cut plan's diagnostics (6xx) of a result.
std::vector<Diagnostic> plan_of(const CheckResult& r) {
    std::vector<Diagnostic> v;
    for (const Diagnostic& d : r.diagnostics)
        if (static_cast<int>(d.code) >= 600) v.push_back(d);
    return v;
}

std::string codes_of(const std::vector<Diagnostic>& v) {
    std::string s;
    for (const Diagnostic& d : v) s += essi::code_name(d.code) + "@" + std::to_string(d.line) + " ";
    return s;
}

}  // namespace

TEST(CutPlanLoops, LeadInAndLeadOutAroundTheLoop) {
    // Pierce at (50, 100), lead-in to (60, 100), the loop, then a lead-out back out to (50, 100).
    Tape t;
    t.rapid(50, 100).function("29").function("7");
    t.to(60, 100).to(60, 150).to(260, 150).to(260, 50).to(60, 50).to(60, 100).to(50, 100);
    t.function("8").function("38");
    const auto contours = essi::plan_contours(t.end(), essi::Profile{});
    ASSERT_EQ(contours.size(), 1u);
    const essi::PlanContour& c = contours[0];
    EXPECT_EQ(c.first_line, 7u);       // the lead-in
    EXPECT_EQ(c.loop_first_line, 8u);  // the loop: lines 8-12
    EXPECT_EQ(c.loop_last_line, 12u);
    EXPECT_EQ(c.last_line, 13u);  // the lead-out
    EXPECT_TRUE(c.lead_in);
    EXPECT_DOUBLE_EQ(c.area_mm2, -200.0 * 100.0);  // clockwise
    EXPECT_EQ(c.role, ContourRole::LonePart);      // kerf left of a clockwise loop: outside
}

TEST(CutPlanLoops, FullCircleHoleAndOvercut) {
    Tape t;
    t.hole(100, 100, 20);
    // The loop closes on its lead-in's line, not at a point it passed: (200, 90) on the lead-in (200, 80)-(200, 100).
    t.rapid(200, 80).function("29").function("7").to(200, 100).to(300, 100).to(300, 150).to(200, 150).to(200, 90);
    t.function("8").function("38");
    const auto contours = essi::plan_contours(t.end(), essi::Profile{});
    ASSERT_EQ(contours.size(), 2u);
    EXPECT_NEAR(contours[0].area_mm2, essi::kPi * 400, 1e-9);  // the circle exactly, not its chords
    EXPECT_EQ(contours[0].loop_first_line, contours[0].loop_last_line);
    EXPECT_DOUBLE_EQ(std::fabs(contours[1].area_mm2), 100.0 * 50.0);
    EXPECT_EQ(contours[1].loop_last_line, contours[1].last_line);
}

TEST(CutPlanLoops, ParentsAreIndicesInTheListOfContours) {
    // On each plate: a cut with no loop (not a contour of the list), a hole, the part around it.
    Tape t;
    t.rapid(10, 10).function("7").to(100, 10).to(10, 10).function("8");
    t.hole(150, 100, 20).part_cw(50, 40, 350, 160);
    t.next_plate();
    t.rapid(10, 10).function("7").to(100, 10).to(10, 10).function("8");
    t.hole(150, 100, 20).part_cw(50, 40, 350, 160);
    const auto c = essi::plan_contours(t.end(), essi::Profile{});
    ASSERT_EQ(c.size(), 4u);
    EXPECT_EQ(c[0].role, ContourRole::Hole);
    EXPECT_EQ(c[0].parent, 1);
    EXPECT_EQ(c[1].role, ContourRole::Part);
    EXPECT_EQ(c[1].parent, -1);
    EXPECT_EQ(c[2].plate, 2);
    EXPECT_EQ(c[2].parent, 3);
    EXPECT_EQ(c[3].parent, -1);
}

TEST(CutPlanLoops, AStraightCutOutAndBackHasNoLoop) {
    Tape t;
    t.rapid(10, 10).function("7").to(100, 10).to(10, 10).function("8");
    EXPECT_TRUE(essi::plan_contours(t.end(), essi::Profile{}).empty());
    EXPECT_TRUE(plan_of(check(t.end())).empty());
}

TEST(CutPlanRoles, ByNestingAndByKerf) {
    Tape t;
    t.hole(150, 100, 20);                   // a hole of the part below
    t.part_cw(50, 40, 350, 160);            // a part: holds a hole
    t.hole(600, 100, 80);                   // a hole (of the part around it) ...
    t.part_cw(570, 80, 630, 120, "29", 5);  // ... with a part inside it, cut first? no: after (W604 below)
    t.part_cw(500, 0, 700, 200, "29", 10);  // the part around both
    t.hole(900, 100, 30, "29");             // lone, kerf inside: a hole in the plate by its program
    t.part_cw(1000, 50, 1100, 150, "29");   // lone, kerf outside: a part by its program
    t.rapid(1200, 100).function("7").to(1210, 100).to(1210, 150).to(1300, 150).to(1300, 50).to(1210, 50).to(1210, 100);
    t.function("8");  // lone, no compensation: unknown
    const auto c = essi::plan_contours(t.end(), essi::Profile{});
    ASSERT_EQ(c.size(), 8u);
    const ContourRole want[] = {ContourRole::Hole, ContourRole::Part,     ContourRole::Hole,     ContourRole::Part,
                                ContourRole::Part, ContourRole::LoneHole, ContourRole::LonePart, ContourRole::Lone};
    const int depth[] = {1, 0, 1, 2, 0, 0, 0, 0};
    const int parent[] = {1, -1, 4, 2, -1, -1, -1, -1};
    for (std::size_t i = 0; i < c.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(c[i].role, want[i]) << essi::contour_role_name(c[i].role);
        EXPECT_EQ(c[i].depth, depth[i]);
        EXPECT_EQ(c[i].parent, parent[i]);
    }
}

TEST(CutPlanRules, GapWithItsSizeAndPlace) {
    Tape t;
    t.rapid(50, 50).function("29").function("7").to(60, 50).to(60, 150).to(260, 150).to(260, 50).to(62, 50);
    t.function("8").function("38");
    const auto d = plan_of(check(t.end()));
    ASSERT_EQ(d.size(), 1u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::W601_ContourGap);
    EXPECT_EQ(d[0].line, 11u);
    EXPECT_NE(essi::diagnostic_message(d[0], essi::Lang::En).find("stops 2.000 mm short"), std::string::npos)
        << essi::diagnostic_message(d[0], essi::Lang::En);
    EXPECT_NE(essi::diagnostic_message(d[0], essi::Lang::En).find("began at line 8"), std::string::npos)
        << essi::diagnostic_message(d[0], essi::Lang::En);
    ASSERT_TRUE(d[0].has_at);
    EXPECT_DOUBLE_EQ(d[0].at.x, 61);  // halfway across the gap
    EXPECT_DOUBLE_EQ(d[0].at.y, 50);
    ASSERT_EQ(d[0].related().size(), 1u);
    EXPECT_EQ(d[0].related()[0].line, 8u);
    EXPECT_EQ(d[0].contour_first, 7u);
    EXPECT_EQ(d[0].contour_last, 11u);
    // A gap over closure_gap_mm is an open cut, not a contour left open.
    essi::Profile tight;
    tight.closure_gap_mm = 1.5;
    EXPECT_TRUE(plan_of(check(t.end(), tight)).empty());
}

TEST(CutPlanRules, KerfSideOfPartsHolesAndLoneContours) {
    Tape t;
    t.hole(160, 100, 20, "30");          // a hole with its kerf outside (right of counter-clockwise): E602
    t.part_cw(60, 50, 260, 150, "29");   // right
    t.hole(650, 100, 20, "30", false);   // right of clockwise: inside the hole, right
    t.part_cw(550, 50, 750, 150, "30");  // a part with its kerf inside (right of clockwise): E602
    t.hole(900, 100, 40, "29");          // lone, kerf inside: N603
    const auto d = plan_of(check(t.end()));
    ASSERT_EQ(d.size(), 3u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::E602_KerfIntoPart);
    EXPECT_EQ(d[0].severity, essi::Severity::Error);
    EXPECT_EQ(essi::diagnostic_message(d[0], essi::Lang::En),
              "the kerf is outside this hole (right (30), travelling counter-clockwise): the hole comes out a kerf too "
              "small; travelling counter-clockwise, a hole's kerf belongs on the left (29)");
    EXPECT_EQ(d[1].code, DiagCode::E602_KerfIntoPart);
    EXPECT_NE(
        essi::diagnostic_message(d[1], essi::Lang::En).find("inside this part (right (30), travelling clockwise)"),
        std::string::npos)
        << essi::diagnostic_message(d[1], essi::Lang::En);
    EXPECT_NE(essi::diagnostic_message(d[1], essi::Lang::En).find("belongs on the left (29)"), std::string::npos);
    EXPECT_EQ(d[2].code, DiagCode::N603_KerfInsideLoneContour);
    EXPECT_EQ(d[2].severity, essi::Severity::Note);
    EXPECT_EQ(
        essi::diagnostic_message(d[0], essi::Lang::De),
        "die Schnittfuge liegt außerhalb dieses Lochs (rechts (30), Fahrt gegen den Uhrzeigersinn): das Loch wird um "
        "eine Fuge zu klein; bei Fahrt gegen den Uhrzeigersinn gehört die Fuge eines Lochs nach links (29)");
}

TEST(CutPlanRules, PartBeforeItsHolesNamesThem) {
    Tape t;
    t.part_cw(60, 50, 260, 150);
    t.hole(110, 100, 20);
    t.hole(210, 100, 20);
    const auto d = plan_of(check(t.end()));
    ASSERT_EQ(d.size(), 1u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::W604_CutBeforeInside);
    EXPECT_EQ(d[0].line, 7u);  // the part's lead-in: lines 7-12
    ASSERT_EQ(d[0].related().size(), 2u);
    EXPECT_EQ(d[0].related()[0].line, 20u);
    EXPECT_EQ(d[0].related()[1].line, 29u);
    EXPECT_EQ(essi::related_message(d[0].related()[0], essi::Lang::En), "a hole cut after its part");
    EXPECT_NE(
        essi::diagnostic_message(d[0], essi::Lang::En).find("before 2 holes inside it (the first at lines 20-21)"),
        std::string::npos)
        << essi::diagnostic_message(d[0], essi::Lang::En);
    // Holes first: nothing to say.
    Tape good;
    good.hole(110, 100, 20).hole(210, 100, 20).part_cw(60, 50, 260, 150);
    EXPECT_TRUE(plan_of(check(good.end())).empty());
}

TEST(CutPlanRules, CollisionsOverlapAndTooClose) {
    Tape t;
    t.part_cw(60, 50, 260, 150);
    t.part_cw(240, 50, 440, 150, "29", 5);    // overlaps the first by 20 x 100 mm
    t.part_cw(441, 50, 641, 150, "29", 0.5);  // 1 mm from the second: less than the 2 mm kerf
    const auto d = plan_of(check(t.end()));
    ASSERT_EQ(d.size(), 2u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::E605_PartsCollide);
    EXPECT_NE(essi::diagnostic_message(d[0], essi::Lang::En).find("overlaps the part at lines 7-12"), std::string::npos)
        << essi::diagnostic_message(d[0], essi::Lang::En);
    ASSERT_EQ(d[0].overlap().size(), 2u);  // the two rectangles: their intersection is the overlap
    EXPECT_EQ(d[0].overlap()[0].size(), 5u);
    ASSERT_EQ(d[0].related().size(), 1u);
    EXPECT_EQ(d[0].related()[0].line, 7u);
    EXPECT_EQ(d[1].code, DiagCode::E605_PartsCollide);
    EXPECT_NE(essi::diagnostic_message(d[1], essi::Lang::En)
                  .find("comes within 1.000 mm of the part at lines 20-25, closer than the kerf width (2.000 mm)"),
              std::string::npos)
        << essi::diagnostic_message(d[1], essi::Lang::En);
    EXPECT_TRUE(d[1].overlap().empty());
    // Without compensation only a real overlap counts, and the roles are unknown: a note.
    Tape plain;
    plain.part_cw(60, 50, 260, 150, "38").part_cw(240, 50, 440, 150, "38", 5).part_cw(441, 50, 641, 150, "38", 0.5);
    const auto p = plan_of(check(plain.end()));
    ASSERT_EQ(p.size(), 1u) << codes_of(p);
    EXPECT_EQ(p[0].code, DiagCode::N612_ContoursOverlap);
}

// 120 parts in one column (every cut over the same x: too many comparisons for the sweep along x, so the plate's
// neighbours come from the grid) and the same parts in one row (the sweep): the same finding, the one overlap.
TEST(CutPlanRules, ACrowdedColumnAndARowGiveTheSameFindings) {
    for (const bool column : {true, false}) {
        SCOPED_TRACE(column ? "one column" : "one row");
        Tape t;
        const auto corner = [&](int k) {
            return column ? std::pair{100.0, 100.0 + 20 * k} : std::pair{100.0 + 20 * k, 100.0};
        };
        for (int k = 0; k < 120; ++k) {
            const auto [x, y] = corner(k);
            if (k == 60) t.hole(x + 5, y + 5, 2);  // (a hole in part 60, cut before it)
            t.part_cw(x, y, x + 10, y + 10, "29", 3);
        }
        const auto [x, y] = corner(30);
        t.part_cw(x, y + 5, x + 10, y + 15, "29", 3);  // over part 30 by 5 mm
        const auto d = plan_of(check(t.end()));
        ASSERT_EQ(d.size(), 1u) << codes_of(d);
        EXPECT_EQ(d[0].code, DiagCode::E605_PartsCollide);
        ASSERT_EQ(d[0].related().size(), 1u);
        EXPECT_EQ(d[0].related()[0].line,
                  2 + 30 * 13 + 5u);  // (part 30's first cut: 30 parts of 13 lines and the feed before it)
    }
}

TEST(CutPlanRules, HolesOverlappingInOnePartMakeASlot) {
    Tape t;
    t.hole(150, 100, 20).hole(170, 100, 20).part_cw(60, 50, 260, 150);
    EXPECT_TRUE(plan_of(check(t.end())).empty());
}

TEST(CutPlanRules, CutAcrossAPartCutFree) {
    Tape t;
    t.part_cw(60, 50, 260, 150);
    t.part_cw(300, 50, 400, 150, "29", 50);  // pierced inside the first part
    const auto d = plan_of(check(t.end()));
    ASSERT_EQ(d.size(), 1u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::E606_CutCrossesCutPart);
    ASSERT_TRUE(d[0].has_at);
    EXPECT_DOUBLE_EQ(d[0].at.x, 260);  // where the lead-in crosses the part's right side
    EXPECT_DOUBLE_EQ(d[0].at.y, 100);
}

TEST(CutPlanRules, SamePathTwiceButNotOnAnotherPlate) {
    Tape twice;
    twice.part_cw(60, 50, 260, 150).part_cw(60, 50, 260, 150);
    const auto d = plan_of(check(twice.end()));
    ASSERT_EQ(d.size(), 1u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::W607_SamePathTwice);
    EXPECT_EQ(d[0].related()[0].line, 7u);
    // The same part on the next plate (home, stop 0 between them): nothing.
    Tape plates;
    plates.part_cw(60, 50, 260, 150).next_plate().part_cw(60, 50, 260, 150);
    EXPECT_TRUE(plan_of(check(plates.end())).empty());
    const auto c = essi::plan_contours(plates.end(), essi::Profile{});
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].plate, 1);
    EXPECT_EQ(c[1].plate, 2);
}

TEST(CutPlanRules, FeedDwellLeadInAndTableFromTheProfile) {
    Tape t;
    t.function("39+30").rapid(50, 100).function("29").function("41+600").function("7");
    t.to(50, 150).to(250, 150).to(250, 50).to(50, 50).to(50, 100).function("8").function("38");
    t.function("39+2000").part_cw(300, 50, 400, 150);
    essi::Profile p;
    p.lead_in_required = true;
    p.table = essi::TableLimits{0, 0, 150, 1000};
    const auto d = plan_of(check(t.end(), p));
    ASSERT_EQ(d.size(), 4u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::W609_DwellTooLong);  // line 7
    EXPECT_EQ(essi::diagnostic_message(d[0], essi::Lang::En),
              "a dwell of 600 s, longer than the profile's max_dwell_s (120 s); check the dwell's value and unit");
    EXPECT_EQ(d[1].code, DiagCode::W608_FeedOutOfRange);  // once, at the first cut at 30 mm/min (line 9)
    EXPECT_EQ(d[1].line, 9u);
    ASSERT_EQ(d[1].related().size(), 1u);
    EXPECT_EQ(d[1].related()[0].line, 2u);                    // where 39+30 is
    EXPECT_EQ(d[2].code, DiagCode::W611_CutLargerThanTable);  // the first cut, 200 mm on a 150 mm table
    EXPECT_NE(essi::diagnostic_message(d[2], essi::Lang::En)
                  .find("this cut is 200.000 x 100.000 mm, larger than the table's travel (150.000 x 1000.000 mm)"),
              std::string::npos)
        << essi::diagnostic_message(d[2], essi::Lang::En);
    EXPECT_EQ(d[3].code, DiagCode::W610_PierceWithoutLeadIn);  // the second part (110 mm wide) fits and has a lead-in
    // The defaults: no lead-in asked for, no table.
    const auto defaults = plan_of(check(t.end()));
    ASSERT_EQ(defaults.size(), 2u) << codes_of(defaults);
}

TEST(CutPlanRules, TheGeneratedNestIsClean) {
    // Many plates of parts with holes (cut first, kerf on the right side), 35 mm apart.
    const std::string nest = essi::bench::generate_nest_tape(1 << 20, 11);
    const CheckResult r = check(nest);
    EXPECT_TRUE(r.diagnostics.empty()) << codes_of(r.diagnostics);
    const auto c = essi::plan_contours(nest, essi::Profile{});
    ASSERT_GT(c.size(), 1000u);
    EXPECT_GT(c.back().plate, 2);
    std::size_t holes = 0;
    for (const auto& k : c) holes += k.role == ContourRole::Hole ? 1 : 0;
    EXPECT_GT(holes, 300u);
}

TEST(CutPlanRules, AHoleInThePlateOverAPartWhicheverIsCutFirst) {
    for (const bool hole_first : {true, false}) {
        SCOPED_TRACE(hole_first ? "hole first" : "part first");
        Tape t;
        if (hole_first) t.hole(260, 100, 20, "29");  // lone, kerf inside: a hole in the plate, over the part's edge
        t.part_cw(60, 50, 260, 150);
        if (!hole_first) t.hole(260, 100, 20, "29");
        const auto d = plan_of(check(t.end()));
        std::size_t collisions = 0;
        for (const Diagnostic& x : d) {
            if (x.code != DiagCode::E605_PartsCollide) continue;
            ++collisions;
            EXPECT_NE(essi::diagnostic_message(x, essi::Lang::En)
                          .find(hole_first ? "this part overlaps the hole in the plate at lines 7-8"
                                           : "this hole in the plate (a lone contour with its kerf inside) "
                                             "overlaps the part at lines 7-12"),
                      std::string::npos)
                << essi::diagnostic_message(x, essi::Lang::En);
            EXPECT_EQ(x.overlap().size(), 2u);
        }
        EXPECT_EQ(collisions, 1u) << codes_of(d);
    }
}

TEST(CutPlanRules, PiercedOnTheLoopWithAnOvercutStillHasNoLeadIn) {
    // Pierced at (60, 100) on the left side; the loop runs past the pierce up to (60, 120) on its first side.
    Tape t;
    t.rapid(60, 100).function("29").function("7").to(60, 150).to(260, 150).to(260, 50).to(60, 50).to(60, 120);
    t.function("8").function("38");
    essi::Profile p;
    p.lead_in_required = true;
    const auto d = plan_of(check(t.end(), p));
    ASSERT_EQ(d.size(), 1u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::W610_PierceWithoutLeadIn);
    EXPECT_DOUBLE_EQ(d[0].at.x, 60);
    EXPECT_DOUBLE_EQ(d[0].at.y, 100);
}

TEST(CutPlanRules, PartsWithoutCompensationThatTouch) {
    Tape t;
    // Two parts, each with a hole (so their role is certain), sharing the edge x = 260 without compensation.
    t.hole(160, 100, 20, "38").part_cw(60, 50, 260, 150, "38");
    t.hole(360, 100, 20, "38").part_cw(260, 50, 460, 150, "38", 5);
    const auto d = plan_of(check(t.end()));
    ASSERT_EQ(d.size(), 1u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::E605_PartsCollide);
    EXPECT_NE(essi::diagnostic_message(d[0], essi::Lang::En)
                  .find("this part touches or overlaps the part at lines 16-21: neither has kerf compensation"),
              std::string::npos)
        << essi::diagnostic_message(d[0], essi::Lang::En);
}

TEST(CutPlanRules, TheHeadsOfAThreeAxisTapeAreComparedApart) {
    // Head 2 cuts the same rectangle in its own coordinates (it sits elsewhere on the gantry): not the same path
    // twice, no collision; each head's contour is lone, with its kerf inside.
    const std::string tape =
        "39+1000\n19\n29\n7\n1+100+0\n2+100+0\n1+0+500\n2+0+500\n1-100+0\n2-100+0\n1+0-500\n2+0-500\n8\n38\n64\n";
    const auto d = plan_of(check(tape));
    ASSERT_EQ(d.size(), 2u) << codes_of(d);
    EXPECT_EQ(d[0].code, DiagCode::N603_KerfInsideLoneContour);
    EXPECT_EQ(d[0].line, 5u);
    EXPECT_EQ(d[1].code, DiagCode::N603_KerfInsideLoneContour);
    EXPECT_EQ(d[1].line, 6u);
}

// --- Plates kept and analysed later (CutPlan::defer_plates, TapeChecker::defer_plan: the viewer's way) ---

TEST(CutPlanDeferred, KeptPlatesGiveTheDiagnosticsOfTheCheck) {
    Tape t;
    t.part_cw(60, 50, 260, 150);
    t.part_cw(240, 50, 440, 150, "29", 5);  // E605 with the first
    t.hole(500, 100, 20).part_cw(460, 50, 560, 150);
    t.part_cw(600, 50, 700, 150).hole(650, 100, 20);  // W604: the part before its hole
    t.next_plate();
    t.part_cw(60, 50, 260, 150).part_cw(60, 50, 260, 150);     // W607 on the second plate
    t.function("39+30").part_cw(300, 50, 400, 150, "29", 50);  // W608, and E606 across the first part
    const std::string tape = t.end();
    {
        SCOPED_TRACE("built tape");
        const auto found = plan_of(check(tape));
        EXPECT_GE(found.size(), 5u) << codes_of(found);  // (a tape that has something to compare)
        expect_deferred_plan_is_the_same(tape, essi::Profile{});
    }
    {
        SCOPED_TRACE("generated nest, several plates, CR LF");
        expect_deferred_plan_is_the_same(essi::bench::generate_nest_tape(200000, 3), essi::Profile{});
    }
}
