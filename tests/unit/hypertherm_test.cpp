// The hypertherm dialect (docs/semantics.md, "Hypertherm"): its ESSI table as its controls read it (codes that
// act as other ISO codes, its own 40, 63, 65/90/99 and the milliseconds of 41+v, a complete table: any other code
// is W201) and its EIA words, with the values some of them stand for.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "essi/dialect.hpp"
#include "essi/functions.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/pipeline.hpp"
#include "essi/text.hpp"
#include "essi/write.hpp"
#include "test_util.hpp"

using namespace essi;

namespace {

Profile hypertherm() { return *builtin_profile("hypertherm"); }

bool has(const CheckResult& r, DiagCode c) {
    return std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [&](const Diagnostic& d) { return d.code == c; });
}

// The events of kind Function, as "code" or "code+value", in order.
std::string function_events(const essi_test::RunResult& r) {
    std::string s;
    for (const MachineEvent& e : r.events()) {
        if (e.kind != EventKind::Function) continue;
        s += (s.empty() ? "" : " ") + std::to_string(e.code);
        if (e.has_value) s += "+" + std::to_string(static_cast<long long>(e.value));
    }
    return s;
}

}  // namespace

TEST(Hypertherm, FiftyThreeCutsAsSevenAndItsEventSaysSeven) {
    const auto r = essi_test::run("53\n+1000+0\n54\n+0+1000\n64\n", hypertherm());
    ASSERT_TRUE(r.diags.empty()) << r.dump();
    ASSERT_EQ(r.motions().size(), 2u);
    EXPECT_EQ(r.motions()[0].kind, MotionKind::Cut);
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Travel);
    EXPECT_EQ(function_events(r), "7 8");  // the canonical stream: what the machine does
    // 53 ... 8 (one device) leaves nothing on; under iso6582 53 is plasma and 8 leaves it on
    const CheckResult h = check_tape("53\n+1000+0\n8\n+0+1000\n64\n", hypertherm());
    EXPECT_DOUBLE_EQ(h.stats.cut_length_mm, 100.0);
    const CheckResult iso = check_tape("53\n+1000+0\n8\n+0+1000\n64\n", *builtin_profile("iso6582"));
    EXPECT_DOUBLE_EQ(iso.stats.cut_length_mm, 200.0);
}

TEST(Hypertherm, MarkerTwoMarksAndFifteenIsMarkerOffsetTwo) {
    const auto r = essi_test::run("15\n13\n+500+0\n14\n16\n64\n", hypertherm());
    ASSERT_TRUE(r.diags.empty()) << r.dump();
    ASSERT_EQ(r.motions().size(), 1u);
    EXPECT_EQ(r.motions()[0].kind, MotionKind::Mark);
    EXPECT_EQ(function_events(r), "11+2 112 113 12+2");
    const CheckResult c = check_tape("13\n+500+0\n14\n64\n", hypertherm());
    EXPECT_DOUBLE_EQ(c.stats.mark_length_mm, 50.0);
    EXPECT_DOUBLE_EQ(c.stats.cut_length_mm, 0.0);
    EXPECT_EQ(c.stats.pierces, 0u);
}

TEST(Hypertherm, MarkerOffsetsOneToEight) {
    EXPECT_FALSE(has(check_tape("11+8\n12+8\n64\n", hypertherm()), DiagCode::E216_FunctionValueRange));
    const CheckResult nine = check_tape("11+9\n64\n", hypertherm());
    ASSERT_TRUE(has(nine, DiagCode::E216_FunctionValueRange));
    EXPECT_NE(essi::diagnostic_message(nine.diagnostics.front(), essi::Lang::En).find("outside 1 to 8"),
              std::string::npos)
        << essi::diagnostic_message(nine.diagnostics.front(), essi::Lang::En);
}

TEST(Hypertherm, DwellValueInMilliseconds) {
    const auto r = essi_test::run("41+1500\n41\n64\n", hypertherm());
    ASSERT_TRUE(r.diags.empty()) << r.dump();
    const auto dwells = r.sink.events_of(EventKind::Dwell);
    ASSERT_EQ(dwells.size(), 2u);
    EXPECT_DOUBLE_EQ(dwells[0].value, 1.5);
    EXPECT_DOUBLE_EQ(dwells[1].value, hypertherm().default_dwell_s);
    // the range is in seconds: 3600 s is 3 600 000 ms
    EXPECT_FALSE(has(check_tape("41+3600000\n64\n", hypertherm()), DiagCode::E216_FunctionValueRange));
    const CheckResult over = check_tape("41+3600001\n64\n", hypertherm());
    ASSERT_TRUE(has(over, DiagCode::E216_FunctionValueRange));
    EXPECT_NE(essi::diagnostic_message(over.diagnostics.front(), essi::Lang::En).find("(3600.001 s at 0.001 s a unit)"),
              std::string::npos)
        << essi::diagnostic_message(over.diagnostics.front(), essi::Lang::En);
    // iso6582: seconds
    EXPECT_DOUBLE_EQ(
        essi_test::run("41+2\n64\n", *builtin_profile("iso6582")).sink.events_of(EventKind::Dwell)[0].value, 2.0);
}

