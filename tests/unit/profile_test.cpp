// Profiles: the built-ins, partial JSON over a base, errors as E402 diagnostics, JSON round trip.
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <string>

#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "test_util.hpp"

using namespace essi;
using namespace essi_test;

namespace {

void expect_same(const Profile& a, const Profile& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.dialect, b.dialect);
    EXPECT_DOUBLE_EQ(a.unit_mm, b.unit_mm);
    EXPECT_EQ(a.whitespace, b.whitespace);
    EXPECT_EQ(a.end_codes, b.end_codes);
    EXPECT_DOUBLE_EQ(a.arc_tolerance_units, b.arc_tolerance_units);
    EXPECT_DOUBLE_EQ(a.chord_tolerance_mm, b.chord_tolerance_mm);
    EXPECT_EQ(a.optional_ignore, b.optional_ignore);
    EXPECT_EQ(a.rapid_single_block, b.rapid_single_block);
    EXPECT_EQ(a.kerf_value, b.kerf_value);
    EXPECT_DOUBLE_EQ(a.kerf_units, b.kerf_units);
    EXPECT_DOUBLE_EQ(a.default_dwell_s, b.default_dwell_s);
    EXPECT_DOUBLE_EQ(a.feed_mm_min, b.feed_mm_min);
    EXPECT_DOUBLE_EQ(a.rapid_mm_min, b.rapid_mm_min);
    EXPECT_DOUBLE_EQ(a.pierce_time_s, b.pierce_time_s);
    EXPECT_EQ(a.zero_offsets, b.zero_offsets);
    EXPECT_EQ(a.zero_offset, b.zero_offset);
    EXPECT_DOUBLE_EQ(a.plate_rotation_deg, b.plate_rotation_deg);
    EXPECT_EQ(a.marker_offset, b.marker_offset);
    EXPECT_EQ(a.powder_marker_offset, b.powder_marker_offset);
    ASSERT_EQ(a.table.has_value(), b.table.has_value());
    if (a.table) {
        EXPECT_DOUBLE_EQ(a.table->min_x_mm, b.table->min_x_mm);
        EXPECT_DOUBLE_EQ(a.table->min_y_mm, b.table->min_y_mm);
        EXPECT_DOUBLE_EQ(a.table->max_x_mm, b.table->max_x_mm);
        EXPECT_DOUBLE_EQ(a.table->max_y_mm, b.table->max_y_mm);
    }
}

}  // namespace

TEST(ProfileBuiltin, Iso6582Defaults) {
    auto p = builtin_profile("iso6582");
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->name, "iso6582");
    EXPECT_EQ(p->dialect, Dialect::Iso6582);
    // the defaults of docs/semantics.md
    EXPECT_DOUBLE_EQ(p->unit_mm, 0.1);
    EXPECT_EQ(p->whitespace, WhitespacePolicy::Skip);
    EXPECT_DOUBLE_EQ(p->arc_tolerance_units, 2.0);
    EXPECT_FALSE(p->optional_ignore);
    EXPECT_EQ(p->kerf_value, KerfValueMeaning::Width);
    EXPECT_DOUBLE_EQ(p->feed_mm_min, 1000.0);
    EXPECT_DOUBLE_EQ(p->rapid_mm_min, 10000.0);
    EXPECT_DOUBLE_EQ(p->pierce_time_s, 2.0);
    EXPECT_DOUBLE_EQ(p->default_dwell_s, 1.0);
    EXPECT_FALSE(p->table.has_value());
    const auto has_end = [&](EndCode e) {
        return std::find(p->end_codes.begin(), p->end_codes.end(), e) != p->end_codes.end();
    };
    EXPECT_FALSE(has_end({63, 0}));  // ISO: 63 cancels the stored functions, 64 ends the tape
    EXPECT_TRUE(has_end({64, 0}));
    EXPECT_FALSE(has_end({-1, '/'}));  // Woyda's
    EXPECT_TRUE(p->end_at_data_end);
    expect_same(*p, Profile{});
}

TEST(ProfileBuiltin, Woyda) {
    auto p = builtin_profile("woyda");
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->name, "woyda");
    EXPECT_EQ(p->dialect, Dialect::Woyda);
    EXPECT_DOUBLE_EQ(p->unit_mm, 0.1);  // Woyda: 1/10 mm
    EXPECT_NE(std::find(p->end_codes.begin(), p->end_codes.end(), EndCode{-1, '/'}), p->end_codes.end());
}

TEST(ProfileBuiltin, NamesAndUnknown) {
    auto names = builtin_profile_names();
    EXPECT_NE(std::find(names.begin(), names.end(), "iso6582"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "woyda"), names.end());
    for (const auto& n : names) EXPECT_TRUE(builtin_profile(n).has_value()) << n;
    EXPECT_FALSE(builtin_profile("hypertherm-xyz").has_value());
    EXPECT_FALSE(builtin_profile("").has_value());
}

