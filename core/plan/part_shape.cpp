// A part's shape made canonical and compared under turns and moves (part_shape.hpp, docs/semantics.md §9).
#include "part_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "essi/parts.hpp"
#include "essi/plan.hpp"

namespace essi::parts {
namespace {

constexpr std::size_t kMaxTurns = kPartsMaxAlignments;
constexpr double kOutlineTolerance = kPartsOutlineToleranceMm;
constexpr double kOutlineCoarseMm = kPartsOutlineCoarseMm;
constexpr int kOutlineMaxChords = kPlanMaxArcChords;
// Runs of material this close in width (mm) are as wide for the label: a symmetric part's label does not move
// from one side to the other with the rounding of its points.
constexpr double kLabelTieMm = 1e-9;

double dist(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }
double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
Point sub(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }

// A turn by `angle` about `from`, then a move of `from` to `to`.
struct Rigid {
    double c = 1, s = 0;
    Point from, to;
    Rigid(double angle, Point f, Point t) : c(std::cos(angle)), s(std::sin(angle)), from(f), to(t) {}
    [[nodiscard]] Point operator()(Point p) const {
        const double x = p.x - from.x, y = p.y - from.y;
        return {to.x + c * x - s * y, to.y + s * x + c * y};
    }
    [[nodiscard]] double angle() const { return std::atan2(s, c); }
};

// The direction from `centre` to `p` (cos, sin), and that turned by `angle`.
Point direction(Point p, Point centre) {
    const double r = dist(p, centre);
    return r > 0 ? Point{(p.x - centre.x) / r, (p.y - centre.y) / r} : Point{1, 0};
}
Point turned(Point d, double c, double s) { return {d.x * c - d.y * s, d.x * s + d.y * c}; }

// The point halfway along an arc motion (point_at(m, 0.5): its radius halfway from the start's to the end's).
Point arc_middle(const MotionRecord& m) {
    const Point d = turned(direction(m.start, m.centre), std::cos(m.sweep / 2), std::sin(m.sweep / 2));
    const double r = (m.radius + m.end_radius) / 2;
    return {m.centre.x + r * d.x, m.centre.y + r * d.y};
}

// The piece of a motion.
Seg seg_of(const MotionRecord& m) {
    Seg s;
    s.curve = m.curve;
    s.a = m.start;
    s.b = m.end;
    s.mid = m.curve == CurveKind::Arc ? arc_middle(m) : point_at(m, 0.5);
    s.length = m.length_mm;
    if (m.curve == CurveKind::Arc) {
        s.centre = m.centre;
        s.radius = (m.radius + m.end_radius) / 2;
        s.sweep = m.sweep;
    } else if (m.curve == CurveKind::Parabola) {
        s.control = {2 * s.mid.x - (s.a.x + s.b.x) / 2, 2 * s.mid.y - (s.a.y + s.b.y) / 2};
    } else {
        s.length = dist(s.a, s.b);
    }
    return s;
}

Seg reversed(Seg s) {
    std::swap(s.a, s.b);
    s.sweep = -s.sweep;
    return s;
}

// The point of an arc piece at `angle` from its start about its centre.
Point arc_point(const Seg& s, double angle) {
    const Point d = turned(direction(s.a, s.centre), std::cos(angle), std::sin(angle));
    return {s.centre.x + s.radius * d.x, s.centre.y + s.radius * d.y};
}

// `next` goes on as `s` (s then next are one line or one arc) within `tolerance`: s grows by it.
bool merge_into(Seg& s, const Seg& next, double tolerance) {
    if (s.curve != next.curve) return false;
    if (s.curve == CurveKind::Line) {
        const Point d = sub(s.b, s.a), e = sub(next.b, next.a);
        const double len = std::hypot(d.x, d.y);
        if (len <= 0 || d.x * e.x + d.y * e.y <= 0) return false;
        if (std::fabs(cross(d, sub(next.b, s.a))) / len > tolerance) return false;
        s.b = next.b;
        s.length = dist(s.a, s.b);
        s.mid = {(s.a.x + s.b.x) / 2, (s.a.y + s.b.y) / 2};
        return true;
    }
    if (s.curve == CurveKind::Arc) {
        if ((s.sweep > 0) != (next.sweep > 0) || dist(s.centre, next.centre) > tolerance ||
            std::fabs(s.radius - next.radius) > tolerance || std::fabs(s.sweep + next.sweep) > 2 * kPi + 1e-9)
            return false;
        s.b = next.b;
        s.sweep += next.sweep;
        s.length += next.length;
        s.mid = arc_point(s, s.sweep / 2);
        return true;
    }
    return false;
}

// Pieces shorter than this (mm) are dropped: a loop closing exactly on a vertex leaves none.
constexpr double kNoLengthMm = 1e-9;

void merge_pieces(std::vector<Seg>& segs, double tolerance) {
    std::vector<Seg> out;
    out.reserve(segs.size());
    for (const Seg& s : segs) {
        if (s.curve == CurveKind::Line && s.length <= kNoLengthMm) continue;
        if (out.empty() || !merge_into(out.back(), s, tolerance)) out.push_back(s);
    }
    // across the loop's start: the last piece may go on as the first
    while (out.size() > 1) {
        Seg last = out.back();
        if (!merge_into(last, out.front(), tolerance)) break;
        out.front() = last;
        out.pop_back();
    }
    segs.swap(out);
}

}  // namespace

Loop make_loop(std::span<const MotionRecord> motions, double tolerance) {
    Loop loop;
    AreaTerms sum;
    for (const MotionRecord& m : motions) {
        const AreaTerms t = area_terms(m);
        sum.twice_area += t.twice_area;
        sum.x2dy += t.x2dy;
        sum.y2dx += t.y2dx;
        loop.segs.push_back(seg_of(m));
    }
    if (loop.segs.empty()) return loop;
    // (the loop closes within the arc tolerance: the gap as a line, for the area; the pieces meet exactly)
    MotionRecord gap;
    gap.start = loop.segs.back().b;
    gap.end = loop.segs.front().a;
    const AreaTerms g = area_terms(gap);
    sum.twice_area += g.twice_area;
    sum.x2dy += g.x2dy;
    sum.y2dx += g.y2dx;
    loop.segs.back().b = loop.segs.front().a;
    loop.area = sum.twice_area / 2;
    loop.centroid = loop.area != 0 ? Point{sum.x2dy / sum.twice_area, -sum.y2dx / sum.twice_area} : loop.segs[0].a;
    if (loop.area < 0) {
        std::reverse(loop.segs.begin(), loop.segs.end());
        for (Seg& s : loop.segs) s = reversed(s);
        loop.area = -loop.area;
    }
    merge_pieces(loop.segs, tolerance);
    loop.circle = loop.segs.size() == 1 && loop.segs[0].curve == CurveKind::Arc &&
                  std::fabs(loop.segs[0].sweep) >= 2 * kPi - 1e-6;
    return loop;
}

Shape make_shape(std::vector<Loop> loops) {
    Shape s;
    s.loops = std::move(loops);
    double mx = 0, my = 0;
    for (std::size_t k = 0; k < s.loops.size(); ++k) {
        const Loop& l = s.loops[k];
        const double sign = k == 0 ? 1 : -1;
        s.area += sign * l.area;
        mx += sign * l.area * l.centroid.x;
        my += sign * l.area * l.centroid.y;
        for (const Seg& g : l.segs) {  // (by their chords: an arc's ends rounded to the unit turn its length)
            const double chord = g.curve == CurveKind::Line || !(dist(g.a, g.b) > 0) ? g.length : dist(g.a, g.b);
            s.perimeter += chord;
            s.lengths.push_back(chord);
        }
        s.pieces += l.segs.size();
    }
    s.centroid = s.area != 0 ? Point{mx / s.area, my / s.area} : s.loops.empty() ? Point{} : s.loops[0].centroid;
    for (std::size_t k = 1; k < s.loops.size(); ++k) {
        s.hole_areas.push_back(s.loops[k].area);
        s.hole_distances.push_back(dist(s.loops[k].centroid, s.centroid));
    }
    std::sort(s.lengths.begin(), s.lengths.end());
    std::sort(s.hole_areas.begin(), s.hole_areas.end());
    std::sort(s.hole_distances.begin(), s.hole_distances.end());
    s.by_x.resize(s.loops.size());
    for (std::size_t k = 0; k < s.by_x.size(); ++k) s.by_x[k] = k;
    std::sort(s.by_x.begin(), s.by_x.end(),
              [&](std::size_t a, std::size_t b) { return s.loops[a].centroid.x < s.loops[b].centroid.x; });
    return s;
}

Shape mirrored(const Shape& s) {
    std::vector<Loop> loops = s.loops;
    const auto flip = [](Point& p) { p.y = -p.y; };
    for (Loop& l : loops) {
        flip(l.centroid);
        for (Seg& g : l.segs) {
            flip(g.a);
            flip(g.b);
            flip(g.mid);
            flip(g.centre);
            flip(g.control);
            g.sweep = -g.sweep;
        }
        // (mirrored, the loop runs clockwise: back to counter-clockwise)
        std::reverse(l.segs.begin(), l.segs.end());
        for (Seg& g : l.segs) g = reversed(g);
    }
    return make_shape(std::move(loops));
}

namespace {

// Sorted lists equal element by element within `tolerance`.
bool close_lists(const std::vector<double>& a, const std::vector<double>& b, double tolerance) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::fabs(a[k] - b[k]) > tolerance) return false;
    return true;
}

