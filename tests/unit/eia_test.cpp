// The EIA (RS-274) front end (core/read/eia_reader.cpp), the dialect tables of the built-in profiles and the
// choice of format and dialect from a tape's content (core/dialect/dialect.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/pipeline.hpp"
#include "essi/trace.hpp"

using namespace essi;

namespace {

Profile builtin(const char* name) { return *builtin_profile(name); }

CheckResult check_eia(const std::string& text, const char* profile) {
    return check_tape(text, builtin(profile), InputFormat::Eia);
}

bool has(const CheckResult& r, DiagCode c) {
    return std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [&](const Diagnostic& d) { return d.code == c; });
}

}  // namespace

TEST(EiaRead, WoydaBlocksBecomeEssiBlocks) {
    const Tape t = read_tape("N1 M70\nN2 G01 X100.5 Y-20\nN3 G03 X0 Y100 I0 J50\nN4 G04 X500\nN5 M02\n",
                             builtin("woyda"), InputFormat::Eia);
    ASSERT_TRUE(t.diagnostics().empty());
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t.block(0).kind, BlockKind::Function);
    EXPECT_EQ(t.block(0).code, 7);  // M70: cutting on
    EXPECT_EQ(t.block(1).kind, BlockKind::Motion);
    EXPECT_EQ(t.words(1)[0], 1005);  // mm -> 0.1 mm units
    EXPECT_EQ(t.words(1)[1], -200);
    EXPECT_EQ(t.block(2).word_count(), 5);
    EXPECT_TRUE(t.block(2).tc_positive());  // G03: counter-clockwise
    EXPECT_EQ(t.block(3).code, 41);
    EXPECT_DOUBLE_EQ(t.block(3).function_value(t.words(3)[0]), 0.5);  // 500 ms
    EXPECT_TRUE(t.block(4).ends_program());                           // M02 = 63: the end under woyda
    EXPECT_EQ(t.block(4).line, 5u);
}

TEST(EiaRead, ModalArcsAndFullCircle) {
    // G02 stays in force for the blocks with I/J; a block with only X/Y is a line; I/J alone: a full circle
    const std::string trace =
        trace_tape("G02 X20 Y0 I10 J0\nX0 Y-20 I0 J-10\nX5\nI-5 J0\nM02\n", builtin("woyda"), InputFormat::Eia);
    EXPECT_NE(trace.find("1 travel arc (0.000,0.000)->(20.000,0.000) c=(10.000,0.000) r=10.000 cw"), std::string::npos)
        << trace;
    EXPECT_NE(trace.find("2 travel arc (20.000,0.000)->(20.000,-20.000) c=(20.000,-10.000) r=10.000 cw"),
              std::string::npos)
        << trace;
    EXPECT_NE(trace.find("3 travel line (20.000,-20.000)->(25.000,-20.000)"), std::string::npos) << trace;
    EXPECT_NE(trace.find("sweep=-360.000"), std::string::npos) << trace;
}

TEST(EiaRead, AbsoluteModeKeepsMissingAxesAndCentresStayRelative) {
    // Woyda G92 = absolute (82): X only keeps Y; I/J relative to the block's start
    const std::string trace =
        trace_tape("G92\nX100 Y50\nX150\nG03 X150 Y150 I0 J50\nM02\n", builtin("woyda"), InputFormat::Eia);
    EXPECT_NE(trace.find("3 travel line (100.000,50.000)->(150.000,50.000)"), std::string::npos) << trace;
    EXPECT_NE(trace.find("c=(150.000,100.000) r=50.000 ccw"), std::string::npos) << trace;
}

TEST(EiaRead, DinPresetRapidAndSeconds) {
    const std::string text = "G90\nG00 X50 Y50\nG92 X0 Y0\nG01 X10 Y0\nG04 X2\nG91\nG00 X5\nM30\n";
    const std::string trace = trace_tape(text, builtin("din66025"), InputFormat::Eia);
    EXPECT_NE(trace.find("2 rapid line (0.000,0.000)->(50.000,50.000)"), std::string::npos) << trace;
    // after G92 X0 Y0 at (50, 50), X10 absolute lands at machine (60, 50)
    EXPECT_NE(trace.find("4 travel line (50.000,50.000)->(60.000,50.000)"), std::string::npos) << trace;
    EXPECT_NE(trace.find("5 dwell 2.000 s"), std::string::npos) << trace;
    EXPECT_NE(trace.find("7 rapid line (60.000,50.000)->(65.000,50.000)"), std::string::npos) << trace;
    EXPECT_NE(trace.find("8 end 64"), std::string::npos) << trace;
}

TEST(EiaRead, InchWordsScaleCoordinates) {
    const std::string trace = trace_tape("G20\nG01 X1 Y0\nG21\nX1\nM30\n", builtin("hypertherm"), InputFormat::Eia);
    EXPECT_NE(trace.find("(0.000,0.000)->(25.400,0.000)"), std::string::npos) << trace;
    EXPECT_NE(trace.find("(25.400,0.000)->(26.400,0.000)"), std::string::npos) << trace;
}

