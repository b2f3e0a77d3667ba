// The remnant of a plate (remnant.hpp): the plate cut into horizontal slabs at its outlines' points; in each slab
// the outlines reach to some x (their edges clipped to the slab, grown by the margin); the largest rectangle that
// ends at the plate's far end is the largest rectangle of that histogram (widths: from that x to the far end). The
// outlines run counter-clockwise round their parts: an edge going down has the part to its right, so at each height
// the outline reaches further right than it; only the edges going up or level are followed slab by slab.
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

// reach() of the edge a-b in each slab of [s0, s1), raising `reached` to it: the same clip of the edge to each slab
// widened by the margin, the edge's slope worked out once.
void raise_slabs(Point a, Point b, double margin, const std::vector<double>& ys, std::size_t s0, std::size_t s1,
                 std::vector<double>& reached) {
    const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
    if (a.y == b.y) {
        const double x = std::max(a.x, b.x) + margin;
        for (std::size_t s = s0; s < s1; ++s)
            if (hi + margin > ys[s] && lo - margin < ys[s + 1]) reached[s] = std::max(reached[s], x);
        return;
    }
    const double slope = (b.x - a.x) / (b.y - a.y);
    for (std::size_t s = s0; s < s1; ++s) {
        const double y0 = ys[s], y1 = ys[s + 1];
        if (hi + margin <= y0 || lo - margin >= y1) continue;
        const double c0 = std::max(y0 - margin, lo), c1 = std::min(y1 + margin, hi);
        const double x = std::max(a.x + slope * (c0 - a.y), a.x + slope * (c1 - a.y)) + margin;
        reached[s] = std::max(reached[s], x);
    }
}

// Past kPartsMaxRemnantSteps, an edge is cut into at most this many pieces over the slabs it spans.
constexpr std::size_t kRemnantPieces = 16;

// How far the outlines reach in each slab: the largest x of the ranges of slabs given (a tree of ranges: each
// range is kept at the O(log slabs) nodes that cover it, and a slab's reach is the largest on its way to the root).
class Reach {
public:
    Reach(std::size_t slabs, double floor) : size_(slabs), tree_(2 * slabs, floor) {}
    void raise(std::size_t first, std::size_t end, double x) {  // slabs [first, end)
        for (std::size_t l = first + size_, r = end + size_; l < r; l /= 2, r /= 2) {
            if (l & 1) tree_[l] = std::max(tree_[l], x), ++l;
            if (r & 1) --r, tree_[r] = std::max(tree_[r], x);
        }
    }
    [[nodiscard]] double at(std::size_t slab) const {
        double x = tree_[slab + size_];
        for (std::size_t k = (slab + size_) / 2; k > 0; k /= 2) x = std::max(x, tree_[k]);
        return x;
    }

private:
    std::size_t size_;
    std::vector<double> tree_;
};

}  // namespace

std::optional<Box> remnant(const Box& plate, const std::vector<std::vector<Point>>& outlines, double margin) {
    if (plate.empty || !(plate.max_x > plate.min_x) || !(plate.max_y > plate.min_y)) return std::nullopt;
    const std::vector<double> ys = slab_bounds(plate, outlines, margin);
    const std::size_t slabs = ys.size() - 1;
    const auto slab_of = [&](double y) {  // (the slab holding y, plus one)
        return static_cast<std::size_t>(std::upper_bound(ys.begin(), ys.end(), y) - ys.begin());
    };
    // Each edge over the slabs it spans, slab by slab while that takes at most kPartsMaxRemnantSteps steps in all;
    // past that an edge over more than kRemnantPieces slabs is cut into that many pieces, each raising its slabs to
    // its largest x (a little more than the edge reaches in some of them: the remnant only gets smaller).
    std::size_t steps = 0;
    for (const std::vector<Point>& o : outlines)
        for (std::size_t k = 0; k < o.size(); ++k) {
            const Point a = o[k], b = o[(k + 1) % o.size()];
            steps += slab_of(std::max(a.y, b.y) + margin) - std::min(slab_of(std::min(a.y, b.y) - margin), slabs) + 1;
        }
    const bool exact = steps <= kPartsMaxRemnantSteps;
    std::vector<double> reached(slabs, plate.min_x);
    Reach reach_of(exact ? 0 : slabs, plate.min_x);  // (exact: each slab raised on its own, no tree)
    for (const std::vector<Point>& o : outlines)
        for (std::size_t k = 0; k < o.size(); ++k) {
            const Point a = o[k], b = o[(k + 1) % o.size()];
            const std::size_t s0 = std::max<std::size_t>(slab_of(std::min(a.y, b.y) - margin), 1) - 1;
            const std::size_t s1 = std::min(slabs, slab_of(std::max(a.y, b.y) + margin));
            if (s1 <= s0) continue;
            if (exact) {
                if (b.y < a.y) continue;  // (going down: the part's material lies to its right, so does its outline)
                raise_slabs(a, b, margin, ys, s0, s1, reached);
                continue;
            }
            const std::size_t pieces = std::min<std::size_t>(s1 - s0, kRemnantPieces);
            for (std::size_t p = 0; p < pieces; ++p) {
                const std::size_t first = s0 + (s1 - s0) * p / pieces, end = s0 + (s1 - s0) * (p + 1) / pieces;
                if (const auto x = reach(a, b, ys[first], ys[end], margin)) reach_of.raise(first, end, *x);
            }
        }
    if (!exact)
        for (std::size_t s = 0; s < slabs; ++s) reached[s] = reach_of.at(s);
    // The largest rectangle of the histogram (a stack of slabs whose free width only grows)
    double best = 0;
    Box out;
    std::vector<std::size_t> stack;
    for (std::size_t s = 0; s <= slabs; ++s) {
        const double width = s < slabs ? plate.max_x - std::min(plate.max_x, reached[s]) : -1;
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
        }
        if (s < slabs) stack.push_back(s);
    }
    if (!(best > 0)) return std::nullopt;
    return out;
}

}  // namespace essi::parts
