// The viewer's colour by (web/app/ColourBy.cpp, web/render/PathBuffers.cpp): the cuts' segments take the kinds of
// the ramp's bins by their feed or their cut's order, the other motions keep their kinds, and the legend says what
// each colour stands for.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "app/ColourBy.hpp"
#include "essi/interp.hpp"
#include "essi/parts.hpp"
#include "paths.hpp"
#include "render/PathBuffers.hpp"
#include "test_util.hpp"
#include "viewer_util.hpp"

using namespace essi;
using essi::viewer::ColourBy;
using essi::viewer::PathBuffers;

namespace {

// The tape's parts and planned motions as the viewer's TapeFacts makes them (the core's tape_parts and
// planned_motions).
struct Facts final : viewer::ColourSources {
    Facts(const std::string& bytes, const Profile& profile)
        : parts_(tape_parts(bytes, profile)), planned_(planned_motions(bytes, profile, InputFormat::Essi)) {}
    const PartsList* parts() const override { return &parts_; }
    const std::vector<PlannedMotion>* planned() const override { return &planned_; }
    PartsList parts_;
    std::vector<PlannedMotion> planned_;
};

// The segments' kinds, counted, when the document is drawn coloured `by`.
std::map<int, int> kinds_drawn(const viewer::Document& doc, ColourBy by, PathBuffers& b,
                               const viewer::ColourSources* sources = nullptr) {
    b.begin(doc, 0.01, by, sources);
    while (!b.step(1000)) {
    }
    std::map<int, int> count;
    for (const std::uint8_t k : b.staged_kinds) ++count[k];
    return count;
}

constexpr int kTravel = static_cast<int>(MotionKind::Travel), kCut = static_cast<int>(MotionKind::Cut);
constexpr int kFirstBin = viewer::kColourByCutKind, kLastBin = viewer::kColourByCutKind + viewer::kColourBins - 1;

}  // namespace

// feed_dwell.esi: one rectangle, its right edge (+0+500) at 150 mm/min, its three other edges at 300.
TEST(ViewerColourBy, TwoFeedsAreTheRampsEnds) {
    const auto doc = essi_test::load_document(read_file(examples_dir() + "/feed_dwell.esi"));
    PathBuffers b;
    const std::map<int, int> by_kind = kinds_drawn(*doc, ColourBy::Kind, b);
    EXPECT_EQ(by_kind.at(kCut), 4);
    EXPECT_TRUE(b.colour_legend(Lang::En).empty());
    const std::map<int, int> by_feed = kinds_drawn(*doc, ColourBy::Feed, b);
    EXPECT_EQ(by_feed.count(kCut), 0u);
    EXPECT_EQ(by_feed.at(kFirstBin), 1);                  // 150 mm/min
    EXPECT_EQ(by_feed.at(kLastBin), 3);                   // 300 mm/min
    EXPECT_EQ(by_feed.at(kTravel), by_kind.at(kTravel));  // (the travel keeps its kind)
    const auto legend = b.colour_legend(Lang::En);
    ASSERT_EQ(legend.size(), 2u);
    EXPECT_EQ(legend[0].text, "150 mm/min");
    EXPECT_EQ(legend[0].first_bin, 0);
    EXPECT_EQ(legend[1].text, "300 mm/min");
    EXPECT_EQ(legend[1].first_bin, viewer::kColourBins - 1);
    EXPECT_EQ(b.colour_by(), ColourBy::Feed);
}

// 20 cuts at 100, 110 ... 290 mm/min: more feeds than colours, so the range is cut into 16 equal bins.
TEST(ViewerColourBy, ManyFeedsAreBinnedByTheirRange) {
    std::string tape = "3\nTWENTY FEEDS\n4\n";
    for (int k = 0; k < 20; ++k) tape += "39+" + std::to_string(100 + 10 * k) + "\n7\n+100+0\n8\n+0+100\n";
    tape += "63\n";
    const auto doc = essi_test::load_document(tape);
    PathBuffers b;
    const std::map<int, int> by_feed = kinds_drawn(*doc, ColourBy::Feed, b);
    // floor((feed - 100) / 190 * 16): 100 and 110 in bin 0, 280 and 290 in bin 15 (the range's top is the last
    // bin's), 270 in bin 14
    EXPECT_EQ(by_feed.at(kFirstBin), 2);
    EXPECT_EQ(by_feed.at(kLastBin), 2);
    EXPECT_EQ(by_feed.at(kLastBin - 1), 1);
    int cuts = 0;
    for (int k = kFirstBin; k <= kLastBin; ++k) cuts += by_feed.count(k) ? by_feed.at(k) : 0;
    EXPECT_EQ(cuts, 20);
    const auto legend = b.colour_legend(Lang::En);
    ASSERT_EQ(legend.size(), viewer::kColourBins);
    EXPECT_EQ(legend.front().text, "100 mm/min - 112 mm/min");
    EXPECT_EQ(legend.back().text, "278 mm/min - 290 mm/min");
}

