// Phase 2 (interp): the effect of every machine function on the emitted motion stream
// (docs/semantics.md §3-§10, §12). Expectations are worked out by hand; the unit is 0.1 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "essi/interp.hpp"
#include "test_util.hpp"

using namespace essi;
using namespace essi_test;

// ---------------------------------------------------------------- tools and motion kinds

TEST(InterpTools, TravelWhenNoTool) {
    auto r = run("+300+400\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    const auto& m = r.motions()[0];
    EXPECT_EQ(m.kind, MotionKind::Travel);
    EXPECT_EQ(m.curve, CurveKind::Line);
    EXPECT_EQ(m.tools, 0);
    EXPECT_POINT_NEAR(m.start, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(m.end, 30.0, 40.0, kPosTol);
    EXPECT_NEAR(m.length_mm, 50.0, kLenTol);
    EXPECT_NEAR(m.feed_mm_min, 1000.0, kTimeTol);
    EXPECT_EQ(m.head, 1);
    EXPECT_EQ(m.kerf, KerfSide::Off);
    EXPECT_TRUE(r.diags.empty()) << r.dump();
}

TEST(InterpTools, CuttingTools) {
    struct Case {
        int on, off;
        std::uint8_t bit;
    };
    const Case cases[] = {
        {7, 8, kToolOxygen}, {13, 14, kToolLeftBevel}, {15, 16, kToolRightBevel}, {53, 54, kToolPlasma}};
    for (const auto& c : cases) {
        const std::string src = std::to_string(c.on) + "\n+100+0\n" + std::to_string(c.off) + "\n+0+100\n64\n";
        auto r = run(src);
        ASSERT_EQ(r.motions().size(), 2u) << src << r.dump();
        EXPECT_EQ(r.motions()[0].kind, MotionKind::Cut) << c.on;
        EXPECT_EQ(r.motions()[0].tools, c.bit) << c.on;
        EXPECT_EQ(r.motions()[1].kind, MotionKind::Travel) << c.on;
        EXPECT_EQ(r.motions()[1].tools, 0) << c.on;
        const MachineEvent* on = r.sink.event_with_code(EventKind::Function, c.on);
        ASSERT_NE(on, nullptr) << c.on;
        EXPECT_EQ(on->tools_after, c.bit);
        const MachineEvent* off = r.sink.event_with_code(EventKind::Function, c.off);
        ASSERT_NE(off, nullptr) << c.off;
        EXPECT_EQ(off->tools_after, 0);
        EXPECT_TRUE(r.diags.empty()) << src << r.dump();
    }
}

TEST(InterpTools, MarkingTools) {
    struct Case {
        int on, off;
        std::uint8_t bit;
    };
    const Case cases[] = {{9, 10, kToolPunch}, {110, 111, kToolLineMarker}, {112, 113, kToolFive}};
    for (const auto& c : cases) {
        const std::string src = std::to_string(c.on) + "\n+100+0\n" + std::to_string(c.off) + "\n+0+100\n64\n";
        auto r = run(src);
        ASSERT_EQ(r.motions().size(), 2u) << src << r.dump();
        EXPECT_EQ(r.motions()[0].kind, MotionKind::Mark) << c.on;
        EXPECT_EQ(r.motions()[0].tools, c.bit) << c.on;
        EXPECT_EQ(r.motions()[1].kind, MotionKind::Travel) << c.on;
        EXPECT_TRUE(r.diags.empty()) << src << r.dump();
    }
}

TEST(InterpTools, CutWinsOverMark) {
    auto r = run("9\n7\n+100+0\n8\n+100+0\n10\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_EQ(r.motions()[0].kind, MotionKind::Cut);
    EXPECT_EQ(r.motions()[0].tools, kToolPunch | kToolOxygen);
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Mark);
    EXPECT_EQ(r.motions()[1].tools, kToolPunch);
}

TEST(InterpTools, SeveralCuttingTools) {
    auto r = run("7\n13\n15\n+100+0\n8\n14\n+100+0\n16\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_EQ(r.motions()[0].tools, kToolOxygen | kToolLeftBevel | kToolRightBevel);
    EXPECT_EQ(r.motions()[1].tools, kToolRightBevel);
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Cut);
}

TEST(InterpTools, RapidTraverse) {
    auto r = run("5\n+100+0\n+100+0\n6\n+100+0\n64\n");
    ASSERT_EQ(r.motions().size(), 3u) << r.dump();
    EXPECT_EQ(r.motions()[0].kind, MotionKind::Rapid);
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Rapid);
    EXPECT_EQ(r.motions()[2].kind, MotionKind::Travel);
    EXPECT_NEAR(r.motions()[0].feed_mm_min, 10000.0, kTimeTol);
    EXPECT_NEAR(r.motions()[2].feed_mm_min, 1000.0, kTimeTol);
    EXPECT_POINT_NEAR(r.motions()[2].end, 30.0, 0.0, kPosTol);
}

TEST(InterpTools, RapidSingleBlockSetting) {
    Profile p;
    p.rapid_single_block = true;
    auto r = run("5\n+100+0\n+100+0\n64\n", p);
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_EQ(r.motions()[0].kind, MotionKind::Rapid);
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Travel);
}

