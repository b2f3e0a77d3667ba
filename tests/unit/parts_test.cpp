// The parts list (essi/parts.hpp): tapes of tests/data/parts/ against the numbers worked out by hand beside them
// (NAME.expected; NAME.profile.json when the tape needs a profile of its own), a real tape of the corpus, and the
// exact areas of essi/geom.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "essi/geom.hpp"
#include "essi/parts.hpp"
#include "essi/parts_report.hpp"
#include "essi/pipeline.hpp"
#include "essi/plan.hpp"
#include "essi/read.hpp"
#include "essi/interp.hpp"
#include "essi/profile.hpp"
#include "essi/report_json.hpp"
#include "paths.hpp"
#include "test_util.hpp"

namespace {

using essi::PartsList;

// A line of NAME.expected: "KIND N key value key value ..." (KIND: parts, groups, group, part, plate).
struct Expected {
    std::string kind;
    unsigned number = 0;
    std::map<std::string, std::string> values;
};

std::vector<Expected> read_expected(const std::string& path) {
    std::vector<Expected> out;
    std::istringstream in(read_file(path));
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        Expected e;
        words >> e.kind >> e.number;
        std::string key, value;
        while (words >> key >> value) e.values[key] = value;
        out.push_back(e);
    }
    return out;
}

struct Case {
    essi::Profile profile;
    PartsList parts;
    std::vector<Expected> expected;
};

Case run_case(const std::string& name) {
    const std::string dir = test_data_dir() + "/parts/";
    Case c;
    try {
        const essi::ProfileResult r = essi::parse_profile(read_file(dir + name + ".profile.json"));
        EXPECT_TRUE(r.profile.has_value()) << name << ": its profile";
        if (r.profile) c.profile = *r.profile;
    } catch (const std::runtime_error&) {
        // (no profile of its own: the default)
    }
    c.parts = essi::tape_parts(read_file(dir + name + ".esi"), c.profile);
    c.expected = read_expected(dir + name + ".expected");
    return c;
}

double number(const Expected& e, const std::string& key) { return std::stod(e.values.at(key)); }

// Each value of the line against `actual` (key -> value), within the line's "tolerance" (default 1e-6).
void expect_values(const Expected& e, const std::map<std::string, double>& actual, const std::string& what) {
    const double tolerance = e.values.count("tolerance") ? number(e, "tolerance") : 1e-6;
    for (const auto& [key, text] : e.values) {
        if (key == "tolerance" || key == "lines") continue;
        const auto it = actual.find(key);
        ASSERT_NE(it, actual.end()) << what << ": no " << key;
        EXPECT_NEAR(it->second, std::stod(text), tolerance) << what << " " << key;
    }
}

std::string lines_text(const essi::Part& p) {
    std::string s;
    for (const essi::PartCut& c : p.cuts)
        s += (s.empty() ? "" : ",") + std::to_string(c.first_line) + "-" + std::to_string(c.last_line);
    return s;
}

void check_case(const std::string& name) {
    SCOPED_TRACE(name);
    const Case c = run_case(name);
    const PartsList& p = c.parts;
    for (const Expected& e : c.expected) {
        const std::string what = e.kind + " " + std::to_string(e.number);
        if (e.kind == "parts") {
            EXPECT_EQ(p.parts.size(), e.number);
        } else if (e.kind == "groups") {
            EXPECT_EQ(p.groups.size(), e.number);
        } else if (e.kind == "group") {
            ASSERT_LE(e.number, p.groups.size()) << what;
            const essi::PartGroup& g = p.groups[e.number - 1];
            std::map<std::string, double> actual{
                {"count", g.count},       {"net_area_mm2", g.net_area_mm2},   {"length_mm", g.length_mm},
                {"width_mm", g.width_mm}, {"cut_length_mm", g.cut_length_mm}, {"holes", g.holes},
                {"pierces", g.pierces},   {"mirror_of", g.mirror_of}};
            if (g.mass_kg) actual["mass_kg"] = *g.mass_kg;
            expect_values(e, actual, what);
        } else if (e.kind == "part") {
            ASSERT_LE(e.number, p.parts.size()) << what;
            const essi::Part& part = p.parts[e.number - 1];
            expect_values(e, {{"group", part.group}, {"plate", part.plate}, {"turned_deg", part.turned_deg}}, what);
            if (e.values.count("lines")) {
                EXPECT_EQ(lines_text(part), e.values.at("lines")) << what;
            }
        } else if (e.kind == "plate") {
            ASSERT_LE(e.number, p.plates.size()) << what;
            const essi::PlateUse& u = p.plates[e.number - 1];
            std::map<std::string, double> actual{
                {"x0", u.area.min_x},          {"y0", u.area.min_y}, {"x1", u.area.max_x},
                {"y1", u.area.max_y},          {"parts", u.parts},   {"net_area_mm2", u.net_area_mm2},
                {"utilisation", u.utilisation}};
            if (u.scrap_kg) actual["scrap_kg"] = *u.scrap_kg;
            if (u.remnant) {
                actual["remnant_x0"] = u.remnant->min_x;
                actual["remnant_y0"] = u.remnant->min_y;
                actual["remnant_x1"] = u.remnant->max_x;
                actual["remnant_y1"] = u.remnant->max_y;
            }
            expect_values(e, actual, what);
        } else {
            ADD_FAILURE() << "unknown line " << e.kind;
        }
    }
}

