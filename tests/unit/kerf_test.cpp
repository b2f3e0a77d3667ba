// KerfPath (core/geom/kerf.cpp): the compensated path of small contours, against the points LinuxCNC's rs274
// gives for the same contours as G-code with G41.1 D2 (a kerf offset of 1 mm to the left). The full comparison
// over every example runs in tests/convert/rs274_kerf.py; these keep each rule (entry, convex join, concave trim,
// tangent, arc entry, exit, gouge) in the unit suite of both builds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "essi/geom.hpp"
#include "essi/kerf.hpp"

namespace essi {
namespace {

struct Collect : MotionSink {
    std::vector<MotionRecord> motions;
    std::vector<MachineEvent> events;
    std::vector<std::size_t> events_after;  // how many motions came before each event
    void on_motion(const MotionRecord& m) override { motions.push_back(m); }
    void on_event(const MachineEvent& e) override {
        events.push_back(e);
        events_after.push_back(motions.size());
    }
};

// The programmed stream of a contour: lines and arcs from one point to the next, kerf `side` of `kerf_mm`.
class Contour {
public:
    explicit Contour(Point start, KerfSide side = KerfSide::Left, double kerf_mm = 1)
        : at_(start), side_(side), kerf_(kerf_mm) {}
    Contour& line(double x, double y) {
        MotionRecord m = base({x, y});
        m.curve = CurveKind::Line;
        m.length_mm = std::hypot(x - m.start.x, y - m.start.y);
        return push(m);
    }
    Contour& arc(double x, double y, double cx, double cy, bool ccw) {
        MotionRecord m = base({x, y});
        m.curve = CurveKind::Arc;
        m.centre = {cx, cy};
        m.ccw = ccw;
        m.radius = std::hypot(m.start.x - cx, m.start.y - cy);
        m.end_radius = std::hypot(x - cx, y - cy);
        m.sweep = arc_sweep(m.start, m.end, m.centre, ccw, false);
        m.length_mm = std::abs(m.sweep) * m.radius;
        return push(m);
    }
    Contour& kerf(KerfSide side) {
        side_ = side;
        return *this;
    }
    std::vector<MotionRecord> records;

private:
    MotionRecord base(Point end) {
        MotionRecord m;
        m.line = static_cast<std::uint32_t>(records.size() + 1);
        m.block = m.line - 1;
        m.kind = MotionKind::Cut;
        m.start = at_;
        m.end = end;
        m.kerf = side_;
        m.kerf_mm = side_ == KerfSide::Off ? 0 : kerf_;
        m.feed_mm_min = 1000;
        return m;
    }
    Contour& push(const MotionRecord& m) {
        records.push_back(m);
        at_ = m.end;
        return *this;
    }
    Point at_;
    KerfSide side_;
    double kerf_;
};

Collect compensate(const std::vector<MotionRecord>& records, std::vector<KerfGouge>* gouges = nullptr) {
    Collect out;
    KerfPath path(out, 0.01);
    for (const auto& m : records) path.motion(m);
    path.finish();
    if (gouges) *gouges = path.take_gouges();
    return out;
}

void expect_end(const MotionRecord& m, double x, double y, CurveKind curve) {
    EXPECT_NEAR(m.end.x, x, 1e-4) << "line " << m.line;
    EXPECT_NEAR(m.end.y, y, 1e-4) << "line " << m.line;
    EXPECT_EQ(m.curve, curve) << "line " << m.line;
}

// G0 X0 Y-10 / G41.1 D2 / G1 X0 Y0 / X10 Y0 / X10 Y10 / G3 X0 Y10 I-5 J0 / G1 X0 Y0 / G40 / G1 X0 Y-10
TEST(KerfPath, SquareWithArcAsLinuxCncCutsIt) {
    Contour c({0, -10});
    c.line(0, 0).line(10, 0).line(10, 10).arc(0, 10, 5, 10, true).line(0, 0).kerf(KerfSide::Off).line(0, -10);
    const Collect out = compensate(c.records);
    ASSERT_EQ(out.motions.size(), 7u);
    expect_end(out.motions[0], -1, 0, CurveKind::Line);  // entry: the end shifted along the entry's normal
    expect_end(out.motions[1], 0, 1, CurveKind::Arc);    // convex corner: joined around (0,0)
    EXPECT_FALSE(out.motions[1].ccw);
    EXPECT_NEAR(out.motions[1].radius, 1, 1e-12);
    EXPECT_EQ(out.motions[1].line, 2u);                  // the join belongs to the motion after the corner
    expect_end(out.motions[2], 9, 1, CurveKind::Line);   // concave corner at (10,0): trimmed
    expect_end(out.motions[3], 9, 10, CurveKind::Line);  // tangent into the arc
    expect_end(out.motions[4], 1, 10, CurveKind::Arc);   // the arc's radius shrinks by the offset
    EXPECT_NEAR(out.motions[4].radius, 4, 1e-12);
    EXPECT_NEAR(out.motions[4].length_mm, 4 * kPi, 1e-9);
    expect_end(out.motions[5], 1, 0, CurveKind::Line);    // the last compensated piece: its end shifted
    expect_end(out.motions[6], 0, -10, CurveKind::Line);  // exit: to the programmed end
}

// G0 X3 Y-10 / G41.1 D2 / G1 X0 Y0 / X10 Y0 / X10 Y10 / G40 / G1 X13 Y20: a slanted entry
TEST(KerfPath, SlantedEntryEndsOnItsOwnNormal) {
    Contour c({3, -10});
    c.line(0, 0).line(10, 0).line(10, 10).kerf(KerfSide::Off).line(13, 20);
    const Collect out = compensate(c.records);
    ASSERT_EQ(out.motions.size(), 5u);
    expect_end(out.motions[0], -0.9578, -0.2873, CurveKind::Line);
    expect_end(out.motions[1], 0, 1, CurveKind::Arc);
    expect_end(out.motions[2], 9, 1, CurveKind::Line);
    expect_end(out.motions[3], 9, 10, CurveKind::Line);
    expect_end(out.motions[4], 13, 20, CurveKind::Line);
}

// G3 X0 Y0 I0 J5 as the entry (centre moved to (0,-5.5)), and a cw arc that grows, then G40.
TEST(KerfPath, ArcEntryMovesItsCentreAlongTheEndRadius) {
    Contour c({0, -10});
    c.arc(0, 0, 0, -5, true).line(10, 0).line(10, 10).arc(20, 10, 15, 10, false).kerf(KerfSide::Off).line(25, 20);
    const Collect out = compensate(c.records);
    ASSERT_EQ(out.motions.size(), 6u);
    expect_end(out.motions[0], 0, -1, CurveKind::Arc);
    EXPECT_NEAR(out.motions[0].centre.x, 0, 1e-12);
    EXPECT_NEAR(out.motions[0].centre.y, -5.5, 1e-12);
    EXPECT_TRUE(out.motions[0].ccw);
    expect_end(out.motions[1], 0, 1, CurveKind::Arc);
    expect_end(out.motions[2], 9, 1, CurveKind::Line);
    expect_end(out.motions[3], 9, 10, CurveKind::Line);
    expect_end(out.motions[4], 21, 10, CurveKind::Arc);
    EXPECT_NEAR(out.motions[4].radius, 6, 1e-12);
    expect_end(out.motions[5], 25, 20, CurveKind::Line);
}

// A bump one offset high: a piece trimmed to nothing (rs274 keeps it, of length 0), convex joins around it.
TEST(KerfPath, PieceTrimmedToNothingStays) {
    Contour c({0, -10});
    c.line(0, 0).line(10, 0).line(10, 1).line(11, 1).line(11, 0).line(20, 0).kerf(KerfSide::Off).line(25, -10);
    const Collect out = compensate(c.records);
    const std::vector<std::pair<double, double>> want = {{-1, 0}, {0, 1},  {9, 1},  {9, 1},  {10, 2},
                                                         {11, 2}, {12, 1}, {12, 1}, {20, 1}, {25, -10}};
    ASSERT_EQ(out.motions.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_NEAR(out.motions[i].end.x, want[i].first, 1e-9);
        EXPECT_NEAR(out.motions[i].end.y, want[i].second, 1e-9);
    }
    EXPECT_NEAR(out.motions[3].length_mm, 0, 1e-12);
}

// A line into a small cw arc: the concave corner is a line-circle intersection (rs274: 9.2679, 1).
TEST(KerfPath, LineIntoArcTrimsAtTheirIntersection) {
    Contour c({0, -10});
    c.line(0, 0).line(10, 0).arc(12, 0, 11, 0, false).line(20, 0).kerf(KerfSide::Off).line(25, -10);
    const Collect out = compensate(c.records);
    ASSERT_EQ(out.motions.size(), 6u);
    expect_end(out.motions[2], 9.2679, 1, CurveKind::Line);
    expect_end(out.motions[3], 12.7321, 1, CurveKind::Arc);
    EXPECT_NEAR(out.motions[3].centre.x, 11, 1e-12);
    expect_end(out.motions[4], 20, 1, CurveKind::Line);
}

// A slot narrower than the kerf: the piece of X9.5 Y5 runs backwards from the trim, and rs274 stops with
// "Straight feed in concave corner cannot be reached by the tool without gouging" at the convex corner after it,
// converting X9.5 Y10; the compensated path names that motion and goes on.
TEST(KerfPath, NarrowSlotIsAGougeNamingItsMotion) {
    Contour c({0, -10});
    c.line(0, 0).line(10, 0).line(10, 5).line(9.5, 5).line(9.5, 10).kerf(KerfSide::Off).line(25, -10);
    std::vector<KerfGouge> gouges;
    const Collect out = compensate(c.records, &gouges);
    ASSERT_EQ(gouges.size(), 1u);
    EXPECT_EQ(gouges[0].line, 5u);
    const std::string why = essi::format_message(gouges[0].msg, essi::Lang::En, gouges[0].args);
    EXPECT_NE(why.find("gouge"), std::string::npos) << why;
    EXPECT_EQ(out.motions.back().end, (Point{25, -10}));
}

// Two 100 mm lines turning 178° to the left, kerf left 5 mm (29+100): within 0.05 rad of a full reversal rs274
// joins them round the tip as at a convex corner (G41 D1 of 10 mm: the arc to (99.8255, -4.9970) about
// (100, 0), clockwise), and takes the program: the join crosses the contour, and nothing is a gouge.
TEST(KerfPath, LineIntoLineNearlyReversedIsJoinedAsLinuxCncDoes) {
    const double a = 178 * kPi / 180;
    Contour c({0, 0}, KerfSide::Left, 5);
    c.line(100, 0).line(100 + 100 * std::cos(a), 100 * std::sin(a));
    std::vector<KerfGouge> gouges;
    const Collect out = compensate(c.records, &gouges);
    EXPECT_TRUE(gouges.empty());
    ASSERT_EQ(out.motions.size(), 3u);
    expect_end(out.motions[0], 100, 5, CurveKind::Line);
    expect_end(out.motions[1], 99.825503, -4.996954, CurveKind::Arc);
    EXPECT_FALSE(out.motions[1].ccw);
    EXPECT_NEAR(out.motions[1].centre.x, 100, 1e-12);
    EXPECT_NEAR(out.motions[1].centre.y, 0, 1e-12);
    EXPECT_NEAR(out.motions[1].sweep, -182 * kPi / 180, 1e-9);
    expect_end(out.motions[2], -0.113580, -1.507004, CurveKind::Line);
}

// The same at 175°: the corner is concave, the entry is trimmed 114.5 mm back (rs274: to (-14.5188, 5); an
// entry never runs backwards for it) and the second line then runs backwards from there. rs274 refuses the
// program where that line ends, at G40: the gouge names the motion after the compensation.
TEST(KerfPath, PieceRunningBackwardsIsAGougeWhereItEnds) {
    const double a = 175 * kPi / 180;
    Contour c({0, 0}, KerfSide::Left, 5);
    c.line(100, 0).line(100 + 100 * std::cos(a), 100 * std::sin(a)).kerf(KerfSide::Off).line(0, 0);
    std::vector<KerfGouge> gouges;
    const Collect out = compensate(c.records, &gouges);
    ASSERT_EQ(gouges.size(), 1u);
    EXPECT_EQ(gouges[0].line, 3u);
    ASSERT_EQ(out.motions.size(), 3u);
    expect_end(out.motions[0], -14.518768, 5, CurveKind::Line);
}

// A line into an arc whose start turns 178.5° to the left, kerf left 1 mm, outside the clockwise arc
// (29/7/+1000+0/-487+513+13+500-/8/38/64): rs274 trims both at (87.0970, 1), the intersection behind the
// arc's centre along the line, and does not join them round the corner.
TEST(KerfPath, LineIntoArcNearlyReversedIsTrimmedWhenTheTorchIsOutside) {
    Contour c({0, 0});
    c.line(100, 0).arc(51.3, 51.3, 101.3, 50, false);
    std::vector<KerfGouge> gouges;
    const Collect out = compensate(c.records, &gouges);
    EXPECT_TRUE(gouges.empty());
    ASSERT_EQ(out.motions.size(), 2u);
    expect_end(out.motions[0], 87.097050, 1, CurveKind::Line);
    expect_end(out.motions[1], 50.300338, 51.325991, CurveKind::Arc);
    EXPECT_NEAR(out.motions[1].centre.x, 101.3, 1e-12);
    EXPECT_NEAR(out.motions[1].centre.y, 50, 1e-12);
    EXPECT_FALSE(out.motions[1].ccw);
}

// G3 X0 Y0 I0 J5 as the entry (centre moved to (0,-5.5), radius 4.5), then a line turning 45° to the left: the
// concave corner trims the entry on its own circle, which keeps its centre (rs274: ARC_FEED to (0.3967, -1.0175)
// about (0, -5.5), STRAIGHT_FEED to (-9.2929, -10.7071)), not on the programmed arc's offset.
TEST(KerfPath, EntryArcIsTrimmedOnItsOwnCircle) {
    Contour c({0, -10});
    c.arc(0, 0, 0, -5, true).line(-10, -10);
    std::vector<KerfGouge> gouges;
    const Collect out = compensate(c.records, &gouges);
    EXPECT_TRUE(gouges.empty());
    ASSERT_EQ(out.motions.size(), 2u);
    expect_end(out.motions[0], 0.396694, -1.017519, CurveKind::Arc);
    EXPECT_NEAR(out.motions[0].centre.x, 0, 1e-12);
    EXPECT_NEAR(out.motions[0].centre.y, -5.5, 1e-12);
    EXPECT_NEAR(out.motions[0].radius, 4.5, 1e-12);
    EXPECT_TRUE(out.motions[0].ccw);
    expect_end(out.motions[1], -9.292893, -10.707107, CurveKind::Line);
}

// Right of the direction of travel mirrors left: a square run the other way round with kerf right gives the
// mirror image of the left square.
TEST(KerfPath, RightIsTheMirrorOfLeft) {
    Contour left({0, -10}), right({0, -10}, KerfSide::Right);
    left.line(0, 0).line(10, 0).line(10, 10).kerf(KerfSide::Off).line(10, 20);
    right.line(0, 0).line(-10, 0).line(-10, 10).kerf(KerfSide::Off).line(-10, 20);
    const Collect a = compensate(left.records), b = compensate(right.records);
    ASSERT_EQ(a.motions.size(), b.motions.size());
    for (std::size_t i = 0; i < a.motions.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_NEAR(a.motions[i].end.x, -b.motions[i].end.x, 1e-12);
        EXPECT_NEAR(a.motions[i].end.y, b.motions[i].end.y, 1e-12);
        EXPECT_EQ(a.motions[i].curve, b.motions[i].curve);
    }
}

// Events that come while a piece is open follow it: the pierce after the entry is passed on after the entry.
TEST(KerfPath, EventsFollowTheOpenPiece) {
    Collect out;
    KerfPath path(out, 0.01);
    Contour c({0, -10});
    c.line(0, 0).line(10, 0);
    path.motion(c.records[0]);
    MachineEvent e;
    e.code = 7;
    path.event(e);
    EXPECT_TRUE(out.motions.empty());
    path.motion(c.records[1]);
    path.finish();
    ASSERT_EQ(out.events.size(), 1u);
    EXPECT_EQ(out.events_after[0], 1u);  // after the entry, before the join arc
    EXPECT_EQ(out.motions.size(), 3u);
}

// Motions without compensation pass unchanged (the same record, bit for bit).
TEST(KerfPath, WithoutCompensationNothingChanges) {
    Contour c({1, 2}, KerfSide::Off);
    c.line(5, 2).arc(9, 2, 7, 2, true).line(9, 9);
    const Collect out = compensate(c.records);
    ASSERT_EQ(out.motions.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(out.motions[i].start, c.records[i].start);
        EXPECT_EQ(out.motions[i].end, c.records[i].end);
        EXPECT_EQ(out.motions[i].length_mm, c.records[i].length_mm);
    }
}

// A square run clockwise with the kerf to the left (outside): once round, the compensated path is the square's
// length plus the four quarter circles of the offset.
TEST(KerfPath, OutsideOfASquareAddsACircle) {
    Contour c({0, -5});
    c.line(0, 0).line(0, 10).line(10, 10).line(10, 0).line(0, 0).line(0, 10).kerf(KerfSide::Off).line(-5, 10);
    const Collect out = compensate(c.records);
    // from the first corner around the square once: pieces 1 .. 8 (4 sides, 4 joins) after the entry
    double around = 0;
    for (std::size_t i = 2; i < 10 && i < out.motions.size(); ++i) around += out.motions[i].length_mm;
    EXPECT_NEAR(around, 40 + 2 * kPi * 1, 1e-9);
}

}  // namespace
}  // namespace essi
