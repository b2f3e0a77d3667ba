// The loading window's bar (web/app/ShownProgress.hpp): it moves on at most every kEverySeconds, at once when a new
// load starts, and shows the progress it was last given once that time has passed.
#include <gtest/gtest.h>

#include "app/ShownProgress.hpp"

namespace essi::viewer {
namespace {

constexpr double kEvery = ShownProgress::kEverySeconds;

TEST(ViewerProgress, TheFirstProgressShowsAtOnce) {
    ShownProgress bar;
    EXPECT_FLOAT_EQ(bar.update(0.1f, 100.0), 0.1f);
}

TEST(ViewerProgress, MovesOnAtMostEveryPeriod) {
    ShownProgress bar;
    bar.update(0.1f, 10.0);
    EXPECT_FLOAT_EQ(bar.update(0.2f, 10.0 + kEvery / 2), 0.1f);
    EXPECT_FLOAT_EQ(bar.update(0.3f, 10.0 + kEvery * 0.99), 0.1f);
    EXPECT_FLOAT_EQ(bar.update(0.4f, 10.0 + kEvery), 0.4f);  // the latest progress, not one in between
    EXPECT_FLOAT_EQ(bar.update(0.5f, 10.0 + kEvery * 1.5), 0.4f);
    EXPECT_FLOAT_EQ(bar.update(0.5f, 10.0 + kEvery * 2), 0.5f);
}

TEST(ViewerProgress, AnUnchangedProgressDoesNotRestartThePeriod) {
    ShownProgress bar;
    bar.update(0.1f, 0.0);
    EXPECT_FLOAT_EQ(bar.update(0.1f, kEvery * 10), 0.1f);
    // Long after the bar last moved: the next change shows at once.
    EXPECT_FLOAT_EQ(bar.update(0.2f, kEvery * 10 + 0.001), 0.2f);
}

TEST(ViewerProgress, ANewLoadStartsTheBarAgainAtOnce) {
    ShownProgress bar;
    bar.update(0.9f, 5.0);
    EXPECT_FLOAT_EQ(bar.update(0.02f, 5.0 + kEvery / 10), 0.02f);
    EXPECT_FLOAT_EQ(bar.update(0.04f, 5.0 + kEvery / 5), 0.02f);
}

}  // namespace
}  // namespace essi::viewer
