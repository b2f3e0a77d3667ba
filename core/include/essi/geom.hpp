// Phase 3, geom: exact primitives. Lines, arcs (start radius, signed sweep, the end point exactly) and
// parabolas (§6) with closed-form lengths, exact bounding boxes and flattening within a chord tolerance.
#pragma once

#include <cmath>
#include <vector>

#include "essi/motion.hpp"

namespace essi {

struct Box {
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
    bool empty = true;
    // As bytes (essi/wire.hpp; a member at a time: the struct has padding), and read back.
    void save(WireWriter& out) const { out.put_all(min_x, min_y, max_x, max_y, empty); }
    [[nodiscard]] bool restore(WireReader& in) { return in.get_all(min_x, min_y, max_x, max_y, empty); }
    void add(Point p) {
        if (empty) {
            min_x = max_x = p.x;
            min_y = max_y = p.y;
            empty = false;
            return;
        }
        min_x = p.x < min_x ? p.x : min_x;
        max_x = p.x > max_x ? p.x : max_x;
        min_y = p.y < min_y ? p.y : min_y;
        max_y = p.y > max_y ? p.y : max_y;
    }
    void add(const Box& b) {
        if (b.empty) return;
        if (empty) {
            *this = b;
            return;
        }
        min_x = b.min_x < min_x ? b.min_x : min_x;
        max_x = b.max_x > max_x ? b.max_x : max_x;
        min_y = b.min_y < min_y ? b.min_y : min_y;
        max_y = b.max_y > max_y ? b.max_y : max_y;
    }
    // Whether `o` lies inside this box (edges included); false when either is empty.
    [[nodiscard]] bool contains(const Box& o) const {
        return !empty && !o.empty && o.min_x >= min_x && o.max_x <= max_x && o.min_y >= min_y && o.max_y <= max_y;
    }
    // The box of two points (a line's).
    [[nodiscard]] static Box of(Point a, Point b) {
        return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, false};
    }
};

// Arc sweep from start to end around centre: (0, 2*pi] for ccw, [-2*pi, 0) for cw; a full circle when
// the end equals the start.
[[nodiscard]] double arc_sweep(Point start, Point end, Point centre, bool ccw, bool full_circle);

// A parabola block's curve (docs/semantics.md §6), worked out in the block's own frame (the tape's axes, unit
// increments): from its start and end, XP and YP, TP (true: the axis is parallel to Y) and whether XP/YP count
// from the frame's origin (absolute) or from the start. `p_signed` (YP or XP, the radius of curvature at the
// vertex) must not be 0. `residual` is how far the end lies off the curve, measured along the axis.
struct ParabolaPiece {
    ParabolaGeom curve;
    double residual = 0;
};
[[nodiscard]] ParabolaPiece parabola_from_words(Point start, Point end, double xp, double yp, bool axis_parallel_y,
                                                bool absolute);
// Whether the piece turns counter-clockwise as t goes from t0 to t1 (t1 != t0).
[[nodiscard]] bool parabola_turns_ccw(const ParabolaGeom& g);

namespace geom_detail {
// A vector scaled to length 1; the zero vector stays zero.
[[nodiscard]] inline Point unit_vector(double x, double y) {
    const double n = std::sqrt(x * x + y * y);  // (hypot: much slower, no range needed)
    if (!(n > 0)) return {};
    const double k = 1 / n;
    return {x * k, y * k};
}
}  // namespace geom_detail

// The direction of travel (a unit vector) of an arc at a point of it, `radius` from the centre when that is known
// (a programmed arc's radii: no square root; 0 when not).
[[nodiscard]] inline Point arc_tangent(Point p, Point centre, bool ccw, double radius) {
    Point r;
    if (radius > 0) {
        const double k = 1 / radius;
        r = {(p.x - centre.x) * k, (p.y - centre.y) * k};
    } else {
        r = geom_detail::unit_vector(p.x - centre.x, p.y - centre.y);
    }
    return ccw ? Point{-r.y, r.x} : Point{r.y, -r.x};
}

// A straight motion's direction (a unit vector) from its known length.
[[nodiscard]] inline Point line_direction(const MotionRecord& m) {
    if (!(m.length_mm > 0)) return geom_detail::unit_vector(m.end.x - m.start.x, m.end.y - m.start.y);
    const double k = 1 / m.length_mm;
    return {(m.end.x - m.start.x) * k, (m.end.y - m.start.y) * k};
}

