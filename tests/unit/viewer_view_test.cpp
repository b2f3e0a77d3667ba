// The viewer's camera (web/app/View.hpp) with the machine's view orientation: a quarter turn puts the tape's +x
// up and +y left (Woyda's operator's view); to_world undoes to_screen, a drag moves the drawing with the mouse.
#include <gtest/gtest.h>

#include <cmath>

#include "app/Coordinates.hpp"
#include "app/View.hpp"
#include "essi/profile.hpp"

using essi::Point;
using essi::viewer::Coordinates;
using essi::viewer::Rect;
using essi::viewer::Rotation;
using essi::viewer::View;

namespace {

View view_at(int turns) {
    View v;
    v.cx = 10;
    v.cy = 20;
    v.zoom = 2;
    v.area = Rect{0, 0, 400, 200};
    v.turns = turns;
    return v;
}

TEST(ViewerView, AQuarterTurnPutsXUpAndYLeft) {
    const View v = view_at(1);
    const Point c = v.to_screen({10, 20});
    EXPECT_DOUBLE_EQ(c.x, 200);
    EXPECT_DOUBLE_EQ(c.y, 100);
    const Point x_plus = v.to_screen({15, 20});  // 5 mm along +x: 10 px up
    EXPECT_DOUBLE_EQ(x_plus.x, 200);
    EXPECT_DOUBLE_EQ(x_plus.y, 90);
    const Point y_plus = v.to_screen({10, 25});  // 5 mm along +y: 10 px left
    EXPECT_DOUBLE_EQ(y_plus.x, 190);
    EXPECT_DOUBLE_EQ(y_plus.y, 100);
}

TEST(ViewerView, ToWorldUndoesToScreenInEveryOrientation) {
    for (int q = 0; q < 4; ++q) {
        SCOPED_TRACE(q);
        const View v = view_at(q);
        for (const Point p : {Point{0, 0}, Point{-37.5, 12.25}, Point{100, -3}}) {
            const Point s = v.to_screen(p);
            const Point back = v.to_world(s.x, s.y);
            EXPECT_NEAR(back.x, p.x, 1e-12);
            EXPECT_NEAR(back.y, p.y, 1e-12);
        }
    }
}

TEST(ViewerView, ADragMovesTheDrawingWithTheMouse) {
    for (int q = 0; q < 4; ++q) {
        SCOPED_TRACE(q);
        View v = view_at(q);
        const Point p{12, 18};
        const Point before = v.to_screen(p);
        v.pan_by(7, -3);
        const Point after = v.to_screen(p);
        EXPECT_NEAR(after.x - before.x, 7, 1e-9);
        EXPECT_NEAR(after.y - before.y, -3, 1e-9);
    }
}

TEST(ViewerView, FitSwapsWidthAndHeightWhenTurned) {
    essi::Box wide{0, 0, 300, 10, false};
    View flat = view_at(0), turned = view_at(1);
    flat.fit(wide, {0, 0}, 0);
    turned.fit(wide, {0, 0}, 0);
    EXPECT_DOUBLE_EQ(flat.zoom, 400.0 / 300);    // the width fills the area's width
    EXPECT_DOUBLE_EQ(turned.zoom, 200.0 / 300);  // turned, it runs up the area's height
}

// Machine coordinates: the plate's rotation turns the drawing before the orientation's quarter turns.
TEST(ViewerView, ThePlatesRotationTurnsTheDrawingBeforeTheQuarterTurns) {
    View v = view_at(1);
    v.plate = {0.6, 0.8};             // (cos, sin) of about 53.13 degrees
    const Rotation r = v.rotation();  // then a quarter turn: (cos, sin) = (-0.8, 0.6)
    EXPECT_NEAR(r.c, -0.8, 1e-15);
    EXPECT_NEAR(r.s, 0.6, 1e-15);
    const Point x_plus = v.to_screen({15, 20});  // 5 mm along +x: turned to (-4, 3) mm, 2 px/mm
    EXPECT_NEAR(x_plus.x, 200 - 8, 1e-12);
    EXPECT_NEAR(x_plus.y, 100 - 6, 1e-12);
    for (const Point p : {Point{0, 0}, Point{-37.5, 12.25}}) {
        const Point s = v.to_screen(p);
        const Point back = v.to_world(s.x, s.y);
        EXPECT_NEAR(back.x, p.x, 1e-12);
        EXPECT_NEAR(back.y, p.y, 1e-12);
    }
    const Point before = v.to_screen({12, 18});
    v.pan_by(7, -3);
    const Point after = v.to_screen({12, 18});
    EXPECT_NEAR(after.x - before.x, 7, 1e-9);
    EXPECT_NEAR(after.y - before.y, -3, 1e-9);
}

TEST(ViewerView, FitUsesTheTurnedBoxesExtent) {
    essi::Box square{0, 0, 100, 100, false};
    View v = view_at(0);
    v.area = Rect{0, 0, 400, 400};
    v.plate = {std::sqrt(0.5), std::sqrt(0.5)};  // 45 degrees: the square's diagonal across the area
    v.fit(square, {0, 0}, 0);
    EXPECT_NEAR(v.zoom, 400 / (100 * std::sqrt(2.0)), 1e-9);
    EXPECT_DOUBLE_EQ(v.cx, 50);
    EXPECT_DOUBLE_EQ(v.cy, 50);
}

// Machine coordinates are the placement without a tool offset (docs/semantics.md §12).
TEST(ViewerCoordinates, MachineCoordinatesAreThePlacementWithoutTheToolOffset) {
    essi::Profile p;
    p.zero_offsets["G54"] = {500, 20};
    p.plate_rotation_deg = 90;
    p.marker_offset = {80, 0};
    const Coordinates machine(p), program;
    EXPECT_STREQ(machine.name(), "machine");
    EXPECT_STREQ(program.name(), "program");
    const Point m = machine.shown({10, 0});
    EXPECT_NEAR(m.x, 500, 1e-12);
    EXPECT_NEAR(m.y, 30, 1e-12);
    const Point back = machine.program(m);
    EXPECT_NEAR(back.x, 10, 1e-12);
    EXPECT_NEAR(back.y, 0, 1e-12);
    EXPECT_NEAR(machine.plate().c, 0, 1e-15);
    EXPECT_NEAR(machine.plate().s, 1, 1e-15);
    EXPECT_EQ(program.shown({10, 0}).x, 10);
    EXPECT_EQ(program.plate(), Rotation{});
}

}  // namespace