// The area a loop of this perimeter gains or loses when its points move by `tolerance`.
double area_slack(double perimeter, double tolerance) { return 2 * tolerance * perimeter + 4 * tolerance * tolerance; }

// Whether piece `p`, moved by `t`, is piece `q` within `tolerance`: its ends, and an arc's centre, radius and turn
// (a rounded arc's middle moves with its centre and both ends), a parabola's middle.
bool same_piece(const Seg& p, const Seg& q, const Rigid& t, double tolerance) {
    if (p.curve != q.curve || dist(t(p.a), q.a) > tolerance || dist(t(p.b), q.b) > tolerance) return false;
    switch (p.curve) {
        case CurveKind::Line: return true;
        case CurveKind::Arc:
            return (p.sweep > 0) == (q.sweep > 0) && std::fabs(std::fabs(p.sweep) - std::fabs(q.sweep)) < kPi &&
                   dist(t(p.centre), q.centre) <= tolerance && std::fabs(p.radius - q.radius) <= tolerance;
        case CurveKind::Parabola: return dist(t(p.mid), q.mid) <= tolerance;
    }
    return false;
}

// Whether loop `a`, moved by `t`, is loop `b` within `tolerance`: the same pieces from some start of b's.
bool same_loop(const Loop& a, const Loop& b, const Rigid& t, double tolerance) {
    const std::size_t n = a.segs.size();
    if (n != b.segs.size() || a.circle != b.circle || n == 0) return false;
    if (a.circle)
        return dist(t(a.segs[0].centre), b.segs[0].centre) <= tolerance &&
               std::fabs(a.segs[0].radius - b.segs[0].radius) <= tolerance;
    const Point first = t(a.segs[0].a);
    for (std::size_t j = 0; j < n; ++j) {
        if (b.segs[j].curve != a.segs[0].curve || dist(b.segs[j].a, first) > tolerance) continue;
        bool all = true;
        for (std::size_t i = 0; i < n && all; ++i) all = same_piece(a.segs[i], b.segs[(j + i) % n], t, tolerance);
        if (all) return true;
    }
    return false;
}