TEST(Hypertherm, ProgrammableKerfIsWhatTwentyNineUsesWithoutAValue) {
    // 40+40: a 4 mm kerf (width, 0.1 mm a unit): the torch runs 2 mm to the left of the line
    const auto r = essi_test::run("40+40\n29\n7\n+1000+0\n8\n38\n64\n", hypertherm());
    ASSERT_TRUE(r.diags.empty()) << r.dump();
    ASSERT_EQ(r.motions().size(), 1u);
    EXPECT_DOUBLE_EQ(r.motions()[0].kerf_mm, 2.0);
    EXPECT_DOUBLE_EQ(essi_test::run("29+10\n7\n+1000+0\n8\n64\n", hypertherm()).motions()[0].kerf_mm, 0.5);
    // 40 needs its value; under iso6582 40 is unassigned
    EXPECT_TRUE(essi_test::run("40\n64\n", hypertherm()).has(DiagCode::E203_FunctionValueMissing));
    EXPECT_TRUE(essi_test::run("40+40\n64\n", *builtin_profile("iso6582")).has(DiagCode::W201_UnknownFunction));
}

TEST(Hypertherm, SixtyThreeResetsCutMarkerAndKerfOnly) {
    // 63 under hypertherm (M31): the cut and the kerf end, rapid, incremental mode and the mapping stay
    const auto r = essi_test::run("82\n23\n29\n7\n+1000+0\n63\n+2000+0\n64\n", hypertherm());
    ASSERT_EQ(r.motions().size(), 2u) << r.dump();
    EXPECT_EQ(r.motions()[1].kind, MotionKind::Travel);
    EXPECT_EQ(r.motions()[1].kerf, KerfSide::Off);
    // absolute mode and the 180 degree turn (23) stay: from (-100, 0) to (-200, 0)
    EXPECT_DOUBLE_EQ(r.motions()[1].end.x, -200.0);
    const auto events = r.events();
    EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const MachineEvent& e) { return e.code == 63; }));
    // iso6582: the mapping goes back to 21 and incremental mode (81) returns: +2000 from (-100, 0)
    const auto iso = essi_test::run("82\n23\n29\n7\n+1000+0\n63\n+2000+0\n64\n", *builtin_profile("iso6582"));
    ASSERT_EQ(iso.motions().size(), 2u);
    EXPECT_DOUBLE_EQ(iso.motions()[1].end.x, 100.0);
}

TEST(Hypertherm, NinetyNinetyNineAndSixtyFiveEndTheProgram) {
    for (const char* end : {"64", "65", "90", "99"}) {
        SCOPED_TRACE(end);
        const CheckResult r = check_tape(std::string("7\n+100+0\n8\n") + end + "\n+100+0\n", hypertherm());
        EXPECT_TRUE(has(r, DiagCode::W110_ContentAfterEnd)) << essi_test::dump(r.diagnostics);
        EXPECT_DOUBLE_EQ(r.stats.travel_length_mm, 0.0);
    }
}

TEST(Hypertherm, CodesNotInItsTableAreUnknown) {
    // its controls refuse a code their table does not list: 1, 17, 49, 110, 135 are W201 here
    for (const char* code : {"1", "17", "49", "110", "135+2"}) {
        SCOPED_TRACE(code);
        const auto r = essi_test::run(std::string(code) + "\n64\n", hypertherm());
        EXPECT_TRUE(r.has(DiagCode::W201_UnknownFunction)) << r.dump();
    }
    const auto info = function_info(110, Dialect::Hypertherm);
    ASSERT_TRUE(info.has_value());
    EXPECT_FALSE(info->assigned);
    EXPECT_EQ(function_info(13, Dialect::Hypertherm)->name, "Enable marker 2");
    EXPECT_EQ(function_info(13, Dialect::Iso6582)->name, "Left bevel torch ON");
}