TEST(ProfileParse, PartialKeepsBaseValues) {
    ProfileResult r = parse_profile(R"({"name": "shop1", "feed_mm_min": 1500, "optional_ignore": true})");
    ASSERT_TRUE(r.profile.has_value()) << dump(r.diagnostics);
    EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
    const Profile& p = *r.profile;
    EXPECT_EQ(p.name, "shop1");
    EXPECT_DOUBLE_EQ(p.feed_mm_min, 1500.0);
    EXPECT_TRUE(p.optional_ignore);
    // untouched: iso6582 values
    EXPECT_EQ(p.dialect, Dialect::Iso6582);
    EXPECT_DOUBLE_EQ(p.rapid_mm_min, 10000.0);
    EXPECT_DOUBLE_EQ(p.pierce_time_s, 2.0);
    EXPECT_DOUBLE_EQ(p.unit_mm, 0.1);
    EXPECT_DOUBLE_EQ(p.arc_tolerance_units, 2.0);
    EXPECT_EQ(p.whitespace, WhitespacePolicy::Skip);
}

TEST(ProfileParse, WoydaBase) {
    ProfileResult r = parse_profile(R"({"base": "woyda", "pierce_time_s": 3.5, "whitespace": "strict"})");
    ASSERT_TRUE(r.profile.has_value()) << dump(r.diagnostics);
    EXPECT_EQ(r.profile->dialect, Dialect::Woyda);
    EXPECT_DOUBLE_EQ(r.profile->pierce_time_s, 3.5);
    EXPECT_EQ(r.profile->whitespace, WhitespacePolicy::Strict);
    EXPECT_DOUBLE_EQ(r.profile->feed_mm_min, 1000.0);
}

TEST(ProfileParse, EmptyObjectIsTheBase) {
    ProfileResult r = parse_profile("{}");
    ASSERT_TRUE(r.profile.has_value()) << dump(r.diagnostics);
    Profile expected;
    expected.name = r.profile->name;  // a derived name is allowed
    expect_same(*r.profile, expected);
}

TEST(ProfileParse, MalformedJsonE402NeverThrows) {
    // Text that is no JSON object has no key to point at (the message says where the JSON stops); a key's problem
    // is at the key (line 1, column 2 here).
    for (const char* text : {"{ \"feed_mm_min\": ", "not json", "", "[1, 2]", "{\"feed_mm_min\": \"fast\"}",
                             "{\"base\": \"nosuch\"}", "{\"whitespace\": \"sometimes\"}"}) {
        ProfileResult r;
        EXPECT_NO_THROW(r = parse_profile(text)) << text;
        EXPECT_FALSE(r.profile.has_value()) << text;
        ASSERT_FALSE(r.diagnostics.empty()) << text;
        const bool key = std::string_view(text).starts_with("{\"") && std::string_view(text).ends_with("}");
        for (const auto& d : r.diagnostics) {
            EXPECT_EQ(d.code, DiagCode::E402_BadProfile) << text;
            EXPECT_EQ(d.severity, Severity::Error) << text;
            EXPECT_EQ(d.line, key ? 1u : 0u) << text;
            EXPECT_EQ(d.column, key ? 2u : 0u) << text;
            EXPECT_FALSE(essi::diagnostic_message(d, essi::Lang::En).empty()) << text;
        }
    }
}

TEST(ProfileParse, ValuesBeyondTheirRangeAreErrorsNamingKeyAndRange) {
    // A unit of 1e308 mm gave "inf" lengths and a report that said "ok".
    struct Case {
        const char* json;
        const char* key;
    } cases[] = {
        {R"({"unit_mm": 1e308})", "\"unit_mm\" must be between"},
        {R"({"feed_mm_min": 1e300})", "\"feed_mm_min\" must be between"},
        {R"({"rapid_mm_min": -5})", "\"rapid_mm_min\" must be between"},
        {R"({"pierce_time_s": 1e20})", "\"pierce_time_s\" must be between"},
        {R"({"kerf": 1e300})", "\"kerf\" must be between"},
        {R"({"setup_offset_x_mm": 1e300})", "\"setup_offset_x_mm\" must be between"},
        {R"({"plate_rotation_deg": 400})", "\"plate_rotation_deg\" must be a number between -360 and 360"},
        {R"({"zero_offset": "G57"})", "\"zero_offset\" names \"G57\", which \"zero_offsets\" does not have"},
        {R"({"zero_offsets": {"G55": {"x_mm": 1}}})", "\"zero_offsets\" entry \"G55\" needs a number \"y_mm\""},
        {R"({"zero_offsets": {"G55": {"x_mm": 1, "y_mm": 2, "z_mm": 3}}})", "unknown key \"z_mm\""},
        {R"({"tool_offsets": {"scribe": {"x_mm": 1, "y_mm": 2}}})", "\"tool_offsets\": unknown key \"scribe\""},
        {R"({"tool_offsets": {"marker": {"x_mm": 1e300, "y_mm": 2}}})",
         "\"tool_offsets.marker\" needs a number \"x_mm\""},
        {R"({"table": {"min_x_mm": -1e300, "min_y_mm": 0, "max_x_mm": 10, "max_y_mm": 10}})",
         "\"table\" needs a number \"min_x_mm\" between"}};
    for (const Case& c : cases) {
        const ProfileResult r = parse_profile(c.json);
        EXPECT_FALSE(r.profile.has_value()) << c.json;
        ASSERT_EQ(r.diagnostics.size(), 1u) << c.json;
        EXPECT_NE(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En).find(c.key), std::string::npos)
            << essi::diagnostic_message(r.diagnostics[0], essi::Lang::En);
    }
    // The largest allowed values still give finite numbers.
    const ProfileResult big = parse_profile(R"({"unit_mm": 1000, "feed_mm_min": 1e9})");
    ASSERT_TRUE(big.profile.has_value());
    const essi::CheckResult checked = essi::check_tape("7\n+999999999+999999999\n8\n64\n", *big.profile);
    EXPECT_TRUE(std::isfinite(checked.stats.cut_length_mm));
    EXPECT_TRUE(std::isfinite(checked.stats.estimated_time_s));
}