// Whether every loop of `a`, moved by `t`, is a loop of `b` (each of b's matched once).
bool same_loops(const Shape& a, const Shape& b, const Rigid& t, double tolerance) {
    std::vector<bool> used(b.loops.size(), false);
    for (std::size_t k = 0; k < a.loops.size(); ++k) {
        const Loop& la = a.loops[k];
        const Point c = t(la.centroid);
        const double reach = 4 * tolerance;  // (a centroid moves less than the points, but on a thin loop more)
        const auto first = std::lower_bound(b.by_x.begin(), b.by_x.end(), c.x - reach,
                                            [&](std::size_t i, double x) { return b.loops[i].centroid.x < x; });
        bool found = false;
        for (auto it = first; it != b.by_x.end() && b.loops[*it].centroid.x <= c.x + reach && !found; ++it) {
            const Loop& lb = b.loops[*it];
            if (used[*it] || (k == 0) != (*it == 0) || dist(lb.centroid, c) > reach) continue;
            if (same_loop(la, lb, t, tolerance)) found = used[*it] = true;
        }
        if (!found) return false;
    }
    return true;
}

// The points that stand out in a shape: each piece's start, a circle's centre.
std::vector<Point> features(const Shape& s) {
    std::vector<Point> out;
    for (const Loop& l : s.loops) {
        if (l.circle) out.push_back(l.segs[0].centre);
        else
            for (const Seg& g : l.segs) out.push_back(g.a);
    }
    return out;
}

