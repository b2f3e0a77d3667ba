// Two revisions of a tape compared contour by contour (essi/diff.hpp): renumbered lines and another cutting order
// change nothing; a part moved on the plate is "moved" with its offset; an edited one "changed"; the rest removed
// or added.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "essi/diff.hpp"
#include "essi/profile.hpp"

using namespace essi;

namespace {

// A square part of 100 mm at (x, y), a hole of radius 20 mm in it, cut in that order (hole first), 0.1 mm units.
std::string part(int x, int y, int size = 1000) {
    std::string s = "5\n+" + std::to_string(x * 10 + 500) + "+" + std::to_string(y * 10 + 300) + "\n6\n";
    s += "7\n+0+0+0+200+\n8\n";  // the hole (a full circle)
    s += "5\n-500-300\n6\n7\n+" + std::to_string(size) + "+0\n+0+1000\n-" + std::to_string(size) + "+0\n+0-1000\n8\n";
    s += "5\n-" + std::to_string(x * 10) + "-" + std::to_string(y * 10) + "\n6\n";  // back to the origin
    return s;
}

TapeContours contours_of(const std::string& tape) {
    TapeSetup setup;
    setup.profile = *builtin_profile("iso6582");
    return tape_contours(tape, setup);
}

}  // namespace

TEST(Diff, ContoursAreTheCutsAndMarks) {
    const TapeContours t = contours_of(part(0, 0) + "64\n");
    ASSERT_TRUE(t.check.diagnostics.empty()) << essi::diagnostic_message(t.check.diagnostics.front(), essi::Lang::En);
    ASSERT_EQ(t.contours.size(), 2u);
    EXPECT_EQ(t.contours[0].motions, 1u);  // the hole
    EXPECT_NEAR(t.contours[0].length_mm, 2 * 3.14159265358979 * 20, 1e-6);
    EXPECT_EQ(t.contours[1].motions, 4u);  // the square
    EXPECT_DOUBLE_EQ(t.contours[1].length_mm, 400.0);
    EXPECT_EQ(t.contours[1].first_line, 11u);
    EXPECT_EQ(t.contours[1].last_line, 14u);
}

TEST(Diff, RenumberedAndReorderedIsTheSame) {
    // B: a comment block before (every line number moves) and the two parts cut in the other order
    const TapeContours a = contours_of(part(0, 0) + part(200, 0) + "64\n");
    const TapeContours b = contours_of("3\nREVISION B\nNEW HEADER LINE\n4\n" + part(200, 0) + part(0, 0) + "64\n");
    const TapeDiff d = diff_contours(a.contours, b.contours);
    EXPECT_TRUE(d.same());
    EXPECT_EQ(d.count(ContourChange::Same), 4u);
}

TEST(Diff, MovedChangedRemovedAdded) {
    const TapeContours a = contours_of(part(0, 0) + part(200, 0) + part(400, 0) + "64\n");
    // part 1 the same; part 2 moved 50 mm up; part 3's square 120 mm wide (changed, its hole the same); a new part
    const TapeContours b = contours_of(part(0, 0) + part(200, 50) + part(400, 0, 1200) + part(0, 300) + "64\n");
    const TapeDiff d = diff_contours(a.contours, b.contours);
    EXPECT_EQ(d.count(ContourChange::Same), 3u);   // part 1, part 3's hole
    EXPECT_EQ(d.count(ContourChange::Moved), 2u);  // part 2's hole and square
    EXPECT_EQ(d.count(ContourChange::Changed), 1u);
    EXPECT_EQ(d.count(ContourChange::Removed), 0u);
    EXPECT_EQ(d.count(ContourChange::Added), 2u);
    for (const ContourDiff& c : d.contours) {
        if (c.change != ContourChange::Moved) continue;
        EXPECT_NEAR(c.offset.x, 0.0, 1e-9);
        EXPECT_NEAR(c.offset.y, 50.0, 1e-9);
    }
    // removed: the other way round, B's new part is gone
    const TapeDiff back = diff_contours(b.contours, a.contours);
    EXPECT_EQ(back.count(ContourChange::Removed), 2u);
    EXPECT_EQ(back.count(ContourChange::Added), 0u);
}

TEST(Diff, TextAndJsonSayWhatChangedWithTheLines) {
    const TapeContours a = contours_of(part(0, 0) + "64\n");
    const TapeContours b = contours_of("3\nX\n4\n" + part(0, 10) + "64\n");
    const TapeDiff d = diff_contours(a.contours, b.contours);
    const DiffSide sa{"a.esi", &a}, sb{"b.esi", &b};
    const std::string text = diff_text(sa, sb, d);
    EXPECT_NE(text.find("moved: A line 5 -> B line 8, by (+0.000, +10.000) mm: cut 125.664 mm from (50.000, 30.000)\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("contours: 0 same, 2 moved, 0 changed, 0 removed, 0 added\n"), std::string::npos) << text;
    EXPECT_NE(text.find("statistics: travel_length_mm"), std::string::npos) << text;
    const nlohmann::json j = nlohmann::json::parse(diff_json(sa, sb, d));
    EXPECT_EQ(j["same"], false);
    EXPECT_EQ(j["summary"]["moved"], 2);
    ASSERT_EQ(j["contours"].size(), 2u);
    EXPECT_EQ(j["contours"][0]["change"], "moved");
    EXPECT_EQ(j["contours"][0]["a"]["first_line"], 5);
    EXPECT_EQ(j["contours"][0]["b"]["first_line"], 8);
    EXPECT_EQ(j["contours"][0]["offset_mm"][1], 10.0);
    EXPECT_EQ(j["stats_change"]["cut_length_mm"]["change"], 0.0);
    EXPECT_EQ(j["a"]["path"], "a.esi");
}
