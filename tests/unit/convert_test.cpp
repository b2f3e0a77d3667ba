// Conversions (essi/write.hpp): round trips on every example and real tape give the same motion stream, and the
// writers' text on small tapes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "essi/dialect.hpp"
#include "essi/pipeline.hpp"
#include "essi/write.hpp"
#include "paths.hpp"
#include "test_util.hpp"

using namespace essi;
namespace fs = std::filesystem;

namespace {

struct Stream {
    std::vector<MotionRecord> motions;
    bool errors = false;
};

// The motion stream of `text` read as `setup` says.
Stream stream_of(const std::string& text, const TapeSetup& setup) {
    Stream s;
    essi_test::RecordingSink sink;
    std::vector<Diagnostic> diags;
    const Tape tape = read_tape(text, setup.profile, setup.format);
    diags = tape.diagnostics();
    interpret(tape, text, setup.profile, sink, diags);
    s.motions = sink.motions;
    s.errors = !check_tape(text, setup).ok();  // (the kerf path's and the cut plan's errors too: not converted)
    return s;
}

TapeSetup setup_of(InputFormat f, const Profile& p) {
    TapeSetup s;
    s.format = f;
    s.profile = p;
    return s;
}

// Same kinds, tools, curves and end points (within `tol` mm; the same sense for arcs).
void expect_same_stream(const Stream& a, const Stream& b, double tol, const std::string& what) {
    SCOPED_TRACE(what);
    ASSERT_EQ(a.motions.size(), b.motions.size());
    for (std::size_t i = 0; i < a.motions.size(); ++i) {
        const MotionRecord &x = a.motions[i], &y = b.motions[i];
        ASSERT_EQ(x.kind, y.kind) << "motion " << i;
        ASSERT_EQ(x.tools, y.tools) << "motion " << i;
        ASSERT_EQ(x.curve, y.curve) << "motion " << i;
        ASSERT_EQ(x.head, y.head) << "motion " << i;  // (a 3-axis tape's head 2 keeps its address)
        ASSERT_NEAR(x.start.x, y.start.x, tol) << "motion " << i;
        ASSERT_NEAR(x.start.y, y.start.y, tol) << "motion " << i;
        ASSERT_NEAR(x.end.x, y.end.x, tol) << "motion " << i;
        ASSERT_NEAR(x.end.y, y.end.y, tol) << "motion " << i;
        if (x.curve == CurveKind::Arc) {
            ASSERT_EQ(x.ccw, y.ccw) << "motion " << i;
            ASSERT_NEAR(x.centre.x, y.centre.x, tol) << "motion " << i;
        }
    }
}

// Every example and real tape without errors and without parabolas (those become arcs: W502), with its setup.
std::vector<std::pair<std::string, std::string>> tapes() {
    std::vector<std::pair<std::string, std::string>> out;
    std::vector<std::string> dirs{examples_dir()};
    if (const auto c = corpus_dir()) dirs.push_back(*c);
    for (const std::string& dir : dirs) {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir)) {
            const std::string n = e.path().filename().string();
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && n.rfind("bad_", 0) != 0 && ext != ".json" && ext != ".trace" && ext != ".md")
                names.push_back(e.path().string());
        }
        std::sort(names.begin(), names.end());
        for (const std::string& p : names) out.emplace_back(p, read_file(p));
    }
    return out;
}

}  // namespace

TEST(Convert, EssiRoundTripsGiveTheSameMotionStream) {
    for (const auto& [path, text] : tapes()) {
        const TapeSetup source = setup_tape(text, std::nullopt, std::nullopt);
        const Stream want = stream_of(text, source);
        if (want.errors) continue;
        bool parabola = false;
        for (const MotionRecord& m : want.motions) parabola = parabola || m.curve == CurveKind::Parabola;
        if (parabola) continue;  // (tested below: arcs within the tolerance)
        for (bool absolute : {false, true}) {
            ConvertOptions o;
            o.to = OutputFormat::Essi;
            o.target = source.profile;
            o.absolute = absolute;
            const ConvertResult essi = convert_tape(text, source, o);
            const Stream back = stream_of(essi.text, setup_of(InputFormat::Essi, source.profile));
            expect_same_stream(want, back, 1e-9, path + (absolute ? " -> ESSI absolute" : " -> ESSI incremental"));
            // incremental -> absolute -> incremental
            o.absolute = !absolute;
            const ConvertResult again = convert_tape(essi.text, setup_of(InputFormat::Essi, source.profile), o);
            expect_same_stream(want, stream_of(again.text, setup_of(InputFormat::Essi, source.profile)), 1e-9,
                               path + " -> ESSI -> ESSI in the other mode");
        }
    }
}

