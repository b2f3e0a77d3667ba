// The grid's lines for one target: minor lines every `step` mm, every tenth a major one, the axes through the
// origin. The grid program (shaders/grid.vert.glsl) draws each as a thin quad, so a CPU renderer shades the lines'
// pixels only, not every pixel of the image. Positions are offsets from the target's centre (mm, along the shown
// axes), worked out here in double precision: far from the origin a float has no room for a fine step.
#pragma once

#include "app/View.hpp"

namespace essi::viewer {

struct GridLines {
    // Lines along x (x constant, i = 0..count_x-1) lie at first_x + i step from the centre; their grid index
    // (k: the line is at k step in the shown coordinates) is first_index_x + i. The same along y.
    double first_x = 0, first_y = 0, step = 1;
    int count_x = 0, count_y = 0;
    long long first_index_x = 0, first_index_y = 0;
    // The axes (x = 0 and y = 0), offsets from the centre; the line of index 0 is left to them.
    double axis_x = 0, axis_y = 0;
    // What every line spans: from lo to hi along the other axis (offsets from the centre).
    double lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0;

    static constexpr int kMajorEvery = 10;
    // More lines than this along one axis (a step under a pixel): none but the axes. grid_step keeps lines at
    // least 12 px apart, so a target of up to 24 000 px has them all.
    static constexpr int kMaxLines = 2000;
};

// Of lines along one axis whose first has grid index `first_index`: the first's index modulo kMajorEvery (line i is
// major when (phase + i) is a multiple of it), and the line of index 0 (i, -1 when none: the axis draws it).
[[nodiscard]] constexpr int major_phase(long long first_index) {
    return static_cast<int>(((first_index % GridLines::kMajorEvery) + GridLines::kMajorEvery) % GridLines::kMajorEvery);
}
[[nodiscard]] constexpr int line_on_axis(long long first_index, int count) {
    return first_index <= 0 && -first_index < count ? static_cast<int>(-first_index) : -1;
}

// The lines of a grid of `step` mm over a target of w x h pixels, whose centre (cx, cy: mm in the shown
// coordinates, relative to `origin`, the document origin in them) is drawn at pixel (ox, oy) (top-left origin), at
// `zoom` px/mm, turned by `rot` (quarter turns: the grid lies along the screen's axes). `step` kNoGrid: the axes only.
[[nodiscard]] GridLines grid_lines(double cx, double cy, double zoom, double ox, double oy, int w, int h, Rotation rot,
                                   double step, Point origin);

}  // namespace essi::viewer
