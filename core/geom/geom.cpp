// Exact primitives: lengths, bounding boxes, points and flattening of lines, arcs and parabolas.
#include "essi/geom.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace essi {
namespace {

constexpr double kTwoPi = 2 * kPi;

double angle_of(Point p, Point c) { return std::atan2(p.y - c.y, p.x - c.x); }

// Quadrant of the direction (x, y): k for angles in [k * 90, (k + 1) * 90) degrees. The axis extreme k
// (+x, +y, -x, -y) is where quadrant k starts.
int quadrant(Point d) {
    const bool upper = d.y > 0 || (d.y == 0 && d.x > 0);  // [0, 180)
    return upper ? (d.x > 0 ? 0 : 1) : (d.x < 0 ? 2 : 3);
}
// Whether the direction d (in quadrant q) lies exactly on the axis where q starts.
bool starts_quadrant(Point d, int q) { return (q & 1) ? d.x == 0 : d.y == 0; }

// The axis extremes an arc of constant radius reaches, as bits: bit k for the direction at k * 90 degrees from
// the centre (+x, +y, -x, -y). `a` and `e` are its start and end relative to the centre. Decided from the
// quadrants of the two ends, without trigonometry.
unsigned arc_axis_extremes(Point a, Point e, bool ccw) {
    // A cw arc covers what the ccw arc from its end to its start covers. The extremes inside are the starts of
    // the quadrants the arc enters.
    if (!ccw) std::swap(a, e);
    const int qa = quadrant(a), qe = quadrant(e);
    int entered = (qe - qa) & 3;
    // Both ends in one quadrant with the end not after the start: the arc goes all the way round.
    if (entered == 0 && a.x * e.y - a.y * e.x <= 0) entered = 4;
    unsigned extremes = starts_quadrant(a, qa) ? 1u << qa : 0u;  // the start on an axis is its extreme
    for (int i = 1; i <= entered; ++i) extremes |= 1u << ((qa + i) & 3);
    return extremes;
}

// Arc radius at a fraction of the sweep: from the start radius to the end radius, so that the arc ends
// exactly on the programmed end point (the controller moves there; nothing drifts).
double radius_at(const MotionRecord& m, double f) { return m.radius + (m.end_radius - m.radius) * f; }

Point arc_point(const MotionRecord& m, double f) {
    if (f >= 1.0) return m.end;
    if (f <= 0.0) return m.start;
    const double a = angle_of(m.start, m.centre) + m.sweep * f;
    const double r = radius_at(m, f);
    return {m.centre.x + r * std::cos(a), m.centre.y + r * std::sin(a)};
}

Point parabola_point_exact_end(const MotionRecord& m, double f) {
    if (f >= 1.0) return m.end;
    if (f <= 0.0) return m.start;
    const ParabolaGeom& g = m.parabola;
    const double t = g.t0 + (g.t1 - g.t0) * f;
    // The curve point, corrected linearly so the piece ends exactly at the programmed end point.
    const Point on = parabola_point(g, t);
    const Point e = parabola_point(g, g.t1);
    return {on.x + (m.end.x - e.x) * f, on.y + (m.end.y - e.y) * f};
}

// Antiderivative of sqrt(1 + (t/p)^2).
double parabola_arc_integral(double t, double p) {
    const double q = t / p;
    return 0.5 * t * std::sqrt(1 + q * q) + 0.5 * p * std::asinh(q);
}

}  // namespace

double arc_sweep(Point start, Point end, Point centre, bool ccw, bool full_circle) {
    if (full_circle) return ccw ? kTwoPi : -kTwoPi;
    // The angle between the two radius vectors, from one atan2 of their cross and dot products.
    const double ax = start.x - centre.x, ay = start.y - centre.y;
    const double bx = end.x - centre.x, by = end.y - centre.y;
    double d = std::atan2(ax * by - ay * bx, ax * bx + ay * by);  // (-pi, pi]
    if (ccw && d <= 0) d += kTwoPi;
    if (!ccw && d >= 0) d -= kTwoPi;
    return d;
}

Point parabola_point(const ParabolaGeom& g, double t) {
    const double s = t * t / (2 * g.p);
    return {g.vertex.x + t * g.u.x + s * g.n.x, g.vertex.y + t * g.u.y + s * g.n.y};
}

