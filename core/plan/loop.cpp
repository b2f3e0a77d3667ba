// A cut's loop: where its path comes back to a point it passed (essi/plan.hpp), or the gap it leaves open; and the
// plane geometry the cut plan's tests use.
#include <algorithm>
#include <cmath>
#include <limits>

#include "plan_internal.hpp"

namespace essi::plan {
namespace {

double dist2(Point a, Point b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }
double dist(Point a, Point b) { return std::sqrt(dist2(a, b)); }

// The point of segment a-b nearest to p.
Point nearest_on_segment(Point a, Point b, Point p) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    if (len2 <= 0) return a;
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
    return {a.x + t * dx, a.y + t * dy};
}

// Where the end of piece j comes back onto the path before it: the start of a piece i <= j (among the first
// `candidates`), or, for the last piece, a line it ends on (an overcut). Returns i and the point, or false.
bool returns_at(std::span<const Piece> p, std::size_t j, std::size_t candidates, double closure2, std::size_t& at,
                Point& where) {
    const Point e = p[j].end;
    const std::size_t limit = std::min(j + 1, candidates);
    for (std::size_t i = 0; i < limit; ++i) {
        if (i == j && !p[j].arc) break;  // (a line cannot end at its own start)
        if (dist2(p[i].start, e) <= closure2) {
            at = i;
            where = p[i].start;
            return true;
        }
    }
    if (j + 1 != p.size()) return false;
    for (std::size_t i = 0; i + 1 < j && i < candidates; ++i) {
        if (p[i].arc) continue;
        const Point q = nearest_on_segment(p[i].start, p[i].end, e);
        if (dist2(q, e) <= closure2) {
            at = i;
            where = q;
            return true;
        }
    }
    return false;
}

// Twice the area between an arc of unit radius and its chord, signed as the sweep: s - sin s (a full circle and a
// quarter, the commonest arcs of a tape, without the sine).
double circular_segment(double s) {
    constexpr double kQuarter = kPi / 2;
    if (s == 2 * kPi || s == -2 * kPi) return s;
    if (s == kQuarter) return kQuarter - 1;
    if (s == -kQuarter) return 1 - kQuarter;
    return s - std::sin(s);
}

// Bounds grown point by point without Box's empty flag (the hot loop of measure()); a Box at the end.
struct Bounds {
    double min_x, min_y, max_x, max_y;
    explicit Bounds(Point p) : min_x(p.x), min_y(p.y), max_x(p.x), max_y(p.y) {}
    void add(Point p) {
        min_x = p.x < min_x ? p.x : min_x;
        max_x = p.x > max_x ? p.x : max_x;
        min_y = p.y < min_y ? p.y : min_y;
        max_y = p.y > max_y ? p.y : max_y;
    }
    void add(const Box& b) {
        add(Point{b.min_x, b.min_y});
        add(Point{b.max_x, b.max_y});
    }
    // The piece's exact box (piece_box).
    void add(const Piece& q) {
        if (q.arc) {
            add(arc_box(q));
            return;
        }
        add(q.start);
        add(q.end);
    }
    [[nodiscard]] Box box() const { return {min_x, min_y, max_x, max_y, false}; }
};

// The loop's exact signed area (a chord's shoelace term, plus the circular segment of each arc); the boxes of the
// cut and of its loop, each piece's box made once.
void measure(Cut& cut, std::span<const Piece> pieces) {
    if (cut.first_piece == cut.end_piece) {
        cut.box = cut.loop_box = Box{};
        cut.area_mm2 = 0;
        return;
    }
    Bounds box(pieces[cut.first_piece].start);
    if (!cut.closed) {
        for (std::uint32_t k = cut.first_piece; k < cut.end_piece; ++k) box.add(pieces[k]);
        cut.box = box.box();
        cut.loop_box = Box{};
        cut.area_mm2 = 0;
        return;
    }
    for (std::uint32_t k = cut.first_piece; k < cut.loop_begin; ++k) box.add(pieces[k]);
    // The loop, from loop_start: its first piece's start, or a point on it when it closes on a line.
    const Piece& head = pieces[cut.loop_begin];
    Bounds loop(cut.loop_start);
    double twice = 0;
    for (std::uint32_t k = cut.loop_begin; k < cut.loop_end; ++k) {
        const Piece& q = pieces[k];
        const Point a = k == cut.loop_begin ? cut.loop_start : q.start;
        twice += a.x * q.end.y - q.end.x * a.y;
        if (q.arc) {
            twice += q.radius * q.radius * circular_segment(q.sweep);
            loop.add(arc_box(q));
        } else {
            loop.add(a);
            loop.add(q.end);
        }
    }
    box.add(loop.box());
    if (!head.arc) box.add(head.start);  // (the cut's box holds the loop's first piece whole)
    for (std::uint32_t k = cut.loop_end; k < cut.end_piece; ++k) box.add(pieces[k]);
    cut.box = box.box();
    cut.loop_box = loop.box();
    cut.area_mm2 = twice / 2;
}

// The open cut's gap: the point it passed nearest to its end, among those far enough back along the path that
// they are not simply where it is going (more than 3 gaps of path).
void find_gap(Cut& cut, std::span<const Piece> p, double gap_limit_mm) {
    const Point e = p.back().end;
    double behind = 0;  // path length from a piece's start to the end
    double best2 = std::numeric_limits<double>::infinity();
    for (std::size_t k = p.size(); k-- > 0;) {
        behind += piece_length(p[k]);
        if (behind <= 3 * gap_limit_mm) continue;
        const double d2 = dist2(p[k].start, e);
        if (d2 < best2) {
            best2 = d2;
            cut.gap_from = p[k].start;
            cut.gap_line = p[k].line;
        }
    }
    cut.gap_mm = std::sqrt(best2);
}

}  // namespace

