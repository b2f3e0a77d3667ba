#include "essi/text_report.hpp"

#include "essi/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace essi {

namespace {

std::string mm(double v) { return mm_text(v) + " mm"; }

}  // namespace

std::string verdict_text(const CheckResult& r, Lang lang) {
    const std::size_t errors = r.count(Severity::Error);
    const std::size_t warnings = r.count(Severity::Warning);
    if (errors == 0 && warnings == 0) return std::string(text(Msg::ReportOk, lang));
    std::string s;
    if (errors > 0) s = format_message(Msg::ReportErrors, lang, {errors});
    if (warnings > 0) {
        if (!s.empty()) s += text(Msg::ListSeparator, lang);
        s += format_message(Msg::ReportWarnings, lang, {warnings});
    }
    if (errors == 0) s = format_message(Msg::ReportOkWith, lang, {s});
    return s;
}

std::string omitted_text(const FileReport& f, Lang lang) {
    return format_message(Msg::ReportOmitted, lang, {f.omitted(), f.result.diagnostics.size()});
}

std::string_view severity_text(Severity s, Lang lang) {
    switch (s) {
        case Severity::Note: return text(Msg::SeverityNote, lang);
        case Severity::Warning: return text(Msg::SeverityWarning, lang);
        case Severity::Error: break;
    }
    return text(Msg::SeverityError, lang);
}

std::string file_report_text(const FileReport& r, bool quiet, Lang lang) {
    std::string out;
    for (const Diagnostic& d : r.result.diagnostics) {
        if (quiet && d.severity == Severity::Note) continue;
        out += diagnostic_line(r.display_path(), d, lang);
        out += '\n';
    }
    if (r.omitted() > 0)
        out += r.display_path() + ": " + std::string(severity_text(Severity::Note, lang)) + ": " +
               omitted_text(r, lang) + "\n";
    if (!quiet) {
        if (r.result.auto_profile)
            out += format_message(Msg::ReportAutoProfile, lang, {r.display_path(), r.result.profile}) + "\n";
        out += file_stats_line(r, lang);
        out += '\n';
    }
    return out;
}

std::string csv_field(std::string_view s) {
    if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string diagnostics_csv(std::span<const FileReport> files, Lang lang) {
    std::string out = "file,severity,code,line,column,message\r\n";
    for (const FileReport& f : files)
        for (const Diagnostic& d : f.result.diagnostics)
            out += csv_field(f.display_path()) + "," + std::string(severity_name(d.severity)) + "," +
                   code_name(d.code) + "," + std::to_string(d.line) + "," + std::to_string(d.column) + "," +
                   csv_field(diagnostic_message(d, lang)) + "\r\n";
    return out;
}

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return fixed_text(seconds, 1) + " s";
    const auto total = static_cast<unsigned long long>(std::llround(seconds));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%llu:%02llu:%02llu", total / 3600, (total / 60) % 60, total % 60);
    return buf;
}

std::string diagnostic_line(std::string_view path, const Diagnostic& d, Lang lang) {
    std::string s = display_text(path);  // (a file name is any bytes)
    if (d.line > 0) {
        s += ':';
        s += std::to_string(d.line);
        if (d.column > 0) {
            s += ':';
            s += std::to_string(d.column);
        }
    }
    s += ": ";
    s += severity_text(d.severity, lang);
    s += ' ';
    s += code_name(d.code);
    s += ": ";
    s += diagnostic_message(d, lang);
    return s;
}

namespace {
// An amount of money in the cost's currency: "12.35 EUR".
std::string money(double v, const Cost& c) { return fixed_text(v, 2) + (c.currency.empty() ? "" : " " + c.currency); }
std::string electrodes(double v) { return fixed_text(v, 4); }
}  // namespace

std::string file_stats_line(const FileReport& file, Lang lang) {
    const Stats& st = file.result.stats;
    std::string line = format_message(Msg::ReportFileStats, lang,
                                      {file.display_path(), verdict_text(file.result, lang), mm(st.cut_length_mm),
                                       mm(st.mark_length_mm), mm(st.travel_length_mm), mm(st.rapid_length_mm),
                                       st.pierces, st.blocks, st.motions, format_duration(st.estimated_time_s)});
    if (st.machine_time)
        line += "; " + format_message(
                           Msg::ReportMachineTime, lang,
                           {format_duration(st.machine_time->total_s), fixed_text(st.machine_time->acceleration_s, 1)});
    if (st.cost) line += "; " + format_message(Msg::ReportCost, lang, {money(st.cost->total, *st.cost)});
    if (st.consumables)
        line += "; " + format_message(Msg::ReportElectrodes, lang, {electrodes(st.consumables->electrodes)});
    return line;
}