double min_curvature_radius(const MotionRecord& m) {
    switch (m.curve) {
        case CurveKind::Line: break;
        case CurveKind::Arc: return std::min(m.radius, m.end_radius);
        case CurveKind::Parabola: {
            // R(t) = p (1 + t²/p²)^(3/2), smallest at the t of the piece nearest the vertex (t = 0).
            const ParabolaGeom& g = m.parabola;
            const double t = std::clamp(0.0, std::min(g.t0, g.t1), std::max(g.t0, g.t1));
            const double q = 1 + (t / g.p) * (t / g.p);
            return g.p * q * std::sqrt(q);
        }
    }
    return std::numeric_limits<double>::infinity();
}

ParabolaPiece parabola_from_words(Point start, Point end, double xp, double yp, bool axis_parallel_y, bool absolute) {
    ParabolaPiece piece;
    ParabolaGeom& g = piece.curve;
    const double sx = start.x, sy = start.y, ex = end.x, ey = end.y;
    if (axis_parallel_y) {  // y - y_v = (x - x_a)^2 / (2 YP)
        const double xa = (absolute ? 0 : sx) + xp;
        const double yv = sy - (sx - xa) * (sx - xa) / (2 * yp);
        g.vertex = {xa, yv};
        g.u = {1, 0};
        g.n = {0, yp > 0 ? 1.0 : -1.0};
        g.t0 = sx - xa;
        g.t1 = ex - xa;
        piece.residual = ey - (yv + g.t1 * g.t1 / (2 * yp));
        g.p = std::abs(yp);
    } else {  // the roles of X and Y swapped
        const double ya = (absolute ? 0 : sy) + yp;
        const double xv = sx - (sy - ya) * (sy - ya) / (2 * xp);
        g.vertex = {xv, ya};
        g.u = {0, 1};
        g.n = {xp > 0 ? 1.0 : -1.0, 0};
        g.t0 = sy - ya;
        g.t1 = ey - ya;
        piece.residual = ex - (xv + g.t1 * g.t1 / (2 * xp));
        g.p = std::abs(xp);
    }
    return piece;
}

bool parabola_turns_ccw(const ParabolaGeom& g) { return (g.u.x * g.n.y - g.u.y * g.n.x) * (g.t1 - g.t0) > 0; }

double parabola_length(const ParabolaGeom& g) {
    return std::abs(parabola_arc_integral(g.t1, g.p) - parabola_arc_integral(g.t0, g.p));
}

Box bounding_box(const MotionRecord& m) {
    Box b = Box::of(m.start, m.end);
    switch (m.curve) {
        case CurveKind::Line: break;
        case CurveKind::Arc: {
            // Axis extremes (at angles 0, 90, 180, 270 degrees) that lie inside the sweep.
            static constexpr double kAxisCos[4] = {1, 0, -1, 0};
            static constexpr double kAxisSin[4] = {0, 1, 0, -1};
            if (m.radius == m.end_radius) {
                // Constant radius (the usual case): a full circle (holes, common) reaches all four extremes.
                const unsigned extremes =
                    std::abs(m.sweep) >= kTwoPi
                        ? 0xFu
                        : arc_axis_extremes({m.start.x - m.centre.x, m.start.y - m.centre.y},
                                            {m.end.x - m.centre.x, m.end.y - m.centre.y}, m.sweep >= 0);
                for (int k = 0; k < 4; ++k)
                    if (extremes & (1u << k))
                        b.add(Point{m.centre.x + m.radius * kAxisCos[k], m.centre.y + m.radius * kAxisSin[k]});
                break;
            }
            const double a0 = angle_of(m.start, m.centre);
            for (int k = 0; k < 4; ++k) {
                const double a = k * kPi / 2;
                double d = a - a0;  // angle from the start to this extreme, in the arc's direction
                if (m.sweep >= 0) {
                    while (d < 0) d += kTwoPi;
                    while (d >= kTwoPi) d -= kTwoPi;
                    if (d > m.sweep) continue;
                } else {
                    while (d > 0) d -= kTwoPi;
                    while (d <= -kTwoPi) d += kTwoPi;
                    if (d < m.sweep) continue;
                }
                const double r = radius_at(m, m.sweep == 0 ? 0 : d / m.sweep);
                b.add(Point{m.centre.x + r * kAxisCos[k], m.centre.y + r * kAxisSin[k]});
            }
            break;
        }
        case CurveKind::Parabola: {
            // x(t) and y(t) are quadratics; each has one extreme where its derivative vanishes.
            const ParabolaGeom& g = m.parabola;
            const double lo = std::min(g.t0, g.t1), hi = std::max(g.t0, g.t1);
            const double du[2] = {g.u.x, g.u.y};
            const double dn[2] = {g.n.x, g.n.y};
            for (int axis = 0; axis < 2; ++axis) {
                if (dn[axis] == 0) continue;
                const double t = -du[axis] * g.p / dn[axis];
                if (t > lo && t < hi) {
                    const double f = (g.t1 == g.t0) ? 0 : (t - g.t0) / (g.t1 - g.t0);
                    b.add(parabola_point_exact_end(m, f));
                }
            }
            break;
        }
    }
    return b;
}