double piece_length(const Piece& p) { return p.arc ? std::fabs(p.sweep) * p.radius : dist(p.start, p.end); }

std::uint32_t motion_of_piece(const Cut& cut, std::span<const Piece> pieces, std::uint32_t k) {
    std::uint32_t motion = 0;
    for (std::uint32_t i = cut.first_piece + 1; i <= k; ++i) motion += pieces[i].continues ? 0 : 1;
    return motion;
}

int arc_chords(double radius, double sweep) {
    if (!(radius > kPlanChordToleranceMm)) return 1;
    // A chord over angle a has a sagitta r(1 - cos(a/2)) <= r a^2 / 8: steps of sqrt(8 tol / r) stay within tol.
    const double n = std::ceil(std::fabs(sweep) / std::sqrt(8 * kPlanChordToleranceMm / radius));
    return n >= 1 && n <= kPlanMaxArcChords ? static_cast<int>(n) : n > kPlanMaxArcChords ? kPlanMaxArcChords : 1;
}

std::size_t curve_points(const MotionRecord& m) {
    if (m.curve == CurveKind::Parabola)
        return static_cast<std::size_t>(flatten_segments(m, kPlanChordToleranceMm, kPlanMaxArcChords));
    return static_cast<std::size_t>(arc_chords(m.radius, m.sweep));
}

void flatten_piece(const Piece& p, std::vector<Point>& out) {
    if (!p.arc || p.radius <= kPlanChordToleranceMm) {
        out.push_back(p.end);
        return;
    }
    // The points turn about the centre by one rotation each (no trigonometry a point).
    const int n = arc_chords(p.radius, p.sweep);
    const double step = p.sweep / n, c = std::cos(step), s = std::sin(step);
    double vx = p.start.x - p.centre.x, vy = p.start.y - p.centre.y;
    for (int k = 1; k < n; ++k) {
        const double nx = vx * c - vy * s;
        vy = vx * s + vy * c;
        vx = nx;
        out.push_back({p.centre.x + vx, p.centre.y + vy});
    }
    out.push_back(p.end);
}

