// The statistics' rules the viewer shares (essi/stats.hpp): a motion's time and where the pierces are. The viewer's
// playback and markers call the same functions, so its numbers are `essi stats`' numbers.
#include <gtest/gtest.h>

#include <string>

#include "essi/pipeline.hpp"
#include "essi/stats.hpp"

using namespace essi;

TEST(StatsRules, MotionTimeIsLengthOverFeed) {
    EXPECT_DOUBLE_EQ(motion_time_s(100, 600), 10.0);  // 100 mm at 600 mm/min
    EXPECT_DOUBLE_EQ(motion_time_s(2500, 10000), 15.0);
    EXPECT_DOUBLE_EQ(motion_time_s(0, 600), 0.0);
    EXPECT_DOUBLE_EQ(motion_time_s(100, 0), 0.0);  // no feed: no time
    EXPECT_DOUBLE_EQ(motion_time_s(100, -50), 0.0);
}

TEST(StatsRules, APierceIsAtTheFirstMotionAfterCuttingStarts) {
    PierceTracker t;
    EXPECT_FALSE(t.at_motion(0));                        // travel before any tool
    EXPECT_TRUE(t.on_tools(kToolOxygen));                // cutting starts: a pierce
    EXPECT_TRUE(t.at_motion(kToolOxygen));               // ... at the first motion after it
    EXPECT_FALSE(t.at_motion(kToolOxygen));              // not at the next
    EXPECT_FALSE(t.on_tools(kToolOxygen | kToolPunch));  // a cutting tool was on already: none
    EXPECT_FALSE(t.at_motion(kToolOxygen | kToolPunch));
    EXPECT_FALSE(t.on_tools(kToolPunch));  // marking only: none
    EXPECT_TRUE(t.on_tools(kToolPunch | kToolPlasma));
    EXPECT_FALSE(t.on_tools(kToolPunch));  // off again before any motion: the pierce is at no motion
    EXPECT_FALSE(t.at_motion(kToolPunch));
    EXPECT_TRUE(t.on_tools(kToolOxygen));
    EXPECT_FALSE(t.at_motion(0));  // the first motion after it does not cut: none
    EXPECT_FALSE(t.at_motion(kToolOxygen));
}

// The statistics' time is the sum of motion_time_s over the motions (no kerf here: the compensated path is the
// programmed one) and the pierce time once a pierce.
TEST(StatsRules, TheEstimateIsTheMotionsTimesAndThePierces) {
    Profile p;
    p.rapid_mm_min = 12000;
    p.pierce_time_s = 1.5;
    // 5 rapid on, 100 mm; 6 rapid off; 39+600 feed 600 mm/min; 7 oxygen on, 60 and 80 mm; 8 off; again 80 mm; 64 end
    const std::string tape = "5\n+1000+0\n6\n39+600\n7\n+600+0\n+0+800\n8\n7\n+0-800\n8\n64\n";
    const CheckResult r = check_tape(tape, p);
    EXPECT_EQ(r.stats.pierces, 2u);
    const double want =
        motion_time_s(100, 12000) + motion_time_s(60, 600) + motion_time_s(80, 600) + motion_time_s(80, 600) + 2 * 1.5;
    EXPECT_NEAR(r.stats.estimated_time_s, want, 1e-9);
    EXPECT_NEAR(r.stats.estimated_time_s, 0.5 + 6 + 8 + 8 + 3, 1e-9);
}
