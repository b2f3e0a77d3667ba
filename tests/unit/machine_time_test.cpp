// The machine time with acceleration, the cost and the consumables (docs/semantics.md §9), against numbers worked
// out by hand in tests/data/machine_time/NAME.expected beside each tape; the planner's window; and the profile's new
// keys' E402 diagnostics in tests/data/profile_errors/NAME.expected.
#include <algorithm>
#include <cmath>
#include <dirent.h>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "essi/interp.hpp"
#include "essi/machine_time.hpp"
#include "essi/pipeline.hpp"
#include "essi/profile.hpp"
#include "essi/report_json.hpp"
#include "paths.hpp"
#include "test_util.hpp"

namespace {

// The files of `dir` whose names end in `ext`, without it, sorted.
std::vector<std::string> names_with(const std::string& dir, const std::string& ext) {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d)) {
            const std::string n = e->d_name;
            if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0)
                names.push_back(n.substr(0, n.size() - ext.size()));
        }
        ::closedir(d);
    }
    std::sort(names.begin(), names.end());
    return names;
}

// The lines of an .expected file that are not comments or empty.
std::vector<std::string> expected_lines(const std::string& path) {
    std::vector<std::string> lines;
    std::istringstream in(read_file(path));
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') lines.push_back(line);
    return lines;
}

// The value at a path ("cost.material") of a JSON object; null when a part is missing.
nlohmann::json at_path(const nlohmann::json& j, const std::string& path) {
    const nlohmann::json* v = &j;
    std::size_t from = 0;
    for (;;) {
        const std::size_t dot = path.find('.', from);
        const std::string part = path.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
        if (!v->is_object() || !v->contains(part)) return nullptr;
        v = &(*v)[part];
        if (dot == std::string::npos) return *v;
        from = dot + 1;
    }
}

std::string machine_time_dir() { return test_data_dir() + "/machine_time"; }

class MachineTimeTape : public ::testing::TestWithParam<std::string> {};