Point point_at(const MotionRecord& m, double fraction) {
    switch (m.curve) {
        case CurveKind::Line:
            if (fraction >= 1.0) return m.end;
            return {m.start.x + (m.end.x - m.start.x) * fraction, m.start.y + (m.end.y - m.start.y) * fraction};
        case CurveKind::Arc: return arc_point(m, fraction);
        case CurveKind::Parabola: return parabola_point_exact_end(m, fraction);
    }
    return m.end;
}

int flatten_segments(const MotionRecord& m, double chord_tolerance_mm, int max_segments) {
    double segments = 1;  // (a double until it is clamped: a huge or NaN curve never overflows an int)
    const double tol = std::max(chord_tolerance_mm, kMinChordTolerance);
    switch (m.curve) {
        case CurveKind::Line: break;
        case CurveKind::Arc: {
            // Sagitta of a chord over angle a on radius r: r * (1 - cos(a/2)) <= tol.
            const double r = std::max(m.radius, m.end_radius);
            if (r > tol) {
                const double max_step = 2 * std::acos(1 - tol / r);
                segments = std::ceil(std::abs(m.sweep) / max_step);
            }
            segments = std::max(segments, std::abs(m.sweep) > kPi ? 4.0 : 2.0);
            break;
        }
        case CurveKind::Parabola: {
            // Chord error over a parameter step h is at most h^2 * curvature_max / 8, with curvature <= 1/p.
            const double span = std::abs(m.parabola.t1 - m.parabola.t0);
            const double max_step = std::sqrt(8 * tol * m.parabola.p);
            segments = std::max(2.0, std::ceil(span / max_step));
            break;
        }
    }
    const double most = std::max(max_segments, 1);
    return static_cast<int>(segments >= 1 && segments <= most ? segments : segments > most ? most : 1);
}

void flatten(const MotionRecord& m, double chord_tolerance_mm, std::vector<Point>& out, bool include_start,
             int max_segments) {
    if (include_start) out.push_back(m.start);
    const int segments = flatten_segments(m, chord_tolerance_mm, max_segments);
    for (int i = 1; i < segments; ++i) out.push_back(point_at(m, static_cast<double>(i) / segments));
    out.push_back(m.end);
}

