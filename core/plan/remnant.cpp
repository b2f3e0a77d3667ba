// The remnant of a plate (remnant.hpp): the plate cut into horizontal slabs at its outlines' points; in each slab
// the outlines reach to some x (their edges clipped to the slab, grown by the margin); the largest rectangle that
// ends at the plate's far end is the largest rectangle of that histogram (widths: from that x to the far end).
#include "remnant.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "essi/parts.hpp"

namespace essi::parts {
namespace {

// The slabs' bounds: the outlines' ys (each grown by the margin both ways) within the plate, or, past
// kPartsMaxRemnantSlabs of them, that many even slabs.
std::vector<double> slab_bounds(const Box& plate, const std::vector<std::vector<Point>>& outlines, double margin) {
    std::vector<double> ys{plate.min_y, plate.max_y};
    for (const std::vector<Point>& o : outlines)
        for (const Point& p : o)
            for (const double y : {p.y - margin, p.y + margin})
                if (y > plate.min_y && y < plate.max_y) ys.push_back(y);
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    if (ys.size() <= kPartsMaxRemnantSlabs + 1) return ys;
    ys.resize(kPartsMaxRemnantSlabs + 1);
    for (std::size_t k = 0; k <= kPartsMaxRemnantSlabs; ++k)
        ys[k] = plate.min_y + (plate.max_y - plate.min_y) * static_cast<double>(k) / kPartsMaxRemnantSlabs;
    return ys;
}

// The x an edge a-b (grown by the margin) reaches within the slab [y0, y1], or nothing when it misses it.
std::optional<double> reach(Point a, Point b, double y0, double y1, double margin) {
    const double lo = std::min(a.y, b.y) - margin, hi = std::max(a.y, b.y) + margin;
    if (hi <= y0 || lo >= y1) return std::nullopt;
    if (a.y == b.y) return std::max(a.x, b.x) + margin;
    // the edge clipped to the slab widened by the margin: x is linear in y, its largest at an end of the clip
    const double c0 = std::max(y0 - margin, std::min(a.y, b.y)), c1 = std::min(y1 + margin, std::max(a.y, b.y));
    const auto x_at = [&](double y) { return a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y); };
    return std::max(x_at(c0), x_at(c1)) + margin;
}

}  // namespace

std::optional<Box> remnant(const Box& plate, const std::vector<std::vector<Point>>& outlines, double margin) {
    if (plate.empty || !(plate.max_x > plate.min_x) || !(plate.max_y > plate.min_y)) return std::nullopt;
    const std::vector<double> ys = slab_bounds(plate, outlines, margin);
    const std::size_t slabs = ys.size() - 1;
    std::vector<double> reached(slabs, plate.min_x);  // how far the parts reach in each slab
    const auto slab_of = [&](double y) {
        return static_cast<std::size_t>(std::upper_bound(ys.begin(), ys.end(), y) - ys.begin());
    };
    // Each edge over the slabs it spans (its steps, within kPartsMaxRemnantSteps; past that each outline's box)
    std::size_t steps = 0;
    bool by_boxes = false;
    for (const std::vector<Point>& o : outlines)
        for (std::size_t k = 0; k < o.size() && !by_boxes; ++k) {
            const Point a = o[k], b = o[(k + 1) % o.size()];
            const std::size_t s0 = slab_of(std::min(a.y, b.y) - margin), s1 = slab_of(std::max(a.y, b.y) + margin);
            steps += s1 - std::min(s0, s1) + 1;
            by_boxes = steps > kPartsMaxRemnantSteps;
        }
    for (const std::vector<Point>& o : outlines) {
        if (by_boxes) {
            Box b;
            for (const Point& p : o) b.add(p);
            const Point corners[2] = {{b.max_x, b.min_y}, {b.max_x, b.max_y}};
            for (std::size_t s = 0; s < slabs; ++s)
                if (const auto x = reach(corners[0], corners[1], ys[s], ys[s + 1], margin)) reached[s] = std::max(reached[s], *x);
            continue;
        }
        for (std::size_t k = 0; k < o.size(); ++k) {
            const Point a = o[k], b = o[(k + 1) % o.size()];
            const std::size_t s0 = slab_of(std::min(a.y, b.y) - margin);
            const std::size_t s1 = std::min(slabs, slab_of(std::max(a.y, b.y) + margin));
            for (std::size_t s = s0 > 0 ? s0 - 1 : 0; s < s1; ++s)
                if (const auto x = reach(a, b, ys[s], ys[s + 1], margin)) reached[s] = std::max(reached[s], *x);
        }
    }
    // The largest rectangle of the histogram (a stack of slabs whose free width only grows)
    double best = 0;
    Box out;
    std::vector<std::size_t> stack;
    for (std::size_t s = 0; s <= slabs; ++s) {
        const double width = s < slabs ? plate.max_x - std::min(plate.max_x, reached[s]) : -1;
        std::size_t start = s;
        while (!stack.empty() && plate.max_x - std::min(plate.max_x, reached[stack.back()]) >= width) {
            const std::size_t top = stack.back();
            stack.pop_back();
            const double w = plate.max_x - std::min(plate.max_x, reached[top]);
            const std::size_t from = stack.empty() ? 0 : stack.back() + 1;
            const double area = w * (ys[s] - ys[from]);
            if (area > best) {
                best = area;
                out = Box{plate.max_x - w, ys[from], plate.max_x, ys[s], false};
            }
            start = from;
        }
        (void)start;
        if (s < slabs) stack.push_back(s);
    }
    if (!(best > 0)) return std::nullopt;
    return out;
}

}  // namespace essi::parts
