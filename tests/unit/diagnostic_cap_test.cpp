// The bounds on diagnostics (essi/diagnostic_cap.hpp, TapeChecker::set_max_diagnostics): at most max_per_code of a
// code and then one summary of that code; at most max_diagnostics kept while the tape is checked, the same ones
// that cutting the whole list afterwards would keep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "essi/diagnostic_cap.hpp"
#include "essi/diagnostics.hpp"
#include "essi/plan.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"

using namespace essi;

namespace {

std::string word(long long v) { return (v < 0 ? "-" : "+") + std::to_string(v < 0 ? -v : v); }

// `n` thin rectangles (100 mm x 10 mm, counter-clockwise, kerf right: parts), all pierced at the origin and fanned
// out at different angles over a quarter turn: every two of them overlap at the origin, so every pair collides.
std::string fan_of_parts(int n) {
    std::string t = "39+1000\n30+20\n";
    for (int k = 0; k < n; ++k) {
        const double a = 1.5707963267948966 * k / n;
        const long long ax = std::llround(1000 * std::cos(a)), ay = std::llround(1000 * std::sin(a));
        const long long bx = std::llround(-100 * std::sin(a)), by = std::llround(100 * std::cos(a));
        t += "7\n" + word(ax) + word(ay) + "\n" + word(bx) + word(by) + "\n" + word(-ax) + word(-ay) + "\n" +
             word(-bx) + word(-by) + "\n8\n";
    }
    return t + "38\n64\n";
}

std::size_t count_code(const CheckResult& r, DiagCode c) {
    return static_cast<std::size_t>(
        std::count_if(r.diagnostics.begin(), r.diagnostics.end(), [&](const Diagnostic& d) { return d.code == c; }));
}

const Diagnostic* summary_of(const CheckResult& r, DiagCode c) {
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == c && d.msg == Msg::DiagnosticsOmittedOfCode) return &d;
    return nullptr;
}

// A line per block that ends with a blank: one W109 a line.
std::string blanks_tape(int lines) {
    std::string t;
    for (int i = 0; i < lines; ++i) t += "+10+0 \n";
    return t + "64\n";
}

}  // namespace

TEST(DiagnosticCap, KeepsTheFirstOfACodeAndCountsTheRest) {
    DiagnosticCap cap(2);
    EXPECT_TRUE(cap.admit(DiagCode::W109_WhitespaceSkipped, 1, Severity::Warning));
    EXPECT_TRUE(cap.admit(DiagCode::W109_WhitespaceSkipped, 2, Severity::Warning));
    EXPECT_TRUE(cap.admit(DiagCode::E101_InvalidCharacter, 3, Severity::Error));
    EXPECT_FALSE(cap.admit(DiagCode::W109_WhitespaceSkipped, 7, Severity::Warning));
    EXPECT_FALSE(cap.admit(DiagCode::W109_WhitespaceSkipped, 5, Severity::Warning));
    cap.add_omitted(DiagCode::W109_WhitespaceSkipped, 10, 4, Severity::Warning);
    std::vector<Diagnostic> out;
    cap.append_summaries(out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].code, DiagCode::W109_WhitespaceSkipped);
    EXPECT_EQ(out[0].severity, Severity::Warning);
    EXPECT_EQ(out[0].line, 4u);  // the first left out
    EXPECT_EQ(essi::diagnostic_message(out[0], essi::Lang::En),
              "12 more W109 diagnostics not listed (at most 2 of a code: --max-per-code)");
    DiagnosticCap all(0);
    for (int i = 0; i < 5000; ++i) EXPECT_TRUE(all.admit(DiagCode::W109_WhitespaceSkipped, 1, Severity::Warning));
}

