// Phase 3 (geom): arcs, full circles, the end-point tolerance, exact bounding boxes, parabolas with
// closed-form lengths, flattening (docs/semantics.md §5, §6). Expectations worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "essi/geom.hpp"
#include "test_util.hpp"

using namespace essi;
using namespace essi_test;

namespace {

constexpr double kBoxTol = 1e-9;       // mm, bounding boxes
constexpr double kOnCurveTol = 1e-9;   // mm, flattened points lie on the exact curve
constexpr double kChordSlack = 1e-12;  // mm, rounding allowance on top of the chord tolerance

// Arc length of the parabola y = t^2/(2p) from 0 to t: the antiderivative of sqrt(1 + (t/p)^2).
double parabola_F(double t, double p) { return t / 2 * std::sqrt(1 + (t / p) * (t / p)) + p / 2 * std::asinh(t / p); }

MotionRecord make_line(Point s, Point e) {
    MotionRecord m;
    m.curve = CurveKind::Line;
    m.kind = MotionKind::Cut;
    m.start = s;
    m.end = e;
    m.length_mm = std::hypot(e.x - s.x, e.y - s.y);
    return m;
}

MotionRecord make_arc(Point s, Point e, Point c, double sweep) {
    MotionRecord m;
    m.curve = CurveKind::Arc;
    m.kind = MotionKind::Cut;
    m.start = s;
    m.end = e;
    m.centre = c;
    m.ccw = sweep > 0;
    m.radius = std::hypot(s.x - c.x, s.y - c.y);
    m.end_radius = std::hypot(e.x - c.x, e.y - c.y);
    m.sweep = sweep;
    m.length_mm = m.radius * std::abs(sweep);
    return m;
}

// y = -10 + (x-10)^2/10 from (0,0) to (20,0): vertex (10,-10), p = 5, axis +Y.
MotionRecord make_parabola_u() {
    MotionRecord m;
    m.curve = CurveKind::Parabola;
    m.kind = MotionKind::Cut;
    m.start = {0, 0};
    m.end = {20, 0};
    m.ccw = true;
    m.parabola.vertex = {10, -10};
    m.parabola.u = {1, 0};
    m.parabola.n = {0, 1};
    m.parabola.p = 5;
    m.parabola.t0 = -10;
    m.parabola.t1 = 10;
    m.length_mm = 2 * parabola_F(10, 5);
    return m;
}

void expect_box(const Box& b, double x0, double y0, double x1, double y1, const std::string& what) {
    EXPECT_FALSE(b.empty) << what;
    EXPECT_NEAR(b.min_x, x0, kBoxTol) << what << " min_x";
    EXPECT_NEAR(b.min_y, y0, kBoxTol) << what << " min_y";
    EXPECT_NEAR(b.max_x, x1, kBoxTol) << what << " max_x";
    EXPECT_NEAR(b.max_y, y1, kBoxTol) << what << " max_y";
}

// The single motion of a one-block tape (after an optional prefix of function blocks).
MotionRecord one_motion(const std::string& src, RunResult* keep = nullptr) {
    RunResult r = run(src);
    EXPECT_EQ(r.motions().size(), 1u) << src << "\n" << r.dump();
    MotionRecord m = r.motions().empty() ? MotionRecord{} : r.motions()[0];
    if (keep) *keep = std::move(r);
    return m;
}

double dist_point_segment(Point p, Point a, Point b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double dist_point_polyline(Point p, const std::vector<Point>& poly) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < poly.size(); ++i) best = std::min(best, dist_point_segment(p, poly[i - 1], poly[i]));
    return best;
}

}  // namespace

// ---------------------------------------------------------------- arc_sweep

