// A cut's loop: where its path comes back to a point it passed (essi/plan.hpp), or the gap it leaves open; and the
// plane geometry the cut plan's tests use.
#include <algorithm>
#include <cmath>
#include <limits>

#include "plan_internal.hpp"

namespace essi::plan {
namespace {

double dist(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The point of segment a-b nearest to p.
Point nearest_on_segment(Point a, Point b, Point p) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    if (len2 <= 0) return a;
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
    return {a.x + t * dx, a.y + t * dy};
}

// Where the end of piece j comes back onto the path before it: a piece i < j whose start it reaches (or, for the
// last piece, a line it ends on: an overcut). Returns i and the point, or false.
bool returns_at(const Cut& cut, std::size_t j, std::size_t first_candidates, double closure_mm, std::size_t& at,
                Point& where) {
    const Point e = cut.pieces[j].end;
    const std::size_t limit = std::min(j + 1, first_candidates);
    for (std::size_t i = 0; i < limit; ++i) {
        if (i == j && !cut.pieces[j].arc) break;  // (a line cannot end at its own start)
        if (dist(cut.pieces[i].start, e) <= closure_mm) {
            at = i;
            where = cut.pieces[i].start;
            return true;
        }
    }
    if (j + 1 != cut.pieces.size()) return false;
    for (std::size_t i = 0; i + 1 < j && i < first_candidates; ++i) {
        const Piece& p = cut.pieces[i];
        if (p.arc) continue;
        const Point q = nearest_on_segment(p.start, p.end, e);
        if (dist(q, e) <= closure_mm) {
            at = i;
            where = q;
            return true;
        }
    }
    return false;
}

void flatten_loop(Cut& cut) {
    cut.polygon.clear();
    cut.polygon.push_back(cut.loop_start);
    for (std::size_t k = cut.loop_begin; k < cut.loop_end; ++k) {
        Piece p = cut.pieces[k];
        if (k == cut.loop_begin && !p.arc) p.start = cut.loop_start;  // (a loop closing on a line: from the point)
        flatten_piece(p, cut.polygon);
    }
    if (cut.polygon.size() > 1) cut.polygon.pop_back();  // (the end is the start)
    cut.loop_box = Box{};
    for (Point p : cut.polygon) cut.loop_box.add(p);
    cut.area_mm2 = polygon_area(cut.polygon);
}

// The open cut's gap: the point it passed nearest to its end, among those far enough back along the path that
// they are not simply where it is going (more than 3 gaps of path).
void find_gap(Cut& cut, double gap_limit_mm) {
    const Point e = cut.pieces.back().end;
    double behind = 0;  // path length from a piece's start to the end
    cut.gap_mm = std::numeric_limits<double>::infinity();
    for (std::size_t k = cut.pieces.size(); k-- > 0;) {
        behind += cut.pieces[k].length_mm;
        if (behind <= 3 * gap_limit_mm) continue;
        const double d = dist(cut.pieces[k].start, e);
        if (d < cut.gap_mm) {
            cut.gap_mm = d;
            cut.gap_from = cut.pieces[k].start;
            cut.gap_line = cut.pieces[k].line;
        }
    }
}

}  // namespace

void flatten_piece(const Piece& p, std::vector<Point>& out) {
    if (!p.arc) {
        out.push_back(p.end);
        return;
    }
    MotionRecord m;
    m.curve = CurveKind::Arc;
    m.start = p.start;
    m.end = p.end;
    m.centre = p.centre;
    m.radius = p.radius;
    m.end_radius = dist(p.end, p.centre);
    m.sweep = p.sweep;
    m.ccw = p.sweep > 0;
    flatten(m, kPlanChordToleranceMm, out, /*include_start*/ false);
}

void close_loop(Cut& cut, double closure_mm, double gap_limit_mm) {
    cut.closed = false;
    const std::size_t n = cut.pieces.size();
    const std::size_t candidates = n <= kPlanFullClosureMotions ? n : kPlanLeadMotions;
    for (std::size_t j = 0; j < n && !cut.closed; ++j) {
        std::size_t at = 0;
        Point where;
        if (returns_at(cut, j, candidates, closure_mm, at, where)) {
            cut.closed = true;
            cut.loop_begin = at;
            cut.loop_end = j + 1;
            cut.loop_start = where;
        }
    }
    if (cut.closed) {
        flatten_loop(cut);
        if (std::fabs(cut.area_mm2) > 0) return;
        cut.closed = false;  // (a path that goes out and back along itself encloses nothing)
    }
    find_gap(cut, gap_limit_mm);
}

double polygon_area(const std::vector<Point>& polygon) {
    double a = 0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) a += (polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y);
    return n < 3 ? 0 : a / 2;
}

bool inside_polygon(const std::vector<Point>& polygon, Point p) {
    bool in = false;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Point a = polygon[i], b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
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
