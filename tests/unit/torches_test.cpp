// Multiple torches (Woyda 135+n, 136+d; docs/semantics.md §9): every cut made n times, d apart along the
// profile's torch_direction; the statistics count each torch's cut and pierce, the time once.
#include <gtest/gtest.h>

#include <string>

#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "test_util.hpp"

using namespace essi;

namespace {
const std::string kTwoTorches = "135+2\n136+1000\n7\n+100+0\n+0+100+0+50+\n8\n5\n+10+0\n6\n63\n";
}

TEST(Torches, EveryTorchCutsAndPierces) {
    const Profile woyda = *builtin_profile("woyda");
    const CheckResult one = check_tape("7\n+100+0\n+0+100+0+50+\n8\n5\n+10+0\n6\n63\n", woyda);
    const CheckResult two = check_tape(kTwoTorches, woyda);
    ASSERT_TRUE(two.diagnostics.empty()) << essi::diagnostic_message(two.diagnostics.front(), essi::Lang::En);
    EXPECT_DOUBLE_EQ(two.stats.cut_length_mm, 2 * one.stats.cut_length_mm);
    EXPECT_EQ(two.stats.pierces, 2u);
    EXPECT_DOUBLE_EQ(two.stats.travel_length_mm, one.stats.travel_length_mm);  // the carriage travels once
    EXPECT_DOUBLE_EQ(two.stats.estimated_time_s, one.stats.estimated_time_s);  // the torches cut together
    // the second torch 100 mm further along +y: the cut box reaches 100 mm higher
    EXPECT_DOUBLE_EQ(two.stats.cut_bbox.max_y, one.stats.cut_bbox.max_y + 100.0);
    EXPECT_DOUBLE_EQ(two.stats.cut_bbox.min_y, one.stats.cut_bbox.min_y);
}

TEST(Torches, RecordsCarryTheCopiesAndTheDirectionIsAProfileSetting) {
    Profile p = *builtin_profile("woyda");
    p.torch_direction = {-1, 0};
    const auto r = essi_test::run(kTwoTorches, p);
    ASSERT_GE(r.motions().size(), 3u);
    EXPECT_EQ(r.motions()[0].torches, 2);
    EXPECT_DOUBLE_EQ(r.motions()[0].torch_step.x, -100.0);
    EXPECT_DOUBLE_EQ(r.motions()[0].torch_step.y, 0.0);
    EXPECT_EQ(r.motions()[2].torches, 1);  // a travel is the carriage's: once
    const ProfileResult parsed = parse_profile(R"({"base": "woyda", "torch_direction": "-x"})");
    ASSERT_TRUE(parsed.profile.has_value());
    EXPECT_DOUBLE_EQ(parsed.profile->torch_direction.x, -1.0);
    EXPECT_FALSE(parse_profile(R"({"torch_direction": "up"})").profile.has_value());
}

TEST(Torches, CancelledBy63UnderIso) {
    // ISO reads 135/136 as unknown functions (W201): one torch; a 63 that is no end cancels the count anyway
    const CheckResult iso = check_tape(kTwoTorches, *builtin_profile("iso6582"));
    EXPECT_EQ(iso.stats.pierces, 1u);
    Profile p = *builtin_profile("woyda");
    p.end_codes = {{64, 0}};
    const CheckResult after = check_tape("135+2\n136+1000\n63\n7\n+100+0\n8\n64\n", p);
    EXPECT_EQ(after.stats.pierces, 1u);
    EXPECT_DOUBLE_EQ(after.stats.cut_length_mm, 10.0);
}
