// The kerf-compensated path: offset pieces, corners (join, trim, gouge), entry and exit (essi/kerf.hpp).
#include "essi/kerf.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "essi/geom.hpp"
#include "essi/text.hpp"

namespace essi {
namespace {

Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
Point operator*(double k, Point a) { return {k * a.x, k * a.y}; }
double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
double norm(Point a) { return std::sqrt(a.x * a.x + a.y * a.y); }  // (hypot: much slower, no range needed)
Point unit(Point a) {
    const double n = norm(a);
    if (!(n > 0)) return {};
    const double k = 1 / n;
    return {a.x * k, a.y * k};
}
Point left_normal(Point t) { return {-t.y, t.x}; }

const double kCosCornerTolerance = std::cos(kKerfCornerTolerance);
const double kSinCornerTolerance = std::sin(kKerfCornerTolerance);

bool is_full_circle(const MotionRecord& m) { return m.curve == CurveKind::Arc && std::abs(m.sweep) > 2 * kPi - 1e-12; }

// A piece's geometry after its start or end moved: radius, sweep and length again.
void reshape(MotionRecord& r, bool full_circle = false) {
    if (r.curve == CurveKind::Arc) {
        r.radius = norm(r.start - r.centre);
        r.end_radius = norm(r.end - r.centre);
        r.sweep = norm(r.end - r.start) <= kKerfLengthEpsilon && !full_circle
                      ? 0.0
                      : arc_sweep(r.start, r.end, r.centre, r.ccw, full_circle);
        r.length_mm = std::abs(r.sweep) * (r.radius + r.end_radius) / 2;
    } else {
        r.curve = CurveKind::Line;
        r.length_mm = norm(r.end - r.start);
    }
}

// Up to two points (no allocation: a concave corner is common).
struct Points {
    Point p[2];
    int n = 0;
    void push_back(Point q) { p[n++] = q; }
    [[nodiscard]] const Point* begin() const { return p; }
    [[nodiscard]] const Point* end() const { return p + n; }
};

// A piece of the compensated path as a whole line (a point and its unit direction) or circle.
struct Carrier {
    bool line = true;
    Point p, d;  // a line: a point on it, its direction
    Point c;     // a circle: its centre and radius
    double r = 0;
};

// The intersections of two lines or circles.
Points intersections(const Carrier& a, const Carrier& b) {
    Points out;
    const auto line_circle = [&](Point p, Point d, Point c, double r) {
        // |p + s d - c| = r, d a unit vector
        const Point f = p - c;
        const double bq = dot(f, d), cq = dot(f, f) - r * r;
        const double disc = bq * bq - cq;
        if (disc < 0) return;
        const double root = std::sqrt(disc);
        out.push_back(p + (-bq - root) * d);
        out.push_back(p + (-bq + root) * d);
    };
    if (a.line && b.line) {
        const double den = cross(a.d, b.d);
        if (den == 0) return out;
        out.push_back(a.p + (cross(b.p - a.p, b.d) / den) * a.d);
    } else if (a.line || b.line) {
        const Carrier& l = a.line ? a : b;
        const Carrier& c = a.line ? b : a;
        line_circle(l.p, l.d, c.c, c.r);
    } else {
        const double r0 = a.r, r1 = b.r;
        const Point d = b.c - a.c;
        const double dist = norm(d);
        if (dist == 0 || dist > r0 + r1 || dist < std::abs(r0 - r1)) return out;
        const double along = (dist * dist + r0 * r0 - r1 * r1) / (2 * dist);
        const double h = std::sqrt(std::max(0.0, r0 * r0 - along * along));
        const Point e = (1 / dist) * d;
        const Point m = a.c + along * e;
        out.push_back(m + h * left_normal(e));
        out.push_back(m - h * left_normal(e));
    }
    return out;
}

// A monotone stand-in for the angle from direction `from` to direction `to`, counter-clockwise, in [0, 4)
// (0 at `from`, 1 a quarter turn, 2 half, 3 three quarters): comparisons of angles without trigonometry.
double pseudo_angle(Point from, Point to) {
    const double x = dot(from, to), y = cross(from, to);
    const double a = std::abs(x) + std::abs(y);
    if (a == 0) return 0;
    const double q = y / a;  // in [-1, 1]: the "diamond angle"
    return x >= 0 ? (y >= 0 ? q : 4 + q) : 2 - q;
}

// The centre of an entry arc that runs from `torch` to `end` (on the programmed arc's offset): on the line from
// the programmed centre through `end`, as far from the torch as from `end`.
Point entry_arc_centre(Point centre, Point end, Point torch) {
    const Point u = unit(end - centre);
    const double r_end = norm(end - centre);
    const Point ct = centre - torch;
    const double den = 2 * (dot(u, ct) + r_end);
    const double s = den != 0 ? (r_end * r_end - dot(ct, ct)) / den : 0.0;
    return centre + s * u;
}

}  // namespace

KerfPath::KerfPath(MotionSink& out, double chord_tolerance_mm)
    : out_(out), chord_tolerance_mm_(std::max(chord_tolerance_mm, kMinChordTolerance)) {}

std::vector<KerfGouge> KerfPath::take_gouges() {
    std::vector<KerfGouge> g;
    g.swap(gouges_);
    return g;
}

void KerfPath::emit(const MotionRecord& rec) {
    out_.on_motion(rec);
    torch_ = rec.end;
    torch_known_ = true;
}

// The open piece is final: pass it on, then what came behind it (events, motions that go nowhere).
void KerfPath::emit_open() {
    emit(open_piece().rec);
    for (auto& item : held_) {
        if (auto* e = std::get_if<MachineEvent>(&item)) {
            out_.on_event(*e);
        } else {
            MotionRecord z = std::get<MotionRecord>(item);
            z.start = z.end = torch_;
            z.curve = CurveKind::Line;
            z.length_mm = 0;
            emit(z);
        }
    }
    held_.clear();
}

void KerfPath::gouge(const MotionRecord& m, Msg why, MessageArgs args) {
    gouges_.push_back({m.line, m.block, why, std::move(args)});
}

void KerfPath::event(const MachineEvent& e) {
    if (open_) held_.emplace_back(e);
    else out_.on_event(e);
}

void KerfPath::finish() {
    if (!open_) return;
    check_open_end(open_piece().rec);
    emit_open();
    open_ = false;
}

void KerfPath::motion(const MotionRecord& m) {
    if (!torch_known_) {
        torch_ = m.start;
        torch_known_ = true;
    }
    const bool compensated = m.kerf != KerfSide::Off && m.kerf_mm > 0 && m.head == 1;
    if (!compensated) {
        if (open_) {
            leave(m);
        } else {
            emit(m);
        }
        return;
    }
    const double side = m.kerf == KerfSide::Left ? 1.0 : -1.0;
    if (m.length_mm <= kKerfLengthEpsilon && norm(m.end - m.start) <= kKerfLengthEpsilon) {
        // A motion that goes nowhere stays where the torch is (it has no direction to offset along).
        if (open_) {
            held_.emplace_back(m);
        } else {
            MotionRecord z = m;
            z.start = z.end = torch_;
            z.curve = CurveKind::Line;
            emit(z);
        }
        return;
    }
    if (open_ && (side != side_ || m.kerf_mm != radius_)) {
        check_open_end(m);
        emit_open();  // a new side or width: the open piece ends as it stands, the next one enters anew
        open_ = false;
    }
    side_ = side;
    radius_ = m.kerf_mm;
    if (open_) follow(m);
    else enter(m);
}

void KerfPath::offset_piece(const MotionRecord& m, Piece& p) {
    chords_.clear();
    const double off = offset_mm();
    p.rec = m;
    p.corner = m.end;
    if (m.curve == CurveKind::Line) {
        const Point t = line_direction(m);
        const Point shift = off * left_normal(t);
        p.rec.start = m.start + shift;
        p.rec.end = m.end + shift;
        p.tangent_end = p.tangent_start = t;
        p.chord = false;
        p.start_moved = false;
    } else if (m.curve == CurveKind::Arc) {
        // Left of a ccw arc is its centre: the radius shrinks; a cw arc's grows. The angles stay.
        const double grow = m.ccw ? -off : off;
        const auto moved = [&](Point q, double r) {
            const double k = r > 0 ? std::max(r + grow, 0.0) / r : 0.0;
            return m.centre + k * (q - m.centre);
        };
        p.rec.start = moved(m.start, m.radius);
        p.rec.end = moved(m.end, m.end_radius);
        p.rec.radius = std::max(m.radius + grow, 0.0);
        p.rec.end_radius = std::max(m.end_radius + grow, 0.0);
        p.rec.length_mm = std::abs(m.sweep) * (p.rec.radius + p.rec.end_radius) / 2;
        p.tangent_end = end_tangent(m);
        p.tangent_start = start_tangent(m);
        p.sweep = std::abs(m.sweep);
        p.start_radius = m.start - m.centre;
        p.chord = false;
        p.start_moved = false;
    } else {
        const ParabolaGeom& g = m.parabola;
        const double step = std::sqrt(8 * chord_tolerance_mm_ * g.p);
        const int n = std::clamp(static_cast<int>(std::ceil(std::abs(g.t1 - g.t0) / step)), 1, kMaxFlattenSegments);
        const auto at = [&](int i) {
            const double t = g.t0 + (g.t1 - g.t0) * i / n;
            return parabola_point(g, t) + off * left_normal(parabola_tangent(g, t));
        };
        Point prev = at(0);
        for (int i = 1; i <= n; ++i) {
            const Point q = at(i);
            const Point chord = unit(q - prev);
            Piece c{m,     i == n ? m.end : parabola_point(g, g.t0 + (g.t1 - g.t0) * i / n),
                    chord, i == 1 ? start_tangent(m) : chord,
                    0,     {},
                    true};
            c.rec.curve = CurveKind::Line;
            c.rec.start = prev;
            c.rec.end = q;
            reshape(c.rec);
            if (i == n) c.tangent_end = end_tangent(m);
            if (i == 1) p = c;
            else chords_.push_back(c);
            prev = q;
        }
    }
}

// The pieces offset_piece left in chords_ (a parabola's after the first) are final but the last, which stays open.
void KerfPath::take_chords(Piece& first) {
    open_index_ = 1 - open_index_;  // `first` (the next piece) is the open one now
    if (chords_.empty()) return;
    emit(first.rec);
    for (std::size_t i = 0; i + 1 < chords_.size(); ++i) emit(chords_[i].rec);
    open_piece() = chords_.back();
}

// The first motion with compensation: from the torch to the compensated end of its own piece.
void KerfPath::enter(const MotionRecord& m) {
    Piece& first = next_piece();
    offset_piece(m, first);
    if (m.curve == CurveKind::Line) {
        const Point dir = unit(m.end - torch_);
        const Point t = norm(m.end - torch_) > kKerfLengthEpsilon ? dir : unit(m.end - m.start);
        first.rec.end = m.end + offset_mm() * left_normal(t);
        first.tangent_end = t;
    } else if (m.curve == CurveKind::Arc) {
        // The end moves along its radius; the centre moves along the same line until it is as far from the
        // torch as from the new end. The corner after it turns from the programmed arc's direction at its end
        // (LinuxCNC's; the entry's own is the opposite when its centre lies beyond the end): offset_piece's.
        first.rec.centre = entry_arc_centre(m.centre, first.rec.end, torch_);
    }
    first.rec.start = torch_;
    reshape(first.rec);
    take_chords(first);
    open_is_entry_ = chords_.empty();
    open_ = true;
}

// A motion without compensation after compensated ones: from the compensated position to its programmed end.
void KerfPath::leave(const MotionRecord& m) {
    check_open_end(m);
    emit_open();
    open_ = false;
    MotionRecord exit = m;
    if (m.curve == CurveKind::Parabola) {
        MotionRecord link = m;
        link.curve = CurveKind::Line;
        link.start = torch_;
        link.end = m.start;
        reshape(link);
        emit(link);
        emit(m);
        return;
    }
    exit.start = torch_;
    reshape(exit, is_full_circle(m));
    emit(exit);
}

// The next compensated motion: the corner between the open piece and this one, then this one's pieces.
void KerfPath::follow(const MotionRecord& m) {
    Piece& next = next_piece();
    offset_piece(m, next);
    turn_corner(next, m);
    take_chords(next);
    open_is_entry_ = false;
}

void KerfPath::turn_corner(Piece& next, const MotionRecord& m) {
    // The turn from the open piece's direction to the next one's, towards the torch's side (+: convex, the
    // torch goes round the outside) against the tolerance, without trigonometry: for unit vectors, the angle
    // atan2(s, c) exceeds kKerfCornerTolerance when s cos(tol) > c sin(tol).
    const Point ta = open_piece().tangent_end, tb = next.tangent_start;
    const double c = dot(ta, tb), s = -side_ * cross(ta, tb);
    bool convex = s * kCosCornerTolerance > c * kSinCornerTolerance;
    bool concave = -s * kCosCornerTolerance > c * kSinCornerTolerance;
    if (c < -kCosCornerTolerance) {
        // Within the tolerance of a full reversal, either way round (LinuxCNC's rule): trimmed when the torch is
        // outside the next piece's arc, or the next piece is a line and the torch is outside the arc before;
        // else joined round the corner (also a concave turn of a line into a line: the join crosses the
        // contour, as LinuxCNC cuts it).
        concave = torch_outside(next.rec) || (next.rec.curve == CurveKind::Line && torch_outside(open_piece().rec));
        convex = !concave;
    }
    if (convex) {
        // Around the corner on an arc of the offset radius about the programmed corner (a rapid goes straight to
        // where the arc would end, as LinuxCNC's G0). Before a line the open piece is checked as it ends
        // (LinuxCNC's: not before an arc).
        if (m.curve == CurveKind::Line) check_open_end(m);
        emit_open();
        MotionRecord join = m;
        join.curve = m.kind == MotionKind::Rapid ? CurveKind::Line : CurveKind::Arc;
        join.start = torch_;
        join.end = next.rec.start;
        join.centre = open_piece().corner;
        join.ccw = side_ < 0;
        reshape(join);
        emit(join);
        return;
    }
    if (concave && trim_concave(next, m)) return;
    // Nearly straight on (or a gouge, reported): the next piece starts where the open one ends (tangent pieces
    // meet already, up to rounding: their geometry stays).
    emit_open();
    const Point gap = next.rec.start - torch_;
    const bool moved = dot(gap, gap) > kKerfLengthEpsilon * kKerfLengthEpsilon;
    next.rec.start = torch_;
    next.start_moved = moved;
    if (moved) reshape(next.rec, is_full_circle(next.rec));
}

bool KerfPath::torch_outside(const MotionRecord& r) const { return r.curve == CurveKind::Arc && (side_ > 0) != r.ccw; }

// Whether the open piece may end at `x`: a line must not run against its programmed direction, an arc must not
// sweep more than its programmed sweep (plus LinuxCNC's slack of 0.0254 rad) from its start to `x` (a sweep
// that wraps round means the end passed the start). An entry always may (LinuxCNC checks no entry, line or
// arc: it starts at the torch, off the contour).
bool KerfPath::open_may_end_at(Point x) {
    const Piece& p = open_piece();
    const MotionRecord& a = p.rec;
    if (open_is_entry_) return true;
    if (a.curve != CurveKind::Arc) return dot(x - a.start, p.tangent_end) >= -kKerfLengthEpsilon;
    if (norm(x - a.start) <= kKerfLengthEpsilon) return true;
    const Point u = a.start - a.centre, v = x - a.centre;
    // Within the programmed sweep (the common case, without trigonometry: pseudo-angles are monotone)
    const Point w = p.corner - a.centre;
    const double along = a.ccw ? pseudo_angle(u, v) : pseudo_angle(v, u);
    const double programmed = p.sweep >= 2 * kPi - 1e-12 ? 4.0
                              : a.ccw                    ? pseudo_angle(p.start_radius, w)
                                                         : pseudo_angle(w, p.start_radius);
    if (along > 0 && along <= programmed) return true;
    double sweep = std::atan2(a.ccw ? cross(u, v) : cross(v, u), dot(u, v));
    if (sweep <= 0) sweep += 2 * kPi;
    return sweep <= p.sweep + kKerfArcSweepSlack;
}

// The open piece ends as it is (the compensation ends, or the program): a gouge if it runs backwards (only a
// piece whose start moved can).
void KerfPath::check_open_end(const MotionRecord& m) {
    if (!open_ || !open_piece().start_moved || open_may_end_at(open_piece().rec.end)) return;
    gouge(m, Msg::GeomKerfGouge, {mm_text(radius_)});
}

// A concave corner: both pieces end at their intersection (of the two, the one LinuxCNC takes: for a line and
// an arc, the one ahead of the arc's centre along the line when the torch is inside the arc, else the one
// behind; for two arcs, the one on the side of the line between the centres given by the senses). A gouge when
// they do not meet or the piece before would have to run backwards (false: no trim). The next piece is checked
// where it ends.
bool KerfPath::trim_concave(Piece& next, const MotionRecord& m) {
    MotionRecord& before = open_piece().rec;
    const MotionRecord& after = next.rec;
    // The offset of each programmed motion as a whole: a line through the untrimmed end along the programmed
    // direction (a piece that starts where a nearly tangent one ended is not on it; an entry's: along its own),
    // a circle about the centre (an entry arc's: its own, the centre it keeps).
    Carrier ca, cb;
    if (before.curve == CurveKind::Arc) {
        ca = {false, {}, {}, before.centre, before.end_radius};
    } else {
        ca.p = before.end;  // (an entry's: on the normal of the entry's own direction, as LinuxCNC's)
        ca.d = open_piece().chord ? unit(before.end - before.start) : open_piece().tangent_end;
    }
    if (after.curve == CurveKind::Arc) {
        cb = {false, {}, {}, after.centre, after.radius};
    } else {
        cb.p = after.start;
        cb.d = unit(after.end - after.start);
    }
    const Points xs = intersections(ca, cb);
    if (xs.n == 0) {
        gouge(m, Msg::GeomKerfPiecesDoNotMeet, {mm_text(radius_)});
        return false;
    }
    Point x = xs.p[0];
    if (xs.n == 2) {
        // key(q): the larger is taken
        const auto key = [&](Point q) {
            if (ca.line) {
                const double k = dot(q - cb.c, ca.d);
                return torch_outside(after) ? -k : k;
            }
            if (cb.line) {
                const double k = dot(q - ca.c, cb.d);
                return torch_outside(before) ? k : -k;
            }
            const double k = cross(cb.c - ca.c, q - ca.c);
            return torch_outside(before) == after.ccw ? -k : k;
        };
        if (key(xs.p[1]) > key(x)) x = xs.p[1];
    }
    if (!open_may_end_at(x)) {
        gouge(m, Msg::GeomKerfGouge, {mm_text(radius_)});
        return false;
    }
    before.end = x;
    reshape(before);
    emit_open();
    next.rec.start = x;
    next.start_moved = true;
    reshape(next.rec);
    return true;
}

}  // namespace essi