TEST(Parts, RectangleWithARoundHoleInTwoHalfArcs) { check_case("rect_round_hole"); }
TEST(Parts, TurnedBy90AndBy37Degrees) { check_case("turned"); }
TEST(Parts, MirroredCopiesAreTheirTwinsGroup) { check_case("mirrored"); }
TEST(Parts, ALensOfTwoArcsHasItsRectangleAlongItsArcsTangents) { check_case("lens"); }

// A real tape of the corpus (KH18105-1000): a flange of four arcs and four lines round a hole of radius 65 mm,
// worked out by hand in tests/data/parts/KH18105-1000.expected.
TEST(Parts, CorpusFlangeByHand) {
    const auto dir = corpus_dir();
    if (!dir) GTEST_SKIP() << "corpus not found (../shared/corpus/essiconv): skipped";
    const PartsList p = essi::tape_parts(read_file(*dir + "/KH18105-1000.esi"), essi::Profile{});
    const std::vector<Expected> expected = read_expected(test_data_dir() + "/parts/KH18105-1000.expected");
    for (const Expected& e : expected) {
        if (e.kind != "group") continue;
        ASSERT_EQ(p.groups.size(), 1u);
        const essi::PartGroup& g = p.groups[0];
        expect_values(e,
                      {{"count", g.count},
                       {"net_area_mm2", g.net_area_mm2},
                       {"length_mm", g.length_mm},
                       {"width_mm", g.width_mm},
                       {"cut_length_mm", g.cut_length_mm},
                       {"holes", g.holes},
                       {"pierces", g.pierces},
                       {"mirror_of", g.mirror_of}},
                      "group 1");
    }
}

// The same parts list as JSON (the report's members), text and CSV.
TEST(Parts, JsonTextAndCsv) {
    const Case c = run_case("rect_round_hole");
    const nlohmann::json j = essi::parts_to_json(c.parts);
    ASSERT_EQ(j.at("groups").size(), 1u);
    EXPECT_EQ(j.at("groups")[0].at("count"), 1);
    EXPECT_NEAR(j.at("groups")[0].at("net_area_mm2").get<double>(), 4685.840735, 1e-6);
    EXPECT_EQ(j.at("groups")[0].at("mirror_of"), nullptr);
    EXPECT_EQ(j.at("parts")[0].at("cuts")[0].at("first_line"), 15);
    EXPECT_EQ(j.at("plates")[0].at("remnant_mm"), (nlohmann::json{{"x0", 102}, {"y0", 0}, {"x1", 300}, {"y1", 100}}));
    const std::string text = essi::parts_text(c.parts);
    EXPECT_NE(text.find("1 part in 1 group\n"), std::string::npos) << text;
    EXPECT_NE(text.find("group 1: 1 x, net area 4685.841 mm², outline 100.000 x 50.000 mm"), std::string::npos) << text;
    EXPECT_NE(text.find("plate 1: 300.000 x 100.000 mm (profile plate_mm), 1 part, utilisation 15.6 %"),
              std::string::npos)
        << text;
    EXPECT_EQ(essi::parts_csv(c.parts),
              "group,count,net_area_mm2,length_mm,width_mm,cut_length_mm,holes,pierces,mass_kg,mirror_of,parts\r\n"
              "1,1,4685.841,100.000,50.000,362.832,1,2,0.368,,15-18 8-9\r\n");
}

