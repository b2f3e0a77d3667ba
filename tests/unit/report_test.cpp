// Phase 5 (report): statistics and check results of small tapes (docs/semantics.md §9). Lengths, times and
// boxes are worked out by hand. Default profile: feed 1000 mm/min, rapid 10000 mm/min, pierce 2 s, dwell 1 s.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "../bench/nest_generator.hpp"
#include "essi/pipeline.hpp"
#include "essi/text_report.hpp"
#include "paths.hpp"
#include "test_util.hpp"

using namespace essi;
using namespace essi_test;

namespace {

constexpr double kBoxTol = 1e-9;

void expect_box(const Box& b, double x0, double y0, double x1, double y1, const char* what) {
    EXPECT_FALSE(b.empty) << what;
    EXPECT_NEAR(b.min_x, x0, kBoxTol) << what << " min_x";
    EXPECT_NEAR(b.min_y, y0, kBoxTol) << what << " min_y";
    EXPECT_NEAR(b.max_x, x1, kBoxTol) << what << " max_x";
    EXPECT_NEAR(b.max_y, y1, kBoxTol) << what << " max_y";
}

// rapid 100 mm, cut 50 mm + semicircle r=10 (bulging to x=110), mark 30 mm, travel 70 mm
const char* const kTapeA =
    "5\n"
    "+1000+0\n"  // rapid (0,0) -> (100,0)
    "6\n"
    "7\n"
    "+0+500\n"         // cut (100,0) -> (100,50)
    "+0+200+0+100+\n"  // cut arc (100,50) -> (100,70) around (100,60), ccw: through (110,60)
    "8\n"
    "9\n"
    "+300+0\n"  // mark (100,70) -> (130,70)
    "10\n"
    "+0-700\n"  // travel (130,70) -> (130,0)
    "64\n";

}  // namespace

TEST(ReportStats, MixedTape) {
    CheckResult r = check_tape(kTapeA, Profile{});
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
    const Stats& s = r.stats;
    EXPECT_NEAR(s.cut_length_mm, 50.0 + 10.0 * kPi, kLenTol);
    EXPECT_NEAR(s.mark_length_mm, 30.0, kLenTol);
    EXPECT_NEAR(s.travel_length_mm, 170.0, kLenTol);
    EXPECT_NEAR(s.rapid_length_mm, 100.0, kLenTol);
    EXPECT_EQ(s.pierces, 1u);
    EXPECT_EQ(s.blocks, 12u);
    EXPECT_EQ(s.motions, 5u);
    // rapid 100/10000 min = 0.6 s; cut (50+10pi)/1000 min; mark 30/1000 min = 1.8 s; travel 70/1000 min = 4.2 s;
    // one pierce 2 s
    const double expected_time = 0.6 + (50.0 + 10.0 * kPi) * 60.0 / 1000.0 + 1.8 + 4.2 + 2.0;
    EXPECT_NEAR(expected_time, 13.484955592153876, 1e-9);
    EXPECT_NEAR(s.estimated_time_s, expected_time, kTimeTol);
    expect_box(s.cut_bbox, 100, 0, 110, 70, "cut_bbox");
    expect_box(s.motion_bbox, 0, 0, 130, 70, "motion_bbox");
    EXPECT_POINT_NEAR(s.end_position, 130.0, 0.0, kPosTol);
}

TEST(ReportStats, FeedAndDwellInTime) {
    // cut 100 mm at 500 mm/min = 12 s, dwell 3 s + default 1 s, pierce 2 s
    CheckResult r = check_tape("39+500\n7\n+1000+0\n41+3\n41\n8\n64\n", Profile{});
    EXPECT_TRUE(r.ok()) << dump(r.diagnostics);
    EXPECT_NEAR(r.stats.cut_length_mm, 100.0, kLenTol);
    EXPECT_NEAR(r.stats.estimated_time_s, 18.0, kTimeTol);
}

TEST(ReportStats, FeedChangesMidway) {
    // 100 mm at 1000 (6 s), then 39+2000: 100 mm at 2000 (3 s), pierce 2 s
    CheckResult r = check_tape("7\n+1000+0\n39+2000\n+1000+0\n8\n64\n", Profile{});
    EXPECT_NEAR(r.stats.estimated_time_s, 11.0, kTimeTol);
}