namespace {

// The derivative of point_at by the fraction.
Point velocity_at(const MotionRecord& m, double f) {
    switch (m.curve) {
        case CurveKind::Line: break;
        case CurveKind::Arc: {
            const double a = angle_of(m.start, m.centre) + m.sweep * f;
            const double r = radius_at(m, f), dr = m.end_radius - m.radius;
            const double c = std::cos(a), s = std::sin(a);
            return {dr * c - r * m.sweep * s, dr * s + r * m.sweep * c};
        }
        case CurveKind::Parabola: {
            // d/df of parabola_point(g, t0 + (t1 - t0) f) + f (end - e)
            const ParabolaGeom& g = m.parabola;
            const double dt = g.t1 - g.t0, t = g.t0 + dt * f;
            const Point e = parabola_point(g, g.t1);
            return {dt * (g.u.x + t / g.p * g.n.x) + (m.end.x - e.x), dt * (g.u.y + t / g.p * g.n.y) + (m.end.y - e.y)};
        }
    }
    return {m.end.x - m.start.x, m.end.y - m.start.y};
}

// Gauss-Legendre nodes and weights on [0, 1] (5 points: exact for polynomials up to degree 9).
constexpr double kGaussNodes[5] = {0.04691007703066800, 0.23076534494715845, 0.5, 0.76923465505284155,
                                   0.95308992296933200};
constexpr double kGaussWeights[5] = {0.11846344252809454, 0.23931433524968324, 0.28444444444444444, 0.23931433524968324,
                                     0.11846344252809454};
// An arc's moments are integrated over pieces of at most this sweep (radians).
constexpr double kMomentStep = kPi / 16;

// ∮ x² dy and ∮ y² dx over the fractions [f0, f1] of the motion, by quadrature.
void add_moments(const MotionRecord& m, double f0, double f1, AreaTerms& t) {
    for (int k = 0; k < 5; ++k) {
        const double f = f0 + (f1 - f0) * kGaussNodes[k], w = (f1 - f0) * kGaussWeights[k];
        const Point p = point_at(m, f), v = velocity_at(m, f);
        t.x2dy += w * p.x * p.x * v.y;
        t.y2dx += w * p.y * p.y * v.x;
    }
}

// The moments of an arc of one radius r about centre c, in closed form: with x = cx + r cos a, y = cy + r sin a
// from the start's angle a0 to a1 = a0 + sweep,
//   ∫ x² dy = cx² r [sin a] + cx r² [a + sin a cos a] + r³ [sin a - sin³ a / 3],
//   ∫ y² dx = cy² r [cos a] - cy r² [a - sin a cos a] + r³ [cos a - cos³ a / 3]
// (each [f] is f(a1) - f(a0); a1's direction is the start's turned by the sweep).
void add_circular_arc_moments(const MotionRecord& m, AreaTerms& t) {
    const double r = m.radius, cx = m.centre.x, cy = m.centre.y;
    const double r0 = std::hypot(m.start.x - cx, m.start.y - cy);
    const double c0 = r0 > 0 ? (m.start.x - cx) / r0 : 1, s0 = r0 > 0 ? (m.start.y - cy) / r0 : 0;
    const double turn_c = std::cos(m.sweep), turn_s = std::sin(m.sweep);
    const double c1 = c0 * turn_c - s0 * turn_s, s1 = s0 * turn_c + c0 * turn_s;
    const double sc = s1 * c1 - s0 * c0;
    t.x2dy += cx * cx * r * (s1 - s0) + cx * r * r * (m.sweep + sc) +
              r * r * r * ((s1 - s1 * s1 * s1 / 3) - (s0 - s0 * s0 * s0 / 3));
    t.y2dx += cy * cy * r * (c1 - c0) - cy * r * r * (m.sweep - sc) +
              r * r * r * ((c1 - c1 * c1 * c1 / 3) - (c0 - c0 * c0 * c0 / 3));
}

// add_moments over an arc's pieces of at most kMomentStep, the points' directions turned from the start's by
// rotations rather than each found by its own sine and cosine (the same nodes, the same sums).
void add_arc_moments(const MotionRecord& m, AreaTerms& t) {
    if (m.radius == m.end_radius) {
        add_circular_arc_moments(m, t);
        return;
    }
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(m.sweep) / kMomentStep)));
    const double step = m.sweep / pieces, dr = m.end_radius - m.radius;
    const double r0 = std::hypot(m.start.x - m.centre.x, m.start.y - m.centre.y);
    // the direction of the piece's start (cos, sin), and the turn from it to each node
    double c = r0 > 0 ? (m.start.x - m.centre.x) / r0 : 1, s = r0 > 0 ? (m.start.y - m.centre.y) / r0 : 0;
    double node_c[5], node_s[5];
    for (int i = 0; i < 5; ++i) {
        node_c[i] = std::cos(step * kGaussNodes[i]);
        node_s[i] = std::sin(step * kGaussNodes[i]);
    }
    const double step_c = std::cos(step), step_s = std::sin(step);
    for (int k = 0; k < pieces; ++k) {
        for (int i = 0; i < 5; ++i) {
            const double f = (k + kGaussNodes[i]) / pieces, w = kGaussWeights[i] / pieces;
            const double ca = c * node_c[i] - s * node_s[i], sa = s * node_c[i] + c * node_s[i];
            const double r = m.radius + dr * f;
            const Point p{m.centre.x + r * ca, m.centre.y + r * sa};
            const Point v{dr * ca - r * m.sweep * sa, dr * sa + r * m.sweep * ca};
            t.x2dy += w * p.x * p.x * v.y;
            t.y2dx += w * p.y * p.y * v.x;
        }
        const double next_c = c * step_c - s * step_s;
        s = s * step_c + c * step_s;
        c = next_c;
    }
}

}  // namespace