// Cut order: the first cut in the first colour, the last in the last, the others between in order.
TEST(ViewerColourBy, CutOrderRunsFromTheFirstPierceToTheLast) {
    std::string tape = "3\nFIVE CUTS\n4\n";
    for (int k = 0; k < 5; ++k) tape += "39+300\n7\n+100+0\n+0+100\n8\n+100+0\n";
    tape += "63\n";
    const auto doc = essi_test::load_document(tape);
    ASSERT_EQ(doc->pierces.size(), 5u);
    PathBuffers b;
    const std::map<int, int> by_order = kinds_drawn(*doc, ColourBy::CutOrder, b);
    // (cut - 1) * 15 / 4: bins 0, 3, 7, 11, 15, two segments each
    for (const int bin : {0, 3, 7, 11, 15}) EXPECT_EQ(by_order.at(kFirstBin + bin), 2) << bin;
    const auto legend = b.colour_legend(Lang::De);
    ASSERT_EQ(legend.size(), 2u);
    EXPECT_EQ(legend[0].text, "erster Schnitt");
    EXPECT_EQ(legend[1].text, "Schnitt 5 (der letzte)");
}

// mirrored.esi (tests/data/parts): part 1 is group 1, parts 2 and 3 (its mirror image, once turned) group 2.
// Group g takes bin ((g - 1) x 7) mod 16: every cut of the three is in bin 0 or bin 7, and more in 7.
TEST(ViewerColourBy, PartGroupsTakeTheirGroupsColours) {
    const std::string bytes = read_file(test_data_dir() + "/parts/mirrored.esi");
    const auto doc = essi_test::load_document(bytes);
    const Facts facts(bytes, doc->profile);
    ASSERT_EQ(facts.parts_.groups.size(), 2u);
    PathBuffers b;
    const std::map<int, int> by_group = kinds_drawn(*doc, ColourBy::PartGroup, b, &facts);
    EXPECT_EQ(by_group.count(kCut), 0u);
    EXPECT_GT(by_group.at(kFirstBin), 0);
    EXPECT_GT(by_group.at(kFirstBin + 7), by_group.at(kFirstBin));
    EXPECT_EQ(by_group.size(), 3u) << "travel, bin 0, bin 7";
    const auto legend = b.colour_legend(Lang::En);
    ASSERT_EQ(legend.size(), 2u);
    EXPECT_EQ(legend[0].text, "group 1 (1\u00d7)");
    EXPECT_EQ(legend[0].first_bin, 0);
    EXPECT_EQ(legend[1].text, "group 2 (2\u00d7)");
    EXPECT_EQ(legend[1].first_bin, 7);
    // Without a parts list (no sources), the cuts keep their kind.
    EXPECT_EQ(kinds_drawn(*doc, ColourBy::PartGroup, b).count(kFirstBin), 0u);
}

// Speed: what the planner reaches. circle.esi (tests/data/machine_time) cuts a circle of radius 5 mm at 6000 mm/min;
// with a = 500 mm/s² it runs at sqrt(a r) = 50 mm/s = 3000 mm/min at most. Without accel_mm_s2 speed is the feed.
TEST(ViewerColourBy, SpeedIsThePlannersTopSpeed) {
    const std::string bytes = read_file(test_data_dir() + "/machine_time/circle.esi");
    const ProfileResult accel = parse_profile(R"({"accel_mm_s2": 500, "pierce_time_s": 0})");
    ASSERT_TRUE(accel.profile);
    const auto doc = essi_test::load_document(bytes, *accel.profile);
    const Facts facts(bytes, *accel.profile);
    PathBuffers b;
    const std::map<int, int> by_speed = kinds_drawn(*doc, ColourBy::Speed, b, &facts);
    EXPECT_EQ(by_speed.count(kCut), 0u);
    auto legend = b.colour_legend(Lang::En);
    ASSERT_EQ(legend.size(), 1u);
    EXPECT_EQ(legend[0].text, "3000 mm/min");
    const auto plain = essi_test::load_document(bytes);
    const Facts none(bytes, plain->profile);
    EXPECT_TRUE(none.planned_.empty());
    (void)kinds_drawn(*plain, ColourBy::Speed, b, &none);
    legend = b.colour_legend(Lang::En);
    ASSERT_EQ(legend.size(), 1u);
    EXPECT_EQ(legend[0].text, "6000 mm/min");
}

TEST(ViewerColourBy, NamesBothWays) {
    for (const ColourBy by : viewer::kColourByModes) EXPECT_EQ(viewer::colour_by_named(viewer::colour_by_name(by)), by);
    EXPECT_EQ(viewer::colour_by_named("order"), ColourBy::CutOrder);
    EXPECT_FALSE(viewer::colour_by_named("speed!"));
    EXPECT_EQ(viewer::colour_by_named("group"), ColourBy::PartGroup);
    EXPECT_EQ(viewer::colour_by_named("speed"), ColourBy::Speed);
}
