// The measure mode: two clicked points (program mm), snapped to end points and arc centres (Input.hpp's snap).
#pragma once

#include "essi/geom.hpp"

namespace essi::viewer {

struct Measure {
    bool active = false;
    int points = 0;  // 0, 1 (a fixed, b follows the mouse) or 2
    Point a, b;

    void toggle() {
        active = !active;
        points = 0;
    }
    void leave() {
        active = false;
        points = 0;
    }
    void click(Point p) {
        if (points != 1) {
            a = p;
            points = 1;
        } else {
            b = p;
            points = 2;
        }
    }
};

}  // namespace essi::viewer