// The exact area of a parabola: the segment of y = x²/20 under its chord y = 5 is 2/3 of 20 x 5 (Archimedes), its
// centroid 3/5 of the height above the vertex.
TEST(Parts, ParabolaAreaIsExact) {
    essi::MotionRecord parabola;
    parabola.curve = essi::CurveKind::Parabola;
    parabola.start = {-10, 5};
    parabola.end = {10, 5};
    parabola.parabola = {{0, 0}, {1, 0}, {0, 1}, 10, -10, 10};
    essi::MotionRecord chord;
    chord.start = {10, 5};
    chord.end = {-10, 5};
    const essi::AreaTerms a = essi::area_terms(parabola), b = essi::area_terms(chord);
    const double twice = a.twice_area + b.twice_area;
    EXPECT_NEAR(twice / 2, 2.0 / 3 * 20 * 5, 1e-9);
    EXPECT_NEAR(-(a.y2dx + b.y2dx) / twice, 3.0, 1e-9);
    EXPECT_NEAR((a.x2dy + b.x2dy) / twice, 0.0, 1e-9);
}

// An arc's area term about its centre: a full circle of radius 10 about (3, 4) encloses 100 pi, its centroid is the
// centre.
TEST(Parts, FullCircleAreaAndCentroid) {
    essi::MotionRecord circle;
    circle.curve = essi::CurveKind::Arc;
    circle.start = circle.end = {13, 4};
    circle.centre = {3, 4};
    circle.radius = circle.end_radius = 10;
    circle.sweep = 2 * essi::kPi;
    const essi::AreaTerms t = essi::area_terms(circle);
    EXPECT_NEAR(t.twice_area / 2, 100 * essi::kPi, 1e-9);
    EXPECT_NEAR(t.x2dy / t.twice_area, 3, 1e-9);
    EXPECT_NEAR(-t.y2dx / t.twice_area, 4, 1e-9);
}

// The three ways to a parts list give the same list: the check's own pass (check_tape with parts), tape_parts, and
// find_parts over the plan's contours with the motions read back from a store (as the viewer has them).
class AllMotions final : public essi::MotionSink, public essi::MotionStore {
public:
    void on_motion(const essi::MotionRecord& m) override { motions_.push_back(m); }
    [[nodiscard]] essi::MotionRecord motion(std::size_t index) const override { return motions_.at(index); }

private:
    std::vector<essi::MotionRecord> motions_;
};

TEST(Parts, TheChecksPassTapePartsAndAStoreAgree) {
    for (const char* name : {"rect_round_hole", "turned", "mirrored"}) {
        SCOPED_TRACE(name);
        const Case c = run_case(name);
        const std::string bytes = read_file(test_data_dir() + "/parts/" + name + ".esi");
        const essi::CheckResult checked =
            essi::check_tape(bytes, c.profile, essi::InputFormat::Essi, static_cast<std::size_t>(-1), true);
        ASSERT_TRUE(checked.parts.has_value());
        AllMotions store;
        std::vector<essi::Diagnostic> ignored;
        essi::interpret(essi::read_tape(bytes, c.profile), bytes, c.profile, store, ignored);
        const PartsList stored = essi::find_parts(essi::plan_contours(bytes, c.profile), store, c.profile);
        const std::string expected = essi::parts_to_json(c.parts).dump();
        EXPECT_EQ(essi::parts_to_json(*checked.parts).dump(), expected);
        EXPECT_EQ(essi::parts_to_json(stored).dump(), expected);
        EXPECT_GT(c.parts.parts.size(), 0u);
    }
}

// The report written a piece at a time (write_report_json: the parts lists never made JSON values) is the text of
// the report's JSON value, byte for byte.
TEST(Parts, ReportWrittenInPiecesIsTheDump) {
    std::vector<essi::FileReport> files;
    for (const char* name : {"rect_round_hole", "mirrored"}) {
        const Case c = run_case(name);
        essi::FileReport f;
        f.path = std::string(name) + ".esi";
        f.result = essi::check_tape(read_file(test_data_dir() + "/parts/" + name + ".esi"), c.profile,
                                    essi::InputFormat::Essi, static_cast<std::size_t>(-1), true);
        files.push_back(std::move(f));
    }
    essi::FileReport without;  // (a file without parts between them)
    without.path = "none.esi";
    files.insert(files.begin() + 1, std::move(without));
    std::string written;
    std::size_t pieces = 0;
    essi::write_report_json(files, "iso6582", essi::Lang::En, 2, [&](std::string_view s) {
        written += s;
        ++pieces;
    });
    EXPECT_EQ(written, essi::report_to_json(files, "iso6582", essi::Lang::En).dump(2));
    EXPECT_GT(pieces, 3u);
}

}  // namespace