void close_loop(Cut& cut, std::span<const Piece> pieces, double closure_mm, double gap_limit_mm) {
    const std::span<const Piece> p = pieces.subspan(cut.first_piece, cut.end_piece - cut.first_piece);
    cut.closed = false;
    const std::size_t n = p.size();
    if (n == 0) return;  // (a cut left out of the plan's tests, N615: no pieces, an empty box, no gap)
    const double closure2 = closure_mm * closure_mm;
    // First the loops that begin on the lead-in's first pieces (nearly every contour), then any other point passed.
    for (const std::size_t candidates :
         {std::min(n, kPlanLeadMotions), n <= kPlanFullClosureMotions ? n : std::size_t{0}}) {
        // (an end away from every candidate start, by more than the closure, returns nowhere but on the last piece)
        Box starts;
        for (std::size_t i = 0; i < candidates; ++i)
            if (std::isfinite(p[i].start.x) && std::isfinite(p[i].start.y)) starts.add(p[i].start);
        const Box near{starts.min_x - closure_mm, starts.min_y - closure_mm, starts.max_x + closure_mm,
                       starts.max_y + closure_mm, starts.empty};
        for (std::size_t j = 0; j < n && candidates > 0 && !cut.closed; ++j) {
            std::size_t at = 0;
            Point where;
            const Point e = p[j].end;
            if (j + 1 != n && !(e.x >= near.min_x && e.x <= near.max_x && e.y >= near.min_y && e.y <= near.max_y))
                continue;
            if (!returns_at(p, j, candidates, closure2, at, where)) continue;
            cut.closed = true;
            cut.loop_begin = cut.first_piece + static_cast<std::uint32_t>(at);
            cut.loop_end = cut.first_piece + static_cast<std::uint32_t>(j + 1);
            cut.loop_start = where;
            measure(cut, pieces);
            cut.closed = std::fabs(cut.area_mm2) > 0;  // (out and back along itself encloses nothing)
        }
        if (cut.closed || candidates >= n) break;
    }
    if (cut.closed) return;
    measure(cut, pieces);
    find_gap(cut, p, gap_limit_mm);
}

std::vector<Point> loop_polygon(const Cut& cut, std::span<const Piece> pieces) {
    std::vector<Point> polygon{cut.loop_start};
    for (std::uint32_t k = cut.loop_begin; k < cut.loop_end; ++k) {
        Piece p = pieces[k];
        if (k == cut.loop_begin) p.start = cut.loop_start;  // (a loop closing on a line: from the point)
        flatten_piece(p, polygon);
    }
    if (polygon.size() > 1) polygon.pop_back();  // (the end is the start)
    return polygon;
}

std::vector<Point> pieces_points(std::span<const Piece> pieces, std::uint32_t first, std::uint32_t end) {
    std::vector<Point> pts;
    if (first >= end) return pts;
    pts.push_back(pieces[first].start);
    for (std::uint32_t k = first; k < end; ++k) flatten_piece(pieces[k], pts);
    return pts;
}

