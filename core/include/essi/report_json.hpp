// The JSON form of check results (the report contract documented in docs/report-schema.json).
// Shared by the `essi` CLI, the server and the viewer's state(): no files, no I/O, only values in and a JSON
// value out. The formats only the CLI writes (text, SARIF, JUnit, GitHub) live in native/.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "essi/diagnostics.hpp"
#include "essi/report.hpp"
#include "essi/text.hpp"

namespace essi {

// Lengths, coordinates and times are written as doubles rounded to this many decimals
// (1e-6 mm is far below any machine resolution; it keeps reports stable across platforms).
constexpr int kJsonLengthDecimals = 6;
// The report text written a piece at a time (write_report_json) is handed on in pieces of about this many bytes.
constexpr std::size_t kJsonFlushBytes = std::size_t{1} << 16;

// Rounds `value` to kJsonLengthDecimals decimals; -0 becomes 0. Non-finite values are returned unchanged
// (nlohmann::json writes them as null).
[[nodiscard]] double round_for_json(double value);

// One checked tape: the path as the user gave it and the pipeline's result.
struct FileReport {
    std::string path;
    CheckResult result;  // its omitted_*: the diagnostics `--max-diagnostics` left out

    // The path as every report writes it: valid UTF-8 without control characters (essi/text.hpp). `path`
    // keeps the bytes as given (a SARIF URI is made from them).
    [[nodiscard]] std::string display_path() const { return display_text(path); }
    [[nodiscard]] std::size_t omitted() const { return result.omitted(); }
    [[nodiscard]] std::size_t errors() const { return result.count(Severity::Error); }
    [[nodiscard]] std::size_t warnings() const { return result.count(Severity::Warning); }
    [[nodiscard]] bool ok() const { return errors() == 0; }
};

// {"severity","code","line","column","message"}, and for the cut plan's (6xx) "contour": {"first_line","last_line"},
// "at": {"x","y"}, "related": [{"line","end_line","message"}] and "overlap": [[[x, y], ...], ...] (the overlapping
// area is inside every one of the polygons) when they have them.
[[nodiscard]] nlohmann::json diagnostic_to_json(const Diagnostic& d, Lang lang = Lang::En);

// [diagnostic_to_json of each]
[[nodiscard]] nlohmann::json diagnostics_to_json(std::span<const Diagnostic> diagnostics, Lang lang = Lang::En);

// {"min_x","min_y","max_x","max_y"}, or null for an empty box
[[nodiscard]] nlohmann::json box_to_json(const Box& b);

// {"cut_length_mm", ..., "cut_bbox_mm": {...} or null, "end_position_mm": {"x","y"}}
[[nodiscard]] nlohmann::json stats_to_json(const Stats& s);

// {"parts":[...],"groups":[...],"plates":[...]} (docs/report-schema.json)
[[nodiscard]] nlohmann::json parts_to_json(const PartsList& parts);

// {"path","ok","diagnostics":[...],"stats":{...}} (+ "diagnostics_omitted": N when --max-diagnostics cut some; the
// members of parts_to_json when the result has parts)
[[nodiscard]] nlohmann::json file_report_to_json(const FileReport& file, Lang lang = Lang::En);

// The whole report of `essi check --format json`:
// {"files":[...],"summary":{"files","files_ok","errors","warnings"},"profile":"name"}
[[nodiscard]] nlohmann::json report_to_json(std::span<const FileReport> files, std::string_view profile_name,
                                            Lang lang = Lang::En);

// report_to_json(files, profile_name, lang).dump(indent) (indent > 0), written to `write` a piece at a time: the
// files' diagnostics one at a time (write_diagnostics_json) and their parts lists from the lists
// (write_parts_member_json), never made one JSON value, so a report of many diagnostics or parts takes little memory
// beyond them.
void write_report_json(std::span<const FileReport> files, std::string_view profile_name, Lang lang, int indent,
                       const std::function<void(std::string_view)>& write);
// The array diagnostics_to_json(diagnostics, lang) as dump(indent) writes it at `depth` levels of indentation, to
// `write` a piece at a time (one diagnostic made a JSON value at a time).
void write_diagnostics_json(std::span<const Diagnostic> diagnostics, Lang lang, int indent, int depth,
                            const std::function<void(std::string_view)>& write);
// The member `member` ("parts", "groups" or "plates") of parts_to_json(parts), written as dump(indent) writes it
// at `depth` levels of indentation, to `write` a piece at a time.
void write_parts_member_json(const PartsList& parts, std::string_view member, int indent, int depth,
                             const std::function<void(std::string_view)>& write);

// The report of `essi stats --format json`: {"files":[{"path","stats"}],"profile":"name"}
[[nodiscard]] nlohmann::json stats_report_to_json(std::span<const FileReport> files, std::string_view profile_name);

}  // namespace essi
