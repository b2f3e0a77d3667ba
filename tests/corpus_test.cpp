// The real tapes of ../shared/corpus/essiconv (Northewind/EssiConv, GPL-3.0: read in place, never copied into
// this repository). Skipped with a message when the folder is absent.
//
// What is checked:
//   - every file: check_tape and trace_tape return (no crash, no exception);
//   - every real tape except the comment tests (comment1, comment2, example.txt): no error;
//   - comment1: the text outside a 3/4 section on line 7 is an E101 error, and the only error;
//   - example.txt: every line carrying a `#` annotation (or the `.....` placeholders) is an E101 error;
//   - invariants on the real tapes: something is cut, one pierce per `7` block, finite boxes and lengths;
//   - exact hand-computed statistics for PR7.esi, 115_046.esi and PS178.esi (see the comments there);
//   - the cut plan's diagnostics (6xx) of every file are exactly the ones docs/diagnostics.md lists and explains
//     ("The cut plan on the real tapes"): code and line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/trace.hpp"
#include "paths.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kLengthTolMm = 1e-6;
constexpr double kTimeTolS = 1e-3;
constexpr double kPi = 3.14159265358979323846;

// The files that test comments and annotations rather than being production tapes.
const std::set<std::string> kCommentTests = {"comment1", "comment2", "example.txt"};

