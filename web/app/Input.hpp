// The mouse and the keyboard on the drawing: pan, zoom, pick a motion, measure between snapped points, and the
// shortcuts (the Help window lists them).
#pragma once

#include <cstddef>

#include "app/Document.hpp"
#include "app/View.hpp"

namespace essi::viewer {

class App;

// The measure mode: two clicked points (machine mm), snapped to end points and arc centres.
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
    void click(Point p);
};

// The motion under screen point (sx, sy) among motions [0, limit) of the kinds in `kind_mask`, from the exact
// geometry (the segments live on the GPU only); Selection::npos when none is within the pick radius.
[[nodiscard]] std::size_t pick(const Document& d, const View& view, std::size_t limit, int kind_mask, double sx,
                               double sy);
// The machine point under (sx, sy), snapped to the nearest end point or arc centre within the snap radius.
[[nodiscard]] Point snap(const Document* d, const View& view, double sx, double sy, bool* snapped);

class Input {
public:
    void handle_shortcuts(App& app);
    void handle_canvas(App& app);

    Measure measure;

private:
    void handle_characters(App& app);
    void handle_keys(App& app);
    void click(App& app, double sx, double sy);

    bool dragging_ = false;
    bool press_in_canvas_ = false;
    float press_x_ = 0, press_y_ = 0;
};

}  // namespace essi::viewer