std::string summary_line(std::span<const FileReport> files, std::string_view profile_name, Lang lang) {
    std::size_t ok = 0, errors = 0, warnings = 0;
    for (const FileReport& f : files) {
        if (f.ok()) ++ok;
        errors += f.errors();
        warnings += f.warnings();
    }
    return format_message(
        Msg::ReportSummary, lang,
        {files.size(), profile_name, ok, files.size() - ok, format_message(Msg::ReportErrors, lang, {errors}),
         format_message(Msg::ReportWarnings, lang, {warnings})});
}

std::vector<StatsRow> stats_rows(const Stats& st) {
    std::vector<StatsRow> rows;
    rows.push_back({Msg::StatsCutLength, mm(st.cut_length_mm)});
    rows.push_back({Msg::StatsCutLengthCompensated, mm(st.cut_length_compensated_mm)});
    rows.push_back({Msg::StatsMarkLength, mm(st.mark_length_mm)});
    rows.push_back({Msg::StatsTravelLength, mm(st.travel_length_mm)});
    rows.push_back({Msg::StatsRapidLength, mm(st.rapid_length_mm)});
    rows.push_back({Msg::StatsPierces, std::to_string(st.pierces)});
    rows.push_back({Msg::StatsBlocks, std::to_string(st.blocks)});
    rows.push_back({Msg::StatsMotions, std::to_string(st.motions)});
    rows.push_back({Msg::StatsEstimatedTime,
                    fixed_text(st.estimated_time_s, 1) + " s (" + format_duration(st.estimated_time_s) + ")"});
    if (st.machine_time) {
        const MachineTime& t = *st.machine_time;
        const auto s1 = [](double v) { return fixed_text(v, 1); };
        rows.push_back({Msg::StatsMachineTime, s1(t.total_s) + " s (" + format_duration(t.total_s) + ")"});
        rows.push_back({Msg::StatsMachineTimeBreakdown,
                        "",
                        {Msg::StatsMachineTimeParts,
                         {s1(t.cutting_s), s1(t.marking_s), s1(t.rapid_s), s1(t.travel_s), s1(t.pierce_s),
                          s1(t.dwell_s), s1(t.acceleration_s)}}});
    }
    if (st.cost) {
        const Cost& c = *st.cost;
        rows.push_back({Msg::StatsCost, money(c.total, c)});
        rows.push_back({Msg::StatsCostBreakdown,
                        "",
                        {Msg::StatsCostParts,
                         {money(c.machine, c), c.machine_time ? Msg::StatsMachineTime : Msg::StatsEstimatedTime,
                          money(c.pierces, c), money(c.cut, c),
                          c.material ? MessageArgs::Arg(money(*c.material, c)) : MessageArgs::Arg(Msg::StatsNone)}}});
    }
    if (st.consumables) {
        const ConsumableUse& u = *st.consumables;
        rows.push_back({Msg::StatsElectrodes,
                        "",
                        {Msg::StatsElectrodesParts, {electrodes(u.electrodes), u.pierces, fixed_text(u.arc_on_s, 1)}}});
    }
    if (st.cut_bbox.empty) {
        rows.push_back({Msg::StatsCutBox, "", Msg::StatsNone});
    } else {
        rows.push_back({Msg::StatsCutBox, "x " + mm_text(st.cut_bbox.min_x) + " .. " + mm_text(st.cut_bbox.max_x) +
                                              ", y " + mm_text(st.cut_bbox.min_y) + " .. " +
                                              mm_text(st.cut_bbox.max_y) + " mm (" +
                                              mm_text(st.cut_bbox.max_x - st.cut_bbox.min_x) + " x " +
                                              mm_text(st.cut_bbox.max_y - st.cut_bbox.min_y) + " mm)"});
    }
    rows.push_back(
        {Msg::StatsEndPosition, "x " + mm_text(st.end_position.x) + ", y " + mm_text(st.end_position.y) + " mm"});
    return rows;
}

std::string stats_block(const FileReport& file, Lang lang) {
    std::vector<std::pair<std::string, std::string>> rows;
    rows.emplace_back(std::string(text(Msg::StatsFile, lang)), file.display_path());
    for (const StatsRow& r : stats_rows(file.result.stats))
        rows.emplace_back(std::string(text(r.key, lang)), r.text(lang));

    std::size_t width = 0;
    for (const auto& [k, v] : rows) width = std::max(width, display_width(k) + 1);
    std::string out;
    for (const auto& [k, v] : rows) {
        out += k;
        out += ':';
        out.append(width - display_width(k) - 1 + 1, ' ');
        out += v;
        out += '\n';
    }
    return out;
}

}  // namespace essi