TEST(ReportStats, ProfileSpeeds) {
    Profile p;
    p.feed_mm_min = 2000;
    p.rapid_mm_min = 5000;
    p.pierce_time_s = 0.5;
    p.default_dwell_s = 4;
    // rapid 100 mm / 5000 = 1.2 s; cut 100 mm / 2000 = 3 s; pierce 0.5 s; dwell 4 s
    CheckResult r = check_tape("5\n+1000+0\n6\n7\n41\n+1000+0\n8\n64\n", p);
    EXPECT_NEAR(r.stats.rapid_length_mm, 100.0, kLenTol);
    EXPECT_NEAR(r.stats.estimated_time_s, 1.2 + 3.0 + 0.5 + 4.0, kTimeTol);
}

TEST(ReportStats, WoydaFeedDwell) {
    // 39+1400: 140 mm cut at 1400 mm/min = 6 s; 41+5 = 5 s; pierce 2 s
    CheckResult r = check_tape("39+1400\n7\n41+5\n+1400+0\n8\n/\n", woyda_profile());
    EXPECT_TRUE(r.ok()) << dump(r.diagnostics);
    EXPECT_NEAR(r.stats.cut_length_mm, 140.0, kLenTol);
    EXPECT_NEAR(r.stats.estimated_time_s, 13.0, kTimeTol);
}

TEST(ReportStats, Pierces) {
    // 7 on: pierce; 13 while 7 on: none; 8 with 13 still on: still cutting; 14: off; 7: pierce; 53: pierce
    const char* tape = "7\n+100+0\n13\n+100+0\n8\n+100+0\n14\n7\n+100+0\n8\n53\n+100+0\n54\n+100+0\n64\n";
    CheckResult r = check_tape(tape, Profile{});
    EXPECT_EQ(r.stats.pierces, 3u);
    EXPECT_NEAR(r.stats.cut_length_mm, 50.0, kLenTol);
    EXPECT_NEAR(r.stats.travel_length_mm, 10.0, kLenTol);
    // 60 mm at 1000 mm/min = 3.6 s, 3 pierces = 6 s
    EXPECT_NEAR(r.stats.estimated_time_s, 9.6, kTimeTol);
    CheckResult m = check_tape("9\n+100+0\n10\n110\n+100+0\n111\n64\n", Profile{});
    EXPECT_EQ(m.stats.pierces, 0u);  // marking is not a pierce
    EXPECT_NEAR(m.stats.mark_length_mm, 20.0, kLenTol);
    EXPECT_TRUE(m.stats.cut_bbox.empty);
}

TEST(ReportStats, FullCircleAndParabolaCut) {
    CheckResult c = check_tape("7\n+0+0+100+0+\n8\n64\n", Profile{});
    EXPECT_NEAR(c.stats.cut_length_mm, 20.0 * kPi, kLenTol);
    expect_box(c.stats.cut_bbox, 0, -10, 20, 10, "circle");
    EXPECT_POINT_NEAR(c.stats.end_position, 0.0, 0.0, kPosTol);
    const double F10 = 10.0 / 2 * std::sqrt(1 + 4.0) + 5.0 / 2 * std::asinh(2.0);  // see geom_test
    CheckResult p = check_tape("7\n+200+0+100+50++\n8\n64\n", Profile{});
    EXPECT_TRUE(p.ok()) << dump(p.diagnostics);
    EXPECT_NEAR(p.stats.cut_length_mm, 2 * F10, kLenTol);
    expect_box(p.stats.cut_bbox, 0, -10, 20, 0, "parabola");
}

TEST(ReportStats, KerfDoesNotChangeCutLength) {
    CheckResult r = check_tape("29+20\n7\n+1000+0\n+0+500\n8\n38\n64\n", Profile{});
    EXPECT_NEAR(r.stats.cut_length_mm, 150.0, kLenTol);
    expect_box(r.stats.cut_bbox, 0, 0, 100, 50, "kerf");
}

TEST(ReportStats, BlocksExcludeEmptyLinesAndComments) {
    CheckResult r = check_tape("7\n\n+100+0\n\r\n8\n64\n", Profile{});
    EXPECT_EQ(r.stats.blocks, 4u);
    EXPECT_EQ(r.stats.motions, 1u);
}