std::vector<std::string> corpus_files(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// The tape's lines as written (split on LF; the corpus has no CR), each without trailing blanks.
std::vector<std::string> tape_lines(const std::string& bytes) {
    std::vector<std::string> lines;
    std::istringstream in(bytes);
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

std::string diagnostics_text(const essi::CheckResult& r) {
    std::string s;
    for (const auto& d : r.diagnostics) {
        s += "\n  " + essi::code_name(d.code) + " line " + std::to_string(d.line) + " col " + std::to_string(d.column) +
             ": " + essi::diagnostic_message(d, essi::Lang::En);
    }
    return s.empty() ? "\n  (none)" : s;
}

bool has_diag(const essi::CheckResult& r, essi::DiagCode code, unsigned line) {
    return std::any_of(r.diagnostics.begin(), r.diagnostics.end(),
                       [&](const essi::Diagnostic& d) { return d.code == code && d.line == line; });
}

essi::Profile iso() { return *essi::builtin_profile("iso6582"); }

#define REQUIRE_CORPUS(dir_var)                                                                  \
    const auto dir_var##_opt = corpus_dir();                                                     \
    if (!dir_var##_opt) GTEST_SKIP() << "corpus not found (../shared/corpus/essiconv): skipped"; \
    const std::string dir_var = *dir_var##_opt

TEST(Corpus, EveryFileChecksAndTracesWithoutCrash) {
    REQUIRE_CORPUS(dir);
    const auto files = corpus_files(dir);
    ASSERT_FALSE(files.empty());
    const essi::Profile profile = iso();
    for (const auto& name : files) {
        SCOPED_TRACE(name);
        const std::string bytes = read_file(dir + "/" + name);
        essi::CheckResult r;
        EXPECT_NO_THROW(r = essi::check_tape(bytes, profile));
        std::string trace;
        EXPECT_NO_THROW(trace = essi::trace_tape(bytes, profile));
        EXPECT_FALSE(trace.empty());
    }
}

TEST(Corpus, RealTapesHaveNoError) {
    REQUIRE_CORPUS(dir);
    const essi::Profile profile = iso();
    int checked = 0;
    for (const auto& name : corpus_files(dir)) {
        if (kCommentTests.count(name)) continue;
        SCOPED_TRACE(name);
        const auto r = essi::check_tape(read_file(dir + "/" + name), profile);
        EXPECT_TRUE(r.ok()) << "diagnostics:" << diagnostics_text(r);
        ++checked;
    }
    EXPECT_GE(checked, 19);
}

TEST(Corpus, RealTapesInvariants) {
    REQUIRE_CORPUS(dir);
    const essi::Profile profile = iso();
    for (const auto& name : corpus_files(dir)) {
        if (kCommentTests.count(name)) continue;
        SCOPED_TRACE(name);
        const std::string bytes = read_file(dir + "/" + name);
        const auto r = essi::check_tape(bytes, profile);
        const essi::Stats& s = r.stats;

        // Each of these tapes cuts, and starts cutting only with `7` (geom1 turns 15 on first, then 7 while
        // 15 is on: still one pierce for its one `7`).
        const auto lines = tape_lines(bytes);
        const auto sevens = static_cast<unsigned long long>(std::count(lines.begin(), lines.end(), std::string("7")));
        EXPECT_GT(s.cut_length_mm, 0.0);
        EXPECT_EQ(s.pierces, sevens) << "one pierce per `7` block";

        for (double v : {s.cut_length_mm, s.mark_length_mm, s.travel_length_mm, s.rapid_length_mm}) {
            EXPECT_TRUE(std::isfinite(v));
            EXPECT_GE(v, 0.0);
        }
        EXPECT_LE(s.rapid_length_mm, s.travel_length_mm + kLengthTolMm) << "rapid is part of travel";
        EXPECT_DOUBLE_EQ(s.mark_length_mm, 0.0) << "no marking tool in these tapes";

        ASSERT_FALSE(s.cut_bbox.empty);
        for (double v : {s.cut_bbox.min_x, s.cut_bbox.min_y, s.cut_bbox.max_x, s.cut_bbox.max_y}) {
            EXPECT_TRUE(std::isfinite(v));
        }
        EXPECT_LE(s.cut_bbox.min_x, s.cut_bbox.max_x);
        EXPECT_LE(s.cut_bbox.min_y, s.cut_bbox.max_y);
        EXPECT_TRUE(std::isfinite(s.end_position.x) && std::isfinite(s.end_position.y));

        // 167_1 programs 39+0 (no usable feed): its time estimate is whatever the profile decides.
        if (std::find(lines.begin(), lines.end(), std::string("39+0")) == lines.end()) {
            EXPECT_TRUE(std::isfinite(s.estimated_time_s));
            EXPECT_GT(s.estimated_time_s, 0.0);
        }
    }
}

// comment1:  1 %  2 3  3 my comment  4 4  5 (empty)  6 +0+0  7 my comment too  8 0
TEST(Corpus, Comment1TextOutsideIgnoreIsAnErrorOnLine7) {
    REQUIRE_CORPUS(dir);
    const auto r = essi::check_tape(read_file(dir + "/comment1"), iso());
    SCOPED_TRACE("comment1");
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_diag(r, essi::DiagCode::E101_InvalidCharacter, 7)) << diagnostics_text(r);
    for (const auto& d : r.diagnostics) {
        if (d.severity == essi::Severity::Error) {
            EXPECT_EQ(d.line, 7u) << "only line 7 is wrong:" << diagnostics_text(r);
        }
    }
}

// comment2: two well-formed 3/4 sections (one holding `39+123`, which is text there), stops, % marks.
TEST(Corpus, Comment2SectionsAreIgnored) {
    REQUIRE_CORPUS(dir);
    const auto r = essi::check_tape(read_file(dir + "/comment2"), iso());
    SCOPED_TRACE("comment2");
    for (const auto& d : r.diagnostics) {
        EXPECT_NE(d.code, essi::DiagCode::E101_InvalidCharacter) << diagnostics_text(r);
        EXPECT_NE(d.code, essi::DiagCode::E107_UnclosedIgnore) << diagnostics_text(r);
    }
    EXPECT_DOUBLE_EQ(r.stats.cut_length_mm, 0.0);
    EXPECT_DOUBLE_EQ(r.stats.travel_length_mm, 0.0);
    EXPECT_EQ(r.stats.pierces, 0u);
}

// example.txt annotates each block with `# ...` and has `.....` placeholder lines: each such line is an E101
// error with its own line number, and no other line is an error.
TEST(Corpus, ExampleTxtAnnotationsAreErrorsOnTheirLines) {
    REQUIRE_CORPUS(dir);
    const std::string bytes = read_file(dir + "/example.txt");
    const auto r = essi::check_tape(bytes, iso());
    SCOPED_TRACE("example.txt");
    EXPECT_FALSE(r.ok());
    const auto lines = tape_lines(bytes);
    std::set<unsigned> bad_lines;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].find_first_of("#.") != std::string::npos) bad_lines.insert(static_cast<unsigned>(i + 1));
    }
    ASSERT_GE(bad_lines.size(), 15u);
    for (unsigned line : bad_lines) {
        EXPECT_TRUE(has_diag(r, essi::DiagCode::E101_InvalidCharacter, line))
            << "no E101 on line " << line << ":" << diagnostics_text(r);
    }
    for (const auto& d : r.diagnostics) {
        if (d.severity == essi::Severity::Error) {
            EXPECT_TRUE(bad_lines.count(d.line)) << "unexpected error:" << diagnostics_text(r);
        }
    }
}