TEST(GeomArcSweep, QuarterHalfThreeQuarterFull) {
    const Point c{0, 0};
    EXPECT_NEAR(arc_sweep({10, 0}, {0, 10}, c, true, false), kPi / 2, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {0, 10}, c, false, false), -3 * kPi / 2, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {0, -10}, c, false, false), -kPi / 2, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {0, -10}, c, true, false), 3 * kPi / 2, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {-10, 0}, c, true, false), kPi, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {-10, 0}, c, false, false), -kPi, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {10, 0}, c, true, true), 2 * kPi, kAngTol);
    EXPECT_NEAR(arc_sweep({10, 0}, {10, 0}, c, false, true), -2 * kPi, kAngTol);
    // off-origin centre, start at angle pi/2: ccw to angle pi is a quarter
    EXPECT_NEAR(arc_sweep({5, 8}, {2, 5}, {5, 5}, true, false), kPi / 2, kAngTol);
}

// ---------------------------------------------------------------- arcs through the interpreter

TEST(GeomArc, QuarterCcwAndCw) {
    // start (0,0), centre (10,0): end (10,-10) ccw is a quarter (angle pi -> 3pi/2)
    MotionRecord q = one_motion("+100-100+100+0+\n64\n");
    EXPECT_EQ(q.curve, CurveKind::Arc);
    EXPECT_TRUE(q.ccw);
    EXPECT_NEAR(q.sweep, kPi / 2, kAngTol);
    EXPECT_NEAR(q.radius, 10.0, kPosTol);
    EXPECT_NEAR(q.end_radius, 10.0, kPosTol);
    EXPECT_NEAR(q.length_mm, 5 * kPi, kLenTol);
    expect_box(bounding_box(q), 0, -10, 10, 0, "quarter ccw");
    // end (10,10) cw: angle pi -> pi/2
    MotionRecord w = one_motion("+100+100+100+0-\n64\n");
    EXPECT_FALSE(w.ccw);
    EXPECT_NEAR(w.sweep, -kPi / 2, kAngTol);
    expect_box(bounding_box(w), 0, 0, 10, 10, "quarter cw");
}

TEST(GeomArc, HalfCircleSides) {
    // CCW semicircle from (0,0) to (20,0) around (10,0): from angle pi ccw through 3pi/2: the low side
    MotionRecord ccw = one_motion("+200+0+100+0+\n64\n");
    EXPECT_NEAR(ccw.sweep, kPi, kAngTol);
    EXPECT_NEAR(ccw.length_mm, 10 * kPi, kLenTol);
    EXPECT_POINT_NEAR(ccw.end, 20.0, 0.0, kPosTol);
    expect_box(bounding_box(ccw), 0, -10, 20, 0, "half ccw");
    EXPECT_POINT_NEAR(point_at(ccw, 0.5), 10.0, -10.0, 1e-9);
    // CW: through pi/2, the high side
    MotionRecord cw = one_motion("+200+0+100+0-\n64\n");
    EXPECT_NEAR(cw.sweep, -kPi, kAngTol);
    expect_box(bounding_box(cw), 0, 0, 20, 10, "half cw");
    EXPECT_POINT_NEAR(point_at(cw, 0.5), 10.0, 10.0, 1e-9);
}

TEST(GeomArc, ThreeQuarter) {
    // start (0,0), centre (10,0), end (10,10): ccw from pi to 5pi/2 = 3pi/2
    MotionRecord m = one_motion("+100+100+100+0+\n64\n");
    EXPECT_NEAR(m.sweep, 3 * kPi / 2, kAngTol);
    EXPECT_NEAR(m.length_mm, 15 * kPi, kLenTol);
    expect_box(bounding_box(m), 0, -10, 20, 10, "three-quarter ccw");
    // end (10,-10) cw: pi -> -pi/2 the long way, -3pi/2
    MotionRecord w = one_motion("+100-100+100+0-\n64\n");
    EXPECT_NEAR(w.sweep, -3 * kPi / 2, kAngTol);
    expect_box(bounding_box(w), 0, -10, 20, 10, "three-quarter cw");
}