TEST(ReportStats, NothingCut) {
    CheckResult r = check_tape("+100+0\n+0+100\n64\n", Profile{});
    EXPECT_TRUE(r.stats.cut_bbox.empty);
    EXPECT_EQ(r.stats.pierces, 0u);
    EXPECT_NEAR(r.stats.travel_length_mm, 20.0, kLenTol);
    EXPECT_NEAR(r.stats.rapid_length_mm, 0.0, kLenTol);
    EXPECT_NEAR(r.stats.estimated_time_s, 1.2, kTimeTol);
    expect_box(r.stats.motion_bbox, 0, 0, 10, 10, "motion");
    EXPECT_POINT_NEAR(r.stats.end_position, 10.0, 10.0, kPosTol);
}

TEST(ReportStats, WoydaReturnToZero) {
    CheckResult r = check_tape("+100+50\n7\n+100+0\n8\n62\n/\n", woyda_profile());
    EXPECT_POINT_NEAR(r.stats.end_position, 0.0, 0.0, kPosTol);
    // travel sqrt(10^2+5^2) + sqrt(20^2+5^2), cut 10
    EXPECT_NEAR(r.stats.travel_length_mm, std::sqrt(125.0) + std::sqrt(425.0), kLenTol);
    EXPECT_NEAR(r.stats.cut_length_mm, 10.0, kLenTol);
}

// ---------------------------------------------------------------- the check result

TEST(ReportCheck, DiagnosticsSortedByLine) {
    // W201 on line 1 (interp), E101 on line 3 (read): sorted by line, the warning comes first
    CheckResult r = check_tape("37\n7\n+1X+0\n8\n64\n", Profile{});
    ASSERT_GE(r.diagnostics.size(), 2u) << dump(r.diagnostics);
    EXPECT_EQ(r.diagnostics[0].code, DiagCode::W201_UnknownFunction) << dump(r.diagnostics);
    EXPECT_EQ(r.diagnostics[0].line, 1u);
    EXPECT_TRUE(has_code_at(r.diagnostics, DiagCode::E101_InvalidCharacter, 3, 3)) << dump(r.diagnostics);
    for (std::size_t i = 1; i < r.diagnostics.size(); ++i) {
        const auto& a = r.diagnostics[i - 1];
        const auto& b = r.diagnostics[i];
        EXPECT_TRUE(a.line < b.line || (a.line == b.line && a.column <= b.column)) << dump(r.diagnostics);
    }
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.count(Severity::Error), 1u) << dump(r.diagnostics);
    EXPECT_EQ(r.count(Severity::Warning), 1u) << dump(r.diagnostics);
}

TEST(ReportCheck, WarningsOnlyIsOk) {
    CheckResult r = check_tape("37\n+100+0\n64\n", Profile{});
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.count(Severity::Warning), 1u) << dump(r.diagnostics);
    EXPECT_EQ(r.count(Severity::Error), 0u);
}

TEST(ReportCheck, ArcErrorFromGeometry) {
    CheckResult r = check_tape("7\n+253+0+125+0+\n8\n64\n", Profile{});
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_code(r.diagnostics, DiagCode::E301_ArcEndNotOnCircle)) << dump(r.diagnostics);
}

// The carriage is on the table again once a motion ends on it: the next exit is reported too, even right after.
TEST(ReportCheck, TableLimitsE401AtEveryExit) {
    Profile p;
    p.table = TableLimits{0, 0, 100, 100};
    // (50,0) on; (250,0) off; back to (50,0): on; (250,0) off again; back; then (50,150): off a third time
    const CheckResult r = check_tape("+500+0\n+2000+0\n-2000+0\n+2000+0\n-2000+0\n+0+1500\n64\n", p);
    std::vector<std::uint32_t> lines;
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == DiagCode::E401_LeavesTable) lines.push_back(d.line);
    EXPECT_EQ(lines, (std::vector<std::uint32_t>{2, 4, 6})) << dump(r.diagnostics);
    // Moving about off the table is one exit.
    const CheckResult off = check_tape("+500+0\n+2000+0\n+100+0\n-100+0\n64\n", p);
    std::size_t n = 0;
    for (const Diagnostic& d : off.diagnostics) n += d.code == DiagCode::E401_LeavesTable;
    EXPECT_EQ(n, 1u) << dump(off.diagnostics);
}

