// The viewer's camera (web/app/View.hpp) with the machine's view orientation: a quarter turn puts the tape's +x
// up and +y left (Woyda's operator's view); to_world undoes to_screen, a drag moves the drawing with the mouse.
#include <gtest/gtest.h>

#include "app/View.hpp"

using essi::Point;
using essi::viewer::Rect;
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
    EXPECT_DOUBLE_EQ(flat.zoom, 400.0 / 300);   // the width fills the area's width
    EXPECT_DOUBLE_EQ(turned.zoom, 200.0 / 300);  // turned, it runs up the area's height
}

}  // namespace