TEST(ProfileParse, AnUnknownKeyIsQuotedShort) {
    const std::string key(100000, 'k');
    const ProfileResult r = parse_profile("{\"" + key + "\": 1}");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_LT(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En).size(), 100u);
    EXPECT_NE(essi::diagnostic_message(r.diagnostics[0], essi::Lang::En).find("unknown key \"kkkk"), std::string::npos);
}

TEST(ProfileParse, SettingsTakeEffect) {
    ProfileResult r = parse_profile(R"({"feed_mm_min": 600, "pierce_time_s": 0, "rapid_mm_min": 6000})");
    ASSERT_TRUE(r.profile.has_value()) << dump(r.diagnostics);
    // 100 mm cut at 600 mm/min = 10 s; no pierce time
    auto run_result = run("7\n+1000+0\n8\n64\n", *r.profile);
    ASSERT_EQ(run_result.motions().size(), 1u);
    EXPECT_NEAR(run_result.motions()[0].feed_mm_min, 600.0, kTimeTol);
}

TEST(ProfileJson, RoundTripDefaults) {
    for (const auto& name : builtin_profile_names()) {
        Profile p = *builtin_profile(name);
        ProfileResult r = parse_profile(profile_to_json(p));
        ASSERT_TRUE(r.profile.has_value()) << name << dump(r.diagnostics);
        EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
        expect_same(*r.profile, p);
    }
}

TEST(ProfileJson, RoundTripEverySetting) {
    Profile p;
    p.name = "custom";
    p.unit_mm = 0.05;
    p.whitespace = WhitespacePolicy::Strict;
    p.end_codes = {{0, 0}, {99, 0}, {-1, '='}};
    p.arc_tolerance_units = 3.5;
    p.chord_tolerance_mm = 0.002;
    p.optional_ignore = true;
    p.rapid_single_block = true;
    p.kerf_value = KerfValueMeaning::Offset;
    p.kerf_units = 17;
    p.default_dwell_s = 0.25;
    p.feed_mm_min = 1234.5;
    p.rapid_mm_min = 15000;
    p.pierce_time_s = 1.75;
    p.zero_offsets["G54"] = {-12.5, 40};
    p.zero_offsets["G55"] = {1000, 0.25};
    p.zero_offset = "G55";
    p.plate_rotation_deg = 1.5;
    p.marker_offset = {80, -5};
    p.powder_marker_offset = {-120, 0};
    p.table = TableLimits{-10, -20, 3000, 12000};
    const std::string json = profile_to_json(p);
    ProfileResult r = parse_profile(json);
    ASSERT_TRUE(r.profile.has_value()) << json << dump(r.diagnostics);
    expect_same(*r.profile, p);
    // and once more: the JSON is stable
    EXPECT_EQ(profile_to_json(*r.profile), json);

    Profile w = *builtin_profile("woyda");
    w.feed_mm_min = 777;
    ProfileResult rw = parse_profile(profile_to_json(w));
    ASSERT_TRUE(rw.profile.has_value()) << dump(rw.diagnostics);
    expect_same(*rw.profile, w);
}

TEST(Profile, UnitsToMmAndBack) {
    essi::Profile p = *essi::builtin_profile("iso6582");
    p.zero_offsets["G54"] = {-12.5, 40};  // (program coordinates: the zero offset is the placement's)
    const essi::Point mm = essi::units_to_mm(p, 1234, -56);
    EXPECT_DOUBLE_EQ(mm.x, 1234 * 0.1);
    EXPECT_DOUBLE_EQ(mm.y, -56 * 0.1);
    long long x = 0, y = 0;
    ASSERT_TRUE(essi::mm_to_units(p, mm, x, y));
    EXPECT_EQ(x, 1234);
    EXPECT_EQ(y, -56);
    EXPECT_FALSE(essi::mm_to_units(p, {mm.x + 0.03, mm.y}, x, y));  // between two units
    EXPECT_FALSE(essi::mm_to_units(p, {1e300, 0}, x, y));           // beyond any integer
    EXPECT_FALSE(essi::mm_to_units(p, {std::nan(""), 0}, x, y));
}