TEST(Convert, EiaRoundTripsGiveTheSameMotionStream) {
    std::size_t compared = 0;
    for (const auto& [path, text] : tapes()) {
        const TapeSetup source = setup_tape(text, std::nullopt, std::nullopt);
        const Stream want = stream_of(text, source);
        if (want.errors) continue;
        bool parabola = false;
        for (const MotionRecord& m : want.motions) parabola = parabola || m.curve == CurveKind::Parabola;
        if (parabola) continue;
        for (const char* dialect : {"woyda", "din66025"}) {
            ConvertOptions o;
            o.to = OutputFormat::Eia;
            o.target = *builtin_profile(dialect);
            const ConvertResult eia = convert_tape(text, source, o);
            // (a function the dialect has no word for is a comment: the stream differs there, by design)
            const bool complete = std::none_of(eia.diagnostics.begin(), eia.diagnostics.end(), [](const Diagnostic& d) {
                return d.code == DiagCode::W501_NoCounterpart;
            });
            if (!complete) continue;
            ++compared;
            const Stream back = stream_of(eia.text, setup_of(InputFormat::Eia, o.target));
            ASSERT_FALSE(back.errors) << path << " as " << dialect << " EIA:\n" << eia.text;
            expect_same_stream(want, back, 1e-9, path + " -> EIA " + dialect);
            // and back to ESSI in the source's dialect
            ConvertOptions to_essi;
            to_essi.target = source.profile;
            const ConvertResult essi = convert_tape(eia.text, setup_of(InputFormat::Eia, o.target), to_essi);
            expect_same_stream(want, stream_of(essi.text, setup_of(InputFormat::Essi, source.profile)), 1e-9,
                               path + " -> EIA " + dialect + " -> ESSI");
        }
    }
    EXPECT_GE(compared, 20u);  // (most tapes have a word for every function in both dialects)
}

// G-code's compensation is the motions' (docs/conversions.md): a mirror (22) puts the kerf of 29 on the right of
// the machine's direction of travel (G42.1), a new side while one is on gets G40 first (LinuxCNC refuses G41 on G42).
TEST(Convert, GcodeKerfSideAsTheMotionsHaveIt) {
    const Profile iso = *builtin_profile("iso6582");
    ConvertOptions o;
    o.target = iso;
    o.to = OutputFormat::Gcode;
    o.absolute = true;
    const std::string tape = "22\n29+20\n7\n+1000+0\n30+30\n+0+1000\n8\n38\n+100+0\n64\n";
    const ConvertResult g = convert_tape(tape, setup_of(InputFormat::Essi, iso), o);
    EXPECT_EQ(g.text,
              "G17 G21 G40 G90 G91.1 G94\nM3 $0 S1\nG42.1 D2\nG1 X100 Y0 F1000\nG40\nG41.1 D3\nG1 X100 Y-100\n"
              "M5 $0\nG40\nG1 X110 Y-100\nM2\n");
}

TEST(Convert, WritersText) {
    const Profile woyda = *builtin_profile("woyda");
    const std::string tape = "39+600\n29\n7\n+1000+0\n+0+0+0+500+\n8\n38\n41+2\n45\n/\n";
    ConvertOptions o;
    o.target = woyda;
    o.to = OutputFormat::Essi;
    EXPECT_EQ(convert_tape(tape, setup_of(InputFormat::Essi, woyda), o).text,
              "%\n39+600\n29\n7\n+1000+0\n+0+0+0+500+\n8\n38\n41+2\n45\n63\n");
    o.to = OutputFormat::Eia;
    const ConvertResult eia = convert_tape(tape, setup_of(InputFormat::Essi, woyda), o);
    EXPECT_EQ(eia.text, "%\nG91\nF600\nM67\nM70\nG01 X100 Y0\nG03 X0 Y0 I0 J50\nM71\nM69\nG04 X2000\nM72\nM02\n");
    o.to = OutputFormat::Gcode;
    o.absolute = true;
    const ConvertResult g = convert_tape(tape, setup_of(InputFormat::Essi, woyda), o);
    EXPECT_EQ(g.text,
              "G17 G21 G40 G90 G91.1 G94\nM3 $0 S1\nG41.1 D2\nG1 X100 Y0 F600\nG3 X100 Y0 I0 J50\nM5 $0\n"
              "G4 P2\n(ESSI 45: Torch head lower)\nG40\nM2\n");
    // The check's (N603: the kerf inside a lone contour), then the conversion's: 45 has no G-code counterpart.
    ASSERT_EQ(g.diagnostics.size(), 2u);
    EXPECT_EQ(g.diagnostics[0].code, DiagCode::N603_KerfInsideLoneContour);
    EXPECT_EQ(g.diagnostics[1].code, DiagCode::W501_NoCounterpart);
    EXPECT_EQ(g.diagnostics[1].line, 9u);
}