// The move `t` refined by least squares over the outlines' points (2D Procrustes), when `t` lines them up within
// a few tolerances: the points of a copy turned by an odd angle are rounded, and one pair of points alone turns
// the rest by their error.
Rigid refined(const Shape& a, const Shape& b, const Rigid& t, double tolerance) {
    const Loop& la = a.loops[0];
    const Loop& lb = b.loops[0];
    const std::size_t n = la.segs.size();
    if (la.circle || n != lb.segs.size()) return t;
    const double loose = 4 * tolerance;
    const Point first = t(la.segs[0].a);
    for (std::size_t j = 0; j < n; ++j) {
        if (dist(lb.segs[j].a, first) > loose) continue;
        bool near = true;
        for (std::size_t i = 0; i < n && near; ++i) near = dist(t(la.segs[i].a), lb.segs[(j + i) % n].a) <= loose;
        if (!near) continue;
        Point pa{}, pb{};
        for (std::size_t i = 0; i < n; ++i) {
            pa = {pa.x + la.segs[i].a.x / n, pa.y + la.segs[i].a.y / n};
            const Point q = lb.segs[(j + i) % n].a;
            pb = {pb.x + q.x / n, pb.y + q.y / n};
        }
        double sc = 0, ss = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const Point p = sub(la.segs[i].a, pa), q = sub(lb.segs[(j + i) % n].a, pb);
            sc += p.x * q.x + p.y * q.y;
            ss += cross(p, q);
        }
        return Rigid(std::atan2(ss, sc), pa, pb);
    }
    return t;
}

}  // namespace

bool similar(const Shape& a, const Shape& b, double tolerance) {
    return a.loops.size() == b.loops.size() && a.pieces == b.pieces &&
           std::fabs(a.area - b.area) <= area_slack(a.perimeter, tolerance) &&
           std::fabs(a.perimeter - b.perimeter) <= 2 * tolerance * static_cast<double>(a.pieces) &&
           close_lists(a.lengths, b.lengths, 2 * tolerance) &&
           close_lists(a.hole_distances, b.hole_distances, 4 * tolerance) &&
           close_lists(a.hole_areas, b.hole_areas, area_slack(a.perimeter, tolerance));
}

std::optional<double> turn_onto(const Shape& a, const Shape& b, double tolerance) {
    if (a.loops.empty() || a.loops.size() != b.loops.size()) return std::nullopt;
    const std::vector<Point> fa = features(a);
    Point ref = a.centroid;
    double far = -1;
    for (const Point& p : fa)
        if (const double d = dist(p, a.centroid); d > far + 1e-12) {
            far = d;
            ref = p;
        }
    std::vector<double> turns;
    if (far <= tolerance) {
        turns.push_back(0);  // (everything at the centroid: concentric circles turn onto each other any way)
    } else {
        const double from = std::atan2(ref.y - a.centroid.y, ref.x - a.centroid.x);
        for (const Point& p : features(b)) {
            if (std::fabs(dist(p, b.centroid) - far) > 4 * tolerance) continue;
            turns.push_back(std::atan2(p.y - b.centroid.y, p.x - b.centroid.x) - from);
            if (turns.size() == kMaxTurns) break;
        }
    }
    for (const double turn : turns) {
        const Rigid t = refined(a, b, Rigid(turn, a.centroid, b.centroid), tolerance);
        if (same_loops(a, b, t, tolerance)) return t.angle();
    }
    return std::nullopt;
}

void flatten_loop(const Loop& loop, double tolerance, int max_chords, std::vector<Point>& out) {
    for (const Seg& s : loop.segs) {
        out.push_back(s.a);
        int n = 1;
        if (s.curve == CurveKind::Arc && s.radius > tolerance) {
            n = static_cast<int>(std::ceil(std::fabs(s.sweep) / (2 * std::acos(1 - tolerance / s.radius))));
        } else if (s.curve == CurveKind::Parabola) {
            // a quadratic Bézier's chord error over a step h of its parameter is at most h² |a - 2q + b| / 4
            const double bend = std::hypot(s.a.x - 2 * s.control.x + s.b.x, s.a.y - 2 * s.control.y + s.b.y);
            n = static_cast<int>(std::ceil(std::sqrt(bend / (4 * tolerance))));
        }
        n = std::clamp(n, 1, max_chords);
        if (s.curve == CurveKind::Arc && n > 1) {  // (each point the one before turned by the step)
            const double c = std::cos(s.sweep / n), sn = std::sin(s.sweep / n);
            Point d = direction(s.a, s.centre);
            for (int k = 1; k < n; ++k) {
                d = turned(d, c, sn);
                out.push_back({s.centre.x + s.radius * d.x, s.centre.y + s.radius * d.y});
            }
            continue;
        }
        for (int k = 1; k < n; ++k) {
            const double f = static_cast<double>(k) / n;
            {
                const double u = 1 - f;
                out.push_back({u * u * s.a.x + 2 * u * f * s.control.x + f * f * s.b.x,
                               u * u * s.a.y + 2 * u * f * s.control.y + f * f * s.b.y});
            }
        }
    }
}