TEST_P(MachineTimeTape, MatchesTheNumbersWorkedOutByHand) {
    const std::string base = machine_time_dir() + "/" + GetParam();
    const std::string tape = read_file(base + ".esi");
    const std::vector<std::string> lines = expected_lines(base + ".expected");
    ASSERT_FALSE(lines.empty());
    ASSERT_EQ(lines[0].rfind("profile ", 0), 0u) << "the first line gives the profile";
    const essi::ProfileResult profile = essi::parse_profile(lines[0].substr(8));
    ASSERT_TRUE(profile.profile) << essi_test::dump(profile.diagnostics);
    const essi::CheckResult result = essi::check_tape(tape, *profile.profile);
    EXPECT_TRUE(result.diagnostics.empty()) << essi_test::dump(result.diagnostics);
    const nlohmann::json stats = essi::stats_to_json(result.stats);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        const std::size_t space = line.find(' ');
        ASSERT_NE(space, std::string::npos) << line;
        const std::string key = line.substr(0, space), value = line.substr(space + 1);
        const nlohmann::json got = at_path(stats, key);
        if (value == "null") {
            EXPECT_TRUE(got.is_null()) << key << " = " << got.dump();
        } else if (value[0] == '"') {
            EXPECT_EQ(got, nlohmann::json::parse(value)) << key;
        } else {
            ASSERT_TRUE(got.is_number()) << key << " = " << got.dump();
            EXPECT_NEAR(got.get<double>(), std::stod(value), 1.5e-6) << key;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Data, MachineTimeTape, ::testing::ValuesIn(names_with(machine_time_dir(), ".esi")),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

TEST(MachineTimeData, HasTheCasesOfTheSemantics) {
    const std::vector<std::string> names = names_with(machine_time_dir(), ".esi");
    for (const char* name : {"line", "square", "square_17", "circle", "rapids", "junction_90", "cost_machine"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    for (const std::string& n : names) EXPECT_FALSE(read_file(machine_time_dir() + "/" + n + ".expected").empty()) << n;
}

// The planner's motions one by one (planned_motions: colour by speed): line.esi's 100 mm cut reaches its feed in
// 1.2 s, circle.esi's circle only sqrt(a r) = 50 mm/s in 0.728319 s (their .expected files work both out); together
// they make the machine time. Without accel_mm_s2 there are none.
TEST(PlannedMotions, TheirTimesAndTopSpeedsAreTheMachineTimes) {
    const essi::ProfileResult profile = essi::parse_profile(R"({"accel_mm_s2": 500, "pierce_time_s": 0})");
    ASSERT_TRUE(profile.profile);
    for (const auto& [name, seconds, peak] :
         {std::tuple{"line", 1.2, 6000.0}, std::tuple{"circle", 0.728319, 3000.0}}) {
        SCOPED_TRACE(name);
        const std::string tape = read_file(machine_time_dir() + "/" + name + ".esi");
        const std::vector<essi::PlannedMotion> planned =
            essi::planned_motions(tape, *profile.profile, essi::InputFormat::Essi);
        ASSERT_EQ(planned.size(), 1u);
        EXPECT_EQ(planned[0].line, 3u);
        EXPECT_EQ(planned[0].kind, essi::MotionKind::Cut);
        EXPECT_NEAR(planned[0].seconds, seconds, 1e-5);
        EXPECT_NEAR(planned[0].peak_mm_min, peak, 1e-2);
        EXPECT_NEAR(planned[0].seconds, essi::check_tape(tape, *profile.profile).stats.machine_time->cutting_s, 1e-5);
    }
    EXPECT_TRUE(essi::planned_motions("39+6000\n7\n+1000+0\n8\n64\n", essi_test::iso_profile(), essi::InputFormat::Essi)
                    .empty());
}

// The seconds of each motion (motion_seconds: the playback's clock): a rapid of 100 mm at the rapid speed (10 000
// mm/min: 0.6 s), then a cut of 100 mm at 6000 mm/min (1 s) with the pierce before it (2 s) on the line that switches
// the torch on. They add up to the statistics' time, with the planner's times too.
TEST(MotionSeconds, EachMotionHasItsLinesTimeAndTheyAddUpToTheStatistics) {
    const std::string tape = "5\n+1000+0\n6\n39+6000\n7\n+1000+0\n8\n64\n";
    const std::vector<float> seconds = essi::motion_seconds(tape, essi_test::iso_profile(), essi::InputFormat::Essi);
    ASSERT_EQ(seconds.size(), 2u);
    EXPECT_NEAR(seconds[0], 0.6, 1e-6);
    EXPECT_NEAR(seconds[1], 3.0, 1e-6);
    EXPECT_NEAR(seconds[0] + seconds[1], essi::check_tape(tape, essi_test::iso_profile()).stats.estimated_time_s, 1e-6);

    const essi::ProfileResult accel = essi::parse_profile(R"({"accel_mm_s2": 500, "pierce_time_s": 0})");
    ASSERT_TRUE(accel.profile);
    const std::string line = read_file(machine_time_dir() + "/line.esi");
    const std::vector<float> planned = essi::motion_seconds(line, *accel.profile, essi::InputFormat::Essi);
    ASSERT_EQ(planned.size(), 1u);
    EXPECT_NEAR(planned[0], 1.2, 1e-5);  // (line.expected works it out)
    EXPECT_NEAR(planned[0], essi::check_tape(line, *accel.profile).stats.machine_time->total_s, 1e-5);
}

// Without accel_mm_s2 (the built-in profiles) nothing of it is reported, and the estimate is what it was.
TEST(MachineTime, AbsentWithoutTheProfileKeys) {
    const essi::CheckResult r = essi::check_tape("39+6000\n7\n+1000+0\n8\n64\n", essi_test::iso_profile());
    EXPECT_FALSE(r.stats.machine_time.has_value());
    EXPECT_FALSE(r.stats.cost.has_value());
    EXPECT_FALSE(r.stats.consumables.has_value());
    const nlohmann::json j = essi::stats_to_json(r.stats);
    for (const char* key : {"machine_time_s", "machine_time_breakdown_s", "cost", "consumables"})
        EXPECT_FALSE(j.contains(key)) << key;
    EXPECT_DOUBLE_EQ(r.stats.estimated_time_s, 3.0);  // 1 s of cut, 2 s of pierce
}

// The planner on its own: a straight line cut into pieces that together are longer than the braking distance in
// any half window takes the time of the one line, exactly (within rounding), however many pieces.
TEST(MachineTimer, PiecesOfALineTakeTheLinesTime) {
    const double a = 500, feed = 6000;  // 100 mm/s: braking distance 10 mm
    essi::MachineTimer whole(a, 0.01), pieces(a, 0.01);
    whole.line(essi::MotionKind::Cut, {0, 0}, {200, 0}, 200, feed, 1);
    const int n = 2000;  // 0.1 mm each: 512 of them are 51.2 mm, beyond the 10 mm
    for (int i = 0; i < n; ++i) pieces.line(essi::MotionKind::Cut, {i * 0.1, 0}, {(i + 1) * 0.1, 0}, 0.1, feed, 1);
    whole.finish(0);
    pieces.finish(0);
    EXPECT_NEAR(whole.time().total_s, 2.2, 1e-12);  // 0.2 + 0.2 + 180/100
    EXPECT_NEAR(pieces.time().total_s, 2.2, 1e-9);
}

// Pieces so short that half a window cannot brake from the feed: planned as a machine with that much look-ahead
// (it slows down at the end of each half window), never faster than the ideal.
TEST(MachineTimer, TooShortForTheWindowIsPlannedAsAShorterLookAhead) {
    const double a = 500, feed = 6000;
    essi::MachineTimer pieces(a, 0.01);
    const int n = 5000;  // 0.001 mm each: half a window is 0.512 mm, far below the 10 mm to brake from 100 mm/s
    for (int i = 0; i < n; ++i)
        pieces.line(essi::MotionKind::Cut, {i * 0.001, 0}, {(i + 1) * 0.001, 0}, 0.001, feed, 1);
    pieces.finish(0);
    const double ideal = 2 * std::sqrt(5.0 / a);  // 5 mm never reach the feed: a triangle of peak √(a·L)
    EXPECT_GE(pieces.time().total_s, ideal - 1e-12);
    EXPECT_TRUE(std::isfinite(pieces.time().total_s));
    EXPECT_GT(pieces.time().total_s, ideal * 1.1);  // it does slow down
}

// 17 acts at the end of each block: the two pieces of one block (a parabola's chords, a join arc and its side)
// do not stop between them; two blocks do.
TEST(MachineTimer, BlockStopsSeparateBlocksOnly) {
    essi::MachineTimer t(500, 0.01);
    t.pause(true, true, -1);  // (17)
    essi::MotionRecord m;
    m.kind = essi::MotionKind::Cut;
    m.feed_mm_min = 6000;
    m.block = 3;
    m.start = {0, 0};
    m.end = {50, 0};
    m.length_mm = 50;
    t.motion(m);
    m.start = {50, 0};
    m.end = {100, 0};
    t.motion(m);  // the same block: straight on, no stop
    t.finish(0);
    EXPECT_NEAR(t.time().total_s, 1.2, 1e-12);
}

// The E402 of the new keys, at the line and column of the key they are about.
std::string profile_errors_dir() { return test_data_dir() + "/profile_errors"; }

class ProfileErrorFile : public ::testing::TestWithParam<std::string> {};

TEST_P(ProfileErrorFile, GivesTheseE402) {
    const std::string base = profile_errors_dir() + "/" + GetParam();
    const essi::ProfileResult r = essi::parse_profile(read_file(base + ".json"));
    EXPECT_FALSE(r.profile.has_value());
    std::vector<std::string> got;
    for (const essi::Diagnostic& d : r.diagnostics) {
        EXPECT_EQ(d.code, essi::DiagCode::E402_BadProfile);
        got.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                      essi::diagnostic_message(d, essi::Lang::En));
    }
    EXPECT_EQ(got, expected_lines(base + ".expected"));
}

INSTANTIATE_TEST_SUITE_P(Data, ProfileErrorFile, ::testing::ValuesIn(names_with(profile_errors_dir(), ".json")),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// Every new key read, shown (profile_to_json) and read back the same.
TEST(ProfileCostKeys, ReadShownAndReadBack) {
    const essi::ProfileResult r = essi::parse_profile(R"({
        "accel_mm_s2": 800, "junction_deviation_mm": 0.02,
        "material": {"name": "S355", "thickness_mm": 15, "density_kg_m3": 7850},
        "plate_mm": {"x": 3000, "y": 1500},
        "costs": {"currency": "EUR", "machine_per_hour": 90, "per_pierce": 0.05, "per_m_cut": 0.4, "material_per_kg": 1.1},
        "consumables": {"electrode_pierces": 800}})");
    ASSERT_TRUE(r.profile) << essi_test::dump(r.diagnostics);
    const essi::Profile& p = *r.profile;
    EXPECT_EQ(p.accel_mm_s2, 800);
    EXPECT_EQ(p.junction_deviation_mm, 0.02);
    ASSERT_TRUE(p.material && p.plate && p.costs && p.consumables);
    EXPECT_EQ(p.material->name, "S355");
    EXPECT_EQ(p.material->density_kg_m3, 7850);
    EXPECT_EQ(p.plate->y_mm, 1500);
    EXPECT_EQ(p.costs->currency, "EUR");
    EXPECT_EQ(p.costs->material_per_kg, 1.1);
    EXPECT_EQ(p.consumables->pierces, 800);
    EXPECT_FALSE(p.consumables->arc_s.has_value());
    const std::string shown = essi::profile_to_json(p);
    const essi::ProfileResult again = essi::parse_profile(shown);
    ASSERT_TRUE(again.profile) << essi_test::dump(again.diagnostics);
    EXPECT_EQ(essi::profile_to_json(*again.profile), shown);
    // null switches each off again
    const essi::ProfileResult off = essi::parse_profile(
        R"({"accel_mm_s2": null, "material": null, "plate_mm": null, "costs": null, "consumables": null})");
    ASSERT_TRUE(off.profile) << essi_test::dump(off.diagnostics);
    EXPECT_FALSE(off.profile->accel_mm_s2 || off.profile->material || off.profile->plate || off.profile->costs ||
                 off.profile->consumables);
}

// The built-in profiles have none of them: shown as null (and the default junction deviation).
TEST(ProfileCostKeys, BuiltInsHaveNone) {
    for (const std::string& name : essi::builtin_profile_names()) {
        const auto p = essi::builtin_profile(name);
        ASSERT_TRUE(p) << name;
        EXPECT_FALSE(p->accel_mm_s2 || p->material || p->plate || p->costs || p->consumables) << name;
        const nlohmann::json j = nlohmann::json::parse(essi::profile_to_json(*p));
        for (const char* key : {"accel_mm_s2", "material", "plate_mm", "costs", "consumables"})
            EXPECT_TRUE(j.at(key).is_null()) << name << " " << key;
        EXPECT_EQ(j.at("junction_deviation_mm"), 0.01) << name;
    }
}

}  // namespace