TEST(ReportCheck, TableLimitsE401) {
    Profile p;
    p.table = TableLimits{0, 0, 100, 100};
    CheckResult r = check_tape("+500+0\n+2000+0\n64\n", p);  // (50,0) inside, (250,0) beyond max_x 100
    const Diagnostic* d = find_code(r.diagnostics, DiagCode::E401_LeavesTable);
    ASSERT_NE(d, nullptr) << dump(r.diagnostics);
    EXPECT_EQ(d->line, 2u);
    EXPECT_FALSE(r.ok());
    CheckResult inside = check_tape("+500+0\n+0+900\n64\n", p);
    EXPECT_FALSE(has_code(inside.diagnostics, DiagCode::E401_LeavesTable)) << dump(inside.diagnostics);
    // an arc whose end points are inside but whose bulge leaves the table: (50,0) -> (70,0) around (60,0),
    // ccw goes down to y = -10
    CheckResult bulge = check_tape("+500+0\n+200+0+100+0+\n64\n", p);
    EXPECT_TRUE(has_code(bulge.diagnostics, DiagCode::E401_LeavesTable)) << dump(bulge.diagnostics);
    // an arc whose circle leaves the table but which does not: (90,50) -> (78,86) ccw around (30,50), radius 60,
    // turns 36.87 degrees and passes no extreme of its circle (the exact box, not the circle's, decides)
    CheckResult short_arc = check_tape("+900+500\n-120+360-600+0+\n64\n", p);
    EXPECT_FALSE(has_code(short_arc.diagnostics, DiagCode::E401_LeavesTable)) << dump(short_arc.diagnostics);
    // the same circle's arc on to its top (30,110), beyond max_y 100
    CheckResult past_top = check_tape("+900+500\n-600+600-600+0+\n64\n", p);
    const Diagnostic* top = find_code(past_top.diagnostics, DiagCode::E401_LeavesTable);
    ASSERT_NE(top, nullptr) << dump(past_top.diagnostics);
    EXPECT_EQ(top->line, 2u);
}

TEST(ReportCheck, EmptyAndGarbageNeverThrow) {
    CheckResult e = check_tape("", Profile{});
    EXPECT_FALSE(e.ok());
    EXPECT_TRUE(has_code(e.diagnostics, DiagCode::E113_EmptyTape));
    std::string bin;
    for (int i = 0; i < 5000; ++i) bin.push_back(static_cast<char>((i * 37 + 11) & 0xFF));
    EXPECT_NO_THROW({
        CheckResult g = check_tape(bin, Profile{});
        EXPECT_FALSE(g.ok());
    });
}

TEST(ReportSink, StatsSinkFromInterpreter) {
    const std::string src = kTapeA;
    Profile p;
    Tape t = read_tape(src, p);
    std::vector<Diagnostic> diags;
    StatsSink sink(p);
    interpret(t, src, p, sink, diags);
    EXPECT_NEAR(sink.stats().cut_length_mm, 50.0 + 10.0 * kPi, kLenTol);
    EXPECT_NEAR(sink.stats().mark_length_mm, 30.0, kLenTol);
    EXPECT_EQ(sink.stats().pierces, 1u);
}

TEST(ReportStats, RapidWithCuttingToolCountsAsCut) {
    // §9: cut length is motion while any cutting tool is on, whatever the speed
    CheckResult r = check_tape("7\n5\n+1000+0\n6\n8\n64\n", Profile{});
    EXPECT_TRUE(has_code(r.diagnostics, DiagCode::W210_RapidWhileCutting)) << dump(r.diagnostics);
    EXPECT_NEAR(r.stats.cut_length_mm, 100.0, kLenTol);
    EXPECT_NEAR(r.stats.travel_length_mm, 0.0, kLenTol);
    EXPECT_EQ(r.stats.pierces, 1u);
}

