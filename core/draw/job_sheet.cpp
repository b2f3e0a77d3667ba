// The job sheet's content (essi/job_sheet.hpp): the drawing collected from the motion stream, and the sections in
// their order with their texts in the sheet's language.
#include "essi/job_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "essi/diagnostic_marks.hpp"
#include "essi/interp.hpp"
#include "essi/parts.hpp"
#include "essi/pipeline.hpp"
#include "essi/read.hpp"
#include "essi/render_svg.hpp"
#include "essi/stats.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"

namespace essi {

SheetStroke sheet_stroke(MotionKind kind) {
    switch (kind) {
        case MotionKind::Cut: return {kSvgCutColor, 0.35, 0};
        case MotionKind::Mark: return {kSvgMarkColor, 0.25, 0};
        case MotionKind::Travel: return {kSvgTravelColor, 0.15, 0.8};
        case MotionKind::Rapid: break;
    }
    return {kSvgRapidColor, 0.15, 1.5};
}

std::string_view sheet_mark_color(Severity s) {
    switch (s) {
        case Severity::Error: return kSvgErrorColor;
        case Severity::Warning: return kSvgWarningColor;
        case Severity::Note: break;
    }
    return kSvgNoteColor;
}

Point SheetDrawing::to_paper(Point p) const {
    const double w = box.max_x - box.min_x;
    const double scale = w > 0 ? width_mm / w : 1.0;
    return {(p.x - box.min_x) * scale, (box.max_y - p.y) * scale};
}

SheetParts sheet_parts(const CheckResult& result) {
    SheetParts out;
    if (!result.parts) return out;
    for (const PartGroup& g : result.parts->groups)
        out.groups.push_back({g.number, g.count, g.length_mm, g.width_mm, g.net_area_mm2});
    for (const Part& p : result.parts->parts) out.parts.push_back({p.group, p.label_at});
    for (const PlateUse& p : result.parts->plates)
        out.plates.push_back({static_cast<unsigned>(p.plate), p.area.max_x - p.area.min_x, p.area.max_y - p.area.min_y,
                              p.utilisation, p.remnant});
    return out;
}

namespace {

// Collects the drawing from the motion stream: polylines by kind (a point only where it is `tolerance` or more from
// the last one kept), the pierces, and the diagnostics' places.
class SheetSink final : public MotionSink {
public:
    SheetSink(SheetDrawing& drawing, double tolerance, DiagnosticPlaces& places)
        : drawing_(drawing), tolerance_(tolerance), places_(places) {}

