// Golden tests over examples/: every examples/NAME.esi is checked against
//   NAME.expected.json  — ok, the multiset of (code, line) diagnostics, and statistics whose numbers were
//                         computed by hand from docs/semantics.md (not taken from the core's output);
//   NAME.trace          — the golden output of essi::trace_tape (good tapes only);
//   NAME.kerf.trace     — the golden `essi trace --kerf` of every good tape that uses kerf compensation;
//   NAME.profile.json   — the tape's own profile when the expected file names it ("profile_file"), e.g. a
//                         placement on the machine; then NAME.machine.trace is the golden `essi trace --machine`.
//
// The tape list is read from the directory at run time (natively the source tree, in WASM the preloaded
// /examples), so a new tape is tested as soon as its files are added.
//
// Regenerating the traces: run the native test binary with ESSI_UPDATE_GOLDEN=1. It then writes NAME.trace
// for every good tape instead of comparing (the expected.json files are never written: they are hand-made).
// Read every regenerated trace before committing it.
//
// expected.json format:
//   {"profile": "iso6582" | "woyda" | ..., ["profile_file": "NAME.profile.json",] "ok": bool,
//    "diagnostics": [{"code": "E301", "line": 9}, ...],          exact multiset: no extra, none missing
//    "stats": {"cut_length_mm", "mark_length_mm", "travel_length_mm", "rapid_length_mm", "pierces", "blocks",
//              "estimated_time_s", "cut_bbox_mm": {"min_x","min_y","max_x","max_y"} | null,
//              "end_position_mm": {"x","y"}, optional: "cut_length_compensated_mm", "machine_cut_bbox_mm",
//              "machine_motion_bbox_mm"}}
//   The compensated length and the time along the compensated path are the core's numbers, checked against
//   LinuxCNC's compensation by the rs274_kerf test (every end point and length within 1e-3 mm) and against
//   Clipper's offset areas by clipper_kerf.
//   A good tape (ok: true) must give every key. A bad tape may leave out keys whose value the semantics do not
//   define (e.g. where a rejected arc leaves the machine): absent keys are not compared.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "deferred_plan.hpp"
#include "essi/diagnostics.hpp"
#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/trace.hpp"
#include "paths.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Named tolerances: hand-computed lengths and positions are given to 1e-9 mm; times to 1e-9 s.
constexpr double kLengthTolMm = 1e-6;
constexpr double kTimeTolS = 1e-3;
constexpr std::size_t kMinExampleTapes = 14;

