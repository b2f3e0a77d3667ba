#include "essi/text_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace essi {

namespace {

std::string fixed(double v, int decimals = kTextLengthDecimals) {
    if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    // No "-0.000": a value that rounds to zero is zero.
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

std::string mm(double v) { return fixed(v) + " mm"; }

std::string count_of(unsigned long long n, std::string_view singular, std::string_view plural) {
    return std::to_string(n) + " " + std::string(n == 1 ? singular : plural);
}

std::string verdict(const FileReport& f) {
    const std::size_t errors = f.errors();
    const std::size_t warnings = f.warnings();
    if (errors == 0 && warnings == 0) return "ok";
    std::string s;
    if (errors > 0) s = count_of(errors, "error", "errors");
    if (warnings > 0) {
        if (!s.empty()) s += ", ";
        s += count_of(warnings, "warning", "warnings");
    }
    if (errors == 0) s = "ok, " + s;
    return s;
}

}  // namespace

std::string omitted_text(const FileReport& f) {
    return count_of(f.omitted(), "more diagnostic", "more diagnostics") + " not shown (--max-diagnostics " +
           std::to_string(f.result.diagnostics.size()) + ")";
}

std::string file_report_text(const FileReport& r, bool quiet) {
    std::string text;
    for (const Diagnostic& d : r.result.diagnostics) {
        if (quiet && d.severity == Severity::Note) continue;
        text += diagnostic_line(r.display_path(), d);
        text += '\n';
    }
    if (r.omitted() > 0) text += r.display_path() + ": note: " + omitted_text(r) + "\n";
    if (!quiet) {
        text += file_stats_line(r);
        text += '\n';
    }
    return text;
}

namespace {
// A CSV field: quoted when it holds a comma, a quote or a line end (quotes doubled).
std::string csv_field(std::string_view s) {
    if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}
}  // namespace

std::string diagnostics_csv(std::span<const FileReport> files) {
    std::string out = "file,severity,code,line,column,message\r\n";
    for (const FileReport& f : files)
        for (const Diagnostic& d : f.result.diagnostics)
            out += csv_field(f.display_path()) + "," + std::string(severity_name(d.severity)) + "," + code_name(d.code) + "," +
                   std::to_string(d.line) + "," + std::to_string(d.column) + "," + csv_field(d.message) + "\r\n";
    return out;
}

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return fixed(seconds, 1) + " s";
    const auto total = static_cast<unsigned long long>(std::llround(seconds));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%llu:%02llu:%02llu", total / 3600, (total / 60) % 60, total % 60);
    return buf;
}

std::string diagnostic_line(std::string_view path, const Diagnostic& d) {
    std::string s(path);
    if (d.line > 0) {
        s += ':';
        s += std::to_string(d.line);
        if (d.column > 0) {
            s += ':';
            s += std::to_string(d.column);
        }
    }
    s += ": ";
    s += severity_name(d.severity);
    s += ' ';
    s += code_name(d.code);
    s += ": ";
    s += d.message;
    return s;
}

std::string file_stats_line(const FileReport& file) {
    const Stats& st = file.result.stats;
    std::string s = file.display_path();
    s += ": ";
    s += verdict(file);
    s += "; cut " + mm(st.cut_length_mm);
    s += ", mark " + mm(st.mark_length_mm);
    s += ", travel " + mm(st.travel_length_mm);
    s += " (rapid " + mm(st.rapid_length_mm) + ")";
    s += ", " + count_of(st.pierces, "pierce", "pierces");
    s += ", " + count_of(st.blocks, "block", "blocks");
    s += ", " + count_of(st.motions, "motion", "motions");
    s += ", time " + format_duration(st.estimated_time_s);
    return s;
}

std::string summary_line(std::span<const FileReport> files, std::string_view profile_name) {
    std::size_t ok = 0, errors = 0, warnings = 0;
    for (const FileReport& f : files) {
        if (f.ok()) ++ok;
        errors += f.errors();
        warnings += f.warnings();
    }
    std::string s = count_of(files.size(), "file", "files");
    s += " checked (profile ";
    s += profile_name;
    s += "): ";
    s += std::to_string(ok) + " ok, " + std::to_string(files.size() - ok) + " with errors; ";
    s += count_of(errors, "error", "errors") + ", " + count_of(warnings, "warning", "warnings");
    return s;
}

std::string stats_block(const FileReport& file) {
    const Stats& st = file.result.stats;
    std::vector<std::pair<std::string, std::string>> rows;
    rows.emplace_back("file", file.display_path());
    rows.emplace_back("cut length", mm(st.cut_length_mm));
    rows.emplace_back("cut length compensated", mm(st.cut_length_compensated_mm));
    rows.emplace_back("mark length", mm(st.mark_length_mm));
    rows.emplace_back("travel length", mm(st.travel_length_mm));
    rows.emplace_back("rapid length", mm(st.rapid_length_mm));
    rows.emplace_back("pierces", std::to_string(st.pierces));
    rows.emplace_back("blocks", std::to_string(st.blocks));
    rows.emplace_back("motions", std::to_string(st.motions));
    rows.emplace_back("estimated time",
                      fixed(st.estimated_time_s, 1) + " s (" + format_duration(st.estimated_time_s) + ")");
    if (st.cut_bbox.empty) {
        rows.emplace_back("cut bbox", "none");
    } else {
        rows.emplace_back("cut bbox", "x " + fixed(st.cut_bbox.min_x) + " .. " + fixed(st.cut_bbox.max_x) + ", y " +
                                          fixed(st.cut_bbox.min_y) + " .. " + fixed(st.cut_bbox.max_y) + " mm (" +
                                          fixed(st.cut_bbox.max_x - st.cut_bbox.min_x) + " x " +
                                          fixed(st.cut_bbox.max_y - st.cut_bbox.min_y) + " mm)");
    }
    rows.emplace_back("end position", "x " + fixed(st.end_position.x) + ", y " + fixed(st.end_position.y) + " mm");

    std::size_t width = 0;
    for (const auto& [k, v] : rows) width = std::max(width, k.size() + 1);
    std::string out;
    for (const auto& [k, v] : rows) {
        out += k;
        out += ':';
        out.append(width - k.size() - 1 + 1, ' ');
        out += v;
        out += '\n';
    }
    return out;
}

}  // namespace essi
