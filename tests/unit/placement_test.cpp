// The placement chain (core/geom/placement.cpp, docs/semantics.md §12): machine = zero offset + R(plate rotation)
// · program − tool offset, in the statistics' machine boxes, in E401 and in `essi trace --machine`.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "essi/placement.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/trace.hpp"

namespace essi {
namespace {

// A 100 x 50 mm rectangle cut from the origin (units of 0.1 mm).
const char* kRectangle = "7\n+1000+0\n+0+500\n-1000+0\n+0-500\n8\n64\n";

void expect_box(const Box& b, double min_x, double min_y, double max_x, double max_y) {
    ASSERT_FALSE(b.empty);
    EXPECT_NEAR(b.min_x, min_x, 1e-9);
    EXPECT_NEAR(b.min_y, min_y, 1e-9);
    EXPECT_NEAR(b.max_x, max_x, 1e-9);
    EXPECT_NEAR(b.max_y, max_y, 1e-9);
}

bool has(const CheckResult& r, DiagCode code, std::uint32_t line) {
    for (const auto& d : r.diagnostics)
        if (d.code == code && d.line == line) return true;
    return false;
}

TEST(Placement, ZeroOffsetMovesTheMachineBoxesOnly) {
    Profile p = *builtin_profile("iso6582");
    p.zero_offsets["G54"] = {1000, 500};
    const CheckResult r = check_tape(kRectangle, p);
    expect_box(r.stats.cut_bbox, 0, 0, 100, 50);  // program coordinates
    expect_box(r.stats.machine_cut_bbox, 1000, 500, 1100, 550);
    expect_box(r.stats.machine_motion_bbox, 1000, 500, 1100, 550);
}

TEST(Placement, TheActiveEntryOfTheTableCounts) {
    const auto parsed =
        parse_profile(R"({"zero_offsets": {"G54": {"x_mm": 1, "y_mm": 2}, "G55": {"x_mm": 2000, "y_mm": 0}},
                                          "zero_offset": "G55"})");
    ASSERT_TRUE(parsed.profile.has_value());
    const CheckResult r = check_tape(kRectangle, *parsed.profile);
    expect_box(r.stats.machine_cut_bbox, 2000, 0, 2100, 50);
}

TEST(Placement, SetupOffsetKeysAreTheDefaultEntry) {
    const auto parsed = parse_profile(R"({"setup_offset_x_mm": -12.5, "setup_offset_y_mm": 40})");
    ASSERT_TRUE(parsed.profile.has_value());
    EXPECT_EQ(parsed.profile->active_zero_offset(), (Point{-12.5, 40}));
    const CheckResult r = check_tape(kRectangle, *parsed.profile);
    expect_box(r.stats.cut_bbox, 0, 0, 100, 50);
    expect_box(r.stats.machine_cut_bbox, -12.5, 40, 87.5, 90);
}

// A plate lying turned by 90 degrees counter-clockwise: the rectangle's x becomes the machine's y.
TEST(Placement, PlateRotationTurnsAboutTheProgramOrigin) {
    Profile p = *builtin_profile("iso6582");
    p.zero_offsets["G54"] = {500, 0};
    p.plate_rotation_deg = 90;
    const CheckResult r = check_tape(kRectangle, p);
    expect_box(r.stats.machine_cut_bbox, 450, 0, 500, 100);
    // an arc's box turns exactly: a full circle of radius 10 about (10, 0) stays a circle's box
    const CheckResult c = check_tape("7\n+0+0+100+0+\n8\n64\n", p);
    expect_box(c.stats.machine_cut_bbox, 490, 0, 510, 20);
}

TEST(Placement, MarkerOffsetMovesTheCarriageAtOnce) {
    Profile p = *builtin_profile("iso6582");
    p.marker_offset = {80, 0};
    // mark a line with the marker offset on, then cancel it
    const CheckResult r = check_tape("+1000+0\n11\n9\n+1000+0\n10\n12\n+0+100\n64\n", p);
    // program: (0,0)->(100,0); 11: the carriage to (100-80, 0); marks (20,0)->(120,0); 12: back to (200,0)
    expect_box(r.stats.machine_motion_bbox, 0, 0, 200, 10);
    EXPECT_TRUE(r.stats.machine_cut_bbox.empty);
    const CheckResult first = check_tape("11\n9\n+1000+0\n10\n64\n", p);
    expect_box(first.stats.machine_motion_bbox, -80, 0, 20, 0);
}

TEST(Placement, LeavingTheTableIsE401ThroughEveryLink) {
    Profile p = *builtin_profile("iso6582");
    p.table = TableLimits{0, 0, 1000, 1000};
    p.zero_offsets["G54"] = {10, 10};
    EXPECT_TRUE(check_tape(kRectangle, p).diagnostics.empty());
    p.plate_rotation_deg = 180;  // the rectangle turns to x -90..10: off the table at its first motion
    const CheckResult turned = check_tape(kRectangle, p);
    EXPECT_TRUE(has(turned, DiagCode::E401_LeavesTable, 2));
    p.plate_rotation_deg = 0;
    p.marker_offset = {50, 0};
    // 11 at (0,0): the carriage goes to (10-50, 10): off the table at the 11
    const CheckResult marker = check_tape("11\n9\n+1000+0\n10\n12\n64\n", p);
    EXPECT_TRUE(has(marker, DiagCode::E401_LeavesTable, 1));
    EXPECT_NE(essi::diagnostic_message(marker.diagnostics.front(), essi::Lang::En).find("tool offset"),
              std::string::npos)
        << essi::diagnostic_message(marker.diagnostics.front(), essi::Lang::En);
}

TEST(Placement, TraceMachinePlacesEveryRecord) {
    Profile p = *builtin_profile("iso6582");
    p.zero_offsets["G54"] = {100, 200};
    p.plate_rotation_deg = 90;
    std::string out;
    (void)trace_tape(
        "7\n+1000+0\n+0+0+0+100+\n8\n64\n", p, [&](std::string_view s) { out += s; }, InputFormat::Essi, 3,
        TraceView{false, true});
    EXPECT_NE(out.find("cut line (100.000,200.000)->(100.000,300.000)"), std::string::npos) << out;
    EXPECT_NE(out.find("c=(90.000,300.000) r=10.000 ccw"), std::string::npos) << out;
}

}  // namespace
}  // namespace essi