TEST(Hypertherm, EiaWordsThatStandForAFunctionWithAValue) {
    // M275 = 11+3 (marker offset 3), M73 = 15 = 11+2, M13/M14 marker 2, M31 reset, G04 X in seconds
    const std::string tape = "G91\nM275\nM274\nM73\nM72\nM13\nG01 X50 Y0\nM14\nG04 X2.5\nM36 T1\nM07\nX10\nM08\nM02\n";
    const Profile p = hypertherm();
    const Tape t = read_tape(tape, p, InputFormat::Eia);
    essi_test::RecordingSink sink;
    std::vector<Diagnostic> diags = t.diagnostics();
    interpret(t, tape, p, sink, diags);
    std::string fns;
    for (const MachineEvent& e : sink.events) {
        if (e.kind == EventKind::Dwell) fns += " dwell:" + number_text(e.value);
        if (e.kind != EventKind::Function) continue;
        fns += " " + std::to_string(e.code);
        if (e.has_value) fns += "+" + number_text(e.value);
    }
    EXPECT_EQ(fns, " 81 11+3 12+3 11+2 12+2 112 113 dwell:2.5 7 8");
    // M36 (process select) is not in the table; T1 is a word essikit does not read: W124 each
    std::size_t w124 = 0;
    for (const Diagnostic& d : diags) w124 += d.code == DiagCode::W124_EiaUnknownCode;
    EXPECT_EQ(w124, 2u) << essi_test::dump(diags);
    ASSERT_EQ(sink.motions.size(), 2u);
    EXPECT_EQ(sink.motions[0].kind, MotionKind::Mark);
    EXPECT_EQ(sink.motions[1].kind, MotionKind::Cut);
}

TEST(Hypertherm, ProfileCodesTakeAValueAndRoundTrip) {
    const ProfileResult ok =
        parse_profile(R"({"base": "hypertherm", "eia": {"codes": [["M275", 11, 3], ["M07", 7]]}})");
    ASSERT_TRUE(ok.profile.has_value());
    ASSERT_EQ(ok.profile->eia.codes.size(), 2u);
    EXPECT_EQ(ok.profile->eia.codes[0].value, 3);
    EXPECT_EQ(ok.profile->eia.codes[1].value, -1);
    const ProfileResult again = parse_profile(profile_to_json(*ok.profile));  // written as ["M275", 11, 3]
    ASSERT_TRUE(again.profile.has_value());
    EXPECT_EQ(again.profile->eia.codes, ok.profile->eia.codes);
    for (const char* bad :
         {R"([["M275", 11, -1]])", R"([["M275", 11, 10000]])", R"([["M275", 11, 3, 4]])", R"([["M275", 11, 1.5]])"}) {
        SCOPED_TRACE(bad);
        const ProfileResult r = parse_profile(std::string(R"({"eia": {"codes": )") + bad + "}}");
        EXPECT_FALSE(r.profile.has_value());
        ASSERT_FALSE(r.diagnostics.empty());
        EXPECT_NE(essi::diagnostic_message(r.diagnostics.front(), essi::Lang::En).find("eia.codes"), std::string::npos)
            << essi::diagnostic_message(r.diagnostics.front(), essi::Lang::En);
    }
    const ProfileResult unit = parse_profile(R"({"dwell_unit_s": 0})");
    ASSERT_FALSE(unit.profile.has_value());
    EXPECT_NE(essi::diagnostic_message(unit.diagnostics.front(), essi::Lang::En).find("dwell_unit_s"),
              std::string::npos);
}

TEST(Hypertherm, ConversionWritesTheTargetsDwellUnit) {
    // an iso6582 dwell of 2 s is 41+2000 for a Hypertherm control, and back
    ConvertOptions to_h;
    to_h.to = OutputFormat::Essi;
    to_h.target = hypertherm();
    const ConvertResult h =
        convert_tape("41+2\n64\n", TapeSetup{InputFormat::Essi, *builtin_profile("iso6582"), false, {}, {}}, to_h);
    EXPECT_NE(h.text.find("41+2000"), std::string::npos) << h.text;
    ConvertOptions to_iso;
    to_iso.to = OutputFormat::Essi;
    to_iso.target = *builtin_profile("iso6582");
    const ConvertResult back = convert_tape(h.text, TapeSetup{InputFormat::Essi, hypertherm(), false, {}, {}}, to_iso);
    EXPECT_NE(back.text.find("41+2"), std::string::npos) << back.text;
    EXPECT_EQ(back.text.find("41+2000"), std::string::npos) << back.text;
}