TEST(InterpTools, RapidWhileCuttingW210) {
    auto r = run("7\n5\n+100+0\n6\n8\n64\n");
    EXPECT_TRUE(r.has(DiagCode::W210_RapidWhileCutting)) << r.dump();
}

TEST(InterpTools, ToolOnAtEndW211) {
    auto r = run("7\n+100+0\n64\n");
    EXPECT_TRUE(r.has(DiagCode::W211_ToolOnAtEnd)) << r.dump();
    auto ok = run("7\n+100+0\n8\n64\n");
    EXPECT_FALSE(ok.has(DiagCode::W211_ToolOnAtEnd)) << ok.dump();
}

TEST(InterpTools, LineAndBlockOfMotion) {
    auto r = run("7\n\n+100+0\r\n8\n64\n");
    ASSERT_EQ(r.motions().size(), 1u);
    EXPECT_EQ(r.motions()[0].line, 3u);
    EXPECT_EQ(r.motions()[0].block, 1u);
    const MachineEvent* e = r.sink.event_with_code(EventKind::Function, 8);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->line, 4u);
    EXPECT_EQ(e->block, 2u);
}

TEST(InterpTools, EventsAndMotionsInProgramOrder) {
    auto r = run("7\n+100+0\n8\n64\n");
    // events: 7, 8, End; motion between 7 and 8
    ASSERT_GE(r.sink.order.size(), 3u);
    EXPECT_EQ(r.sink.order.substr(0, 3), "eme");
}

// ---------------------------------------------------------------- 81 / 82 / 83

TEST(InterpModes, IncrementalIsDefault) {
    auto r = run("+100+100\n+200+100\n-50+0\n64\n");
    ASSERT_EQ(r.motions().size(), 3u);
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].start, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].end, 30.0, 20.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[2].end, 25.0, 20.0, kPosTol);
}

TEST(InterpModes, AbsoluteThenIncremental) {
    auto r = run("82\n+100+100\n+200+100\n81\n+100+0\n64\n");
    ASSERT_EQ(r.motions().size(), 3u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].start, 10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].end, 20.0, 10.0, kPosTol);
    EXPECT_NEAR(r.motions()[1].length_mm, 10.0, kLenTol);
    EXPECT_POINT_NEAR(r.motions()[2].end, 30.0, 10.0, kPosTol);
}