TEST(DiagnosticCap, PartsCollidingInOnePlaceCostMaxPerCodeFindings) {
    const std::string tape = fan_of_parts(60);  // 1 770 pairs
    Profile p;
    p.max_per_code = 0;
    const CheckResult all = check_tape(tape, p);
    EXPECT_EQ(count_code(all, DiagCode::E605_PartsCollide), 60u * 59u / 2u);
    p.max_per_code = 100;
    const CheckResult capped = check_tape(tape, p);
    EXPECT_EQ(count_code(capped, DiagCode::E605_PartsCollide), 101u);  // 100 and the summary
    const Diagnostic* s = summary_of(capped, DiagCode::E605_PartsCollide);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->severity, Severity::Error);
    EXPECT_EQ(essi::diagnostic_message(*s, essi::Lang::En),
              "1670 more E605 diagnostics not listed (at most 100 of a code: --max-per-code)");
    EXPECT_FALSE(capped.ok());
    // The statistics do not depend on the cap.
    EXPECT_EQ(capped.stats.pierces, all.stats.pierces);
    EXPECT_DOUBLE_EQ(capped.stats.cut_length_mm, all.stats.cut_length_mm);
}

TEST(DiagnosticCap, TheDefaultIsAThousandOfACode) {
    EXPECT_EQ(Profile{}.max_per_code, 1000u);
    const CheckResult r = check_tape(blanks_tape(1500), Profile{});
    EXPECT_EQ(count_code(r, DiagCode::W109_WhitespaceSkipped), 1001u);
    const Diagnostic* s = summary_of(r, DiagCode::W109_WhitespaceSkipped);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->line, 1001u);
    EXPECT_EQ(s->column, 1u);
    EXPECT_EQ(essi::diagnostic_message(*s, essi::Lang::En),
              "500 more W109 diagnostics not listed (at most 1000 of a code: --max-per-code)");
    EXPECT_EQ(diagnostic_message(*s, Lang::De),
              "500 weitere Meldungen W109 nicht aufgeführt (höchstens 1000 je Code: --max-per-code)");
}

TEST(DiagnosticCap, ProfileKeyMaxPerCode) {
    const ProfileResult ok = parse_profile(R"({"max_per_code": 0})");
    ASSERT_TRUE(ok.profile);
    EXPECT_EQ(ok.profile->max_per_code, 0u);
    EXPECT_NE(profile_to_json(*ok.profile).find("\"max_per_code\": 0"), std::string::npos);
    for (const char* bad : {R"({"max_per_code": -1})", R"({"max_per_code": 1.5})", R"({"max_per_code": "10"})",
                            R"({"max_per_code": 10000000000})"}) {
        const ProfileResult r = parse_profile(bad);
        EXPECT_FALSE(r.profile) << bad;
        ASSERT_FALSE(r.diagnostics.empty()) << bad;
        EXPECT_NE(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En)
                      .find("\"max_per_code\" must be a whole number from 0 to 1000000000"),
                  std::string::npos)
            << essi::diagnostic_message(r.diagnostics[0], essi::Lang::En);
    }
}

// Cut while the tape is checked, the list is what cutting the whole sorted list afterwards keeps, and the
// left-out are counted by severity.
TEST(DiagnosticCap, MaxDiagnosticsWhileCheckingKeepsWhatCuttingAfterwardsKeeps) {
    Profile p;
    p.max_per_code = 0;
    for (const std::string& tape : {blanks_tape(3000), fan_of_parts(40) + "+10+0 \n"}) {
        for (std::size_t max : {0u, 1u, 10u, 777u}) {
            CheckResult after = check_tape(tape, p);
            const std::size_t errors = after.count(Severity::Error), warnings = after.count(Severity::Warning);
            limit_diagnostics(after, max);
            const CheckResult during = check_tape(tape, p, InputFormat::Essi, max);
            ASSERT_EQ(during.diagnostics.size(), after.diagnostics.size()) << max;
            for (std::size_t i = 0; i < during.diagnostics.size(); ++i) {
                EXPECT_EQ(during.diagnostics[i].code, after.diagnostics[i].code) << i;
                EXPECT_EQ(during.diagnostics[i].line, after.diagnostics[i].line) << i;
                EXPECT_EQ(essi::diagnostic_message(during.diagnostics[i], essi::Lang::En),
                          essi::diagnostic_message(after.diagnostics[i], essi::Lang::En))
                    << i;
            }
            EXPECT_EQ(during.count(Severity::Error), errors);
            EXPECT_EQ(during.count(Severity::Warning), warnings);
            EXPECT_EQ(during.omitted(), after.omitted());
        }
    }
}