std::vector<std::string> example_names() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(examples_dir(), ec)) {
        if (!entry.is_regular_file()) continue;
        const fs::path& p = entry.path();
        if (p.extension() == ".esi" || p.extension() == ".eia") names.push_back(p.stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string path_of(const std::string& name, const std::string& suffix) { return examples_dir() + "/" + name + suffix; }

bool file_exists(const std::string& path) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

bool update_golden() {
#ifdef __EMSCRIPTEN__
    return false;  // the preloaded file system is not the source tree
#else
    const char* v = std::getenv("ESSI_UPDATE_GOLDEN");
    return v != nullptr && std::string(v) == "1";
#endif
}

// "E301 line 9"
std::string diag_key(const std::string& code, unsigned line) { return code + " line " + std::to_string(line); }

std::string list_text(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += "\n  " + x;
    return s.empty() ? "\n  (none)" : s;
}

// First line where two texts differ, for a readable failure.
std::string first_difference(const std::string& expected, const std::string& actual) {
    std::istringstream e(expected), a(actual);
    std::string le, la;
    for (int n = 1;; ++n) {
        const bool he = static_cast<bool>(std::getline(e, le));
        const bool ha = static_cast<bool>(std::getline(a, la));
        if (!he && !ha) return "(texts differ only in line ends)";
        if (!he || !ha || le != la) {
            return "line " + std::to_string(n) + "\n  golden: " + (he ? le : "<end>") +
                   "\n  actual: " + (ha ? la : "<end>");
        }
    }
}

void expect_near_key(const json& stats, const char* key, double actual, double tol) {
    if (!stats.contains(key)) return;
    SCOPED_TRACE(key);
    ASSERT_TRUE(stats[key].is_number()) << key << " must be a number";
    EXPECT_NEAR(actual, stats[key].get<double>(), tol) << key;
}

// A golden file: compared, or written under ESSI_UPDATE_GOLDEN=1.
void expect_golden(const std::string& path, const std::string& text) {
    if (update_golden()) {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        ASSERT_TRUE(out) << "cannot write " << path;
        out << text;
        std::cout << "[ golden ] wrote " << path << "\n";
        return;
    }
    ASSERT_TRUE(file_exists(path)) << "missing golden " << path
                                   << " (run the native tests with ESSI_UPDATE_GOLDEN=1, then read it)";
    const std::string golden = read_file(path);
    EXPECT_TRUE(golden == text) << "trace differs from " << path << " at " << first_difference(golden, text);
}

class ExampleTape : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleTape, MatchesExpectedAndTrace) {
    const std::string name = GetParam();
    SCOPED_TRACE(name);

    const std::string tape_path = file_exists(path_of(name, ".esi")) ? path_of(name, ".esi") : path_of(name, ".eia");
    const std::string expected_path = path_of(name, ".expected.json");
    const std::string trace_path = path_of(name, ".trace");
    ASSERT_TRUE(file_exists(expected_path)) << "missing " << expected_path;

    const std::string bytes = read_file(tape_path);
    json expected;
    try {
        expected = json::parse(read_file(expected_path));
    } catch (const json::exception& e) {
        FAIL() << expected_path << ": " << e.what();
    }

    const std::string profile_name = expected.value("profile", std::string("iso6582"));
    std::optional<essi::Profile> profile = essi::builtin_profile(profile_name);
    ASSERT_TRUE(profile.has_value()) << "unknown profile " << profile_name;
    const std::string profile_file = expected.value("profile_file", std::string());
    if (!profile_file.empty()) {
        const essi::ProfileResult own = essi::parse_profile(read_file(examples_dir() + "/" + profile_file));
        ASSERT_TRUE(own.profile.has_value()) << profile_file << " does not parse";
        profile = own.profile;
    }

    // The format from the content; `--profile auto` names the example's dialect.
    const essi::InputFormat format = essi::detect_input_format(bytes);
    EXPECT_EQ(essi::input_format_name(format), expected.value("input", std::string("essi")));
    const essi::DialectGuess guess = essi::guess_dialect(bytes, format);
    EXPECT_EQ(guess.profile, profile_name) << "--profile auto chooses " << guess.profile;
    const essi::CheckResult result = essi::check_tape(bytes, *profile, format);
    {
        SCOPED_TRACE("the cut plan's plates kept and analysed after the check (the viewer's way for big tapes)");
        expect_deferred_plan_is_the_same(bytes, *profile, format);
    }

    // --- ok and diagnostics: the multiset of (code, line) ---
    ASSERT_TRUE(expected.contains("ok") && expected["ok"].is_boolean());
    const bool expected_ok = expected["ok"].get<bool>();
    EXPECT_EQ(result.ok(), expected_ok);

    std::vector<std::string> want, got;
    for (const auto& d : expected.at("diagnostics")) {
        want.push_back(diag_key(d.at("code").get<std::string>(), d.at("line").get<unsigned>()));
    }
    std::string got_detail;
    for (const auto& d : result.diagnostics) {
        got.push_back(diag_key(essi::code_name(d.code), d.line));
        got_detail += "\n  " + essi::code_name(d.code) + " line " + std::to_string(d.line) + " col " +
                      std::to_string(d.column) + ": " + essi::diagnostic_message(d, essi::Lang::En);
    }
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    EXPECT_EQ(want, got) << "expected diagnostics:" << list_text(want)
                         << "\nactual diagnostics:" << (got_detail.empty() ? std::string("\n  (none)") : got_detail);

    // --- statistics ---
    ASSERT_TRUE(expected.contains("stats") && expected["stats"].is_object());
    const json& st = expected["stats"];
    const essi::Stats& s = result.stats;
    if (expected_ok) {
        for (const char* key : {"cut_length_mm", "mark_length_mm", "travel_length_mm", "rapid_length_mm", "pierces",
                                "blocks", "estimated_time_s", "cut_bbox_mm", "end_position_mm"}) {
            EXPECT_TRUE(st.contains(key)) << "a good tape's expected file must give " << key;
        }
    }
    expect_near_key(st, "cut_length_mm", s.cut_length_mm, kLengthTolMm);
    expect_near_key(st, "mark_length_mm", s.mark_length_mm, kLengthTolMm);
    expect_near_key(st, "travel_length_mm", s.travel_length_mm, kLengthTolMm);
    expect_near_key(st, "rapid_length_mm", s.rapid_length_mm, kLengthTolMm);
    expect_near_key(st, "estimated_time_s", s.estimated_time_s, kTimeTolS);
    if (st.contains("pierces")) {
        EXPECT_EQ(s.pierces, st["pierces"].get<unsigned long long>()) << "pierces";
    }
    if (st.contains("blocks")) {
        EXPECT_EQ(s.blocks, st["blocks"].get<unsigned long long>()) << "blocks";
    }
    if (st.contains("cut_bbox_mm")) {
        const json& b = st["cut_bbox_mm"];
        if (b.is_null()) {
            EXPECT_TRUE(s.cut_bbox.empty) << "nothing is cut, the cut box must be empty";
        } else {
            EXPECT_FALSE(s.cut_bbox.empty) << "cut box";
            EXPECT_NEAR(s.cut_bbox.min_x, b.at("min_x").get<double>(), kLengthTolMm) << "cut_bbox min_x";
            EXPECT_NEAR(s.cut_bbox.min_y, b.at("min_y").get<double>(), kLengthTolMm) << "cut_bbox min_y";
            EXPECT_NEAR(s.cut_bbox.max_x, b.at("max_x").get<double>(), kLengthTolMm) << "cut_bbox max_x";
            EXPECT_NEAR(s.cut_bbox.max_y, b.at("max_y").get<double>(), kLengthTolMm) << "cut_bbox max_y";
        }
    }
    expect_near_key(st, "cut_length_compensated_mm", s.cut_length_compensated_mm, kLengthTolMm);
    for (const auto& [key, box] : {std::pair<const char*, const essi::Box*>{"machine_cut_bbox_mm", &s.machine_cut_bbox},
                                   {"machine_motion_bbox_mm", &s.machine_motion_bbox}}) {
        if (!st.contains(key)) continue;
        SCOPED_TRACE(key);
        const json& b = st[key];
        ASSERT_FALSE(box->empty);
        EXPECT_NEAR(box->min_x, b.at("min_x").get<double>(), kLengthTolMm);
        EXPECT_NEAR(box->min_y, b.at("min_y").get<double>(), kLengthTolMm);
        EXPECT_NEAR(box->max_x, b.at("max_x").get<double>(), kLengthTolMm);
        EXPECT_NEAR(box->max_y, b.at("max_y").get<double>(), kLengthTolMm);
    }
    if (st.contains("end_position_mm")) {
        const json& e = st["end_position_mm"];
        EXPECT_NEAR(s.end_position.x, e.at("x").get<double>(), kLengthTolMm) << "end x";
        EXPECT_NEAR(s.end_position.y, e.at("y").get<double>(), kLengthTolMm) << "end y";
    }

    // --- trace goldens (good tapes): the stream, the kerf path where there is one, the machine's with its own profile
    // ---
    if (!expected_ok) return;
    const std::string trace = essi::trace_tape(bytes, *profile, format);
    expect_golden(trace_path, trace);
    if (trace.find(" kerf=") != std::string::npos) {
        std::string kerf;
        (void)essi::trace_tape(
            bytes, *profile, [&](std::string_view piece) { kerf += piece; }, format, essi::kTraceDecimals,
            essi::TraceView{true, false});
        expect_golden(path_of(name, ".kerf.trace"), kerf);
    }
    if (!profile_file.empty()) {
        std::string placed;
        (void)essi::trace_tape(
            bytes, *profile, [&](std::string_view piece) { placed += piece; }, format, essi::kTraceDecimals,
            essi::TraceView{false, true});
        expect_golden(path_of(name, ".machine.trace"), placed);
    }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string n = info.param;
    for (char& c : n) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (!ok) c = '_';
    }
    return n;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleTape, ::testing::ValuesIn(example_names()), param_name);

// The folder itself: enough tapes, every expected file and golden belongs to a tape.
TEST(ExamplesDir, HasTapesAndNoOrphans) {
    const auto names = example_names();
    EXPECT_GE(names.size(), kMinExampleTapes) << "examples/ should hold at least " << kMinExampleTapes << " tapes";
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(examples_dir(), ec)) {
        const std::string file = entry.path().filename().string();
        for (const std::string suffix :
             {".expected.json", ".kerf.trace", ".machine.trace", ".profile.json", ".trace"}) {
            if (file.size() > suffix.size() && file.ends_with(suffix)) {
                const std::string stem = file.substr(0, file.size() - suffix.size());
                EXPECT_TRUE(std::binary_search(names.begin(), names.end(), stem))
                    << file << " has no " << stem << ".esi or .eia beside it";
                break;  // (the longest suffix first: x.kerf.trace is not a trace of "x.kerf")
            }
        }
    }
    EXPECT_FALSE(ec) << ec.message();
}

}  // namespace