// A parabola's direction of travel (a unit vector) at parameter t, t running from t0 to t1.
[[nodiscard]] inline Point parabola_tangent(const ParabolaGeom& g, double t) {
    const double k = t / g.p;
    const double sign = g.t1 >= g.t0 ? 1.0 : -1.0;
    return geom_detail::unit_vector(sign * (g.u.x + k * g.n.x), sign * (g.u.y + k * g.n.y));
}
// The direction of travel (a unit vector) at a motion's start or end: a line's direction, the tangent of an arc
// or a parabola; the zero vector for a motion that has none (a line of length 0). Inline: the kerf path asks
// for them at every corner.
[[nodiscard]] inline Point tangent_at(const MotionRecord& m, bool end) {
    switch (m.curve) {
        case CurveKind::Line: return line_direction(m);
        case CurveKind::Arc: return arc_tangent(end ? m.end : m.start, m.centre, m.ccw, end ? m.end_radius : m.radius);
        case CurveKind::Parabola: return parabola_tangent(m.parabola, end ? m.parabola.t1 : m.parabola.t0);
    }
    return {};
}
[[nodiscard]] inline Point start_tangent(const MotionRecord& m) { return tangent_at(m, false); }
[[nodiscard]] inline Point end_tangent(const MotionRecord& m) { return tangent_at(m, true); }
// The smallest radius of curvature along a motion (mm): an arc's smaller radius, a parabola's at its point
// nearest the vertex; infinity for a line.
[[nodiscard]] double min_curvature_radius(const MotionRecord& m);

// Closed-form length of a parabola piece.
[[nodiscard]] double parabola_length(const ParabolaGeom& g);
// Point of a parabola at parameter t.
[[nodiscard]] Point parabola_point(const ParabolaGeom& g, double t);

// Exact bounding box of a motion (arc and parabola extremes included).
[[nodiscard]] Box bounding_box(const MotionRecord& m);

// A motion is flattened into at most this many chords (by default), whatever the tolerance. The fuzz-fast build
// sets a smaller cap (ESSI_FUZZ_MAX_FLATTEN_SEGMENTS, core/CMakeLists.txt): its executions go to reading tapes,
// not to the thousands of chords of every random parabola.
#ifdef ESSI_MAX_FLATTEN_SEGMENTS
constexpr int kMaxFlattenSegments = ESSI_MAX_FLATTEN_SEGMENTS;
#else
constexpr int kMaxFlattenSegments = 4096;
#endif

// How many chords flatten() makes of the motion: enough to stay within `chord_tolerance_mm`, at most `max_segments`.
[[nodiscard]] int flatten_segments(const MotionRecord& m, double chord_tolerance_mm, int max_segments);

// Appends points approximating the motion within `chord_tolerance_mm` (in at most `max_segments` chords) to `out`.
// The first point (the start) is appended only when `include_start`; the last point appended is exactly `m.end`.
void flatten(const MotionRecord& m, double chord_tolerance_mm, std::vector<Point>& out, bool include_start = true,
             int max_segments = kMaxFlattenSegments);

// Point at the given fraction [0,1] of the motion's parameter (for playback and selection).
[[nodiscard]] Point point_at(const MotionRecord& m, double fraction);

// The motion's share of a closed run's area and centroid (Green's theorem), from its exact curve: ∮ (x dy - y dx)
// (a closed run's sum is twice its area, > 0 counter-clockwise), ∮ x² dy and ∮ y² dx (its centroid is
// (Σ x²dy, -Σ y²dx) / (2 · area)). Exact for lines, arcs (their radius going from the start's to the end's, as
// point_at draws them) and parabolas; the arcs' moments by Gauss-Legendre quadrature (below 1e-12 of the value).
struct AreaTerms {
    double twice_area = 0, x2dy = 0, y2dx = 0;
};
[[nodiscard]] AreaTerms area_terms(const MotionRecord& m);

// The part of the motion between two fractions of its parameter (0 <= from < to <= 1): a line or an arc cut
// exactly; a parabola's piece on the same curve (its end correction scaled with it).
[[nodiscard]] MotionRecord sub_motion(const MotionRecord& m, double from, double to);
// The fraction of the motion's parameter at its point nearest to `p` (within 1e-9 of the parameter).
[[nodiscard]] double nearest_fraction(const MotionRecord& m, Point p);

// Tolerances that are not profile settings.
constexpr double kPi = 3.14159265358979323846;
constexpr double kMinChordTolerance = 1e-6;  // mm

}  // namespace essi
