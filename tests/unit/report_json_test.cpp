// The JSON report contract (docs/report-schema.json) as built by core/report/report_json.cpp, which the CLI,
// the server and the viewer's state() share.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "essi/report_json.hpp"

namespace {

using essi::FileReport;

essi::Diagnostic diag(essi::Severity s, essi::DiagCode c, std::uint32_t line, std::uint32_t col, const char* msg) {
    essi::Diagnostic d;
    d.severity = s;
    d.code = c;
    d.line = line;
    d.column = col;
    d.set_text(msg);
    return d;
}

FileReport sample_ok() {
    FileReport f;
    f.path = "a.esi";
    essi::Stats& s = f.result.stats;
    s.cut_length_mm = 100.123456789;
    s.mark_length_mm = 0;
    s.travel_length_mm = 20.0000004;
    s.rapid_length_mm = 10;
    s.pierces = 2;
    s.blocks = 17;
    s.motions = 9;
    s.estimated_time_s = 12.5;
    s.cut_bbox.min_x = -10;
    s.cut_bbox.min_y = -5;
    s.cut_bbox.max_x = 30.1234567;
    s.cut_bbox.max_y = 40;
    s.cut_bbox.empty = false;
    s.end_position = {-0.0000001, 3};
    f.result.diagnostics.push_back(
        diag(essi::Severity::Warning, essi::DiagCode::W109_WhitespaceSkipped, 4, 3, "space skipped"));
    return f;
}

FileReport sample_bad() {
    FileReport f;
    f.path = "b.esi";
    f.result.diagnostics.push_back(
        diag(essi::Severity::Error, essi::DiagCode::E101_InvalidCharacter, 2, 7, "invalid character '#'"));
    f.result.diagnostics.push_back(diag(essi::Severity::Warning, essi::DiagCode::W114_NoProgramEnd, 9, 1, "no end"));
    f.result.diagnostics.push_back(diag(essi::Severity::Error, essi::DiagCode::E301_ArcEndNotOnCircle, 12, 1, "arc"));
    return f;
}

TEST(ReportJson, RoundsLengthsToSixDecimals) {
    EXPECT_EQ(essi::kJsonLengthDecimals, 6);
    EXPECT_DOUBLE_EQ(essi::round_for_json(1.23456789), 1.234568);
    EXPECT_DOUBLE_EQ(essi::round_for_json(-2.0000004), -2.0);
    const double z = essi::round_for_json(-0.0000001);
    EXPECT_EQ(z, 0.0);
    EXPECT_FALSE(std::signbit(z)) << "no -0 in reports";
}

TEST(ReportJson, StatsObject) {
    const nlohmann::json j = essi::stats_to_json(sample_ok().result.stats);
    EXPECT_DOUBLE_EQ(j.at("cut_length_mm").get<double>(), 100.123457);
    EXPECT_DOUBLE_EQ(j.at("travel_length_mm").get<double>(), 20.0);
    EXPECT_TRUE(j.at("pierces").is_number_integer());
    EXPECT_EQ(j.at("pierces").get<int>(), 2);
    EXPECT_EQ(j.at("blocks").get<int>(), 17);
    EXPECT_EQ(j.at("motions").get<int>(), 9);
    EXPECT_TRUE(j.at("estimated_time_s").is_number_float());
    const auto& box = j.at("cut_bbox_mm");
    ASSERT_TRUE(box.is_object());
    EXPECT_DOUBLE_EQ(box.at("min_x").get<double>(), -10);
    EXPECT_DOUBLE_EQ(box.at("min_y").get<double>(), -5);
    EXPECT_DOUBLE_EQ(box.at("max_x").get<double>(), 30.123457);
    EXPECT_DOUBLE_EQ(box.at("max_y").get<double>(), 40);
    EXPECT_DOUBLE_EQ(j.at("end_position_mm").at("x").get<double>(), 0);
    EXPECT_DOUBLE_EQ(j.at("end_position_mm").at("y").get<double>(), 3);
    EXPECT_TRUE(j.at("cut_length_compensated_mm").is_number());
    EXPECT_TRUE(j.at("machine_cut_bbox_mm").is_null());  // (Stats as made here: the checker fills them)
    EXPECT_EQ(j.size(), 13u) << j.dump();
}

TEST(ReportJson, EmptyCutBoxIsNull) {
    const nlohmann::json j = essi::stats_to_json(essi::Stats{});
    EXPECT_TRUE(j.at("cut_bbox_mm").is_null());
}

TEST(ReportJson, WholeReport) {
    const std::vector<FileReport> files = {sample_ok(), sample_bad()};
    const nlohmann::json j = essi::report_to_json(files, "woyda");
    EXPECT_EQ(j.at("profile"), "woyda");
    ASSERT_EQ(j.at("files").size(), 2u);

    const auto& a = j.at("files")[0];
    EXPECT_EQ(a.at("path"), "a.esi");
    EXPECT_EQ(a.at("ok"), true);
    ASSERT_EQ(a.at("diagnostics").size(), 1u);
    const auto& d = a.at("diagnostics")[0];
    EXPECT_EQ(d.at("severity"), "warning");
    EXPECT_EQ(d.at("code"), "W109");
    EXPECT_EQ(d.at("line"), 4);
    EXPECT_EQ(d.at("column"), 3);
    EXPECT_EQ(d.at("message"), "space skipped");

    const auto& b = j.at("files")[1];
    EXPECT_EQ(b.at("ok"), false);
    ASSERT_EQ(b.at("diagnostics").size(), 3u);
    // The order the core gave (by line, column) is kept.
    EXPECT_EQ(b.at("diagnostics")[0].at("code"), "E101");
    EXPECT_EQ(b.at("diagnostics")[1].at("code"), "W114");
    EXPECT_EQ(b.at("diagnostics")[2].at("code"), "E301");
    EXPECT_TRUE(b.at("stats").at("cut_bbox_mm").is_null());

    const auto& s = j.at("summary");
    EXPECT_EQ(s.at("files"), 2);
    EXPECT_EQ(s.at("files_ok"), 1);
    EXPECT_EQ(s.at("errors"), 2);
    EXPECT_EQ(s.at("warnings"), 2);
}

// The report written a diagnostic at a time (write_report_json) is the dump of its JSON value byte for byte, in
// each language: a cut plan diagnostic with its point, contour, other places and overlap; free texts that need
// escaping (quotes, control characters, UTF-8); a file without diagnostics between files with them.
TEST(ReportJson, DiagnosticsWrittenOneAtATimeAreTheDump) {
    FileReport plan = sample_ok();
    essi::Diagnostic collide = essi::make_diagnostic(
        essi::Severity::Error, essi::DiagCode::E605_PartsCollide, 7, 0, essi::Msg::PlanKerfInsidePart,
        {essi::Msg::PlanSideLeft, essi::Msg::PlanClockwise, essi::Msg::PlanSideRight});
    collide.contour_first = 7;
    collide.contour_last = 12;
    collide.has_at = true;
    collide.at = {1.00000049, -0.0000001};
    collide.add_related({20, 25, essi::Msg::RelatedOtherPart, {}});
    collide.add_related({30, 30, essi::Msg::None, {}});
    collide.set_overlap(
        {{{0, 0}, {10.5, 0}, {10.5, 10}}, {{5, 5}, {15, 5}, {std::numeric_limits<double>::infinity(), 15}}});
    plan.result.diagnostics.push_back(collide);
    plan.result.diagnostics.push_back(diag(essi::Severity::Note, essi::DiagCode::N403_OtherDialect, 0, 0,
                                           "say \"x\" \\ tab\there\x01 \xE4\xB8\xAD\xE6\x96\x87 {0}"));
    FileReport empty;
    empty.path = "empty.esi";
    const std::vector<FileReport> files = {plan, empty, sample_bad()};
    for (const essi::Lang lang : essi::kLanguages) {
        std::string written;
        std::size_t pieces = 0;
        essi::write_report_json(files, "woyda", lang, 2, [&](std::string_view s) {
            written += s;
            ++pieces;
        });
        const std::string dump = essi::report_to_json(files, "woyda", lang).dump(2);
        EXPECT_EQ(written, dump);
        EXPECT_GT(pieces, 3u);
        EXPECT_NE(dump.find("\"overlap\""), std::string::npos);
        EXPECT_NE(dump.find("\"diagnostics\": []"), std::string::npos);  // (the file without any)
    }
}

TEST(ReportJson, EmptyReport) {
    const nlohmann::json j = essi::report_to_json({}, "iso6582");
    EXPECT_TRUE(j.at("files").is_array());
    EXPECT_TRUE(j.at("files").empty());
    EXPECT_EQ(j.at("summary").at("files"), 0);
}

TEST(ReportJson, StatsReport) {
    const std::vector<FileReport> files = {sample_ok()};
    const nlohmann::json j = essi::stats_report_to_json(files, "iso6582");
    ASSERT_EQ(j.at("files").size(), 1u);
    EXPECT_EQ(j.at("files")[0].at("path"), "a.esi");
    EXPECT_EQ(j.at("files")[0].at("stats"), essi::stats_to_json(files[0].result.stats));
    EXPECT_FALSE(j.contains("summary"));
}

TEST(ReportJson, LimitDiagnosticsCountsTheRest) {
    FileReport f;
    f.result.diagnostics = {diag(essi::Severity::Warning, essi::DiagCode::W109_WhitespaceSkipped, 1, 1, "w"),
                            diag(essi::Severity::Error, essi::DiagCode::E101_InvalidCharacter, 2, 1, "e"),
                            diag(essi::Severity::Error, essi::DiagCode::E101_InvalidCharacter, 3, 1, "e")};
    essi::limit_diagnostics(f.result, 1);
    EXPECT_EQ(f.result.diagnostics.size(), 1u);
    EXPECT_EQ(f.omitted(), 2u);
    EXPECT_EQ(f.errors(), 2u);
    EXPECT_EQ(f.warnings(), 1u);
    EXPECT_FALSE(f.ok());
}

}  // namespace