TEST(Convert, ParabolasBecomeArcsWithinTheTolerance) {
    const std::string text = read_file(examples_dir() + "/parabola.esi");
    const TapeSetup source = setup_tape(text, std::nullopt, std::nullopt);
    const Stream want = stream_of(text, source);
    ConvertOptions o;
    o.target = source.profile;
    o.target.unit_mm = 0.001;  // (fine enough that the arcs' ends are not rounded off the curve)
    const ConvertResult r = convert_tape(text, source, o);
    std::size_t w502 = 0;
    for (const Diagnostic& d : r.diagnostics) w502 += d.code == DiagCode::W502_ParabolaAsArcs;
    EXPECT_EQ(w502, 3u);
    const Stream back = stream_of(r.text, setup_of(InputFormat::Essi, o.target));
    ASSERT_FALSE(back.errors);
    // every motion that is not a parabola is there; each parabola's end is the end of one of the arcs
    std::size_t k = 0;
    for (const MotionRecord& m : want.motions) {
        while (k < back.motions.size() && m.curve == CurveKind::Parabola &&
               std::hypot(back.motions[k].end.x - m.end.x, back.motions[k].end.y - m.end.y) > 1e-3)
            ++k;
        ASSERT_LT(k, back.motions.size());
        EXPECT_NEAR(back.motions[k].end.x, m.end.x, 1e-3);
        EXPECT_NEAR(back.motions[k].end.y, m.end.y, 1e-3);
        ++k;
    }
}

TEST(Convert, HeadTwoKeepsItsAddressInEssiAndIsSaidLeftOutOfEia) {
    const std::string tape = "19\n1+500+500\n2+500+2500\n7\n1+1000+0\n2+1000+0\n8\n20\n64\n";
    const TapeSetup source = setup_of(InputFormat::Essi, *builtin_profile("iso6582"));
    ConvertOptions o;
    o.target = source.profile;
    o.absolute = true;
    const ConvertResult essi = convert_tape(tape, source, o);
    EXPECT_NE(essi.text.find("\n2+500+2500\n"), std::string::npos) << essi.text;
    EXPECT_NE(essi.text.find("\n2+1500+2500\n"), std::string::npos) << essi.text;
    expect_same_stream(stream_of(tape, source), stream_of(essi.text, source), 1e-9, "3-axis -> ESSI absolute");
    o.to = OutputFormat::Eia;
    o.target = *builtin_profile("woyda");
    const ConvertResult eia = convert_tape(tape, source, o);
    const auto w501 = std::find_if(eia.diagnostics.begin(), eia.diagnostics.end(), [](const Diagnostic& d) {
        return d.code == DiagCode::W501_NoCounterpart &&
               essi::diagnostic_message(d, essi::Lang::En).find("head 2") != std::string::npos;
    });
    ASSERT_NE(w501, eia.diagnostics.end());
    EXPECT_NE(essi::diagnostic_message(*w501, essi::Lang::En).find("head 2's motions"), std::string::npos)
        << essi::diagnostic_message(*w501, essi::Lang::En);
    EXPECT_EQ(eia.text.find("X250"), std::string::npos) << eia.text;  // (head 2's cut is not written as head 1's)
}

// A tape that essi check rejects is not converted (every rule: the kerf path's E307, the cut plan's E605) unless
// forced; then the same diagnostics come with what the machine would run.
TEST(Convert, ATapeWithErrorsIsRefusedUnlessForced) {
    for (const char* name : {"bad_kerf_gouge.esi", "plan_collision.esi", "plan_kerf.esi", "plan_cross.esi"}) {
        SCOPED_TRACE(name);
        const std::string text = read_file(examples_dir() + "/" + name);
        const TapeSetup source = setup_tape(text, std::nullopt, std::nullopt);
        const CheckResult check = check_tape(text, source);
        ASSERT_FALSE(check.ok());
        for (OutputFormat to : {OutputFormat::Essi, OutputFormat::Eia, OutputFormat::Gcode}) {
            ConvertOptions o;
            o.to = to;
            o.target = source.profile;
            const ConvertResult refused = convert_tape(text, source, o);
            EXPECT_TRUE(refused.refused);
            EXPECT_TRUE(refused.text.empty());
            EXPECT_FALSE(refused.ok());
            ASSERT_EQ(refused.diagnostics.size(), check.diagnostics.size());
            for (std::size_t i = 0; i < check.diagnostics.size(); ++i)
                EXPECT_EQ(refused.diagnostics[i].code, check.diagnostics[i].code);
            o.force = true;
            const ConvertResult forced = convert_tape(text, source, o);
            EXPECT_FALSE(forced.refused);
            EXPECT_FALSE(forced.text.empty());
            EXPECT_FALSE(forced.ok());
        }
    }
}

// ISO's program end (64) has a word in iso6582's EIA table (M30): the EIA written ends the program, and reads back
// as 64.
TEST(Convert, IsoProgramEndIsM30InEia) {
    const Profile iso = *builtin_profile("iso6582");
    ConvertOptions o;
    o.to = OutputFormat::Eia;
    o.target = iso;
    const ConvertResult r = convert_tape("7\n+1000+0\n8\n64\n", setup_of(InputFormat::Essi, iso), o);
    EXPECT_EQ(r.text, "%\nG91\nM70\nG01 X100 Y0\nM71\nM30\n");
    EXPECT_TRUE(r.diagnostics.empty()) << essi::diagnostic_message(r.diagnostics.front(), essi::Lang::En);
    const CheckResult back = check_tape(r.text, iso, InputFormat::Eia);
    EXPECT_TRUE(back.diagnostics.empty()) << essi::diagnostic_message(back.diagnostics.front(), essi::Lang::En);
}
