// The human-readable forms of check results: compiler-style diagnostics, a one-line stats summary per
// file, the closing summary line, and the aligned `key: value` block of `essi stats`.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/report.hpp"
#include "essi/report_json.hpp"

namespace essi {

// Every text is in `lang` (the message catalogue, essi/i18n.hpp); numbers, codes and paths are the same in all.

// "path:12:5: error E301: message" (without position: "path: error E402: message"), no newline.
[[nodiscard]] std::string diagnostic_line(std::string_view path, const Diagnostic& d, Lang lang = Lang::En);

// "path: ok; cut 123.400 mm, mark 0.000 mm, travel 50.000 mm (rapid 20.000 mm), 2 pierces, 30 blocks,
//  25 motions, time 0:01:05" (no newline)
[[nodiscard]] std::string file_stats_line(const FileReport& file, Lang lang = Lang::En);

// "ok", "ok, 1 warning", "2 errors, 1 warning": the verdict on a checked tape.
[[nodiscard]] std::string verdict_text(const CheckResult& result, Lang lang = Lang::En);

// "2 files checked (profile iso6582): 1 ok, 1 with errors; 3 errors, 1 warning" (no newline)
[[nodiscard]] std::string summary_line(std::span<const FileReport> files, std::string_view profile_name,
                                       Lang lang = Lang::En);

// One statistic as the reports write it: its label and its value, a number with its unit (the same in every
// language), or, when `words` is set, a message of the catalogue in the reader's language ("none"; "cutting 1.2 s,
// marking 0.0 s, ...").
struct StatsRow {
    Msg key;
    std::string value;
    Message words = {};
    [[nodiscard]] std::string text(Lang lang) const { return words.msg == Msg::None ? value : words.text(lang); }
};
// The statistics of a tape in the order `essi stats` lists them (after the file): lengths, pierces, blocks, motions,
// time, the machine time, cost and electrodes (with the profile's accel_mm_s2, costs, consumables), cut box, end
// position. The job sheet (essi/job_sheet.hpp) shows the same rows.
[[nodiscard]] std::vector<StatsRow> stats_rows(const Stats& stats);

// The aligned block of `essi stats` for one file, every line ending in a newline.
[[nodiscard]] std::string stats_block(const FileReport& file, Lang lang = Lang::En);

// "3 more diagnostics not shown (--max-diagnostics 100)": what --max-diagnostics left out of a file.
[[nodiscard]] std::string omitted_text(const FileReport& file, Lang lang = Lang::En);

// What `essi check --format text` prints for one file: its diagnostics (without notes when `quiet`), a note for
// those --max-diagnostics left out, and (unless quiet) its statistics line; every line ends in a newline.
[[nodiscard]] std::string file_report_text(const FileReport& file, bool quiet = false, Lang lang = Lang::En);

// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line end (quotes doubled).
[[nodiscard]] std::string csv_field(std::string_view s);

// The diagnostics as CSV (RFC 4180, a header line, CR LF): file,severity,code,line,column,message.
[[nodiscard]] std::string diagnostics_csv(std::span<const FileReport> files, Lang lang = Lang::En);

// Seconds as "h:mm:ss".
[[nodiscard]] std::string format_duration(double seconds);
// "error", "Fehler", "错误" ...
[[nodiscard]] std::string_view severity_text(Severity s, Lang lang);

}  // namespace essi