TEST(GeomArc, AsymmetricArcExtremes) {
    // start (0,0), centre (-3,4), r = 5, end (-6,0). Start angle atan2(-4,3), end angle atan2(-4,-3).
    MotionRecord m = one_motion("-60+0-30+40+\n64\n");
    const double s = 2 * kPi + std::atan2(-4.0, -3.0) - std::atan2(-4.0, 3.0);  // ccw, passes 0, pi/2, pi
    EXPECT_NEAR(s, 4.996183089593018, 1e-12);
    EXPECT_NEAR(m.sweep, s, kAngTol);
    EXPECT_NEAR(m.length_mm, 5 * s, kLenTol);
    expect_box(bounding_box(m), -8, 0, 2, 9, "asymmetric ccw");
    // cw the short way: passes -pi/2 only -> y = 4 - 5 = -1
    MotionRecord w = one_motion("-60+0-30+40-\n64\n");
    EXPECT_NEAR(w.sweep, -(2 * kPi - s), kAngTol);
    EXPECT_NEAR(w.length_mm, 5 * (2 * kPi - s), kLenTol);
    expect_box(bounding_box(w), -6, -1, 0, 0, "asymmetric cw");
}

TEST(GeomArc, FullCircle) {
    MotionRecord m = one_motion("+0+0+100+0+\n64\n");
    EXPECT_EQ(m.curve, CurveKind::Arc);
    EXPECT_NEAR(m.sweep, 2 * kPi, kAngTol);
    EXPECT_NEAR(m.length_mm, 2 * kPi * 10, kLenTol);
    EXPECT_POINT_NEAR(m.end, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(m.centre, 10.0, 0.0, kPosTol);
    expect_box(bounding_box(m), 0, -10, 20, 10, "full circle");
    MotionRecord w = one_motion("+0+0+100+0-\n64\n");
    EXPECT_NEAR(w.sweep, -2 * kPi, kAngTol);
    EXPECT_NEAR(w.length_mm, 2 * kPi * 10, kLenTol);
    // sign-only words: +++205++ is DX=DY=0, XC=20.5 mm, YC=0, ccw: a full circle around (20.5, 0)
    MotionRecord s = one_motion("+++205++\n64\n");
    EXPECT_NEAR(s.sweep, 2 * kPi, kAngTol);
    EXPECT_NEAR(s.radius, 20.5, kPosTol);
    EXPECT_POINT_NEAR(s.centre, 20.5, 0.0, kPosTol);
    expect_box(bounding_box(s), 0, -20.5, 41, 20.5, "full circle 205");
}

TEST(GeomArc, EndWithinToleranceEndsExactly) {
    // r_start = 125 units, r_end = 126 units: 1 unit off, allowed (tolerance 2 units)
    RunResult r;
    MotionRecord m = one_motion("+251+0+125+0+\n64\n", &r);
    EXPECT_FALSE(r.has(DiagCode::E301_ArcEndNotOnCircle)) << r.dump();
    EXPECT_DOUBLE_EQ(m.end.x, 251 * 0.1);
    EXPECT_DOUBLE_EQ(m.end.y, 0.0);
    EXPECT_NEAR(m.radius, 12.5, kPosTol);
    EXPECT_NEAR(m.end_radius, 12.6, kPosTol);
    EXPECT_NEAR(m.sweep, kPi, kAngTol);
    std::vector<Point> pts;
    flatten(m, 0.01, pts);
    ASSERT_FALSE(pts.empty());
    EXPECT_EQ(pts.back(), m.end);  // exactly the programmed end point, nothing drifts
    // the next block starts exactly there
    auto r2 = run("+251+0+125+0+\n+100+0\n64\n");
    ASSERT_EQ(r2.motions().size(), 2u);
    EXPECT_EQ(r2.motions()[1].start, r2.motions()[0].end);
    EXPECT_NEAR(r2.motions()[1].end.x, 35.1, kPosTol);
}

TEST(GeomArc, EndExactlyAtToleranceIsAccepted) {
    // r_end - r_start = 127 - 125 = 2 units = the tolerance: allowed (<=)
    auto r = run("+252+0+125+0+\n64\n");
    EXPECT_FALSE(r.has(DiagCode::E301_ArcEndNotOnCircle)) << r.dump();
    ASSERT_EQ(r.motions().size(), 1u);
    EXPECT_NEAR(r.motions()[0].end.x, 25.2, kPosTol);
}

TEST(GeomArc, EndBeyondToleranceE301NamesBothRadii) {
    // r_start = 12.5 mm, r_end = 12.8 mm (3 units off)
    auto r = run("7\n+253+0+125+0+\n8\n64\n");
    const Diagnostic* d = find_code(r.diags, DiagCode::E301_ArcEndNotOnCircle);
    ASSERT_NE(d, nullptr) << r.dump();
    EXPECT_EQ(d->severity, Severity::Error);
    EXPECT_EQ(d->line, 2u);
    EXPECT_NE(essi::diagnostic_message(*d, essi::Lang::En).find("12.5"), std::string::npos)
        << essi::diagnostic_message(*d, essi::Lang::En);
    EXPECT_NE(essi::diagnostic_message(*d, essi::Lang::En).find("12.8"), std::string::npos)
        << essi::diagnostic_message(*d, essi::Lang::En);
}

TEST(GeomArc, ToleranceIsAProfileSetting) {
    Profile p;
    p.arc_tolerance_units = 5;
    auto r = run("+253+0+125+0+\n64\n", p);
    EXPECT_FALSE(r.has(DiagCode::E301_ArcEndNotOnCircle)) << r.dump();
    p.arc_tolerance_units = 0.5;
    auto r2 = run("+251+0+125+0+\n64\n", p);
    EXPECT_TRUE(r2.has(DiagCode::E301_ArcEndNotOnCircle)) << r2.dump();
}

TEST(GeomArc, ZeroRadiusE302) {
    auto r = run("+100+0+0+0+\n64\n");
    EXPECT_TRUE(r.has(DiagCode::E302_ArcZeroRadius)) << r.dump();
}

// ---------------------------------------------------------------- bounding boxes (hand-made records)

TEST(GeomBox, AddPointsAndBoxes) {
    Box b;
    EXPECT_TRUE(b.empty);
    b.add(Point{3, -2});
    EXPECT_FALSE(b.empty);
    expect_box(b, 3, -2, 3, -2, "one point");
    b.add(Point{-1, 5});
    expect_box(b, -1, -2, 3, 5, "two points");
    Box c;
    c.add(Point{10, 10});
    c.add(Point{11, 12});
    b.add(c);
    expect_box(b, -1, -2, 11, 12, "union");
    Box empty;
    b.add(empty);
    expect_box(b, -1, -2, 11, 12, "union with empty");
}

TEST(GeomBox, ArcTopExtremeOnly) {
    const double h = 10 / std::sqrt(2.0);
    MotionRecord m = make_arc({h, h}, {-h, h}, {0, 0}, kPi / 2);
    expect_box(bounding_box(m), -h, h, h, 10, "arc pi/4 -> 3pi/4");
    MotionRecord w = make_arc({h, h}, {-h, h}, {0, 0}, -3 * kPi / 2);
    expect_box(bounding_box(w), -10, -10, 10, h, "arc pi/4 -> 3pi/4 cw");
}

TEST(GeomBox, Line) { expect_box(bounding_box(make_line({5, 7}, {-3, 2})), -3, 2, 5, 7, "line"); }

TEST(GeomBox, ParabolaIncludesVertex) { expect_box(bounding_box(make_parabola_u()), 0, -10, 20, 0, "parabola"); }

// ---------------------------------------------------------------- parabolas (§6)

TEST(GeomParabola, ClosedFormLength) {
    EXPECT_NEAR(parabola_F(10, 5), 14.789428575445975, 1e-12);  // hand: 5*sqrt(5) + 2.5*asinh(2)
    const MotionRecord m = make_parabola_u();
    EXPECT_NEAR(parabola_length(m.parabola), 29.57885715089195, kLenTol);
    ParabolaGeom g = m.parabola;
    g.t0 = 10;
    g.t1 = 20;
    EXPECT_NEAR(parabola_length(g), parabola_F(20, 5) - parabola_F(10, 5), kLenTol);
    g.t0 = -20;  // the mirror piece on the other side of the vertex has the same length
    g.t1 = -10;
    EXPECT_NEAR(parabola_length(g), parabola_F(20, 5) - parabola_F(10, 5), kLenTol);
    EXPECT_POINT_NEAR(parabola_point(m.parabola, -10), 0.0, 0.0, 1e-12);
    EXPECT_POINT_NEAR(parabola_point(m.parabola, 0), 10.0, -10.0, 1e-12);
    EXPECT_POINT_NEAR(parabola_point(m.parabola, 5), 15.0, -7.5, 1e-12);
}

TEST(GeomParabola, AxisParallelToYThroughVertex) {
    // TP+: XP = 10 mm to the axis, YP = 5 mm radius at the vertex: y = -10 + (x-10)^2/10
    RunResult r;
    MotionRecord m = one_motion("+200+0+100+50++\n64\n", &r);
    EXPECT_TRUE(r.diags.empty()) << r.dump();
    EXPECT_EQ(m.curve, CurveKind::Parabola);
    EXPECT_POINT_NEAR(m.start, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(m.end, 20.0, 0.0, kPosTol);
    EXPECT_NEAR(m.length_mm, 2 * parabola_F(10, 5), kLenTol);
    EXPECT_POINT_NEAR(m.parabola.vertex, 10.0, -10.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.n, 0.0, 1.0, 1e-12);
    EXPECT_NEAR(m.parabola.p, 5.0, kPosTol);
    EXPECT_POINT_NEAR(parabola_point(m.parabola, m.parabola.t0), 0.0, 0.0, 1e-9);
    EXPECT_POINT_NEAR(parabola_point(m.parabola, m.parabola.t1), 20.0, 0.0, 1e-9);
    expect_box(bounding_box(m), 0, -10, 20, 0, "parabola TP+");
}

TEST(GeomParabola, AsymmetricPieces) {
    // end at x = 30: y = -10 + 400/10 = 30
    MotionRecord a = one_motion("+300+300+100+50++\n64\n");
    EXPECT_NEAR(a.length_mm, parabola_F(20, 5) + parabola_F(10, 5), kLenTol);
    EXPECT_NEAR(a.length_mm, 61.25726619977534, kLenTol);
    expect_box(bounding_box(a), 0, -10, 30, 30, "through vertex");
    // axis at x = -10, vertex (-10,-10): the piece x in [0,10] does not reach the vertex
    MotionRecord b = one_motion("+100+300-100+50++\n64\n");
    EXPECT_POINT_NEAR(b.parabola.vertex, -10.0, -10.0, kPosTol);
    EXPECT_NEAR(b.length_mm, parabola_F(20, 5) - parabola_F(10, 5), kLenTol);
    EXPECT_NEAR(b.length_mm, 31.67840904888339, kLenTol);
    expect_box(bounding_box(b), 0, 0, 10, 30, "beside the vertex");
}

TEST(GeomParabola, NegativeRadiusOpensDown) {
    // YP = -5: y = 10 - (x-10)^2/10, a cap from (0,0) to (20,0): turning clockwise, TC -
    RunResult r;
    MotionRecord m = one_motion("+200+0+100-50-+\n64\n", &r);
    EXPECT_TRUE(r.diags.empty()) << r.dump();
    EXPECT_POINT_NEAR(m.parabola.vertex, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.n, 0.0, -1.0, 1e-12);
    EXPECT_NEAR(m.parabola.p, 5.0, kPosTol);
    EXPECT_NEAR(m.length_mm, 2 * parabola_F(10, 5), kLenTol);
    expect_box(bounding_box(m), 0, 0, 20, 10, "cap");
}

TEST(GeomParabola, AxisParallelToX) {
    // TP-: YP = 10 mm to the axis (y = 10), XP = 5 mm radius: x = -10 + (y-10)^2/10, (0,0) -> (0,20), cw
    RunResult r;
    MotionRecord m = one_motion("+0+200+50+100--\n64\n", &r);
    EXPECT_TRUE(r.diags.empty()) << r.dump();
    EXPECT_EQ(m.curve, CurveKind::Parabola);
    EXPECT_POINT_NEAR(m.end, 0.0, 20.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.vertex, -10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.n, 1.0, 0.0, 1e-12);
    EXPECT_NEAR(m.parabola.p, 5.0, kPosTol);
    EXPECT_NEAR(m.length_mm, 2 * parabola_F(10, 5), kLenTol);
    expect_box(bounding_box(m), -10, 0, 0, 20, "parabola TP-");
}

TEST(GeomParabola, EndOffCurveE303) {
    auto bad = run("+200+10+100+50++\n64\n");  // curve at x=20 is y=0; the end is 1 mm (10 units) off
    const Diagnostic* d = find_code(bad.diags, DiagCode::E303_ParabolaEndNotOnCurve);
    ASSERT_NE(d, nullptr) << bad.dump();
    EXPECT_EQ(d->line, 1u);
    EXPECT_EQ(d->severity, Severity::Error);
    auto ok = run("+200+1+100+50++\n64\n");  // 1 unit off: within the tolerance
    EXPECT_FALSE(ok.has(DiagCode::E303_ParabolaEndNotOnCurve)) << ok.dump();
    ASSERT_EQ(ok.motions().size(), 1u);
    EXPECT_POINT_NEAR(ok.motions()[0].end, 20.0, 0.1, kPosTol);  // ends exactly at the programmed point
}

TEST(GeomParabola, TcDisagreesW305) {
    auto r = run("+200+0+100+50-+\n64\n");  // turns ccw, TC says cw
    const Diagnostic* d = find_code(r.diags, DiagCode::W305_ParabolaDirection);
    ASSERT_NE(d, nullptr) << r.dump();
    EXPECT_EQ(d->severity, Severity::Warning);
    auto r2 = run("+0+200+50+100+-\n64\n");  // turns cw, TC says ccw
    EXPECT_TRUE(r2.has(DiagCode::W305_ParabolaDirection)) << r2.dump();
}

TEST(GeomParabola, ZeroCurvatureE304) {
    auto r = run("+200+0+100+0++\n64\n");
    EXPECT_TRUE(r.has(DiagCode::E304_ParabolaZeroCurvature)) << r.dump();
}

TEST(GeomParabola, MirrorFlipsSense) {
    // 22: machine y = -Y. y = 10 - (x-10)^2/10; TC + in the tape is consistent after mirroring
    RunResult r;
    MotionRecord m = one_motion("22\n+200+0+100+50++\n64\n", &r);
    EXPECT_FALSE(r.has(DiagCode::W305_ParabolaDirection)) << r.dump();
    EXPECT_FALSE(has_severity(r.diags, Severity::Error)) << r.dump();
    EXPECT_POINT_NEAR(m.end, 20.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.vertex, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.n, 0.0, -1.0, 1e-12);
    expect_box(bounding_box(m), 0, 0, 20, 10, "mirrored parabola");
}

TEST(GeomParabola, RotationMapsTheAxis) {
    // 28: machine = (-Y, X). Tape vertex (10,-10) -> (10,10); end (20,0) -> (0,20); axis +Y -> -X
    RunResult r;
    MotionRecord m = one_motion("28\n+200+0+100+50++\n64\n", &r);
    EXPECT_FALSE(r.has(DiagCode::W305_ParabolaDirection)) << r.dump();
    EXPECT_POINT_NEAR(m.end, 0.0, 20.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.vertex, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(m.parabola.n, -1.0, 0.0, 1e-12);
    EXPECT_NEAR(m.length_mm, 2 * parabola_F(10, 5), kLenTol);
    expect_box(bounding_box(m), 0, 0, 10, 20, "rotated parabola");
}

// ---------------------------------------------------------------- flattening

TEST(GeomFlatten, ArcWithinChordTolerance) {
    MotionRecord m = make_arc({10, 0}, {0, 10}, {0, 0}, kPi / 2);
    for (double tol : {0.5, 0.01, 0.001}) {
        std::vector<Point> pts;
        flatten(m, tol, pts);
        ASSERT_GE(pts.size(), 2u) << tol;
        EXPECT_EQ(pts.front(), m.start) << tol;
        EXPECT_EQ(pts.back(), m.end) << tol;
        double prev_angle = -1;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            EXPECT_NEAR(std::hypot(pts[i].x, pts[i].y), 10.0, kOnCurveTol) << tol << " point " << i;
            const double a = std::atan2(pts[i].y, pts[i].x);
            EXPECT_GT(a, prev_angle - 1e-12) << "points go ccw";
            prev_angle = a;
            if (i > 0) {
                const double chord = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
                const double sagitta = 10.0 - std::sqrt(100.0 - chord * chord / 4);
                EXPECT_LE(sagitta, tol + kChordSlack) << tol << " segment " << i;
            }
        }
        // the sagitta for tolerance 0.01 on r=10 allows chords of 2*sqrt(20*0.01 - 0.0001) ~ 0.894 mm:
        // the quarter (15.7 mm) needs at least 18 segments
        if (tol == 0.01) {
            EXPECT_GE(pts.size(), 19u);
        }
    }
}

TEST(GeomFlatten, IncludeStartFlag) {
    MotionRecord m = make_line({1, 2}, {4, 6});
    std::vector<Point> pts{{-7, -7}};
    flatten(m, 0.01, pts, false);
    ASSERT_GE(pts.size(), 2u);
    EXPECT_EQ(pts.front(), (Point{-7, -7}));  // appends, keeps what was there
    EXPECT_EQ(pts.back(), m.end);
    EXPECT_NE(pts[1], m.start);
    std::vector<Point> with;
    flatten(m, 0.01, with, true);
    ASSERT_EQ(with.size(), 2u);  // a line needs no intermediate points
    EXPECT_EQ(with[0], m.start);
    EXPECT_EQ(with[1], m.end);
}

TEST(GeomFlatten, FullCircleClosesExactly) {
    MotionRecord m = one_motion("+0+0+100+0-\n64\n");
    std::vector<Point> pts;
    flatten(m, 0.01, pts);
    ASSERT_GE(pts.size(), 4u);
    EXPECT_EQ(pts.front(), m.start);
    EXPECT_EQ(pts.back(), m.end);
    for (const auto& p : pts) EXPECT_NEAR(std::hypot(p.x - 10, p.y), 10.0, kOnCurveTol);
    // cw from angle pi: the second point is above the x axis
    EXPECT_GT(pts[1].y, 0.0);
}

TEST(GeomFlatten, SegmentCap) {
    MotionRecord m = make_arc({1000, 0}, {1000, 0}, {0, 0}, 2 * kPi);
    std::vector<Point> pts;
    flatten(m, 0.0, pts);  // below kMinChordTolerance
    EXPECT_LE(pts.size(), static_cast<std::size_t>(kMaxFlattenSegments) + 1);
    EXPECT_EQ(pts.back(), m.end);
}

TEST(GeomFlatten, ParabolaWithinChordTolerance) {
    MotionRecord m = one_motion("+300+300+100+50++\n64\n");  // y = -10 + (x-10)^2/10, x in [0,30]
    const double tol = 0.01;
    std::vector<Point> pts;
    flatten(m, tol, pts);
    ASSERT_GE(pts.size(), 3u);
    EXPECT_EQ(pts.front(), m.start);
    EXPECT_EQ(pts.back(), m.end);
    for (const auto& p : pts) EXPECT_NEAR(p.y, -10 + (p.x - 10) * (p.x - 10) / 10, 1e-9);
    // every point of the exact curve is within the tolerance of the polyline
    double worst = 0;
    for (int i = 0; i <= 3000; ++i) {
        const double x = 30.0 * i / 3000;
        worst = std::max(worst, dist_point_polyline({x, -10 + (x - 10) * (x - 10) / 10}, pts));
    }
    EXPECT_LE(worst, tol + 1e-9);
}

// ---------------------------------------------------------------- point_at

TEST(GeomPointAt, LineArcParabola) {
    MotionRecord l = make_line({0, 0}, {10, 20});
    EXPECT_POINT_NEAR(point_at(l, 0.0), 0.0, 0.0, 1e-12);
    EXPECT_POINT_NEAR(point_at(l, 0.25), 2.5, 5.0, 1e-12);
    EXPECT_POINT_NEAR(point_at(l, 1.0), 10.0, 20.0, 1e-12);
    MotionRecord a = make_arc({10, 0}, {0, 10}, {0, 0}, kPi / 2);
    const double h = 10 / std::sqrt(2.0);
    EXPECT_POINT_NEAR(point_at(a, 0.5), h, h, 1e-9);
    EXPECT_POINT_NEAR(point_at(a, 1.0), 0.0, 10.0, 1e-9);
    MotionRecord p = make_parabola_u();
    EXPECT_POINT_NEAR(point_at(p, 0.5), 10.0, -10.0, 1e-9);
    EXPECT_POINT_NEAR(point_at(p, 0.0), 0.0, 0.0, 1e-9);
    EXPECT_POINT_NEAR(point_at(p, 1.0), 20.0, 0.0, 1e-9);
}

TEST(Parabola, FromWords) {
    // Axis parallel to Y (TP +), XP = 10 from the start, YP = 5: y = (x - 10)^2 / 10 - 10 through (0,0) and (20,0).
    const essi::ParabolaPiece y_axis = essi::parabola_from_words({0, 0}, {20, 0}, 10, 5, true, false);
    EXPECT_DOUBLE_EQ(y_axis.curve.vertex.x, 10);
    EXPECT_DOUBLE_EQ(y_axis.curve.vertex.y, -10);
    EXPECT_DOUBLE_EQ(y_axis.curve.t0, -10);
    EXPECT_DOUBLE_EQ(y_axis.curve.t1, 10);
    EXPECT_DOUBLE_EQ(y_axis.curve.p, 5);
    EXPECT_DOUBLE_EQ(y_axis.residual, 0);
    EXPECT_TRUE(essi::parabola_turns_ccw(y_axis.curve));  // opening up, travelled left to right
    // The same words in absolute mode count XP from the origin, and an end 3 units off the curve.
    const essi::ParabolaPiece absolute = essi::parabola_from_words({4, 0}, {16, 3}, 10, 5, true, true);
    EXPECT_DOUBLE_EQ(absolute.curve.vertex.x, 10);
    EXPECT_DOUBLE_EQ(absolute.curve.vertex.y, -3.6);
    EXPECT_DOUBLE_EQ(absolute.residual, 3);
    // Axis parallel to X (TP -), XP = -5 opens towards -x: from (0,0) out to the vertex (10,-10) and back to
    // (0,-20) it turns clockwise.
    const essi::ParabolaPiece x_axis = essi::parabola_from_words({0, 0}, {0, -20}, -5, -10, false, false);
    EXPECT_DOUBLE_EQ(x_axis.curve.vertex.x, 10);
    EXPECT_DOUBLE_EQ(x_axis.curve.vertex.y, -10);
    EXPECT_DOUBLE_EQ(x_axis.curve.n.x, -1);
    EXPECT_DOUBLE_EQ(x_axis.residual, 0);
    EXPECT_FALSE(essi::parabola_turns_ccw(x_axis.curve));
}