Box seg_box(const Seg& s) {
    Box box = Box::of(s.a, s.b);
    if (s.curve == CurveKind::Arc) {
        const double a0 = std::atan2(s.a.y - s.centre.y, s.a.x - s.centre.x);
        for (int k = 0; k < 4; ++k) {  // the circle's extremes at 0, 90, 180, 270 degrees inside the sweep
            double d = k * kPi / 2 - a0;
            if (s.sweep >= 0) {
                d = std::fmod(d, 2 * kPi);
                if (d < 0) d += 2 * kPi;
                if (d > s.sweep) continue;
            } else {
                d = std::fmod(d, 2 * kPi);
                if (d > 0) d -= 2 * kPi;
                if (d < s.sweep) continue;
            }
            box.add(
                Point{s.centre.x + s.radius * std::cos(k * kPi / 2), s.centre.y + s.radius * std::sin(k * kPi / 2)});
        }
    } else if (s.curve == CurveKind::Parabola) {
        const double den[2] = {s.a.x - 2 * s.control.x + s.b.x, s.a.y - 2 * s.control.y + s.b.y};
        const double num[2] = {s.a.x - s.control.x, s.a.y - s.control.y};
        for (int axis = 0; axis < 2; ++axis) {
            if (den[axis] == 0) continue;
            const double f = num[axis] / den[axis], u = 1 - f;
            if (f > 0 && f < 1)
                box.add(Point{u * u * s.a.x + 2 * u * f * s.control.x + f * f * s.b.x,
                              u * u * s.a.y + 2 * u * f * s.control.y + f * f * s.b.y});
        }
    }
    return box;
}

