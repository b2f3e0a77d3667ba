#include "formats.hpp"
#include "essi_version.hpp"

#include <cctype>
#include <cstdio>
#include <map>

#include "essi/diagnostics.hpp"
#include "essi/sha256.hpp"
#include "essi/text_report.hpp"

namespace essi::native {

namespace {

std::string verdict_text(const FileReport& f, Lang lang) {
    return format_message(Msg::ReportErrors, lang, {f.errors()}) + std::string(text(Msg::ListSeparator, lang)) +
           format_message(Msg::ReportWarnings, lang, {f.warnings()});
}

std::string code_anchor(DiagCode c) {
    std::string s = code_name(c);
    for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return s;
}

// SARIF's result levels have our severities' names ("error", "warning", "note").
std::string sarif_level(Severity s) { return std::string(severity_name(s)); }

std::string docs_base(std::string_view docs_url) {
    std::string base(docs_url);
    if (!base.empty() && base.back() != '/') base += '/';
    return base;
}

}  // namespace

bool file_fails(const FileReport& file, FailOn fail_on) {
    if (fail_on == FailOn::Warning) return file.errors() + file.warnings() > 0;
    return file.errors() > 0;
}

void BatchTotals::add(const BatchItem& item, FailOn fail_on) {
    if (!item.read_ok) {
        ++unreadable;
        return;
    }
    ++files;
    if (item.report.ok()) ++files_ok;
    errors += item.report.errors();
    warnings += item.report.warnings();
    if (file_fails(item.report, fail_on)) ++failed;
}

std::string batch_summary_line(const BatchTotals& t, std::string_view profile_name, double seconds, Lang lang) {
    std::string s = format_message(
        Msg::ReportSummary, lang,
        {t.files, profile_name, t.files_ok, t.files - t.files_ok, format_message(Msg::ReportErrors, lang, {t.errors}),
         format_message(Msg::ReportWarnings, lang, {t.warnings})});
    if (t.unreadable > 0) s += "; " + format_message(Msg::ReportUnreadable, lang, {t.unreadable});
    char buf[64];
    std::snprintf(buf, sizeof buf, "; %.3f s", seconds);
    s += buf;
    return s;
}

std::string text_file_block(const BatchItem& item, bool quiet, Lang lang) {
    return file_report_text(item.report, quiet, lang);
}

// --- GitHub ----------------------------------------------------------------------------------------------
namespace {
// Workflow-command escaping: data escapes % CR LF; a property (file=..., title=...) also : and ,.
std::string github_escape(std::string_view s, bool property) {
    std::string out;
    for (char c : s) {
        if (c == '%') out += "%25";
        else if (c == '\r') out += "%0D";
        else if (c == '\n') out += "%0A";
        else if (property && c == ':') out += "%3A";
        else if (property && c == ',') out += "%2C";
        else out += c;
    }
    return out;
}
}  // namespace

std::string github_escape_data(std::string_view s) { return github_escape(s, false); }
std::string github_escape_property(std::string_view s) { return github_escape(s, true); }

std::string github_file_block(const BatchItem& item, Lang lang) {
    const FileReport& r = item.report;
    const std::string file = github_escape_property(r.display_path());
    if (!item.read_ok)
        return "::error file=" + file + ",title=essi::" +
               github_escape_data(format_message(Msg::ReportCannotRead, lang, {r.display_path(), item.error})) + "\n";
    std::string out;
    for (const Diagnostic& d : r.result.diagnostics) {
        out += d.severity == Severity::Error ? "::error" : d.severity == Severity::Warning ? "::warning" : "::notice";
        out += " file=" + file;
        if (d.line > 0) {
            out += ",line=" + std::to_string(d.line);
            if (d.column > 0) out += ",col=" + std::to_string(d.column);
        }
        out += ",title=" + code_name(d.code);
        out += "::" + github_escape_data(diagnostic_message(d, lang)) + "\n";
    }
    if (r.omitted() > 0)
        out += "::notice file=" + file + ",title=essi::" + github_escape_data(omitted_text(r, lang)) + "\n";
    return out;
}

// --- JUnit -----------------------------------------------------------------------------------------------

std::string junit_report(std::span<const BatchItem> items, std::string_view profile_name, double seconds,
                         FailOn fail_on, Lang lang) {
    std::size_t failures = 0, errors = 0;
    for (const BatchItem& it : items) {
        if (!it.read_ok) ++errors;
        else if (file_fails(it.report, fail_on)) ++failures;
    }
    char time_buf[64];
    auto fmt_time = [&](double s) {
        std::snprintf(time_buf, sizeof time_buf, "%.6f", s);
        return std::string(time_buf);
    };
    const std::string counts = "tests=\"" + std::to_string(items.size()) + "\" failures=\"" + std::to_string(failures) +
                               "\" errors=\"" + std::to_string(errors) + "\"";
    std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x += "<testsuites name=\"essi check\" " + counts + " time=\"" + fmt_time(seconds) + "\">\n";
    x += "  <testsuite name=\"essi check (profile " + xml_escape(profile_name) + ")\" " + counts +
         " skipped=\"0\" time=\"" + fmt_time(seconds) + "\">\n";
    x += "    <properties>\n      <property name=\"profile\" value=\"" + xml_escape(profile_name) +
         "\"/>\n      <property name=\"essi.version\" value=\"" + std::string(kVersion) + "\"/>\n    </properties>\n";
    for (const BatchItem& it : items) {
        const FileReport& r = it.report;
        const std::string path = xml_escape(r.display_path());
        x += "    <testcase classname=\"essi.check\" name=\"" + path + "\" file=\"" + path + "\" time=\"" +
             fmt_time(it.seconds) + "\"";
        if (!it.read_ok) {
            x += ">\n      <error type=\"io\" message=\"" +
                 xml_escape(format_message(Msg::ReportCannotRead, lang, {r.display_path(), it.error})) +
                 "\"/>\n    </testcase>\n";
            continue;
        }
        std::string diags;
        for (const Diagnostic& d : r.result.diagnostics) diags += diagnostic_line(r.display_path(), d, lang) + "\n";
        if (r.omitted() > 0)
            diags += r.display_path() + ": " + std::string(severity_text(Severity::Note, lang)) + ": " +
                     omitted_text(r, lang) + "\n";
        const std::string stats = file_stats_line(r, lang);
        if (file_fails(r, fail_on)) {
            std::string type;
            for (const Diagnostic& d : r.result.diagnostics)
                if (d.severity == Severity::Error || (fail_on == FailOn::Warning && d.severity == Severity::Warning)) {
                    type = code_name(d.code);
                    break;
                }
            x += ">\n      <failure message=\"" + xml_escape(verdict_text(r, lang)) + "\" type=\"" +
                 xml_escape(type.empty() ? "essi" : type) + "\">" + xml_escape(diags) + "</failure>\n";
            x += "      <system-out>" + xml_escape(stats) + "</system-out>\n    </testcase>\n";
        } else {
            x += ">\n      <system-out>" + xml_escape(diags + stats) + "</system-out>\n    </testcase>\n";
        }
    }
    x += "  </testsuite>\n</testsuites>\n";
    return x;
}

// --- SARIF -----------------------------------------------------------------------------------------------
std::string path_to_uri(std::string_view path) {
    // Percent-encoded byte by byte: a backslash is a character of a Linux file name (%5C), not a separator.
    std::string p(path);
    while (p.size() > 2 && p.compare(0, 2, "./") == 0) p.erase(0, 2);
    std::string out;
    if (!p.empty() && p[0] == '/') out = "file://";
    static const char* hex = "0123456789ABCDEF";
    for (unsigned char c : p) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
            out += static_cast<char>(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

// A diagnostic's other places (the cut plan's: the other part of a collision, the hole cut after its part ...):
// SARIF relatedLocations, each a region of lines of the same file and what is there.
static nlohmann::json sarif_related(const nlohmann::json& artifact, const Diagnostic& d, Lang lang) {
    nlohmann::json related = nlohmann::json::array();
    int id = 0;
    for (const RelatedLocation& r : d.related()) {
        nlohmann::json phys = artifact;
        phys["region"] = {{"startLine", r.line}, {"endLine", std::max(r.line, r.end_line)}};
        related.push_back(
            {{"id", id++}, {"physicalLocation", phys}, {"message", {{"text", related_message(r, lang)}}}});
    }
    return related;
}

nlohmann::json sarif_rules(std::string_view docs_url, Lang lang) {
    const std::string base = docs_base(docs_url);
    nlohmann::json rules = nlohmann::json::array();
    for (DiagCode c : all_codes()) {
        const std::string id = code_name(c);
        const std::string summary(code_summary(c, lang));
        const std::string uri = base + "diagnostics.md#" + code_anchor(c);
        const int group = static_cast<int>(c) / 100;
        const char* area = group == 1   ? "read"
                           : group == 2 ? "interpret"
                           : group == 3 ? "geometry"
                           : group == 4 ? "machine"
                           : group == 5 ? "conversion"
                                        : "cut-plan";
        rules.push_back({
            {"id", id},
            {"shortDescription", {{"text", summary}}},
            {"fullDescription", {{"text", summary}}},
            {"help",
             {{"text", format_message(Msg::ReportSeeDocs, lang, {summary, uri})},
              {"markdown", format_message(Msg::ReportSeeDocsMarkdown, lang, {summary, id, uri})}}},
            {"helpUri", uri},
            {"defaultConfiguration", {{"level", sarif_level(default_severity(c))}}},
            {"properties", {{"tags", {"essi", area}}}},
        });
    }
    return rules;
}

nlohmann::json sarif_report(std::span<const BatchItem> items, std::string_view profile_name, std::string_view docs_url,
                            Lang lang) {
    std::map<std::string, std::size_t> rule_index;
    {
        std::size_t k = 0;
        for (DiagCode c : all_codes()) rule_index[code_name(c)] = k++;
    }
    nlohmann::json results = nlohmann::json::array();
    nlohmann::json notifications = nlohmann::json::array();
    bool all_read = true;
    for (const BatchItem& it : items) {
        const FileReport& r = it.report;
        const std::string uri = path_to_uri(r.path);  // the bytes as given, percent-encoded
        nlohmann::json artifact = {{"artifactLocation", {{"uri", uri}}}};
        if (!it.read_ok) {
            all_read = false;
            notifications.push_back(
                {{"level", "error"},
                 {"message", {{"text", format_message(Msg::ReportCannotRead, lang, {r.display_path(), it.error})}}},
                 {"locations", {{{"physicalLocation", artifact}}}}});
            continue;
        }
        for (const Diagnostic& d : r.result.diagnostics) {
            const std::string id = code_name(d.code);
            nlohmann::json phys = artifact;
            if (d.line > 0) {
                phys["region"] = {{"startLine", d.line}};
                if (d.column > 0) phys["region"]["startColumn"] = d.column;
            }
            nlohmann::json res = {{"ruleId", id},
                                  {"level", sarif_level(d.severity)},
                                  {"message", {{"text", diagnostic_message(d, lang)}}},
                                  {"locations", {{{"physicalLocation", phys}}}}};
            if (!d.related().empty()) res["relatedLocations"] = sarif_related(artifact, d, lang);
            if (auto f = rule_index.find(id); f != rule_index.end()) res["ruleIndex"] = f->second;
            results.push_back(std::move(res));
        }
        if (r.omitted() > 0)
            notifications.push_back({{"level", "note"},
                                     {"message", {{"text", r.display_path() + ": " + omitted_text(r, lang)}}},
                                     {"locations", {{{"physicalLocation", artifact}}}}});
    }
    const std::string base = docs_base(docs_url);
    nlohmann::json invocation = {{"executionSuccessful", all_read}};
    if (!notifications.empty()) invocation["toolExecutionNotifications"] = std::move(notifications);
    nlohmann::json run = {
        {"tool",
         {{"driver",
           {{"name", "essi"},
            {"fullName", "essikit essi check (ESSI / ISO 6582 cutting tapes)"},
            {"version", kVersion},
            {"semanticVersion", kVersion},
            {"informationUri", base + "cli.md"},
            {"rules", sarif_rules(docs_url, lang)}}}}},
        {"invocations", {std::move(invocation)}},
        {"results", std::move(results)},
        {"columnKind", "utf16CodeUnits"},
        {"properties", {{"profile", std::string(profile_name)}}},
    };
    return {
        {"$schema", "https://json.schemastore.org/sarif-2.1.0.json"}, {"version", "2.1.0"}, {"runs", {std::move(run)}}};
}

std::string_view codeclimate_severity(Severity s) {
    switch (s) {
        case Severity::Error: return "critical";
        case Severity::Warning: return "minor";
        case Severity::Note: break;
    }
    return "info";
}

nlohmann::json codeclimate_report(std::span<const BatchItem> items, Lang lang) {
    nlohmann::json issues = nlohmann::json::array();
    const auto issue = [&](const std::string& path, std::string_view check, std::uint32_t line,
                           std::string_view severity, const std::string& description, const std::string& english) {
        const std::string key = path + '\0' + std::string(check) + '\0' + std::to_string(line) + '\0' + english;
        issues.push_back({{"type", "issue"},
                          {"description", description},
                          {"check_name", check},
                          {"categories", {"Bug Risk"}},
                          {"fingerprint", sha256_hex(key).substr(0, 32)},
                          {"severity", severity},
                          {"location", {{"path", path}, {"lines", {{"begin", std::max<std::uint32_t>(line, 1)}}}}}});
    };
    for (const BatchItem& it : items) {
        const std::string path = it.report.display_path();
        if (!it.read_ok) {
            issue(path, "unreadable", 1, "blocker", format_message(Msg::ReportCannotRead, lang, {path, it.error}),
                  it.error);
            continue;
        }
        for (const Diagnostic& d : it.report.result.diagnostics)
            issue(path, code_name(d.code), d.line, codeclimate_severity(d.severity), diagnostic_message(d, lang),
                  diagnostic_message(d, Lang::En));
    }
    return issues;
}

}  // namespace essi::native