// TapeChecker's `also` sink (the viewer's document) gets the interpreter's stream exactly: the straight lines
// of head 1 come as UnitLines without a record, and what MotionSink::on_line makes of them by default is
// the record interpret() emits, to the bit. A sink that takes the UnitLines gets units that are its mm.
namespace {

// Counts the UnitLines and checks their units against their mm, then records them as the default does.
class UnitLineSink : public RecordingSink {
public:
    explicit UnitLineSink(const Profile& p) : profile_(p) {}
    std::size_t lines = 0;
    void on_line(const UnitLine& l) override {
        ++lines;
        EXPECT_TRUE(same_bits(static_cast<double>(l.start_x) * profile_.unit_mm, l.start.x));
        EXPECT_TRUE(same_bits(static_cast<double>(l.end_y) * profile_.unit_mm, l.end.y));
        RecordingSink::on_line(l);
    }

private:
    const Profile& profile_;
};

void expect_also_gets_the_stream(const std::string& text, const Profile& p, const std::string& what) {
    SCOPED_TRACE(what);
    const RunResult want = run(text, p);
    UnitLineSink also(p);
    TapeChecker checker(text, p, &also);
    TapeReader reader(text, p);
    Tape chunk;
    while (reader.read_chunk(chunk, 1000)) checker.check_chunk(chunk);
    const CheckResult got = checker.finish();
    expect_same_result(got, check_tape(text, p), what);
    ASSERT_EQ(also.motions.size(), want.motions().size());
    for (std::size_t i = 0; i < want.motions().size() && !::testing::Test::HasFatalFailure(); ++i)
        expect_same_record(also.motions[i], want.motions()[i], "motion " + std::to_string(i));
    ASSERT_EQ(also.events.size(), want.events().size());
    for (std::size_t i = 0; i < want.events().size(); ++i) {
        const MachineEvent &a = also.events[i], &b = want.events()[i];
        ASSERT_TRUE(a.line == b.line && a.block == b.block && a.kind == b.kind && a.code == b.code &&
                    a.has_value == b.has_value && same_bits(a.value, b.value) && same_bits(a.x, b.x) &&
                    same_bits(a.y, b.y) && a.tools_after == b.tools_after)
            << "event " << i;
    }
    EXPECT_EQ(also.order, want.sink.order);
    if (!want.motions().empty()) {
        EXPECT_GT(also.lines, 0u);
    }
}

}  // namespace

TEST(TapeCheckerAlso, GetsTheInterpretersStreamExactly) {
    expect_also_gets_the_stream(kTapeA, Profile{}, "tape A");
    // Every example: kerf, absolute mode and zero offsets, 21-28, head 2, parabolas, dwells, bad tapes.
    std::size_t examples = 0;
    for (const auto& e : std::filesystem::directory_iterator(examples_dir())) {
        if (e.path().extension() != ".esi") continue;
        ++examples;
        const std::string text = read_file(e.path().string());
        for (const Profile& p : {iso_profile(), woyda_profile()})
            expect_also_gets_the_stream(text, p, e.path().filename().string() + " " + p.name);
    }
    EXPECT_GE(examples, 10u);
    Profile offset = iso_profile();  // (the placement does not change the stream: program coordinates)
    offset.zero_offsets["G54"] = {-12.5, 40};
    offset.plate_rotation_deg = 3;
    const std::string nest = bench::generate_nest_tape(200000, 3);
    expect_also_gets_the_stream(nest, iso_profile(), "generated");
    expect_also_gets_the_stream(nest, offset, "generated, placed on the machine");
}

TEST(TextReport, FileReportTextIsWhatCheckPrintsAndCsvQuotes) {
    essi::FileReport f;
    f.path = "a,b.esi";
    f.result = essi::check_tape("7\n+100+0\n8\n99\n64\n", essi::Profile{});
    ASSERT_EQ(f.result.diagnostics.size(), 1u);  // 99: W201
    const std::string text = essi::file_report_text(f);
    EXPECT_EQ(text.rfind("a,b.esi:4:1: warning W201: ", 0), 0u) << text;
    EXPECT_NE(text.find("\na,b.esi: ok, 1 warning; cut 10.000 mm"), std::string::npos) << text;
    const std::string csv = essi::diagnostics_csv(std::span<const essi::FileReport>(&f, 1));
    EXPECT_EQ(csv.rfind("file,severity,code,line,column,message\r\n\"a,b.esi\",warning,W201,4,1,", 0), 0u) << csv;
    EXPECT_EQ(csv.substr(csv.size() - 2), "\r\n");
    f.result.diagnostics[0].set_text("say \"x\"");
    EXPECT_NE(essi::diagnostics_csv(std::span<const essi::FileReport>(&f, 1)).find(",\"say \"\"x\"\"\"\r\n"),
              std::string::npos);
}