namespace {

// The convex hull of points, counter-clockwise, without points on its sides (Andrew's monotone chain).
std::vector<Point> convex_hull(std::vector<Point> p) {
    std::sort(p.begin(), p.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    std::vector<Point> h(2 * p.size());
    std::size_t k = 0;
    const auto turns_left = [&](Point c) { return cross(sub(h[k - 1], h[k - 2]), sub(c, h[k - 2])) > 0; };
    for (const Point& q : p) {  // (the lower chain)
        while (k >= 2 && !turns_left(q)) --k;
        h[k++] = q;
    }
    for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {  // (the upper chain)
        while (k >= lower && !turns_left(p[i])) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

// What reaches furthest of an outline in any direction: its pieces' ends, a parabola's points (followed within
// kOutlineTolerance), and each arc, which in a direction within its normals reaches as far as its centre plus its
// radius.
class Support {
public:
    explicit Support(const Loop& outline) {
        for (const Seg& s : outline.segs) {
            points_.push_back(s.a);
            if (s.curve == CurveKind::Arc) {
                const Point start = direction(s.a, s.centre), end = direction(s.b, s.centre);
                const bool wide = std::fabs(s.sweep) > kPi, full = std::fabs(s.sweep) >= 2 * kPi - 1e-9;
                bulges_.push_back(
                    {s.centre, s.radius, s.sweep > 0 ? start : end, s.sweep > 0 ? end : start, wide, full});
            } else if (s.curve == CurveKind::Parabola) {
                Loop one;
                one.segs.push_back(s);
                flatten_loop(one, kOutlineTolerance, kOutlineMaxChords, points_);
            }
        }
    }
    // How far the outline reaches along the unit direction n, and against it: the span of p·n.
    [[nodiscard]] double span(Point n) const {
        double far = -std::numeric_limits<double>::infinity(), near = std::numeric_limits<double>::infinity();
        for (const Point& p : points_) {
            const double along = p.x * n.x + p.y * n.y;
            far = std::max(far, along);
            near = std::min(near, along);
        }
        for (const Bulge& b : bulges_) {
            const double along = b.centre.x * n.x + b.centre.y * n.y;
            if (b.faces(n)) far = std::max(far, along + b.radius);
            if (b.faces({-n.x, -n.y})) near = std::min(near, along - b.radius);
        }
        return far - near;
    }
    // The area of the rectangle around the outline with a side in the direction `angle`.
    [[nodiscard]] double rectangle_area(double angle) const {
        const Point d{std::cos(angle), std::sin(angle)};
        return span(d) * span({-d.y, d.x});
    }

private:
    // An arc as what it reaches: its normals go from `from` to `to` counter-clockwise.
    struct Bulge {
        Point centre;
        double radius;
        Point from, to;
        bool wide, full;  // more than a half turn; a full turn
        [[nodiscard]] bool faces(Point n) const {
            if (full) return true;
            const bool after_from = cross(from, n) >= 0, before_to = cross(n, to) >= 0;
            return wide ? after_from || before_to : after_from && before_to;
        }
    };
    std::vector<Point> points_;
    std::vector<Bulge> bulges_;
};

// The edges' directions (radians) of a convex polygon, counter-clockwise, and the area of the rectangle around it
// with a side along each (rotating calipers: each edge's direction d unscaled, the rectangle's sides along d and
// across it are the spans of p·d and p·d⊥ over |d|, its area their product over |d|²). The smallest of all
// directions lies along one of them (Freeman and Shapira).
struct EdgeRectangle {
    double angle, area;
};
std::vector<EdgeRectangle> caliper_rectangles(const std::vector<Point>& h) {
    const std::size_t n = h.size();
    if (n < 3) return {{n == 2 ? std::atan2(h[1].y - h[0].y, h[1].x - h[0].x) : 0, 0}};
    const auto dot = [](Point a, Point e) { return a.x * e.x + a.y * e.y; };
    const auto after = [n](std::size_t k) { return k + 1 == n ? 0 : k + 1; };
    std::size_t right = 0, top = 0, left = 0;
    // A caliper at h[k] moves on while the next point lies as far along `dir` (sign -1: against it) as its own; the
    // span it reaches along `dir`.
    const auto advance = [&](std::size_t& k, Point dir, double sign) {
        double far = sign * dot(h[k], dir);
        for (std::size_t s = 0; s < n; ++s) {
            const double next = sign * dot(h[after(k)], dir);
            if (next < far) break;
            k = after(k);
            far = next;
        }
        return sign * far;
    };
    std::vector<EdgeRectangle> out;
    for (std::size_t i = 0; i < n; ++i) {
        const Point d = sub(h[after(i)], h[i]), up{-d.y, d.x};
        const double len2 = d.x * d.x + d.y * d.y;
        if (!(len2 > 0)) continue;
        const double far_right = advance(right, d, 1);
        if (i == 0) top = right;
        const double far_up = advance(top, up, 1);
        if (i == 0) left = top;
        const double far_left = advance(left, d, -1);
        out.push_back({std::atan2(d.y, d.x), (far_right - far_left) * (far_up - dot(h[i], up)) / len2});
    }
    return out;
}

// A rectangle turned by a quarter turn is the same rectangle: directions are compared within one.
constexpr double kQuarterTurn = kPi / 2;
double in_quarter(double angle) { return angle - kQuarterTurn * std::floor(angle / kQuarterTurn); }

// Each direction base + (j + 1/2) step (j in [0, n): the chords of an arc) that lies, within a quarter turn, in
// [lo, hi] (0 <= lo <= hi <= lo + a quarter turn).
template <class Visit>
void chords_between(double base, double step, int n, double lo, double hi, Visit&& visit) {
    const double first = base + step / 2, last = first + (n - 1) * step;
    const double low = std::min(first, last), high = std::max(first, last);
    for (double m = std::floor((low - hi) / kQuarterTurn); m * kQuarterTurn + lo <= high; ++m) {
        double j0 = (m * kQuarterTurn + lo - first) / step, j1 = (m * kQuarterTurn + hi - first) / step;
        if (j0 > j1) std::swap(j0, j1);
        for (int j = std::max(0, static_cast<int>(std::ceil(j0))); j < n && j <= j1; ++j) visit(first + j * step);
    }
}

// The direction (radians) of the smallest rectangle around the outline. The hull of the outline's points with its
// arcs followed within kOutlineCoarseMm lies inside the outline: in every direction its rectangle is no larger than
// the outline's. Between two of its edges' directions next to each other within a quarter turn its rectangle is at
// least the smaller of theirs (Freeman and Shapira: the same four points touch the sides, the area has no minimum
// inside). So the outline's rectangle is taken in the direction of each edge whose rectangle is smaller than the
// smallest found so far, and within each such pair of directions, in the directions of the outline's bulging arcs'
// chords within kOutlineTolerance.
double smallest_rectangle_angle(const Loop& outline) {
    std::vector<Point> points;
    flatten_loop(outline, kOutlineCoarseMm, kOutlineMaxChords, points);
    std::vector<EdgeRectangle> edges = caliper_rectangles(convex_hull(std::move(points)));
    if (edges.size() < 3) return edges.empty() ? 0 : edges[0].angle;
    const Support support(outline);
    EdgeRectangle best{0, std::numeric_limits<double>::infinity()};
    const auto take = [&](double angle) {
        if (const double area = support.rectangle_area(angle); area < best.area) best = {angle, area};
    };
    for (EdgeRectangle& e : edges) e.angle = in_quarter(e.angle);
    std::sort(edges.begin(), edges.end(),
              [](const EdgeRectangle& a, const EdgeRectangle& b) { return a.area < b.area; });
    for (const EdgeRectangle& e : edges) {
        if (!(e.area < best.area)) break;
        take(e.angle);
    }
    std::sort(edges.begin(), edges.end(),
              [](const EdgeRectangle& a, const EdgeRectangle& b) { return a.angle < b.angle; });
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const EdgeRectangle& lo = edges[k];
        const EdgeRectangle& hi = edges[(k + 1) % edges.size()];
        if (!(std::min(lo.area, hi.area) < best.area)) continue;
        const double to = k + 1 < edges.size() ? hi.angle : hi.angle + kQuarterTurn;
        for (const Seg& s : outline.segs) {
            if (s.curve != CurveKind::Arc || !(s.sweep > 0) || !(s.radius > kOutlineTolerance)) continue;
            const int chords =
                std::clamp(static_cast<int>(std::ceil(s.sweep / (2 * std::acos(1 - kOutlineTolerance / s.radius)))), 1,
                           kOutlineMaxChords);
            // (a chord's direction: the tangent's halfway along it)
            const double start = std::atan2(s.a.y - s.centre.y, s.a.x - s.centre.x) + kQuarterTurn;
            chords_between(start, s.sweep / chords, chords, lo.angle, to, take);
        }
    }
    return best.angle;
}

}  // namespace

OutlineRect smallest_rectangle(const Loop& outline) {
    // (a circle: any direction)
    const double angle = outline.circle || outline.segs.empty() ? 0 : smallest_rectangle_angle(outline);
    // the loop turned by -angle: its exact box
    const Rigid turn(-angle, {0, 0}, {0, 0});
    Box box;
    for (Seg s : outline.segs) {
        s.a = turn(s.a);
        s.b = turn(s.b);
        s.mid = turn(s.mid);
        s.centre = turn(s.centre);
        s.control = turn(s.control);
        box.add(seg_box(s));
    }
    const double w = box.max_x - box.min_x, h = box.max_y - box.min_y;
    return {std::max(w, h), std::min(w, h)};
}

Point label_point(const Shape& s, const Box& box, std::span<const std::vector<Point>> polygons) {
    // The widest run of material along a horizontal line through the centroid (else the box's middle), the first
    // from the left of runs as wide within kLabelTieMm: the loops' crossings of the line, even-odd (the holes lie
    // inside the outline).
    for (const double y : {s.centroid.y, (box.min_y + box.max_y) / 2}) {
        std::vector<double> xs;
        for (const std::vector<Point>& polygon : polygons) {
            for (std::size_t k = 0; k < polygon.size(); ++k) {
                const Point a = polygon[k], b = polygon[(k + 1) % polygon.size()];
                if ((a.y > y) != (b.y > y)) xs.push_back(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y));
            }
        }
        std::sort(xs.begin(), xs.end());
        double widest = 0;
        Point at{};
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2)
            if (xs[k + 1] - xs[k] > widest + kLabelTieMm) {
                widest = xs[k + 1] - xs[k];
                at = {(xs[k] + xs[k + 1]) / 2, y};
            }
        if (widest > 0) return at;
    }
    return {(box.min_x + box.max_x) / 2, (box.min_y + box.max_y) / 2};
}

}  // namespace essi::parts