    void on_motion(const MotionRecord& m) override {
        places_.motion(m.line, m.end);
        if (pierces_.at_motion(m.tools)) drawing_.pierces.push_back(m.start);
        const auto k = static_cast<std::size_t>(m.kind);
        std::vector<std::vector<Point>>& lines = drawing_.paths[k];
        if (!open_[k] || !(end_[k] == m.start)) lines.push_back({m.start});
        points_.clear();
        flatten(m, tolerance_, points_, false);
        std::vector<Point>& line = lines.back();
        for (const Point& p : points_)
            if (std::hypot(p.x - line.back().x, p.y - line.back().y) >= tolerance_) line.push_back(p);
        end_[k] = m.end;
        open_[k] = true;
    }
    void on_event(const MachineEvent& e) override { (void)pierces_.on_tools(e.tools_after); }

private:
    SheetDrawing& drawing_;
    double tolerance_;
    DiagnosticPlaces& places_;
    PierceTracker pierces_;
    std::array<Point, 4> end_{};
    std::array<bool, 4> open_{};
    std::vector<Point> points_;
};

// The program's area shown and its size on paper.
void place_drawing(SheetDrawing& d, const Stats& stats) {
    Box box = stats.motion_bbox;
    box.add(stats.cut_bbox);
    if (box.empty) box.add(Point{0, 0});
    const double extent = std::max({box.max_x - box.min_x, box.max_y - box.min_y, 10.0});
    const double margin = extent * kSheetDrawingMargin;
    const double cx = (box.min_x + box.max_x) / 2, cy = (box.min_y + box.max_y) / 2;
    const double w = std::max(box.max_x - box.min_x, 10.0) + 2 * margin;
    const double h = std::max(box.max_y - box.min_y, 10.0) + 2 * margin;
    d.box = Box{cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2, false};
    d.width_mm = kSheetContentWidthMm;
    d.height_mm = kSheetContentWidthMm * h / w;
    if (d.height_mm > kSheetDrawingMaxHeightMm) {
        d.height_mm = kSheetDrawingMaxHeightMm;
        d.width_mm = kSheetDrawingMaxHeightMm * w / h;
    }
}

std::string mm_unit(double v) { return mm_text(v) + " mm"; }
std::string size_text(double w, double h) { return mm_text(w) + " x " + mm_text(h) + " mm"; }

// The statistics that go under "Time and cost" rather than "Statistics" (every row of stats_rows about time or
// money belongs in this list).
bool is_time_or_cost(Msg key) {
    switch (key) {
        case Msg::StatsEstimatedTime:
        case Msg::StatsMachineTime:
        case Msg::StatsMachineTimeBreakdown:
        case Msg::StatsCost:
        case Msg::StatsCostBreakdown:
        case Msg::StatsElectrodes: return true;
        default: return false;
    }
}

SheetSection fields_section(std::string id, Msg title, Lang lang) {
    SheetSection s;
    s.id = std::move(id);
    s.title = text(title, lang);
    return s;
}
void add_field(SheetSection& s, Msg label, std::string value, Lang lang) {
    s.fields.push_back({std::string(text(label, lang)), std::move(value)});
}

SheetSection job_section(const CheckResult& result, const JobSheet& sheet, Lang lang) {
    SheetSection s = fields_section("job", Msg::SheetJob, lang);
    add_field(s, Msg::SheetTape, sheet.tape, lang);
    add_field(s, Msg::SheetSha256, sheet.sha256, lang);
    add_field(s, Msg::SheetDate, sheet.date, lang);
    add_field(s, Msg::SheetResult, verdict_text(result, lang), lang);
    add_field(s, Msg::SheetInputFormat, input_format_name(result.input), lang);
    return s;
}

SheetSection drawing_section(const SheetDrawing& d, Lang lang) {
    SheetSection s = fields_section("drawing", Msg::SheetDrawing, lang);
    s.drawing = true;
    s.note = format_message(Msg::SheetDrawingSize, lang,
                            {mm_text(d.box.max_x - d.box.min_x), mm_text(d.box.max_y - d.box.min_y)});
    return s;
}

// The statistics (`time` false) or the time and cost (true): stats_rows, the rows of `essi stats`.
SheetSection stats_section(const Stats& stats, bool time, Lang lang) {
    SheetSection s = time ? fields_section("time", Msg::SheetTimeCost, lang)
                          : fields_section("statistics", Msg::SheetStatistics, lang);
    for (const StatsRow& r : stats_rows(stats))
        if (is_time_or_cost(r.key) == time) add_field(s, r.key, r.text(lang), lang);
    return s;
}

SheetTable table_of(std::initializer_list<Msg> columns, Lang lang) {
    SheetTable t;
    for (const Msg c : columns) t.columns.emplace_back(text(c, lang));
    t.numeric.assign(t.columns.size(), true);
    return t;
}
void add_row(SheetTable& t, std::vector<std::string> cells, std::optional<Severity> severity = std::nullopt) {
    t.rows.push_back(std::move(cells));
    t.row_severity.push_back(severity);
}

SheetSection parts_section(const SheetParts& parts, Lang lang) {
    SheetSection s = fields_section("parts", Msg::SheetParts, lang);
    SheetTable t = table_of({Msg::SheetPartGroup, Msg::SheetPartCount, Msg::SheetPartSize, Msg::SheetPartArea}, lang);
    for (const SheetPartGroup& g : parts.groups) {
        add_row(t, {std::to_string(g.number), std::to_string(g.count), size_text(g.width_mm, g.height_mm),
                    fixed_text(g.area_mm2, 1) + " mm²"});
    }
    s.table = std::move(t);
    return s;
}

SheetSection plates_section(const SheetParts& parts, Lang lang) {
    SheetSection s = fields_section("plates", Msg::SheetPlates, lang);
    SheetTable t = table_of({Msg::SheetPlate, Msg::SheetPartSize, Msg::SheetUtilisation, Msg::SheetRemnant}, lang);
    for (const SheetPlate& p : parts.plates) {
        const std::string remnant = p.remnant && !p.remnant->empty ? size_text(p.remnant->max_x - p.remnant->min_x,
                                                                               p.remnant->max_y - p.remnant->min_y)
                                                                   : std::string(text(Msg::StatsNone, lang));
        add_row(t, {std::to_string(p.number), size_text(p.width_mm, p.height_mm),
                    fixed_text(100 * p.utilisation, 1) + " %", remnant});
    }
    s.table = std::move(t);
    return s;
}

SheetSection profile_section(const CheckResult& result, const Profile& p, Lang lang) {
    SheetSection s = fields_section("profile", Msg::SheetProfile, lang);
    add_field(s, Msg::SheetProfileName, result.profile.empty() ? p.name : result.profile, lang);
    add_field(s, Msg::SheetUnit, number_text(p.unit_mm) + " mm", lang);
    add_field(s, p.kerf_value == KerfValueMeaning::Width ? Msg::SheetKerfWidth : Msg::SheetKerfOffset,
              mm_unit(p.kerf_units * p.unit_mm), lang);
    add_field(s, Msg::SheetFeed, number_text(p.feed_mm_min) + " mm/min", lang);
    add_field(s, Msg::SheetRapid, number_text(p.rapid_mm_min) + " mm/min", lang);
    add_field(s, Msg::SheetPierceTime, number_text(p.pierce_time_s) + " s", lang);
    const Point zero = p.active_zero_offset();
    add_field(s, Msg::SheetZeroOffset, p.zero_offset + ": x " + mm_text(zero.x) + ", y " + mm_text(zero.y) + " mm",
              lang);
    add_field(s, Msg::SheetPlateRotation, number_text(p.plate_rotation_deg) + "°", lang);
    add_field(s, Msg::SheetTravelLimits,
              p.table ? "x " + mm_text(p.table->min_x_mm) + " .. " + mm_text(p.table->max_x_mm) + ", y " +
                            mm_text(p.table->min_y_mm) + " .. " + mm_text(p.table->max_y_mm) + " mm"
                      : std::string(text(Msg::SheetUnlimited, lang)),
              lang);
    return s;
}

SheetSection diagnostics_section(const CheckResult& result, Lang lang) {
    SheetSection s = fields_section("diagnostics", Msg::SheetDiagnostics, lang);
    if (result.diagnostics.empty() && result.omitted() == 0) {
        s.note = text(Msg::SheetNoDiagnostics, lang);
        return s;
    }
    SheetTable t = table_of({Msg::SheetSeverity, Msg::SheetCode, Msg::SheetLine, Msg::SheetMessage}, lang);
    t.numeric = {false, false, true, false};
    for (const Diagnostic& d : result.diagnostics) {
        add_row(t,
                {std::string(severity_text(d.severity, lang)), code_name(d.code),
                 d.line > 0 ? std::to_string(d.line) : std::string(), diagnostic_message(d, lang)},
                d.severity);
    }
    if (!t.rows.empty()) s.table = std::move(t);
    if (result.omitted() > 0)
        s.note = format_message(Msg::ReportOmitted, lang, {result.omitted(), result.diagnostics.size()});
    return s;
}

std::vector<SheetLegendEntry> legend_of(const SheetDrawing& d, Lang lang) {
    std::vector<SheetLegendEntry> legend;
    const std::pair<MotionKind, Msg> kinds[] = {{MotionKind::Cut, Msg::UiKindCut},
                                                {MotionKind::Mark, Msg::UiKindMark},
                                                {MotionKind::Travel, Msg::UiKindTravel},
                                                {MotionKind::Rapid, Msg::UiKindRapid}};
    for (const auto& [kind, word] : kinds)
        if (!d.paths[static_cast<std::size_t>(kind)].empty())
            legend.push_back({SheetLegendEntry::Sample::Stroke, std::string(text(word, lang)), kind});
    if (!d.pierces.empty())
        legend.push_back({SheetLegendEntry::Sample::Pierce, std::string(text(Msg::SheetPierceKey, lang))});
    for (const Severity sev : {Severity::Error, Severity::Warning, Severity::Note}) {
        const bool marked = std::any_of(d.marks.begin(), d.marks.end(),
                                        [sev](const SheetDrawing::Mark& m) { return m.severity == sev; });
        if (marked)
            legend.push_back(
                {SheetLegendEntry::Sample::Mark, std::string(severity_text(sev, lang)), MotionKind::Cut, sev});
    }
    if (!d.labels.empty())
        legend.push_back({SheetLegendEntry::Sample::Label, std::string(text(Msg::SheetPartGroupKey, lang))});
    return legend;
}

// Days since 1970-01-01 to the civil date (H. Hinnant's algorithm): no time zone, no C library.
void civil_date(std::int64_t days, std::int64_t& y, unsigned& m, unsigned& d) {
    days += 719468;
    const std::int64_t era = (days >= 0 ? days : days - 146096) / 146097;
    const auto doe = static_cast<unsigned>(days - era * 146097);
    const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const unsigned mp = (5 * doy + 2) / 153;
    d = doy - (153 * mp + 2) / 5 + 1;
    m = mp < 10 ? mp + 3 : mp - 9;
    y = static_cast<std::int64_t>(yoe) + era * 400 + (m <= 2 ? 1 : 0);
}

}  // namespace

std::string sheet_date_text(std::int64_t unix_seconds) {
    const std::int64_t days = (unix_seconds >= 0 ? unix_seconds : unix_seconds - 86399) / 86400;
    const std::int64_t secs = unix_seconds - days * 86400;
    std::int64_t y = 0;
    unsigned m = 0, d = 0;
    civil_date(days, y, m, d);
    char buf[80];
    std::snprintf(buf, sizeof buf, "%04lld-%02u-%02u %02lld:%02lld UTC", static_cast<long long>(y), m, d,
                  static_cast<long long>(secs / 3600), static_cast<long long>(secs / 60 % 60));
    return buf;
}

SheetDrawing draw_sheet(std::string_view bytes, const TapeSetup& setup, const std::vector<Diagnostic>& marked,
                        const Stats& stats) {
    SheetDrawing drawing;
    place_drawing(drawing, stats);
    const double extent = std::max(drawing.box.max_x - drawing.box.min_x, drawing.box.max_y - drawing.box.min_y);
    const double tolerance =
        std::max(extent * kSheetDrawingTolerance, std::max(setup.profile.chord_tolerance_mm, kMinChordTolerance));
    DiagnosticPlaces places(marked);
    SheetSink sink(drawing, tolerance, places);
    replay_tape(bytes, setup.profile, setup.format, sink);
    const std::vector<std::optional<Point>> at = places.places();
    for (std::size_t k = 0; k < marked.size(); ++k)
        if (at[k]) drawing.marks.push_back({*at[k], marked[k].severity});
    return drawing;
}

JobSheet make_job_sheet(const CheckResult& result, const Profile& profile, SheetDrawing drawing,
                        const SheetParts& parts, const JobSheetInput& in) {
    const Lang lang = in.lang;
    JobSheet sheet;
    sheet.lang = lang;
    sheet.title = text(Msg::SheetTitle, lang);
    sheet.tape = display_text(in.tape_name);
    sheet.sha256 = in.sha256;
    sheet.created_unix = in.created_unix;
    sheet.date = sheet_date_text(in.created_unix);
    sheet.footer = sheet.tape + " · SHA-256 " + sheet.sha256.substr(0, 16) + "… · " + sheet.date;
    sheet.page_template = text(Msg::SheetPage, lang);
    for (const SheetPart& part : parts.parts) drawing.labels.push_back({part.label_at, std::to_string(part.group)});
    sheet.drawing = std::move(drawing);
    sheet.legend = legend_of(sheet.drawing, lang);

    sheet.sections.push_back(job_section(result, sheet, lang));
    sheet.sections.push_back(drawing_section(sheet.drawing, lang));
    sheet.sections.push_back(stats_section(result.stats, false, lang));
    sheet.sections.push_back(stats_section(result.stats, true, lang));
    if (!parts.groups.empty()) sheet.sections.push_back(parts_section(parts, lang));
    if (!parts.plates.empty()) sheet.sections.push_back(plates_section(parts, lang));
    sheet.sections.push_back(profile_section(result, profile, lang));
    sheet.sections.push_back(diagnostics_section(result, lang));
    return sheet;
}

JobSheetResult job_sheet(std::string_view bytes, const TapeSetup& setup, const JobSheetInput& in) {
    JobSheetResult out;
    out.result = check_tape(bytes, setup, in.max_diagnostics, /*parts*/ true);
    out.sheet = job_sheet_of(bytes, setup, out.result, in);
    return out;
}

JobSheet job_sheet_of(std::string_view bytes, const TapeSetup& setup, CheckResult result, const JobSheetInput& in) {
    limit_diagnostics(result, in.max_diagnostics);
    SheetDrawing drawing = draw_sheet(bytes, setup, result.diagnostics, result.stats);
    return make_job_sheet(result, setup.profile, std::move(drawing), sheet_parts(result), in);
}

}  // namespace essi