// Contours piled over each other: the search for neighbours stops at its budget and says so (N613), once.
TEST(PlanBounds, PiledContoursAreComparedWithinABudget) {
    const CheckResult r = check_tape(fan_of_parts(800), Profile{});  // 800 parts, every pair overlapping
    ASSERT_EQ(count_code(r, DiagCode::N613_PlateTooCrowded), 1u);
    const Diagnostic* n = nullptr;
    for (const Diagnostic& d : r.diagnostics)
        if (d.code == DiagCode::N613_PlateTooCrowded) n = &d;
    EXPECT_EQ(n->line, 4u);  // the plate's first cut (its first motion)
    EXPECT_EQ(n->severity, Severity::Note);
    EXPECT_NE(essi::diagnostic_message(*n, essi::Lang::En).find("the search for colliding pairs stopped after"),
              std::string::npos)
        << essi::diagnostic_message(*n, essi::Lang::En);
    EXPECT_EQ(count_code(r, DiagCode::E605_PartsCollide), 1001u);  // (the cap, and its summary)
    // An ordinary number of neighbours: no note.
    EXPECT_EQ(count_code(check_tape(fan_of_parts(30), Profile{}), DiagCode::N613_PlateTooCrowded), 0u);
}

// A plate of more cutting motions than kPlanMaxPlateMotions is analysed in parts, N614 at the end of each part.
TEST(PlanBounds, AHugePlateIsAnalysedInParts) {
    std::string tape = "39+2000\n";
    const std::size_t squares = kPlanMaxPlateMotions / 4 + 10;
    for (std::size_t k = 0; k < squares; ++k) tape += "5\n+200+0\n6\n30\n7\n+100+0\n+0+100\n-100+0\n+0-100\n8\n38\n";
    tape += "64\n";
    const CheckResult r = check_tape(tape, Profile{});
    ASSERT_EQ(count_code(r, DiagCode::N614_PlateSplit), 1u);
    for (const Diagnostic& d : r.diagnostics) {
        if (d.code != DiagCode::N614_PlateSplit) continue;
        // The part ends with the cut that reaches the limit: square kPlanMaxPlateMotions / 4 (11 lines each, after
        // the feed's line), at its last motion, the line before its `8`.
        const std::size_t last_line = 11 * (kPlanMaxPlateMotions / 4) - 1;
        EXPECT_EQ(d.line, last_line);
        EXPECT_EQ(essi::diagnostic_message(d, essi::Lang::En),
                  "the plate is analysed in parts of at most 131072 cutting motions: the cuts after line " +
                      std::to_string(last_line) + " are not compared with those up to it");
    }
    EXPECT_TRUE(r.ok());
}

// A full circle of radius 100 m (1 000 000 units of 0.1 mm) about a centre 100 m to its right: flattened within
// kPlanChordToleranceMm it would need 3 142 chords, so the plan takes kPlanMaxArcChords.
const std::string kBigCircle = "+0+0+1000000+0+\n";