TEST(EiaRead, ErrorsNameLineAndColumn) {
    const CheckResult r = check_eia("N1 X10 G01\nN2 G01 F600\nN3 X\nN4 I5 J0\nN5 Q1\nN6 (open\nM02\n", "woyda");
    const auto at = [&](DiagCode c) -> const Diagnostic* {
        for (const Diagnostic& d : r.diagnostics)
            if (d.code == c) return &d;
        return nullptr;
    };
    ASSERT_NE(at(DiagCode::E120_EiaLetterOrder), nullptr);
    EXPECT_EQ(at(DiagCode::E120_EiaLetterOrder)->line, 1u);
    EXPECT_EQ(at(DiagCode::E120_EiaLetterOrder)->column, 8u);
    ASSERT_NE(at(DiagCode::E121_EiaFunctionsInBlock), nullptr);
    EXPECT_EQ(at(DiagCode::E121_EiaFunctionsInBlock)->column, 8u);
    ASSERT_NE(at(DiagCode::E122_EiaBadNumber), nullptr);
    EXPECT_EQ(at(DiagCode::E122_EiaBadNumber)->line, 3u);
    ASSERT_NE(at(DiagCode::E123_EiaArcWithoutDirection), nullptr);
    EXPECT_EQ(at(DiagCode::E123_EiaArcWithoutDirection)->line, 4u);
    ASSERT_NE(at(DiagCode::E119_EiaUnknownLetter), nullptr);
    EXPECT_EQ(at(DiagCode::E119_EiaUnknownLetter)->line, 5u);
    EXPECT_NE(essi::diagnostic_message(*at(DiagCode::E119_EiaUnknownLetter), essi::Lang::En).find("'Q'"),
              std::string::npos);
    ASSERT_NE(at(DiagCode::E126_EiaUnclosedComment), nullptr);
    EXPECT_EQ(at(DiagCode::E126_EiaUnclosedComment)->line, 6u);
}

TEST(EiaRead, DinAllowsSeveralFunctionsAndAnyOrder) {
    const CheckResult r = check_eia("X10 Y0 G01 F600 M03\nM05 M30\n", "din66025");
    EXPECT_TRUE(r.diagnostics.empty()) << essi::diagnostic_message(r.diagnostics.front(), essi::Lang::En);
    EXPECT_EQ(r.stats.pierces, 1u);
    EXPECT_DOUBLE_EQ(r.stats.cut_length_mm, 10.0);
}

TEST(EiaRead, UnknownCodeAndRounding) {
    const CheckResult r = check_eia("M99\nX1.23 Y0\nX1.26\nM02\n", "woyda");
    EXPECT_TRUE(has(r, DiagCode::W124_EiaUnknownCode));
    const auto rounded = std::count_if(r.diagnostics.begin(), r.diagnostics.end(),
                                       [](const Diagnostic& d) { return d.code == DiagCode::W125_EiaRounded; });
    EXPECT_EQ(rounded, 1);  // one for the tape, with the count
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == DiagCode::W125_EiaRounded) {
            EXPECT_EQ(d.line, 2u);
            EXPECT_NE(essi::diagnostic_message(d, essi::Lang::En).find("2 coordinates"), std::string::npos)
                << essi::diagnostic_message(d, essi::Lang::En);
        }
}

TEST(EiaRead, ChunksGiveTheWholeTape) {
    std::string text = "%\n";
    for (int i = 0; i < 300; ++i) text += "G01 X1 Y0 F600\nG02 X0 Y0 I1 J0\n";
    text += "M30\n";
    const Profile p = builtin("din66025");
    const Tape whole = read_tape(text, p, InputFormat::Eia);
    for (std::size_t n : {1u, 3u, 64u, 1000u}) {
        TapeReader reader(text, p, InputFormat::Eia);
        Tape chunk, all;
        while (reader.read_chunk(chunk, n)) all.append(chunk);
        ASSERT_EQ(all.size(), whole.size()) << n;
        for (std::size_t i = 0; i < whole.size(); ++i) {
            ASSERT_EQ(all.block(i).code, whole.block(i).code) << n << " " << i;
            ASSERT_EQ(all.block(i).line, whole.block(i).line) << n << " " << i;
            ASSERT_TRUE(
                std::equal(all.words(i).begin(), all.words(i).end(), whole.words(i).begin(), whole.words(i).end()));
        }
        EXPECT_EQ(all.end_block(), whole.end_block());
    }
}

TEST(Dialect, FormatFromTheContent) {
    EXPECT_EQ(detect_input_format("%\n(part)\nN1 G01 X1\n"), InputFormat::Eia);
    EXPECT_EQ(detect_input_format("%\n7\n+100+0\n"), InputFormat::Essi);
    EXPECT_EQ(detect_input_format(""), InputFormat::Essi);
}

