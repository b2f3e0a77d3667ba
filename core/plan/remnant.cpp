// The remnant of a plate (remnant.hpp): the plate cut into horizontal slabs at its outlines' points; in each slab
// the outlines reach to some x (their edges clipped to the slab, grown by the margin); the largest rectangle that
// ends at the plate's far end is the largest rectangle of that histogram (widths: from that x to the far end). The
// outlines run counter-clockwise round their parts: an edge going down has the part to its right, so at each height
// the outline reaches further right than it; only the edges going up or level are followed slab by slab.
#include "remnant.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include "essi/parts.hpp"

namespace essi::parts {
namespace {

// The slabs' bounds: the outlines' ys (each grown by the margin both ways) within the plate, or, past
// kPartsMaxRemnantSlabs of them, that many even slabs.
std::vector<double> slab_bounds(const Box& plate, const std::vector<std::vector<Point>>& outlines,
                                const std::vector<std::size_t>& kept, double margin) {
    // (the points' ys sorted once: less the margin and plus it they are two sorted runs, merged)
    std::vector<double> at;
    for (const std::size_t k : kept)
        for (const Point& p : outlines[k])
            if (!std::isnan(p.y)) at.push_back(p.y);
    std::sort(at.begin(), at.end());
    std::vector<double> ys;
    ys.reserve(2 * at.size() + 2);
    ys.push_back(plate.min_y);
    for (std::size_t below = 0, above = 0; below < at.size() || above < at.size();) {
        const bool take_below = above == at.size() || (below < at.size() && at[below] - margin <= at[above] + margin);
        const double y = take_below ? at[below++] - margin : at[above++] + margin;
        if (y > plate.min_y && y < plate.max_y) ys.push_back(y);
    }
    ys.push_back(plate.max_y);
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

// reach() of the edge a-b, its slope worked out once: the x it reaches (grown by the margin) in the slab
// [y0, y1] widened by the margin, -infinity when it misses it.
class EdgeReach {
public:
    EdgeReach(Point a, Point b, double margin)
        : a_(a), lo_(std::min(a.y, b.y)), hi_(std::max(a.y, b.y)), margin_(margin),
          level_x_(std::max(a.x, b.x) + margin), slope_(a.y == b.y ? 0 : (b.x - a.x) / (b.y - a.y)),
          level_(a.y == b.y) {}
    [[nodiscard]] double in(double y0, double y1) const {
        if (hi_ + margin_ <= y0 || lo_ - margin_ >= y1) return -std::numeric_limits<double>::infinity();
        if (level_) return level_x_;
        const double c0 = std::max(y0 - margin_, lo_), c1 = std::min(y1 + margin_, hi_);
        return std::max(a_.x + slope_ * (c0 - a_.y), a_.x + slope_ * (c1 - a_.y)) + margin_;
    }

private:
    Point a_;
    double lo_, hi_, margin_, level_x_, slope_;
    bool level_;
};

// The slab holding y, plus one (the first bound above y), searched outward from `hint` (galloping).
std::size_t slab_near(const std::vector<double>& ys, double y, std::size_t hint) {
    const std::size_t n = ys.size();
    hint = std::min(hint, n);
    const auto first_above = [&](std::size_t lo, std::size_t hi) {
        return static_cast<std::size_t>(std::upper_bound(ys.begin() + static_cast<std::ptrdiff_t>(lo),
                                                         ys.begin() + static_cast<std::ptrdiff_t>(hi), y) -
                                        ys.begin());
    };
    std::size_t step = 1;
    if (hint < n && ys[hint] <= y) {  // (the answer lies right of hint)
        std::size_t lo = hint + 1;
        while (lo + step - 1 < n && ys[lo + step - 1] <= y) {
            lo += step;
            step *= 2;
        }
        return first_above(lo, std::min(n, lo + step - 1));
    }
    std::size_t hi = hint;  // (ys[hi] > y, or hi == n: the answer is hi or left of it)
    while (hi >= step && ys[hi - step] > y) {
        hi -= step;
        step *= 2;
    }
    return first_above(hi >= step ? hi - step + 1 : 0, hi);
}

// An outline's edge a-b and the slabs [s0, s1) it spans (grown by the margin).
struct EdgeSlabs {
    Point a, b;
    std::uint32_t s0 = 0, s1 = 0;
};

// Each slab raised to the largest x the edges reach in it (EdgeReach), the outlines taken from the one that
// reaches furthest: a slab already raised as far as an outline's furthest x cannot be raised by it or any later
// one, so it is passed over from then on (`next`: the next slab that is not, path-halving).
void raise_exactly(const std::vector<std::vector<Point>>& outlines, const std::vector<std::size_t>& kept,
                   const std::vector<EdgeSlabs>& edges, const std::vector<double>& ys, double margin,
                   std::vector<double>& reached) {
    struct Outline {
        std::size_t first_edge, end_edge;
        double furthest;  // its edges' largest x, grown by the margin
    };
    std::vector<Outline> order;
    for (std::size_t i = 0, first = 0; i < kept.size(); first += outlines[kept[i++]].size()) {
        const std::vector<Point>& outline = outlines[kept[i]];
        Outline o{first, first + outline.size(), -std::numeric_limits<double>::infinity()};
        for (const Point& p : outline) o.furthest = std::max(o.furthest, p.x + margin);
        order.push_back(o);
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const Outline& a, const Outline& b) { return a.furthest > b.furthest; });
    std::vector<std::uint32_t> next(reached.size() + 1);
    for (std::size_t s = 0; s < next.size(); ++s) next[s] = static_cast<std::uint32_t>(s);
    const auto open_from = [&](std::uint32_t s) {
        while (next[s] != s) s = next[s] = next[next[s]];
        return s;
    };
    for (const Outline& o : order)
        for (std::size_t k = o.first_edge; k < o.end_edge; ++k) {
            const EdgeSlabs& e = edges[k];
            if (e.b.y < e.a.y) continue;  // (going down: the part's material lies to its right, so does its outline)
            const EdgeReach edge(e.a, e.b, margin);
            for (std::uint32_t s = open_from(e.s0); s < e.s1; s = open_from(s + 1)) {
                reached[s] = std::max(reached[s], edge.in(ys[s], ys[s + 1]));
                if (reached[s] >= o.furthest) next[s] = s + 1;
            }
        }
}

// The outlines that cannot raise any slab: at every height of one (grown by the margin) another outline lies
// wholly to its right. A counter-clockwise outline's rightmost edge at a height within it goes up and lies right of
// its leftmost point, so there the other raises the slab at least as far as this one's furthest. (The outlines
// taken from the one ending furthest right; the heights covered by the outlines starting right of that end kept as
// merged spans.)
std::vector<bool> shadowed(const std::vector<std::vector<Point>>& outlines, double margin) {
    const std::size_t n = outlines.size();
    std::vector<Box> boxes(n);
    for (std::size_t k = 0; k < n; ++k)
        for (const Point& p : outlines[k]) boxes[k].add(p);
    std::vector<std::size_t> by_end(n), by_start(n);
    for (std::size_t k = 0; k < n; ++k) by_end[k] = by_start[k] = k;
    std::sort(by_end.begin(), by_end.end(),
              [&](std::size_t a, std::size_t b) { return boxes[a].max_x > boxes[b].max_x; });
    std::sort(by_start.begin(), by_start.end(),
              [&](std::size_t a, std::size_t b) { return boxes[a].min_x > boxes[b].min_x; });
    std::map<double, double> covered;  // disjoint spans of height: low -> high
    const auto cover = [&](double lo, double hi) {
        auto it = covered.upper_bound(lo);
        if (it != covered.begin() && std::prev(it)->second >= lo) {
            --it;
            lo = it->first;
        }
        while (it != covered.end() && it->first <= hi) {
            hi = std::max(hi, it->second);
            it = covered.erase(it);
        }
        covered.emplace(lo, hi);
    };
    const auto covers = [&](double lo, double hi) {
        auto it = covered.upper_bound(lo);
        return it != covered.begin() && std::prev(it)->second >= hi;
    };
    std::vector<bool> out(n, false);
    std::size_t next = 0;
    for (const std::size_t k : by_end) {
        const Box& b = boxes[k];
        if (b.empty) continue;
        for (; next < n && boxes[by_start[next]].min_x >= b.max_x; ++next)
            if (const Box& o = boxes[by_start[next]]; !o.empty && o.max_y > o.min_y) cover(o.min_y, o.max_y);
        out[k] = b.max_x > b.min_x && covers(b.min_y - margin, b.max_y + margin);  // (not covered by itself)
    }
    return out;
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
    const std::vector<bool> passed = shadowed(outlines, margin);
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < outlines.size(); ++k)
        if (!passed[k]) kept.push_back(k);
    const std::vector<double> ys = slab_bounds(plate, outlines, kept, margin);
    const std::size_t slabs = ys.size() - 1;
    // Each edge over the slabs it spans, slab by slab while that takes at most kPartsMaxRemnantSteps steps in all;
    // past that an edge over more than kRemnantPieces slabs is cut into that many pieces, each raising its slabs to
    // its largest x (a little more than the edge reaches in some of them: the remnant only gets smaller).
    std::vector<EdgeSlabs> edges;
    std::vector<std::size_t> below, above;  // slab_of(y - margin) and slab_of(y + margin) of an outline's points
    std::size_t steps = 0;
    for (const std::size_t i : kept) {
        const std::vector<Point>& o = outlines[i];
        below.resize(o.size());
        above.resize(o.size());
        for (std::size_t k = 0; k < o.size(); ++k) {  // (searched from the point before's: they lie close)
            below[k] = slab_near(ys, o[k].y - margin, k > 0 ? below[k - 1] : slabs / 2);
            above[k] = slab_near(ys, o[k].y + margin, k > 0 ? above[k - 1] : slabs / 2);
        }
        for (std::size_t k = 0; k < o.size(); ++k) {
            const std::size_t next = k + 1 == o.size() ? 0 : k + 1;
            const Point a = o[k], b = o[next];
            // (slab_of(min(a.y, b.y) - margin) and slab_of(max(a.y, b.y) + margin): slab_of only grows with y)
            const std::size_t lo = std::min(below[k], below[next]), hi = std::max(above[k], above[next]);
            steps += hi - std::min(lo, slabs) + 1;
            edges.push_back({a, b, static_cast<std::uint32_t>(std::max<std::size_t>(lo, 1) - 1),
                             static_cast<std::uint32_t>(std::min(slabs, hi))});
        }
    }
    std::vector<double> reached(slabs, plate.min_x);
    if (steps <= kPartsMaxRemnantSteps) {
        raise_exactly(outlines, kept, edges, ys, margin, reached);
    } else {
        Reach reach_of(slabs, plate.min_x);
        for (const EdgeSlabs& e : edges) {
            if (e.s1 <= e.s0) continue;
            const std::size_t pieces = std::min<std::size_t>(e.s1 - e.s0, kRemnantPieces);
            for (std::size_t p = 0; p < pieces; ++p) {
                const std::size_t first = e.s0 + (e.s1 - e.s0) * p / pieces;
                const std::size_t end = e.s0 + (e.s1 - e.s0) * (p + 1) / pieces;
                if (const auto x = reach(e.a, e.b, ys[first], ys[end], margin)) reach_of.raise(first, end, *x);
            }
        }
        for (std::size_t s = 0; s < slabs; ++s) reached[s] = reach_of.at(s);
    }
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