// PR7.esi, a 1275 x 620 mm plate, feed 39+30 (30 mm/min):
//   ++200 (lead-in 20) -12750+0 (1275) +0+6200 (620) +12750+0 (1275) +0-6200 (620) +-200 (lead-out 20)
//   cut = 20 + 1275 + 620 + 1275 + 620 + 20 = 3830 mm; box x -1275..0, y 0..640; ends at (0,0).
//   Kerf 29 (left, the profile's 2 mm: offset 1) round the plate clockwise, i.e. outside: the lead-in runs from
//   (0,0) to the concave corner's trim point (-1,19) (sqrt(1 + 19^2)), the first side is 1 mm shorter (1274), the
//   three convex corners add quarter circles of radius 1, the rest keep their length:
//   compensated = sqrt(362) + 1274 + 620 + 1275 + 620 + 20 + 3 * pi / 2;
//   time = compensated / 30 * 60 + 1 pierce * 2 s (along the torch's path).
TEST(Corpus, PR7ExactStatistics) {
    REQUIRE_CORPUS(dir);
    const auto r = essi::check_tape(read_file(dir + "/PR7.esi"), iso());
    SCOPED_TRACE("PR7.esi");
    const auto& s = r.stats;
    EXPECT_TRUE(r.ok()) << diagnostics_text(r);
    EXPECT_NEAR(s.cut_length_mm, 3830.0, kLengthTolMm);
    EXPECT_NEAR(s.travel_length_mm, 0.0, kLengthTolMm);
    EXPECT_EQ(s.pierces, 1u);
    EXPECT_EQ(s.blocks, 12u);
    EXPECT_NEAR(s.cut_bbox.min_x, -1275.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.min_y, 0.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.max_x, 0.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.max_y, 640.0, kLengthTolMm);
    EXPECT_NEAR(s.end_position.x, 0.0, kLengthTolMm);
    EXPECT_NEAR(s.end_position.y, 0.0, kLengthTolMm);
    const double compensated = std::sqrt(362.0) + 1274 + 620 + 1275 + 620 + 20 + 3 * essi::kPi / 2;
    EXPECT_NEAR(s.cut_length_compensated_mm, compensated, kLengthTolMm);
    EXPECT_NEAR(s.estimated_time_s, compensated / 30 * 60 + 2, kTimeTolS);
}

// 115_046.esi: -200+0 (20) -1700+0 (170) +0+250 (25) +1700+0 (170), now at (-20, 25);
//   +0-250+2102-125+ : ccw arc to (-20, 0) around (-20+210.2, 25-12.5) = (190.2, 12.5),
//   r = hypot(210.2, 12.5) (the end is at the same distance), sweep = 2 * atan(12.5 / 210.2) ccw
//   (it passes angle 180 deg: x reaches 190.2 - r = -20.371, inside the box of the lines).
//   cut = 385 + r * sweep; box x -190..0, y 0..25; ends at (-20, 0).
TEST(Corpus, P115_046ExactStatistics) {
    REQUIRE_CORPUS(dir);
    const auto r = essi::check_tape(read_file(dir + "/115_046.esi"), iso());
    SCOPED_TRACE("115_046.esi");
    const auto& s = r.stats;
    const double radius = std::hypot(210.2, 12.5);
    const double sweep = 2.0 * std::atan2(12.5, 210.2);
    EXPECT_TRUE(r.ok()) << diagnostics_text(r);
    EXPECT_NEAR(s.cut_length_mm, 385.0 + radius * sweep, kLengthTolMm);
    EXPECT_NEAR(s.travel_length_mm, 0.0, kLengthTolMm);
    EXPECT_EQ(s.pierces, 1u);
    EXPECT_EQ(s.blocks, 11u);
    EXPECT_NEAR(s.cut_bbox.min_x, -190.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.min_y, 0.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.max_x, 0.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.max_y, 25.0, kLengthTolMm);
    EXPECT_NEAR(s.end_position.x, -20.0, kLengthTolMm);
    EXPECT_NEAR(s.end_position.y, 0.0, kLengthTolMm);
}