TEST(Dialect, EvidenceNamesTheDialect) {
    DialectGuess g = guess_dialect("3\nPART\n4\n135+2\n136+6000\n7\n+100+0\n8\n/\n", InputFormat::Essi);
    EXPECT_EQ(g.profile, "woyda");
    EXPECT_TRUE(g.clear);
    ASSERT_FALSE(g.evidence.empty());
    EXPECT_EQ(g.evidence[0], "woyda: `135+2` sets the burner count at line 4");
    EXPECT_EQ(guess_dialect("7\n+100+0\n8\n63\n", InputFormat::Essi).profile, "iso6582");
    EXPECT_EQ(guess_dialect("7\n+100+0\n63\n+5+5\n64\n", InputFormat::Essi).evidence.at(0),
              "iso6582: `63` cancels the functions and the program goes on at line 3");
    EXPECT_EQ(guess_dialect("G90 G71\nG00 X1\nM03\n", InputFormat::Eia).profile, "din66025");
    EXPECT_EQ(guess_dialect("G21\nM07\nG01 X1\nM08\n", InputFormat::Eia).profile, "hypertherm");
    EXPECT_EQ(guess_dialect("G01 X1\n", InputFormat::Eia).profile, "woyda");
}

TEST(Dialect, ExplicitProfileGetsANoteWhenTheEvidenceDiffers) {
    const std::string tape = "135+2\n136+6000\n7\n+100+0\n8\n/\n";
    const TapeSetup iso = setup_tape(tape, std::nullopt, builtin("iso6582"));
    ASSERT_TRUE(iso.note.has_value());
    EXPECT_EQ(iso.note->code, DiagCode::N403_OtherDialect);
    EXPECT_EQ(iso.note->severity, Severity::Note);
    EXPECT_NE(essi::diagnostic_message(*iso.note, essi::Lang::En).find("--profile woyda"), std::string::npos);
    EXPECT_FALSE(setup_tape(tape, std::nullopt, builtin("woyda")).note.has_value());
    const TapeSetup chosen = setup_tape(tape, std::nullopt, std::nullopt);
    EXPECT_TRUE(chosen.auto_profile);
    EXPECT_EQ(chosen.profile.name, "woyda");
    const CheckResult r = check_tape(tape, chosen);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.profile, "woyda");
    EXPECT_EQ(r.dialect_evidence.size(), 3u);
}

TEST(ProfileEia, BuiltinsParseAndRoundTrip) {
    for (const std::string& name : builtin_profile_names()) {
        SCOPED_TRACE(name);
        const auto p = builtin_profile(name);
        ASSERT_TRUE(p.has_value());
        EXPECT_EQ(p->name, name);
        const ProfileResult again = parse_profile(profile_to_json(*p));
        ASSERT_TRUE(again.profile.has_value());
        EXPECT_EQ(again.profile->eia, p->eia);
        EXPECT_EQ(profile_to_json(*again.profile), profile_to_json(*p));
    }
    EXPECT_EQ(builtin("woyda").eia, builtin("iso6582").eia);  // woyda's table is the default
    EXPECT_EQ(builtin("din66025").eia.rapid_motion_g, 0);
    EXPECT_EQ(builtin("din66025").eia.position_preset_g, 92);
    EXPECT_DOUBLE_EQ(builtin("din66025").eia.dwell_unit_s, 1.0);
}

TEST(ProfileEia, BadEiaKeysNameTheKey) {
    const auto errors = [](const char* json) {
        std::string all;
        for (const Diagnostic& d : parse_profile(json).diagnostics)
            all += essi::diagnostic_message(d, essi::Lang::En) + "\n";
        return all;
    };
    EXPECT_NE(errors(R"({"eia": {"codes": [["X70", 7]]}})").find("\"eia.codes\""), std::string::npos);
    EXPECT_NE(errors(R"({"eia": {"codes": [["M70", 1000]]}})").find("\"eia.codes\""), std::string::npos);
    EXPECT_NE(errors(R"({"eia": {"dwell_unit_s": 0}})").find("\"eia.dwell_unit_s\""), std::string::npos);
    EXPECT_NE(errors(R"({"eia": {"rapid_motion": "M00"}})").find("\"eia.rapid_motion\""), std::string::npos);
    EXPECT_NE(errors(R"({"eia": {"colour": 1}})").find("unknown key \"eia.colour\""), std::string::npos);
    EXPECT_NE(errors(R"({"eia": 5})").find("\"eia\" must be an object"), std::string::npos);
    EXPECT_EQ(errors(R"({"base": "din66025", "eia": {"dwell_unit_s": 0.001}})"), "");
}

TEST(FunctionValues, OutOfRangeIsAnErrorNamingTheRange) {
    const CheckResult r = check_tape("41+5000\n39+200000\n29+2000\n7\n+100+0\n8\n64\n", builtin("iso6582"));
    ASSERT_EQ(std::count_if(r.diagnostics.begin(), r.diagnostics.end(),
                            [](const Diagnostic& d) { return d.code == DiagCode::E216_FunctionValueRange; }),
              3);
    EXPECT_NE(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En).find("outside 0 to 3600 s"), std::string::npos)
        << essi::diagnostic_message(r.diagnostics[0], essi::Lang::En);
    EXPECT_DOUBLE_EQ(r.stats.estimated_time_s,
                     10.0 / 1000.0 * 60.0 + 2.0);  // none of them took effect (10 mm at the profile feed)
}
