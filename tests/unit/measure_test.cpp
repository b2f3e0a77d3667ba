// measure_motions: the radii and sweeps of arcs a checker works out ahead on its reading thread give the
// very same statistics (bit for bit) as the interpreter computing them itself: every example tape, a
// generated nest tape, and tapes with mirrors (21-28) and absolute mode (82, where nothing is taken ahead).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../bench/nest_generator.hpp"
#include "essi/interp.hpp"
#include "essi/pipeline.hpp"
#include "paths.hpp"
#include "test_util.hpp"

using namespace essi;

namespace {

// Checks `text` a chunk at a time, with or without the measures worked out ahead.
CheckResult check_chunked(std::string_view text, const Profile& p, bool ahead) {
    TapeChecker checker(text, p);
    TapeReader reader(text, p);
    Tape chunk;
    std::vector<MotionMeasure> measures;
    while (reader.read_chunk(chunk, 97)) {
        if (ahead) measure_motions(chunk, measures);
        checker.check_chunk(chunk, ahead ? std::span<const MotionMeasure>(measures) : std::span<const MotionMeasure>());
    }
    return checker.finish();
}

void expect_identical(std::string_view text, const std::string& what) {
    const Profile p;
    essi_test::expect_same_result(check_chunked(text, p, false), check_chunked(text, p, true), what);
}

}  // namespace

TEST(MeasureMotions, OneEntryPerArcInBlockOrder) {
    const Profile p;
    // a line (no entry), an arc (quarter, ccw), a function, a parabola (no entry), a cw full circle, then the end
    const Tape t = read_tape("7\n+300+400\n+100+100+0+100+\n8\n+100+50+0+40++\n+0+0+0-50-\n64\n+0+0+0-5-\n", p);
    std::vector<MotionMeasure> m;
    measure_motions(t, m);
    ASSERT_EQ(m.size(), 2u);
    EXPECT_DOUBLE_EQ(m[0].r0, 100);
    EXPECT_DOUBLE_EQ(m[0].r1, 100);
    EXPECT_NEAR(m[0].sweep, kPi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(m[1].r0, 50);
    EXPECT_DOUBLE_EQ(m[1].sweep, -2 * kPi);
}

TEST(MeasureMotions, SameStatisticsWhenWorkedOutAhead) {
    std::size_t n = 0;
    for (const auto& e : std::filesystem::directory_iterator(examples_dir())) {
        if (e.path().extension() != ".esi") continue;
        expect_identical(read_file(e.path().string()), e.path().filename().string());
        ++n;
    }
    EXPECT_GT(n, 10u);
    expect_identical(essi::bench::generate_nest_tape(400'000, 3), "generated nest tape");
    // Mirrors turn the sweep; absolute mode (82) takes nothing ahead; 83 sets an origin.
    expect_identical("7\n23\n+100+0+50+0+\n+0+100-50+50-\n26\n+100+0+50+0-\n8\n63\n", "mirrors");
    expect_identical("81\n7\n+100+0\n+200+0+150+0+\n82\n83\n+10+10\n+300+300\n+400+200+350+200-\n8\n81\n+50+50\n63\n",
                     "absolute");
}