// Big arcs make long polygons: a plate is also analysed in parts of at most kPlanMaxPlatePoints points. 520 cuts of
// one big circle each, 250 m apart: the 512th cut reaches 512 x 1 024 = 524 288 points and closes the part.
TEST(PlanBounds, BigArcsSplitAPlateByItsPoints) {
    ASSERT_EQ(kPlanMaxArcChords, 1024);
    ASSERT_EQ(kPlanMaxPlatePoints, 512u * 1024u);
    std::string tape;
    for (int k = 0; k < 520; ++k) tape += "7\n" + kBigCircle + "8\n+2500000+0\n";
    tape += "64\n";
    const CheckResult r = check_tape(tape, Profile{});
    ASSERT_EQ(count_code(r, DiagCode::N614_PlateSplit), 1u);
    for (const Diagnostic& d : r.diagnostics) {
        if (d.code != DiagCode::N614_PlateSplit) continue;
        const std::size_t last_line = 4 * 511 + 2;  // the circle of the 512th cut (4 lines a cut)
        EXPECT_EQ(d.line, last_line);
        EXPECT_EQ(essi::diagnostic_message(d, essi::Lang::En),
                  "the plate is analysed in parts of at most 524288 points of its contours flattened: the "
                  "cuts after line " +
                      std::to_string(last_line) + " are not compared with those up to it");
    }
    EXPECT_EQ(count_code(r, DiagCode::N615_CutTooLong), 0u);
}

// One cut of more points than a plate's part holds is left out of the cut plan (N615) and its pieces dropped: 600
// big circles under one pierce are 614 400 points.
TEST(PlanBounds, ACutOfTooManyPointsIsLeftOut) {
    std::string tape = "7\n";
    for (int k = 0; k < 600; ++k) tape += kBigCircle;
    tape += "8\n64\n";
    const CheckResult r = check_tape(tape, Profile{});
    ASSERT_EQ(count_code(r, DiagCode::N615_CutTooLong), 1u);
    for (const Diagnostic& d : r.diagnostics) {
        if (d.code != DiagCode::N615_CutTooLong) continue;
        EXPECT_EQ(d.line, 2u);
        EXPECT_EQ(d.contour_first, 2u);
        EXPECT_EQ(d.contour_last, 601u);
        EXPECT_EQ(d.severity, Severity::Note);
        EXPECT_EQ(essi::diagnostic_message(d, essi::Lang::En),
                  "the cut of lines 2-601 is more than 524288 points when flattened: the cut plan leaves it "
                  "out (no nesting, collision or crossing tests for it)");
    }
    EXPECT_EQ(r.stats.motions, 600u);  // (the statistics still count every motion)
    EXPECT_TRUE(r.ok());
}

// The pairs a plate compares weigh their contours' points: 200 big circles, each 1 mm above the last, overlap
// pairwise (19 900 pairs, under the 64-a-cut budget), but each pair weighs 2 x 1 024 points, so the search stops
// at 32 x 204 800 + 2^24 points' worth of pairs (N613).
TEST(PlanBounds, PairsWeighTheirContoursPoints) {
    std::string tape;
    for (int k = 0; k < 200; ++k) tape += "7\n" + kBigCircle + "8\n+0+10\n";
    tape += "64\n";
    const CheckResult r = check_tape(tape, Profile{});
    ASSERT_EQ(count_code(r, DiagCode::N613_PlateTooCrowded), 1u);
    const std::size_t most_pairs = (32 * 200 * 1024 + (std::size_t{1} << 24)) / (2 * 1024);
    for (const Diagnostic& d : r.diagnostics) {
        if (d.code != DiagCode::N613_PlateTooCrowded) continue;
        // "... the search for colliding pairs stopped after N pairs (at most 64 a cut) ..."
        const std::string after = "stopped after ";
        const std::size_t at = essi::diagnostic_message(d, essi::Lang::En).find(after);
        ASSERT_NE(at, std::string::npos) << essi::diagnostic_message(d, essi::Lang::En);
        const std::size_t pairs = std::stoul(essi::diagnostic_message(d, essi::Lang::En).substr(at + after.size()));
        EXPECT_GT(pairs, 0u);
        EXPECT_LE(pairs, 2 * most_pairs) << essi::diagnostic_message(
            d, essi::Lang::En);  // (a pair found both ways counts twice)
    }
}
