// The viewer's playback (web/app/Playback.cpp): its clock is the statistics' time (essi::statistics_time_s), motion
// by motion as the core gives it (essi::motion_seconds): the whole playback lasts what the Statistics panel shows,
// with the profile's accelerations and without.
#include <gtest/gtest.h>

#include <string>

#include "app/Playback.hpp"
#include "essi/interp.hpp"
#include "paths.hpp"
#include "test_util.hpp"
#include "viewer_util.hpp"

using namespace essi;
using essi::viewer::MotionTimes;
using essi::viewer::Playback;

namespace {

// The motion times as the viewer's TapeFacts makes them.
struct Times final : viewer::MotionTimesSource {
    Times(const std::string& bytes, const Profile& profile)
        : times(motion_seconds(bytes, profile, InputFormat::Essi)) {}
    const MotionTimes* motion_times() const override { return &times; }
    MotionTimes times;
};

// A profile that accelerates: 500 mm/s² (the machine time is longer than the estimate at the feeds).
Profile accelerating() {
    const ProfileResult r = parse_profile(R"({"accel_mm_s2": 500, "junction_deviation_mm": 0.05})");
    return r.profile ? *r.profile : Profile{};
}

// Plays on to the end in frames of `frame_s` machine seconds; returns the frames it took.
int play_to_end(Playback& p, const MotionTimes& times, float frame_s) {
    p.factor = 1;
    int frames = 0;
    while (p.playing && frames < 1000000) {
        p.advance(frame_s, times);
        ++frames;
    }
    return frames;
}

}  // namespace

// kerf_parts.esi (kerf compensation, 3 pierces: 104.63 s at the feeds, as `essi check` has it) and feed_dwell.esi (a
// dwell: 80.70 s), read without and with accelerations: the playback's total is the statistics' time, the motions'
// seconds add up to it, and playing to the end shows it as elapsed.
TEST(ViewerPlayback, LastsTheStatisticsTimeWithAndWithoutAccelerations) {
    const Profile accel = accelerating();
    ASSERT_TRUE(accel.accel_mm_s2.has_value());
    for (const auto& [name, estimate] :
         {std::pair{"kerf_parts.esi", 104.626392}, std::pair{"feed_dwell.esi", 80.697056}}) {
        const std::string bytes = read_file(examples_dir() + "/" + name);
        for (const Profile& profile : {essi_test::iso_profile(), accel}) {
            SCOPED_TRACE(std::string(name) + (profile.accel_mm_s2 ? " with accel_mm_s2" : " at the feeds"));
            const auto doc = essi_test::load_document(bytes, profile);
            const Times source(bytes, profile);
            const MotionTimes& times = source.times;
            const std::size_t n = doc->motions.size();
            ASSERT_EQ(times.size(), n);
            EXPECT_NEAR(doc->stats.estimated_time_s, estimate, 1e-5);
            const double want = profile.accel_mm_s2 ? doc->stats.machine_time->total_s : doc->stats.estimated_time_s;
            if (profile.accel_mm_s2) {
                EXPECT_GT(want, estimate + 0.05);  // (the machine time, not the estimate)
            }
            EXPECT_EQ(Playback::total_s(*doc), want);
            EXPECT_NEAR(times.before(n), want, 1e-4);
            Playback p;
            EXPECT_EQ(p.elapsed_s(*doc, source), want);  // (not playing: everything shown)
            p.toggle(n);
            EXPECT_EQ(p.elapsed_s(*doc, source), 0);
            const int frames = play_to_end(p, times, 0.25f);
            EXPECT_EQ(p.position, static_cast<double>(n));
            EXPECT_EQ(p.elapsed_s(*doc, source), want);
            EXPECT_NEAR(frames, want / 0.25, 1.0);  // (a frame's time runs on over the motions' ends)
        }
    }
}

// The clock moves through each motion in its seconds: half of a motion's seconds take the tool half along it, and
// the time at a motion is the sum of the seconds before it.
TEST(ViewerPlayback, EachMotionTakesItsSeconds) {
    const Profile accel = accelerating();
    const std::string bytes = read_file(examples_dir() + "/kerf_parts.esi");
    const auto doc = essi_test::load_document(bytes, accel);
    const Times source(bytes, accel);
    const MotionTimes& times = source.times;
    double sum = 0;
    std::size_t checked = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
        EXPECT_NEAR(times.before(k), sum, 1e-6);
        if (times.seconds(k) > 0.1) {
            Playback p;
            p.factor = 1;
            p.seek(static_cast<double>(k));
            p.playing = true;
            p.advance(static_cast<float>(times.seconds(k) / 2), times);
            EXPECT_NEAR(p.position, static_cast<double>(k) + 0.5, 1e-6);
            EXPECT_NEAR(p.elapsed_s(*doc, source), sum + times.seconds(k) / 2, 1e-6);
            ++checked;
        }
        sum += times.seconds(k);
    }
    EXPECT_GE(checked, 5u);
}