namespace {

// Whether the segment a-b crosses the ray from p towards +x (half-open in y, so that a point the ray passes
// through counts once for the two segments that meet there).
bool crosses_ray(Point a, Point b, Point p) {
    return (a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x;
}

}  // namespace

// The quadrant of a vector from the centre: 0 (+x, +y], 1 (-x, +y], 2 (-x, -y], 3 (+x, -y]; turning
// counter-clockwise from quadrant q into the next passes the circle's extreme q + 1 (mod 4): 0 right, 1 top,
// 2 left, 3 bottom.
int quadrant(double x, double y) {
    if (y > 0 || (y == 0 && x > 0)) return x > 0 ? 0 : 1;
    return x < 0 ? 2 : 3;
}

Box arc_box(const Piece& p) {
    const double r = p.radius;
    Box b = Box::of(p.start, p.end);
    if (std::fabs(p.sweep) >= 2 * kPi) {  // (a full circle, the commonest hole: its four extremes)
        b.add(Point{p.centre.x - r, p.centre.y - r});
        b.add(Point{p.centre.x + r, p.centre.y + r});
        return b;
    }
    const bool ccw = p.sweep > 0;
    double ux = p.start.x - p.centre.x, uy = p.start.y - p.centre.y;
    double vx = p.end.x - p.centre.x, vy = p.end.y - p.centre.y;
    if (!ccw) {  // a clockwise arc is the counter-clockwise one mirrored in y
        uy = -uy;
        vy = -vy;
    }
    const int qs = quadrant(ux, uy), qe = quadrant(vx, vy);
    int passes = (qe - qs + 4) % 4;
    const bool wraps = std::fabs(p.sweep) >= 2 * kPi || (qs == qe && ux * vy - uy * vx < 0);
    if (wraps) passes += 4;
    for (int k = 1; k <= passes && k <= 4; ++k) {
        const int extreme = (qs + k) % 4;  // 0 right, 1 top, 2 left, 3 bottom (mirrored back for clockwise)
        const double ex = extreme == 0 ? r : extreme == 2 ? -r : 0;
        double ey = extreme == 1 ? r : extreme == 3 ? -r : 0;
        if (!ccw) ey = -ey;
        b.add(Point{p.centre.x + ex, p.centre.y + ey});
    }
    return b;
}

bool inside_loop(const Cut& cut, std::span<const Piece> pieces, Point p) {
    // An arc crosses the ray as its chord does when the ray misses its box or its box lies wholly to the right of p
    // (the curve and the chord then cross the ray's line right of p equally often, mod 2); only an arc whose box
    // holds p is followed along its chords. (Its end point is its chord's: the loop's pieces meet exactly.)
    int crossings = 0;
    std::vector<Point> chords;
    for (std::uint32_t k = cut.loop_begin; k < cut.loop_end; ++k) {
        Piece piece = pieces[k];
        if (k == cut.loop_begin) piece.start = cut.loop_start;
        if (piece.arc) {
            // (the circle's box first: most arcs of a loop are far from the point)
            const double r = piece.radius;
            if (p.y < piece.centre.y - r || p.y > piece.centre.y + r || p.x > piece.centre.x + r) {
                if (crosses_ray(piece.start, piece.end, p)) ++crossings;  // (the arc bulges past its ends: its chord)
                continue;
            }
            const Box box = piece_box(piece);
            if (p.y < box.min_y || p.y > box.max_y || p.x > box.max_x) continue;
            if (p.x >= box.min_x) {
                chords.assign(1, piece.start);
                flatten_piece(piece, chords);
                for (std::size_t c = 1; c < chords.size(); ++c)
                    crossings += crosses_ray(chords[c - 1], chords[c], p) ? 1 : 0;
                continue;
            }
        }
        crossings += crosses_ray(piece.start, piece.end, p) ? 1 : 0;
    }
    return crossings % 2 == 1;
}

double segment_distance(Point a, Point b, Point c, Point d, Point& where) {
    // Crossing: the distance is 0 at the intersection.
    const double d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.x - c.x, d2y = d.y - c.y;
    const double den = d1x * d2y - d1y * d2x;
    if (den != 0) {
        const double t = ((c.x - a.x) * d2y - (c.y - a.y) * d2x) / den;
        const double u = ((c.x - a.x) * d1y - (c.y - a.y) * d1x) / den;
        if (t >= 0 && t <= 1 && u >= 0 && u <= 1) {
            where = {a.x + t * d1x, a.y + t * d1y};
            return 0;
        }
    }
    // Else the nearest of the four end-to-segment distances.
    double best = std::numeric_limits<double>::infinity();
    const auto consider = [&](Point on_ab, Point other) {
        const double dd = dist(on_ab, other);
        if (dd < best) {
            best = dd;
            where = on_ab;
        }
    };
    consider(nearest_on_segment(a, b, c), c);
    consider(nearest_on_segment(a, b, d), d);
    consider(a, nearest_on_segment(c, d, a));
    consider(b, nearest_on_segment(c, d, b));
    return best;
}

}  // namespace essi::plan