AreaTerms area_terms(const MotionRecord& m) {
    AreaTerms t;
    const Point a = m.start, b = m.end;
    switch (m.curve) {
        case CurveKind::Line:
            t.twice_area = a.x * b.y - b.x * a.y;
            t.x2dy = (b.y - a.y) * (a.x * a.x + a.x * b.x + b.x * b.x) / 3;
            t.y2dx = (b.x - a.x) * (a.y * a.y + a.y * b.y + b.y * b.y) / 3;
            return t;
        case CurveKind::Arc: {
            // about the centre: the chord's term of the centre, plus r(f)² dθ integrated (r linear in f)
            const Point c = m.centre;
            const double r0 = m.radius, r1 = m.end_radius;
            t.twice_area = c.x * (b.y - a.y) - c.y * (b.x - a.x) + m.sweep * (r0 * r0 + r0 * r1 + r1 * r1) / 3;
            add_arc_moments(m, t);
            return t;
        }
        case CurveKind::Parabola: {
            // a quadratic curve: a quadratic Bézier with control point q; the area between it and its chord is
            // 2/3 of the triangle a-q-b (Archimedes)
            const Point mid = point_at(m, 0.5);
            const Point q{2 * mid.x - (a.x + b.x) / 2, 2 * mid.y - (a.y + b.y) / 2};
            t.twice_area = a.x * b.y - b.x * a.y + 2.0 / 3 * ((q.x - a.x) * (b.y - a.y) - (q.y - a.y) * (b.x - a.x));
            add_moments(m, 0, 1, t);  // (polynomials of degree 5: exact)
            return t;
        }
    }
    return t;
}

MotionRecord sub_motion(const MotionRecord& m, double from, double to) {
    MotionRecord s = m;
    s.start = point_at(m, from);
    s.end = point_at(m, to);
    switch (m.curve) {
        case CurveKind::Line: break;
        case CurveKind::Arc:
            s.radius = radius_at(m, from);
            s.end_radius = radius_at(m, to);
            s.sweep = m.sweep * (to - from);
            break;
        case CurveKind::Parabola: {
            const ParabolaGeom& g = m.parabola;
            s.parabola.t0 = g.t0 + (g.t1 - g.t0) * from;
            s.parabola.t1 = g.t0 + (g.t1 - g.t0) * to;
            break;
        }
    }
    s.length_mm = m.length_mm * (to - from);  // (lines and arcs exactly; a parabola's piece below)
    if (m.curve == CurveKind::Parabola) s.length_mm = parabola_length(s.parabola);
    return s;
}

double nearest_fraction(const MotionRecord& m, Point p) {
    const auto d2 = [&](double f) {
        const Point q = point_at(m, f);
        return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
    };
    if (m.curve == CurveKind::Line) {
        const double dx = m.end.x - m.start.x, dy = m.end.y - m.start.y, len2 = dx * dx + dy * dy;
        return len2 > 0 ? std::clamp(((p.x - m.start.x) * dx + (p.y - m.start.y) * dy) / len2, 0.0, 1.0) : 0.0;
    }
    // the nearest of 64 samples, then a ternary search on the steps either side of it
    constexpr int kSamples = 64;
    int best = 0;
    for (int k = 1; k <= kSamples; ++k)
        if (d2(static_cast<double>(k) / kSamples) < d2(static_cast<double>(best) / kSamples)) best = k;
    double lo = std::max(0.0, (best - 1.0) / kSamples), hi = std::min(1.0, (best + 1.0) / kSamples);
    while (hi - lo > 1e-10) {
        const double l = lo + (hi - lo) / 3, h = hi - (hi - lo) / 3;
        if (d2(l) < d2(h)) hi = h;
        else lo = l;
    }
    return (lo + hi) / 2;
}

}  // namespace essi
