// The job sheet's content and its HTML (essi/job_sheet.hpp, core/draw/job_sheet*.cpp): the sections in their
// order with the check's numbers as the reports write them, the drawing placed on paper, the parts seam, the date,
// the three languages. (The PDF is native: tests/cli/report_cli.py.)
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "essi/dialect.hpp"
#include "essi/job_sheet.hpp"
#include "essi/profile.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "paths.hpp"

namespace {

using essi::JobSheet;
using essi::Lang;

struct Checked {
    std::string bytes;
    essi::TapeSetup setup;
    essi::JobSheetResult sheet;
};

Checked sheet_of(const std::string& example, Lang lang = Lang::En, std::size_t max_diagnostics = 200) {
    Checked c;
    c.bytes = read_file(examples_dir() + "/" + example);
    c.setup = essi::setup_tape(c.bytes, std::nullopt, essi::builtin_profile("iso6582"));
    essi::JobSheetInput in;
    in.tape_name = example;
    in.sha256 = std::string(64, 'a');
    in.created_unix = 1764201600;  // 2025-11-27 00:00 UTC
    in.lang = lang;
    in.max_diagnostics = max_diagnostics;
    c.sheet = essi::job_sheet(c.bytes, c.setup, in);
    return c;
}

const essi::SheetSection* section(const JobSheet& s, const std::string& id) {
    for (const essi::SheetSection& sec : s.sections)
        if (sec.id == id) return &sec;
    return nullptr;
}

std::string field(const JobSheet& s, const std::string& id, essi::Msg label, Lang lang = Lang::En) {
    const essi::SheetSection* sec = section(s, id);
    if (!sec) return "(no section " + id + ")";
    for (const essi::SheetField& f : sec->fields)
        if (f.label == essi::text(label, lang)) return f.value;
    return "(no field)";
}

std::vector<std::string> ids(const JobSheet& s) {
    std::vector<std::string> out;
    for (const essi::SheetSection& sec : s.sections) out.push_back(sec.id);
    return out;
}

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(JobSheet, SectionsInOrderWithTheReportsNumbers) {
    const Checked c = sheet_of("plan_collision.esi");
    const JobSheet& s = c.sheet.sheet;
    EXPECT_EQ(ids(s), (std::vector<std::string>{"job", "drawing", "statistics", "time", "parts", "plates", "profile",
                                                "diagnostics"}));
    EXPECT_EQ(s.title, "Job sheet");
    EXPECT_EQ(field(s, "job", essi::Msg::SheetTape), "plan_collision.esi");
    EXPECT_EQ(field(s, "job", essi::Msg::SheetSha256), std::string(64, 'a'));
    EXPECT_EQ(field(s, "job", essi::Msg::SheetDate), "2025-11-27 00:00 UTC");
    EXPECT_EQ(field(s, "job", essi::Msg::SheetResult), "2 errors");
    EXPECT_EQ(field(s, "job", essi::Msg::SheetInputFormat), "essi");
    // The statistics are essi stats' rows: the cut length of the expected JSON (1825 mm).
    EXPECT_EQ(field(s, "statistics", essi::Msg::StatsCutLength), "1825.000 mm");
    EXPECT_EQ(field(s, "statistics", essi::Msg::StatsPierces), "3");
    EXPECT_EQ(field(s, "statistics", essi::Msg::StatsEstimatedTime), "(no field)");  // (under time and cost)
    const double t = c.sheet.result.stats.estimated_time_s;
    EXPECT_EQ(field(s, "time", essi::Msg::StatsEstimatedTime),
              essi::fixed_text(t, 1) + " s (" + essi::format_duration(t) + ")");
    EXPECT_EQ(field(s, "profile", essi::Msg::SheetProfileName), "iso6582");
    EXPECT_EQ(field(s, "profile", essi::Msg::SheetUnit), "0.1 mm");
    EXPECT_EQ(field(s, "profile", essi::Msg::SheetKerfWidth), "2.000 mm");
    EXPECT_EQ(field(s, "profile", essi::Msg::SheetFeed), "1000 mm/min");
    EXPECT_EQ(field(s, "profile", essi::Msg::SheetTravelLimits), "unlimited");
    EXPECT_EQ(s.footer, "plan_collision.esi · SHA-256 aaaaaaaaaaaaaaaa… · 2025-11-27 00:00 UTC");
}

TEST(JobSheet, TheOpenDiagnosticsAreListedAndMarked) {
    const Checked c = sheet_of("plan_collision.esi");
    const essi::SheetSection* d = section(c.sheet.sheet, "diagnostics");
    ASSERT_TRUE(d && d->table);
    ASSERT_EQ(d->table->rows.size(), 2u);
    const std::string message = essi::diagnostic_message(c.sheet.result.diagnostics[0], Lang::En);
    EXPECT_EQ(d->table->rows[0], (std::vector<std::string>{"error", "E605", "24", message}));
    EXPECT_EQ(d->table->rows[1][1], "E605");
    EXPECT_EQ(d->table->rows[1][2], "37");
    EXPECT_EQ(d->table->row_severity[0], essi::Severity::Error);
    EXPECT_TRUE(d->note.empty());
    EXPECT_EQ(c.sheet.sheet.drawing.marks.size(), 2u);
    const auto& legend = c.sheet.sheet.legend;
    EXPECT_TRUE(std::any_of(legend.begin(), legend.end(), [](const essi::SheetLegendEntry& e) {
        return e.sample == essi::SheetLegendEntry::Sample::Mark && e.severity == essi::Severity::Error &&
               e.text == "error";
    }));
}

TEST(JobSheet, AtMostMaxDiagnosticsAndANoteForTheRest) {
    const Checked c = sheet_of("plan_collision.esi", Lang::En, 1);
    const essi::SheetSection* d = section(c.sheet.sheet, "diagnostics");
    ASSERT_TRUE(d && d->table);
    EXPECT_EQ(d->table->rows.size(), 1u);
    EXPECT_EQ(d->note, "1 more diagnostic not shown (--max-diagnostics 1)");
    EXPECT_EQ(c.sheet.sheet.drawing.marks.size(), 1u);
    EXPECT_EQ(field(c.sheet.sheet, "job", essi::Msg::SheetResult), "2 errors");  // (the verdict counts them all)
}

TEST(JobSheet, ATapeWithoutDiagnosticsSaysSo) {
    const Checked c = sheet_of("marking.esi");
    const essi::SheetSection* d = section(c.sheet.sheet, "diagnostics");
    ASSERT_TRUE(d);
    EXPECT_FALSE(d->table);
    EXPECT_EQ(d->note, "none: the tape has no open diagnostics");
    EXPECT_EQ(field(c.sheet.sheet, "job", essi::Msg::SheetResult), "ok");
}

TEST(JobSheet, TheDrawingFitsThePageAndKeepsItsAspect) {
    const Checked c = sheet_of("plan_collision.esi");
    const essi::SheetDrawing& d = c.sheet.sheet.drawing;
    EXPECT_LE(d.width_mm, essi::kSheetContentWidthMm + 1e-9);
    EXPECT_LE(d.height_mm, essi::kSheetDrawingMaxHeightMm + 1e-9);
    EXPECT_NEAR(d.width_mm / d.height_mm, (d.box.max_x - d.box.min_x) / (d.box.max_y - d.box.min_y), 1e-9);
    const essi::Point top_left = d.to_paper({d.box.min_x, d.box.max_y});
    const essi::Point bottom_right = d.to_paper({d.box.max_x, d.box.min_y});
    EXPECT_NEAR(top_left.x, 0, 1e-9);
    EXPECT_NEAR(top_left.y, 0, 1e-9);
    EXPECT_NEAR(bottom_right.x, d.width_mm, 1e-9);
    EXPECT_NEAR(bottom_right.y, d.height_mm, 1e-9);
    // Every cut is inside the box, and there is one pierce circle per pierce (one torch).
    const auto& cuts = d.paths[static_cast<std::size_t>(essi::MotionKind::Cut)];
    ASSERT_FALSE(cuts.empty());
    for (const auto& line : cuts)
        for (const essi::Point& p : line) {
            EXPECT_GE(p.x, d.box.min_x);
            EXPECT_LE(p.x, d.box.max_x);
            EXPECT_GE(p.y, d.box.min_y);
            EXPECT_LE(p.y, d.box.max_y);
        }
    EXPECT_EQ(d.pierces.size(), c.sheet.result.stats.pierces);
    EXPECT_EQ(d.labels.size(), 3u);  // (its three parts' group numbers)
}

// The core's parts list (essi/parts.hpp) through the seam: kerf_parts.esi makes part A (with its hole B) and part C.
TEST(JobSheet, PartsFromTheCoresPartsList) {
    const Checked c = sheet_of("kerf_parts.esi");
    const essi::SheetParts parts = essi::sheet_parts(c.sheet.result);
    ASSERT_EQ(parts.groups.size(), 2u);
    EXPECT_EQ(parts.groups[0].count, 1u);
    EXPECT_NEAR(parts.groups[0].width_mm, 110, 1e-9);  // (its smallest rectangle: 110 x 90 mm)
    EXPECT_NEAR(parts.groups[0].height_mm, 90, 1e-9);
    ASSERT_EQ(parts.parts.size(), 2u);
    EXPECT_EQ(parts.parts[1].group, 2u);
    ASSERT_EQ(parts.plates.size(), 1u);
    const essi::SheetSection* p = section(c.sheet.sheet, "parts");
    ASSERT_TRUE(p && p->table);
    EXPECT_EQ(p->table->rows[0], (std::vector<std::string>{"1", "1", "110.000 x 90.000 mm", "8771.7 mm²"}));
    ASSERT_NE(section(c.sheet.sheet, "plates"), nullptr);
    ASSERT_EQ(c.sheet.sheet.drawing.labels.size(), 2u);
    EXPECT_EQ(c.sheet.sheet.drawing.labels[1].text, "2");
}

TEST(JobSheet, PartsThroughTheSeamNumberTheDrawing) {
    Checked c = sheet_of("kerf_parts.esi", Lang::De);
    essi::SheetParts parts;
    parts.groups.push_back({1, 2, 100, 50, 4800.26});
    parts.groups.push_back({2, 1, 30, 30, 706.86});
    parts.parts = {{1, {10, 10}}, {1, {130, 10}}, {2, {60, 80}}};
    parts.plates.push_back({1, 3000, 1500, 0.734, essi::Box{2000, 0, 3000, 1500, false}});
    essi::JobSheetInput in;
    in.tape_name = "kerf_parts.esi";
    in.lang = Lang::De;
    essi::SheetDrawing drawing = c.sheet.sheet.drawing;
    drawing.labels.clear();  // (the labels of the tape's own parts list)
    const JobSheet s = essi::make_job_sheet(c.sheet.result, c.setup.profile, std::move(drawing), parts, in);
    EXPECT_EQ(ids(s), (std::vector<std::string>{"job", "drawing", "statistics", "time", "parts", "plates", "profile",
                                                "diagnostics"}));
    const essi::SheetSection* p = section(s, "parts");
    ASSERT_TRUE(p && p->table);
    EXPECT_EQ(p->title, "Teile");
    EXPECT_EQ(p->table->columns, (std::vector<std::string>{"Gruppe", "Anzahl", "Größe", "Fläche"}));
    EXPECT_EQ(p->table->rows[0], (std::vector<std::string>{"1", "2", "100.000 x 50.000 mm", "4800.3 mm²"}));
    const essi::SheetSection* pl = section(s, "plates");
    ASSERT_TRUE(pl && pl->table);
    EXPECT_EQ(pl->table->rows[0],
              (std::vector<std::string>{"1", "3000.000 x 1500.000 mm", "73.4 %", "1000.000 x 1500.000 mm"}));
    ASSERT_EQ(s.drawing.labels.size(), 3u);
    EXPECT_EQ(s.drawing.labels[2].text, "2");
    EXPECT_EQ(s.legend.back().sample, essi::SheetLegendEntry::Sample::Label);
    EXPECT_EQ(s.legend.back().text, "Teilegruppe");
    const std::string html = essi::job_sheet_html(s);
    EXPECT_EQ(count(html, "class=\"part-label\""), 4u);  // three on the drawing, one in the legend
    EXPECT_NE(html.find("<section id=\"plates\">"), std::string::npos);
}

TEST(JobSheet, EveryLabelInTheSheetsLanguage) {
    const Checked de = sheet_of("plan_collision.esi", Lang::De);
    EXPECT_EQ(de.sheet.sheet.title, "Auftragsblatt");
    EXPECT_EQ(field(de.sheet.sheet, "statistics", essi::Msg::StatsCutLength, Lang::De), "1825.000 mm");
    EXPECT_EQ(section(de.sheet.sheet, "diagnostics")->table->rows[0][0], "Fehler");
    EXPECT_EQ(de.sheet.sheet.page_template, "Seite {0} von {1}");
    const Checked zh = sheet_of("plan_collision.esi", Lang::Zh);
    EXPECT_EQ(zh.sheet.sheet.title, "切割作业单");
    EXPECT_EQ(section(zh.sheet.sheet, "statistics")->title, "统计");
    EXPECT_EQ(field(zh.sheet.sheet, "statistics", essi::Msg::StatsCutLength, Lang::Zh), "1825.000 mm");
    EXPECT_EQ(section(zh.sheet.sheet, "diagnostics")->table->columns[1], "代码");
    EXPECT_EQ(section(zh.sheet.sheet, "diagnostics")->table->rows[0][3],
              essi::diagnostic_message(zh.sheet.result.diagnostics[0], Lang::Zh));
}

TEST(JobSheet, DatesInUtc) {
    EXPECT_EQ(essi::sheet_date_text(0), "1970-01-01 00:00 UTC");
    EXPECT_EQ(essi::sheet_date_text(951782400 + 3600 * 13 + 60 * 7), "2000-02-29 13:07 UTC");
    EXPECT_EQ(essi::sheet_date_text(-1), "1969-12-31 23:59 UTC");
    EXPECT_EQ(essi::sheet_date_text(4102444800), "2100-01-01 00:00 UTC");
}

TEST(JobSheetHtml, OneSelfContainedFileWithTheSheetsNumbers) {
    const Checked c = sheet_of("plan_collision.esi", Lang::Zh);
    const std::string html = essi::job_sheet_html(c.sheet.sheet);
    EXPECT_EQ(html.rfind("<!DOCTYPE html>\n<html lang=\"zh\">", 0), 0u);
    EXPECT_NE(html.find("@page { size: A4 portrait;"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    EXPECT_EQ(html.find("src="), std::string::npos);
    EXPECT_NE(html.find("<h1>切割作业单</h1>"), std::string::npos);
    EXPECT_NE(html.find("<td>1825.000 mm</td>"), std::string::npos);
    EXPECT_NE(html.find(std::string(64, 'a')), std::string::npos);
    EXPECT_EQ(count(html, "<tr class=\"error\">"), 2u);
    EXPECT_EQ(count(html, "<section "), count(html, "</section>"));
    EXPECT_EQ(count(html, "<section "), c.sheet.sheet.sections.size());
    // The drawing: paper millimetres, a path per kind drawn, a mark per placed diagnostic.
    const essi::SheetDrawing& d = c.sheet.sheet.drawing;
    EXPECT_NE(html.find("width=\"" + essi::fixed_text(d.width_mm, 2) + "mm\""), std::string::npos);
    EXPECT_EQ(count(html, "<path class=\"cut\""), 1u);
    EXPECT_EQ(count(html, "<g class=\"mark error\""), d.marks.size() + 1);  // (and the legend's sample)
}

TEST(JobSheetHtml, TextIsEscaped) {
    Checked c = sheet_of("marking.esi");
    essi::JobSheetInput in;
    in.tape_name = "a<b>&\"c\".esi";
    const JobSheet s = essi::make_job_sheet(c.sheet.result, c.setup.profile, c.sheet.sheet.drawing, {}, in);
    const std::string html = essi::job_sheet_html(s);
    EXPECT_NE(html.find("a&lt;b&gt;&amp;&quot;c&quot;.esi"), std::string::npos);
    EXPECT_EQ(html.find("a<b>"), std::string::npos);
}

TEST(StatsRows, WhatEssiStatsLists) {
    essi::Stats st;
    st.cut_length_mm = 12.5;
    st.pierces = 2;
    const std::vector<essi::StatsRow> rows = essi::stats_rows(st);
    ASSERT_EQ(rows.size(), 11u);
    EXPECT_EQ(rows[0].key, essi::Msg::StatsCutLength);
    EXPECT_EQ(rows[0].text(Lang::De), "12.500 mm");
    EXPECT_EQ(rows[9].key, essi::Msg::StatsCutBox);
    EXPECT_EQ(rows[9].text(Lang::De), "keiner");
}

// With the profile's accel_mm_s2, costs and consumables the machine time, the cost and the electrodes are rows of
// essi stats and go under "Time and cost". tests/data/machine_time/line.esi: 1.2 s (line.expected), one pierce
// (of 0 s): machine 3600/h × 1.2 s = 1.20, pierce 0.50, cut 0.00, material none (no plate_mm): 1.70 EUR; an
// electrode lasts 4 pierces: 0.25 of one.
TEST(JobSheet, TheMachineTimeAndTheCostUnderTimeAndCost) {
    const essi::ProfileResult p = essi::parse_profile(
        R"({"accel_mm_s2": 500, "pierce_time_s": 0, "costs": {"currency": "EUR", "machine_per_hour": 3600,
            "per_pierce": 0.5}, "consumables": {"electrode_pierces": 4}})");
    ASSERT_TRUE(p.profile.has_value());
    const std::string bytes = read_file(test_data_dir() + "/machine_time/line.esi");
    const essi::TapeSetup setup = essi::setup_tape(bytes, std::nullopt, *p.profile);
    essi::JobSheetInput in;
    in.tape_name = "line.esi";
    in.lang = Lang::De;
    const essi::JobSheetResult r = essi::job_sheet(bytes, setup, in);
    const JobSheet& s = r.sheet;
    EXPECT_EQ(field(s, "time", essi::Msg::StatsMachineTime, Lang::De), "1.2 s (0:00:01)");
    EXPECT_EQ(field(s, "time", essi::Msg::StatsMachineTimeBreakdown, Lang::De),
              "Schneiden 1.2 s, Markieren 0.0 s, Eilgang 0.0 s, Leerweg 0.0 s, Anschnitt 0.0 s, Verweilen 0.0 s; "
              "davon Beschleunigen 0.2 s");
    EXPECT_EQ(field(s, "time", essi::Msg::StatsCost, Lang::De), "1.70 EUR");
    EXPECT_EQ(field(s, "time", essi::Msg::StatsCostBreakdown, Lang::De),
              "Maschine 1.20 EUR (Maschinenzeit), Anschnitte 0.50 EUR, Schnitt 0.00 EUR, Material keiner");
    EXPECT_EQ(field(s, "time", essi::Msg::StatsElectrodes, Lang::De), "0.2500 (1 Anschnitt, 1.2 s Lichtbogen an)");
    EXPECT_EQ(field(s, "statistics", essi::Msg::StatsMachineTime, Lang::De), "(no field)");
}

TEST(StatsRows, TheMachineTimeCostAndElectrodesAfterTheEstimate) {
    essi::Stats st;
    st.machine_time = essi::MachineTime{};
    st.cost = essi::Cost{};
    st.consumables = essi::ConsumableUse{};
    const std::vector<essi::StatsRow> rows = essi::stats_rows(st);
    ASSERT_EQ(rows.size(), 16u);
    EXPECT_EQ(rows[8].key, essi::Msg::StatsEstimatedTime);
    EXPECT_EQ(rows[9].key, essi::Msg::StatsMachineTime);
    EXPECT_EQ(rows[10].key, essi::Msg::StatsMachineTimeBreakdown);
    EXPECT_EQ(rows[11].key, essi::Msg::StatsCost);
    EXPECT_EQ(rows[12].key, essi::Msg::StatsCostBreakdown);
    EXPECT_EQ(rows[12].text(Lang::En), "machine 0.00 (estimated time), pierces 0.00, cut 0.00, material none");
    EXPECT_EQ(rows[13].key, essi::Msg::StatsElectrodes);
    EXPECT_EQ(rows[14].key, essi::Msg::StatsCutBox);
}