// PS178.esi: -200+0 (lead-in 20) to (-20,0); +++205++ : full ccw circle, centre (-20+20.5, 0) = (0.5, 0),
//   r = 20.5, length 41 pi. 8; rapid +580-550 (hypot(58, 55)) to (38,-55); 7:
//   +0+150 (15) -750+0 (75) +0+400 (40), now at (-37, 0); +750+0+375+0- : cw half circle around (0.5, 0),
//   r = 37.5, through the top (y = 37.5), length 37.5 pi; +0-400 (40), ends at (38, -40).
//   cut = 20 + 15 + 75 + 40 + 40 + 41 pi + 37.5 pi = 190 + 78.5 pi; 2 pierces;
//   box x -37..38, y -55..37.5.
TEST(Corpus, PS178ExactStatistics) {
    REQUIRE_CORPUS(dir);
    const auto r = essi::check_tape(read_file(dir + "/PS178.esi"), iso());
    SCOPED_TRACE("PS178.esi");
    const auto& s = r.stats;
    EXPECT_TRUE(r.ok()) << diagnostics_text(r);
    EXPECT_NEAR(s.cut_length_mm, 190.0 + 78.5 * kPi, kLengthTolMm);
    EXPECT_NEAR(s.rapid_length_mm, std::hypot(58.0, 55.0), kLengthTolMm);
    EXPECT_NEAR(s.travel_length_mm, std::hypot(58.0, 55.0), kLengthTolMm);
    EXPECT_EQ(s.pierces, 2u);
    EXPECT_EQ(s.blocks, 18u);
    EXPECT_NEAR(s.cut_bbox.min_x, -37.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.min_y, -55.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.max_x, 38.0, kLengthTolMm);
    EXPECT_NEAR(s.cut_bbox.max_y, 37.5, kLengthTolMm);
    EXPECT_NEAR(s.end_position.x, 38.0, kLengthTolMm);
    EXPECT_NEAR(s.end_position.y, -40.0, kLengthTolMm);
}

// The cut plan's diagnostics (codes 6xx) of each file of the corpus: exactly these, code and line, as listed and
// explained in docs/diagnostics.md ("The cut plan on the real tapes"). W608: the feed 39+v (v mm/min) is below
// feed_range_mm_min's 50, at the first cutting motion (167_1's 39+0 falls back to the profile's 1000 mm/min,
// 18102826's 39+55 is in the range). N603: lone circles and rectangles cut counter-clockwise with 29, the kerf
// inside (PR002: the circles around (-1420, 370), (-1320, 370) and (-1843, 0) mm, r 90, outside the 2150 x 700 mm
// rectangle that holds the other two; PR6: the circle around (0, 0), r 20, and the 290 x 210 mm rectangle, which
// lie across the edge of the last rectangle, not inside it; N612: that rectangle, cut without compensation, overlaps
// the 290 x 210 mm one, a hole in the plate by its kerf). Every other contour is a part with its kerf outside
// or a hole of one with its kerf inside, cut before it.
TEST(Corpus, CutPlanDiagnosticsAreTheDocumentedOnes) {
    REQUIRE_CORPUS(dir);
    using Expected = std::vector<std::pair<std::string, unsigned>>;
    const std::map<std::string, Expected> documented = {
        {"115_039.esi", {{"W608", 4}}},
        {"115_046.esi", {{"W608", 4}}},
        {"115_065.esi", {{"W608", 4}}},
        {"115_117.esi", {{"W608", 4}}},
        {"115_192.esi", {{"W608", 4}}},
        {"167_1.esi", {}},
        {"18102826.esi", {}},
        {"192_1.esi", {{"W608", 4}}},
        {"KH18105-1000.esi", {{"W608", 4}}},
        {"PR002.esi", {{"W608", 5}, {"N603", 6}, {"N603", 15}, {"N603", 42}}},
        {"PR003.esi", {{"W608", 5}}},
        {"PR11.esi", {{"W608", 5}}},
        {"PR4.esi", {{"W608", 5}}},
        {"PR5.esi", {{"W608", 5}}},
        {"PR6.esi", {{"W608", 4}, {"N603", 5}, {"N603", 12}, {"N612", 20}}},
        {"PR7.esi", {{"W608", 4}}},
        {"PR8.esi", {{"W608", 5}}},
        {"PR9.esi", {{"W608", 5}}},
        {"PS178.esi", {{"W608", 4}}},
        {"comment1", {}},
        {"comment2", {}},
        {"example.txt", {}},
        {"geom1", {{"W608", 13}}},
    };
    const essi::Profile profile = iso();
    const auto files = corpus_files(dir);
    EXPECT_EQ(files.size(), documented.size());
    for (const auto& name : files) {
        SCOPED_TRACE(name);
        const auto it = documented.find(name);
        if (it == documented.end()) {
            ADD_FAILURE() << "not in the documented list (docs/diagnostics.md, The cut plan on the real tapes)";
            continue;
        }
        const auto r = essi::check_tape(read_file(dir + "/" + name), profile);
        Expected found;
        for (const auto& d : r.diagnostics) {
            if (static_cast<int>(d.code) >= 600 && static_cast<int>(d.code) < 700)
                found.push_back({essi::code_name(d.code), d.line});
        }
        std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
            return a.second != b.second ? a.second < b.second : a.first < b.first;
        });
        EXPECT_EQ(found, it->second) << "diagnostics:" << diagnostics_text(r);
    }
}

}  // namespace
