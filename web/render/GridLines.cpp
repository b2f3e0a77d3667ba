#include "render/GridLines.hpp"

#include <algorithm>
#include <cmath>

namespace essi::viewer {

namespace {

// The lines at multiples of `step` in [lo, hi] (absolute: offsets + the centre's absolute position `at`).
void lines_between(double lo, double hi, double at, double step, double& first, int& count, long long& index) {
    const double k0 = std::ceil((lo + at) / step), k1 = std::floor((hi + at) / step);
    count = 0;
    if (!(k1 >= k0) || k1 - k0 + 1 > GridLines::kMaxLines) return;
    count = static_cast<int>(k1 - k0) + 1;
    index = static_cast<long long>(k0);
    first = k0 * step - at;
}

}  // namespace

GridLines grid_lines(double cx, double cy, double zoom, double ox, double oy, int w, int h, Rotation rot, double step,
                     Point origin) {
    GridLines g;
    g.step = step;
    // The target's corners as offsets from its centre along the shown axes (the inverse of the drawing's mapping:
    // pixel = (ox, oy) + rot(offset) x zoom, y down).
    double lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0;
    bool first = true;
    for (const double px : {0.0, static_cast<double>(w)}) {
        for (const double py : {0.0, static_cast<double>(h)}) {
            const Point o = rot.undo({(px - ox) / zoom, (oy - py) / zoom});
            lo_x = first ? o.x : std::min(lo_x, o.x);
            hi_x = first ? o.x : std::max(hi_x, o.x);
            lo_y = first ? o.y : std::min(lo_y, o.y);
            hi_y = first ? o.y : std::max(hi_y, o.y);
            first = false;
        }
    }
    // A line's anti-aliased edge reaches a pixel beyond it.
    const double pad = 2 / zoom;
    g.lo_x = lo_x - pad;
    g.hi_x = hi_x + pad;
    g.lo_y = lo_y - pad;
    g.hi_y = hi_y + pad;
    // Absolute shown coordinates of the centre: (cx, cy) + origin.
    const double at_x = cx + origin.x, at_y = cy + origin.y;
    lines_between(g.lo_x, g.hi_x, at_x, step, g.first_x, g.count_x, g.first_index_x);
    lines_between(g.lo_y, g.hi_y, at_y, step, g.first_y, g.count_y, g.first_index_y);
    g.axis_x = -at_x;
    g.axis_y = -at_y;
    return g;
}

}  // namespace essi::viewer
