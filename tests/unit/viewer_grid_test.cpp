// The viewer's grid lines (web/render/GridLines.hpp): which lines a target shows, where they lie, which are major,
// and the axes, worked out in double precision.
#include <gtest/gtest.h>

#include <cmath>

#include "app/View.hpp"
#include "render/GridLines.hpp"

namespace essi::viewer {
namespace {

// A 200 x 100 px target, its centre (pixel 100, 50) at (cx, cy) mm, 2 px/mm: it shows x in [cx - 50, cx + 50] and
// y in [cy - 25, cy + 25] mm, and a pad of 2 px (1 mm) around for the lines' edges.
GridLines lines_at(double cx, double cy, double step, Point origin = {}, Rotation rot = {}) {
    return grid_lines(cx, cy, 2, 100, 50, 200, 100, rot, step, origin);
}

TEST(ViewerGrid, LinesAtEveryMultipleOfTheStepThatTheTargetShows) {
    const GridLines g = lines_at(3, 0, 10);
    // x from -48 to 54 (padded): lines at -40, -30, ..., 50; y from -26 to 26: -20 ... 20.
    EXPECT_EQ(g.count_x, 10);
    EXPECT_EQ(g.first_index_x, -4);
    EXPECT_DOUBLE_EQ(g.first_x, -40 - 3);  // (offsets from the centre)
    EXPECT_EQ(g.count_y, 5);
    EXPECT_EQ(g.first_index_y, -2);
    EXPECT_DOUBLE_EQ(g.first_y, -20);
    EXPECT_DOUBLE_EQ(g.lo_x, -51);
    EXPECT_DOUBLE_EQ(g.hi_x, 51);
    EXPECT_DOUBLE_EQ(g.lo_y, -26);
    EXPECT_DOUBLE_EQ(g.hi_y, 26);
    EXPECT_DOUBLE_EQ(g.axis_x, -3);
    EXPECT_DOUBLE_EQ(g.axis_y, 0);
}

TEST(ViewerGrid, EveryTenthLineIsMajorAndTheLineAtZeroIsLeftToTheAxis) {
    const GridLines g = lines_at(3, 0, 10);      // indices -4 .. 5 along x
    EXPECT_EQ(major_phase(g.first_index_x), 6);  // -4 + 4 = 0: line 4 (x = 0) is a multiple of 10 steps
    EXPECT_EQ(line_on_axis(g.first_index_x, g.count_x), 4);
    EXPECT_EQ(major_phase(-23), 7);  // line 3 (index -20) is major
    EXPECT_EQ(major_phase(96), 6);   // line 4 (index 100)
    EXPECT_EQ(line_on_axis(96, 10), -1);
    EXPECT_EQ(line_on_axis(-9, 9), -1);  // indices -9 .. -1: the axis is past the last line
    EXPECT_EQ(line_on_axis(0, 1), 0);
}

TEST(ViewerGrid, TheDocumentOriginShiftsTheLinesNotTheAxesMeaning) {
    // The shown coordinates are the document's plus its origin: the centre at 1003 mm shown.
    const GridLines g = lines_at(3, 0, 10, {1000, 500});
    EXPECT_EQ(g.first_index_x, 96);  // 960 mm shown is 1003 - 43
    EXPECT_DOUBLE_EQ(g.first_x, 960 - 1003);
    EXPECT_DOUBLE_EQ(g.axis_x, -1003);
    EXPECT_DOUBLE_EQ(g.axis_y, -500);
}

TEST(ViewerGrid, FineStepsFarFromTheOriginKeepTheirPlaces) {
    // A float has about 0.06 mm of room at 1 000 000 mm; the offsets are exact to far less.
    const GridLines g = grid_lines(0.05, 0, 1e4, 100, 50, 200, 100, {}, 0.001, {1e6, 0});
    ASSERT_GT(g.count_x, 0);
    const double first_shown = 1e6 + 0.05 + g.first_x;
    EXPECT_NEAR(first_shown, static_cast<double>(g.first_index_x) * 0.001, 1e-9);
    EXPECT_NEAR(g.first_x, -0.010, 1e-9);  // 1e6 + 0.040: the first multiple past the padded edge (0.0398)
}

TEST(ViewerGrid, AQuarterTurnSwapsWhatTheTargetShows) {
    const GridLines g = lines_at(0, 0, 10, {}, Rotation::quarter(1));
    // Turned, the 200 px width shows y and the 100 px height shows x.
    EXPECT_DOUBLE_EQ(g.lo_x, -26);
    EXPECT_DOUBLE_EQ(g.hi_x, 26);
    EXPECT_DOUBLE_EQ(g.lo_y, -51);
    EXPECT_DOUBLE_EQ(g.hi_y, 51);
    EXPECT_EQ(g.count_x, 5);
    EXPECT_EQ(g.count_y, 11);
}

TEST(ViewerGrid, NoGridLeavesOnlyTheLineOnTheAxes) {
    const GridLines g = lines_at(3, 0, kNoGrid);
    EXPECT_EQ(g.count_x, 1);
    EXPECT_EQ(g.first_index_x, 0);  // the axis draws it
    EXPECT_EQ(g.count_y, 1);
    EXPECT_EQ(g.first_index_y, 0);
}

TEST(ViewerGrid, AStepUnderAPixelDrawsNoLines) {
    const GridLines g = lines_at(0, 0, 0.01);  // 10 000 lines across 100 mm
    EXPECT_EQ(g.count_x, 0);
    EXPECT_EQ(g.count_y, 0);
    EXPECT_DOUBLE_EQ(g.axis_x, 0);
}

}  // namespace
}  // namespace essi::viewer