TEST(InterpModes, AbsoluteArcCentre) {
    // move to (10,0); arc to absolute (30,0) around absolute (20,0), ccw: r = 10, half circle
    auto r = run("82\n+100+0\n+300+0+200+0+\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    const auto& a = r.motions()[1];
    EXPECT_EQ(a.curve, CurveKind::Arc);
    EXPECT_POINT_NEAR(a.start, 10.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(a.end, 30.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(a.centre, 20.0, 0.0, kPosTol);
    EXPECT_NEAR(a.radius, 10.0, kPosTol);
    EXPECT_TRUE(a.ccw);
    EXPECT_NEAR(a.sweep, kPi, kAngTol);
    EXPECT_NEAR(a.length_mm, 10.0 * kPi, kLenTol);
}

TEST(InterpModes, ZeroOffsetIsNotAMotion) {
    auto r = run("82\n83\n+1000+500\n+100+100\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].start, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[0].end, 110.0, 60.0, kPosTol);
    auto zo = r.sink.events_of(EventKind::ZeroOffset);
    ASSERT_EQ(zo.size(), 1u);
    EXPECT_NEAR(zo[0].x, 100.0, kPosTol);
    EXPECT_NEAR(zo[0].y, 50.0, kPosTol);
    EXPECT_FALSE(r.has(DiagCode::W215_ZeroOffsetInIncremental));
}

TEST(InterpModes, ZeroOffsetIsRelativeToCurrentOrigin) {
    auto r = run("82\n83\n+1000+0\n83\n+100+200\n+0+0\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].end, 110.0, 20.0, kPosTol);
    auto zo = r.sink.events_of(EventKind::ZeroOffset);
    ASSERT_EQ(zo.size(), 2u);
    EXPECT_NEAR(zo[0].x, 100.0, kPosTol);
    EXPECT_NEAR(zo[0].y, 0.0, kPosTol);
    EXPECT_NEAR(zo[1].x, 110.0, kPosTol);
    EXPECT_NEAR(zo[1].y, 20.0, kPosTol);
}

TEST(InterpModes, ZeroOffsetWordsAreMapped) {
    // 23: machine = (-X, -Y). origin = map(100, 50) = (-100,-50); target = origin + map(10,10) = (-110,-60)
    auto r = run("82\n23\n83\n+1000+500\n+100+100\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].end, -110.0, -60.0, kPosTol);
    auto zo = r.sink.events_of(EventKind::ZeroOffset);
    ASSERT_EQ(zo.size(), 1u);
    EXPECT_NEAR(zo[0].x, -100.0, kPosTol);
    EXPECT_NEAR(zo[0].y, -50.0, kPosTol);
}

TEST(InterpModes, ZeroOffsetWithRotation) {
    // 28: machine = (-Y, +X). origin = map(100, 50) = (-50, 100); target = origin + map(20, 0) = (-50, 120)
    auto r = run("82\n28\n83\n+1000+500\n+200+0\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].end, -50.0, 120.0, kPosTol);
}

TEST(InterpModes, IncrementalMovesIgnoreOrigin) {
    auto r = run("82\n83\n+1000+0\n81\n+100+0\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].start, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 0.0, kPosTol);
}

TEST(InterpModes, ZeroOffsetInIncrementalW215) {
    // 83 under 81: warning; incremental moves stay incremental; the next absolute target uses the origin
    auto r = run("83\n+1000+0\n+100+0\n82\n+0+0\n64\n");
    EXPECT_TRUE(r.has(DiagCode::W215_ZeroOffsetInIncremental)) << r.dump();
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].start, 10.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].end, 100.0, 0.0, kPosTol);
}

TEST(InterpModes, AbsoluteArcAfterZeroOffset) {
    // origin (100,0); to (210,0); arc to (230,0) around (220,0), ccw
    auto r = run("82\n83\n+1000+0\n+1100+0\n+1300+0+1200+0+\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    const auto& a = r.motions()[1];
    EXPECT_POINT_NEAR(a.start, 210.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(a.end, 230.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(a.centre, 220.0, 0.0, kPosTol);
    EXPECT_NEAR(a.radius, 10.0, kPosTol);
}

TEST(InterpModes, ZeroOffsetNeedsTwoWordBlockE207) {
    auto r = run("82\n83\n7\n8\n64\n");
    EXPECT_TRUE(r.has(DiagCode::E207_ZeroOffsetBlock)) << r.dump();
    auto r2 = run("82\n83\n+100+0+50+0+\n64\n");
    EXPECT_TRUE(r2.has(DiagCode::E207_ZeroOffsetBlock)) << r2.dump();
}

// ---------------------------------------------------------------- 21-28

TEST(InterpTransform, AxisMappingTable) {
    struct Case {
        int code;
        double x, y;  // machine for tape (10, 5)
        bool mirror;
    };
    const Case cases[] = {
        {21, 10, 5, false},  {22, 10, -5, true},  {23, -10, -5, false}, {24, -10, 5, true},
        {25, -5, -10, true}, {26, 5, -10, false}, {27, 5, 10, true},    {28, -5, 10, false},
    };
    for (const auto& c : cases) {
        AxisMapping m = axis_mapping(c.code);
        Point p = m.apply(10, 5);
        EXPECT_DOUBLE_EQ(p.x, c.x) << c.code;
        EXPECT_DOUBLE_EQ(p.y, c.y) << c.code;
        EXPECT_EQ(m.mirrors(), c.mirror) << c.code;
        Point back = m.invert(p.x, p.y);
        EXPECT_DOUBLE_EQ(back.x, 10) << c.code;
        EXPECT_DOUBLE_EQ(back.y, 5) << c.code;
    }
}

TEST(InterpTransform, Line) {
    struct Case {
        int code;
        double x, y;
    };
    const Case cases[] = {{21, 10, 5},   {22, 10, -5}, {23, -10, -5}, {24, -10, 5},
                          {25, -5, -10}, {26, 5, -10}, {27, 5, 10},   {28, -5, 10}};
    for (const auto& c : cases) {
        auto r = run(std::to_string(c.code) + "\n+100+50\n+100+50\n64\n");
        ASSERT_EQ(r.motions().size(), 2u) << c.code << r.dump();
        EXPECT_POINT_NEAR(r.motions()[0].end, c.x, c.y, kPosTol);
        EXPECT_POINT_NEAR(r.motions()[1].end, 2 * c.x, 2 * c.y, kPosTol);
        EXPECT_FALSE(r.has(DiagCode::W201_UnknownFunction)) << c.code;
    }
}

TEST(InterpTransform, AbsoluteLine) {
    auto r = run("82\n22\n+100+50\n+100+50\n64\n");
    ASSERT_EQ(r.motions().size(), 2u);
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, -5.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].end, 10.0, -5.0, kPosTol);
    EXPECT_NEAR(r.motions()[1].length_mm, 0.0, kLenTol);
}

TEST(InterpTransform, QuarterArc) {
    // tape arc: start (0,0), end (10,10), centre (0,10), TC + : quarter circle ccw, sweep +pi/2.
    struct Case {
        int code;
        double ex, ey, cx, cy;
        bool ccw;
    };
    const Case cases[] = {
        {21, 10, 10, 0, 10, true},   {22, 10, -10, 0, -10, false},  {23, -10, -10, 0, -10, true},
        {24, -10, 10, 0, 10, false}, {25, -10, -10, -10, 0, false}, {26, 10, -10, 10, 0, true},
        {27, 10, 10, 10, 0, false},  {28, -10, 10, -10, 0, true},
    };
    for (const auto& c : cases) {
        auto r = run(std::to_string(c.code) + "\n+100+100+0+100+\n64\n");
        ASSERT_EQ(r.motions().size(), 1u) << c.code << r.dump();
        const auto& a = r.motions()[0];
        EXPECT_EQ(a.curve, CurveKind::Arc) << c.code;
        EXPECT_POINT_NEAR(a.end, c.ex, c.ey, kPosTol);
        EXPECT_POINT_NEAR(a.centre, c.cx, c.cy, kPosTol);
        EXPECT_EQ(a.ccw, c.ccw) << c.code;
        EXPECT_NEAR(a.sweep, c.ccw ? kPi / 2 : -kPi / 2, kAngTol) << c.code;
        EXPECT_NEAR(a.radius, 10.0, kPosTol) << c.code;
        EXPECT_NEAR(a.length_mm, 5.0 * kPi, kLenTol) << c.code;
        EXPECT_FALSE(has_severity(r.diags, Severity::Error)) << c.code << r.dump();
    }
}

TEST(InterpTransform, MirrorThenNormal) {
    auto r = run("24\n+100+100+0+100+\n21\n+100+100+0+100+\n64\n");
    ASSERT_EQ(r.motions().size(), 2u);
    EXPECT_FALSE(r.motions()[0].ccw);
    EXPECT_TRUE(r.motions()[1].ccw);
    EXPECT_POINT_NEAR(r.motions()[1].start, -10.0, 10.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].end, 0.0, 20.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].centre, -10.0, 20.0, kPosTol);
}

// ---------------------------------------------------------------- kerf 29/30/38

TEST(InterpKerf, LeftWithValueIsWidth) {
    auto r = run("29+20\n7\n+100+0\n8\n38\n+100+0\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_EQ(r.motions()[0].kerf, KerfSide::Left);
    EXPECT_NEAR(r.motions()[0].kerf_mm, 1.0, kPosTol);  // 20 units = 2.0 mm width, half of it
    // the record is the programmed path, before the offset
    EXPECT_POINT_NEAR(r.motions()[0].start, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 0.0, kPosTol);
    EXPECT_EQ(r.motions()[1].kerf, KerfSide::Off);
    EXPECT_NEAR(r.motions()[1].kerf_mm, 0.0, kPosTol);
    EXPECT_FALSE(r.has(DiagCode::W204_KerfWhileCutting)) << r.dump();
    EXPECT_FALSE(r.has(DiagCode::W202_FunctionValueIgnored)) << r.dump();
}

TEST(InterpKerf, RightWithoutValueUsesProfile) {
    auto r = run("30\n7\n+100+0\n8\n38\n64\n");
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_EQ(r.motions()[0].kerf, KerfSide::Right);
    EXPECT_NEAR(r.motions()[0].kerf_mm, 1.0, kPosTol);  // kerf_units 20 -> 2.0 mm width
    Profile p;
    p.kerf_units = 35;
    auto r2 = run("30\n7\n+100+0\n8\n38\n64\n", p);
    ASSERT_EQ(r2.motions().size(), 1u);
    EXPECT_NEAR(r2.motions()[0].kerf_mm, 1.75, kPosTol);
}

TEST(InterpKerf, ValueMeaningOffset) {
    Profile p;
    p.kerf_value = KerfValueMeaning::Offset;
    auto r = run("30+20\n7\n+100+0\n8\n38\n64\n", p);
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_EQ(r.motions()[0].kerf, KerfSide::Right);
    EXPECT_NEAR(r.motions()[0].kerf_mm, 2.0, kPosTol);
}

TEST(InterpKerf, SwitchedWhileCuttingW204) {
    auto on = run("7\n29+20\n+100+0\n8\n38\n64\n");
    const Diagnostic* d = find_code(on.diags, DiagCode::W204_KerfWhileCutting);
    ASSERT_NE(d, nullptr) << on.dump();
    EXPECT_EQ(d->line, 2u);
    EXPECT_EQ(d->severity, Severity::Warning);
    auto off = run("29+20\n7\n+100+0\n38\n8\n64\n");
    const Diagnostic* d2 = find_code(off.diags, DiagCode::W204_KerfWhileCutting);
    ASSERT_NE(d2, nullptr) << off.dump();
    EXPECT_EQ(d2->line, 4u);
    auto clean = run("29+20\n7\n+100+0\n8\n38\n64\n");
    EXPECT_FALSE(clean.has(DiagCode::W204_KerfWhileCutting)) << clean.dump();
}

// ---------------------------------------------------------------- heads 19/20, 1/2, 31-36

TEST(InterpHeads, AddressesIn3AxisMode) {
    auto r = run("19\n2+100+0\n1+0+100\n20\n+100+0\n64\n");
    ASSERT_EQ(r.motions().size(), 3u) << r.dump();
    EXPECT_EQ(r.motions()[0].head, 2);
    EXPECT_EQ(r.motions()[1].head, 1);
    EXPECT_EQ(r.motions()[2].head, 1);
    EXPECT_FALSE(r.has(DiagCode::W205_AddressOutside3Axis)) << r.dump();
    EXPECT_FALSE(has_severity(r.diags, Severity::Error)) << r.dump();
}

TEST(InterpHeads, AddressOutside3AxisW205) {
    auto r = run("1+100+0\n64\n");
    const Diagnostic* d = find_code(r.diags, DiagCode::W205_AddressOutside3Axis);
    ASSERT_NE(d, nullptr) << r.dump();
    EXPECT_EQ(d->line, 1u);
    ASSERT_EQ(r.motions().size(), 1u);  // still parsed as an address and executed
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 0.0, kPosTol);
    auto r2 = run("19\n20\n2+100+0\n64\n");
    EXPECT_TRUE(r2.has(DiagCode::W205_AddressOutside3Axis)) << r2.dump();
}

TEST(InterpHeads, BadAddressE206) {
    auto r = run("19\n9+100+0\n64\n");
    const Diagnostic* d = find_code(r.diags, DiagCode::E206_BadHeadAddress);
    ASSERT_NE(d, nullptr) << r.dump();
    EXPECT_EQ(d->line, 2u);
}

TEST(InterpHeads, HeadSelectionEvents) {
    auto r = run("31\n32\n33\n34\n35\n36\n64\n");
    for (int code = 31; code <= 36; ++code)
        EXPECT_NE(r.sink.event_with_code(EventKind::Function, code), nullptr) << code;
    EXPECT_TRUE(r.motions().empty());
    EXPECT_TRUE(r.diags.empty()) << r.dump();
}

// ---------------------------------------------------------------- 100/101, stops, ends

TEST(InterpOptional, IgnoreOffByDefault) {
    auto r = run("100\n+100+0\n101\n+0+100\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[1].end, 10.0, 10.0, kPosTol);
}

TEST(InterpOptional, IgnoreOnSkipsBlocks) {
    Profile p;
    p.optional_ignore = true;
    auto r = run("100\n+100+0\n7\n101\n+0+100\n64\n", p);
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].start, 0.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[0].end, 0.0, 10.0, kPosTol);
    EXPECT_EQ(r.motions()[0].kind, MotionKind::Travel);  // the 7 was skipped as well
}

TEST(InterpOptional, UnclosedW214) {
    Profile p;
    p.optional_ignore = true;
    auto r = run("100\n+100+0\n64\n", p);
    EXPECT_TRUE(r.has(DiagCode::W214_UnclosedOptionalIgnore)) << r.dump();
}

TEST(InterpStops, ProgrammedAndOptionalStop) {
    auto r = run("0\n+100+0\n102\n64\n");
    auto stops = r.sink.events_of(EventKind::Stop);
    ASSERT_EQ(stops.size(), 2u) << r.dump();
    EXPECT_EQ(stops[0].code, 0);
    EXPECT_EQ(stops[0].line, 1u);
    EXPECT_EQ(stops[1].code, 102);
    EXPECT_EQ(stops[1].line, 3u);
    ASSERT_EQ(r.motions().size(), 1u);  // 0 is a stop, not an end, in the default profile
    EXPECT_TRUE(r.diags.empty()) << r.dump();
}

TEST(InterpStops, EndCodes) {
    const Profile woyda = *builtin_profile("woyda");
    for (const char* end : {"63", "64"}) {
        auto r = run(std::string("+100+0\n") + end + "\n", woyda);
        auto ends = r.sink.events_of(EventKind::End);
        ASSERT_EQ(ends.size(), 1u) << end;
        EXPECT_EQ(ends[0].code, std::stoi(end));
        EXPECT_EQ(ends[0].line, 2u);
    }
    auto s = run("+100+0\n/\n", woyda);
    auto ends = s.sink.events_of(EventKind::End);
    ASSERT_EQ(ends.size(), 1u) << s.dump();
    EXPECT_EQ(ends[0].line, 2u);
    EXPECT_TRUE(s.diags.empty()) << s.dump();
}

// ISO 6582 Annex B: 63 cancels the stored functions and the program goes on; the tape ends at 64 or at the end
// of its data, without a warning (docs/semantics.md §1).
TEST(InterpStops, Iso63CancelsAndTheProgramGoesOn) {
    auto r = run("29\n7\n5\n+100+0\n63\n+100+0\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_EQ(r.motions()[1].tools, 0);  // 63 switched the oxygen off
    EXPECT_EQ(r.motions()[1].kerf, KerfSide::Off);
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Travel);  // and rapid traverse
    EXPECT_TRUE(r.sink.events_of(EventKind::End).empty()) << r.dump();
    ASSERT_NE(r.sink.event_with_code(EventKind::Function, 63), nullptr);
    EXPECT_FALSE(r.has(DiagCode::W114_NoProgramEnd)) << r.dump();
    EXPECT_FALSE(r.has(DiagCode::W110_ContentAfterEnd)) << r.dump();
}

TEST(InterpStops, NothingExecutedAfterEnd) {
    const Profile woyda = *builtin_profile("woyda");
    auto r = run("+100+0\n63\n+100+0\n7\n", woyda);
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_EQ(r.sink.event_with_code(EventKind::Function, 7), nullptr);
    EXPECT_TRUE(r.has(DiagCode::W110_ContentAfterEnd)) << r.dump();
    auto s = run("+100+0\n/\n+100+0\n", woyda);
    EXPECT_EQ(s.motions().size(), 1u);
}

// ---------------------------------------------------------------- unknown and manufacturer codes

TEST(InterpFunctions, UnknownW201NamesTheCode) {
    for (int code : {37, 40, 99, 103, 999}) {
        auto r = run(std::to_string(code) + "\n64\n");
        const Diagnostic* d = find_code(r.diags, DiagCode::W201_UnknownFunction);
        ASSERT_NE(d, nullptr) << code << r.dump();
        EXPECT_EQ(d->severity, Severity::Warning);
        EXPECT_EQ(d->line, 1u);
        EXPECT_NE(essi::diagnostic_message(*d, essi::Lang::En).find(std::to_string(code)), std::string::npos)
            << essi::diagnostic_message(*d, essi::Lang::En);
    }
}

TEST(InterpFunctions, KnownCodesGiveNoW201) {
    auto r =
        run("0\n5\n6\n7\n8\n9\n10\n11\n12\n13\n14\n15\n16\n17\n18\n21\n38\n41\n42\n45\n46\n48\n49\n50\n51\n"
            "52\n53\n54\n81\n82\n81\n102\n105\n106\n107\n110\n111\n112\n113\n114\n12\n115\n12\n64\n");
    EXPECT_FALSE(r.has(DiagCode::W201_UnknownFunction)) << r.dump();
}

TEST(InterpFunctions, ManufacturerW208InIso) {
    for (int code : {55, 58, 61, 62}) {
        auto r = run(std::to_string(code) + "\n64\n");
        const Diagnostic* d = find_code(r.diags, DiagCode::W208_ManufacturerFunction);
        ASSERT_NE(d, nullptr) << code << r.dump();
        EXPECT_EQ(d->line, 1u);
        EXPECT_FALSE(r.has(DiagCode::W201_UnknownFunction)) << code;
    }
}

TEST(InterpFunctions, ValueOnPlainFunctionW202) {
    auto r = run("7+5\n8\n64\n");
    EXPECT_TRUE(r.has(DiagCode::W202_FunctionValueIgnored)) << r.dump();
}

TEST(InterpFunctions, FeedAndDwell) {
    auto r = run("39+1400\n7\n+100+0\n41+5\n41\n8\n5\n+100+0\n6\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_NEAR(r.motions()[0].feed_mm_min, 1400.0, kTimeTol);
    EXPECT_NEAR(r.motions()[1].feed_mm_min, 10000.0, kTimeTol);
    auto dw = r.sink.events_of(EventKind::Dwell);
    ASSERT_EQ(dw.size(), 2u) << r.dump();
    EXPECT_NEAR(dw[0].value, 5.0, kTimeTol);
    EXPECT_NEAR(dw[1].value, 1.0, kTimeTol);  // profile default_dwell_s
    EXPECT_FALSE(r.has(DiagCode::W201_UnknownFunction)) << r.dump();
    Profile p;
    p.default_dwell_s = 2.5;
    auto r2 = run("41\n64\n", p);
    auto dw2 = r2.sink.events_of(EventKind::Dwell);
    ASSERT_EQ(dw2.size(), 1u);
    EXPECT_NEAR(dw2[0].value, 2.5, kTimeTol);
}

TEST(InterpFunctions, ZeroFeedW209) {
    auto r = run("39+0\n+100+0\n64\n");
    const Diagnostic* d = find_code(r.diags, DiagCode::W209_ZeroFeed);
    ASSERT_NE(d, nullptr) << r.dump();
    EXPECT_EQ(d->line, 1u);
}

// ---------------------------------------------------------------- Woyda dialect

TEST(InterpWoyda, ReturnToProgramZero62) {
    auto r = run("+100+50\n7\n+100+0\n8\n62\n/\n", woyda_profile());
    ASSERT_EQ(r.motions().size(), 3u) << r.dump();
    const auto& back = r.motions()[2];
    EXPECT_EQ(back.kind, MotionKind::Travel);
    EXPECT_EQ(back.curve, CurveKind::Line);
    EXPECT_POINT_NEAR(back.start, 20.0, 5.0, kPosTol);
    EXPECT_POINT_NEAR(back.end, 0.0, 0.0, kPosTol);
    EXPECT_NEAR(back.length_mm, std::sqrt(20.0 * 20.0 + 5.0 * 5.0), kLenTol);
    EXPECT_EQ(back.line, 5u);
    EXPECT_FALSE(r.has(DiagCode::W208_ManufacturerFunction)) << r.dump();
    EXPECT_FALSE(r.has(DiagCode::W201_UnknownFunction)) << r.dump();
}

TEST(InterpWoyda, BurnerCountAndSpacing) {
    auto ok = run("135+3\n136+12000\n/\n", woyda_profile());
    EXPECT_TRUE(ok.diags.empty()) << ok.dump();
    auto bad = run("135+3\n7\n136+12000\n8\n/\n", woyda_profile());
    const Diagnostic* d = find_code(bad.diags, DiagCode::W212_BurnerCountNotBeforeSpacing);
    ASSERT_NE(d, nullptr) << bad.dump();
    auto missing = run("135\n136+12000\n/\n", woyda_profile());
    EXPECT_TRUE(missing.has(DiagCode::E203_FunctionValueMissing)) << missing.dump();
}

TEST(InterpWoyda, MacroOnlyW213) {
    for (int code : {67, 68}) {
        auto r = run(std::to_string(code) + "\n/\n", woyda_profile());
        const Diagnostic* d = find_code(r.diags, DiagCode::W213_MacroOnlyFunction);
        ASSERT_NE(d, nullptr) << code << r.dump();
        EXPECT_EQ(d->line, 1u);
    }
}

TEST(InterpWoyda, RepeatStart66AndOxygenOff43Known) {
    auto r = run("66\n7\n+100+0\n43\n8\n/\n", woyda_profile());
    EXPECT_FALSE(r.has(DiagCode::W201_UnknownFunction)) << r.dump();
    EXPECT_EQ(r.motions().size(), 1u);
}

TEST(InterpWoyda, FeedDwellKerfValues) {
    auto r = run("39+1400\n41+5\n29+20\n7\n+100+0\n8\n38\n/\n", woyda_profile());
    EXPECT_TRUE(r.diags.empty()) << r.dump();
    ASSERT_EQ(r.motions().size(), 1u);
    EXPECT_NEAR(r.motions()[0].feed_mm_min, 1400.0, kTimeTol);
    EXPECT_NEAR(r.motions()[0].kerf_mm, 1.0, kPosTol);
    auto dw = r.sink.events_of(EventKind::Dwell);
    ASSERT_EQ(dw.size(), 1u);
    EXPECT_NEAR(dw[0].value, 5.0, kTimeTol);
}

// ---------------------------------------------------------------- more combinations

TEST(InterpModes, AbsoluteArcMirrored) {
    // 22 mirrors y: the ccw half circle (10,0) -> (30,0) around (20,0) becomes cw, through (20,10)
    auto r = run("82\n22\n+100+0\n+300+0+200+0+\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    const auto& a = r.motions()[1];
    EXPECT_POINT_NEAR(a.start, 10.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(a.end, 30.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(a.centre, 20.0, 0.0, kPosTol);
    EXPECT_FALSE(a.ccw);
    EXPECT_NEAR(a.sweep, -kPi, kAngTol);
    const Box b = bounding_box(a);
    EXPECT_NEAR(b.max_y, 10.0, kPosTol);
    EXPECT_NEAR(b.min_y, 0.0, kPosTol);
}

TEST(InterpModes, AbsoluteFullCircle) {
    // absolute end equal to the start: the full circle of §5 (DX=DY=0 in incremental terms)
    auto r = run("82\n+100+0\n+100+0+200+0+\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    const auto& a = r.motions()[1];
    EXPECT_NEAR(a.sweep, 2 * kPi, kAngTol);
    EXPECT_NEAR(a.length_mm, 20 * kPi, kLenTol);
}

TEST(InterpModes, InvalidBlockIsSkipped) {
    auto r = run("+100+0\n+1X+0\n+100+0\n64\n");
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[1].start, 10.0, 0.0, kPosTol);
    EXPECT_POINT_NEAR(r.motions()[1].end, 20.0, 0.0, kPosTol);
    EXPECT_EQ(r.motions()[1].line, 3u);
}

TEST(InterpProfile, UnitIncrement) {
    Profile p;
    p.unit_mm = 0.01;
    auto r = run("+1000+250\n+0+0+500+0+\n64\n", p);
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_POINT_NEAR(r.motions()[0].end, 10.0, 2.5, kPosTol);
    EXPECT_NEAR(r.motions()[1].radius, 5.0, kPosTol);
    EXPECT_NEAR(r.motions()[1].length_mm, 10 * kPi, kLenTol);
}

TEST(InterpProfile, OtherEndCodes) {
    Profile p;
    p.end_codes = {{0, 0}};  // e.g. a controller ending programs with 0
    auto r = run("+100+0\n0\n+100+0\n", p);
    ASSERT_EQ(r.motions().size(), 1u) << r.dump();
    EXPECT_EQ(r.sink.events_of(EventKind::End).size(), 1u);
    EXPECT_TRUE(r.has(DiagCode::W110_ContentAfterEnd)) << r.dump();
    Profile q;
    q.end_codes = {{-1, '='}};
    auto e = run("+100+0\n=\n", q);
    EXPECT_TRUE(e.tape.has_program_end());
    ASSERT_GE(e.tape.size(), 2u);
    EXPECT_EQ(e.tape.block(1).kind, BlockKind::EndMark);
    EXPECT_FALSE(has_severity(e.diags, Severity::Error)) << e.dump();
    // '=' is no end (and no allowed character) in the default profile
    auto d = run("+100+0\n=\n64\n");
    EXPECT_TRUE(d.has(DiagCode::E101_InvalidCharacter)) << d.dump();
}

TEST(InterpKerf, MarkingToolIsNoW204) {
    auto r = run("9\n29\n+100+0\n38\n10\n64\n");
    EXPECT_FALSE(r.has(DiagCode::W204_KerfWhileCutting)) << r.dump();
}

TEST(InterpFunctions, DiagnosticColumnsFromSource) {
    auto r = run("7\n8\n  37\n64\n");
    const Diagnostic* d = find_code(r.diags, DiagCode::W201_UnknownFunction);
    ASSERT_NE(d, nullptr) << r.dump();
    EXPECT_EQ(d->line, 3u);
    EXPECT_EQ(d->column, 3u);
}
