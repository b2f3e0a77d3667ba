// The report formats of `essi check` beyond text and JSON: JUnit XML (test reports of Jenkins, GitLab, ...),
// SARIF 2.1.0 (GitHub code scanning and other static-analysis viewers) and GitHub Actions workflow commands
// (annotations on pull requests). All pure functions of the batch results; their texts in `lang` (essi/i18n.hpp).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "batch.hpp"

namespace essi::native {

enum class FailOn { Error, Warning, Never };

// Whether a file counts as failed under the --fail-on policy (never: a file with errors still "fails" in
// the reports, only the exit code ignores it).
[[nodiscard]] bool file_fails(const FileReport& file, FailOn fail_on);

// Totals of a batch, for the summary line and the exit code.
struct BatchTotals {
    std::size_t files = 0;     // read and checked
    std::size_t files_ok = 0;  // without errors
    std::size_t unreadable = 0;
    std::size_t errors = 0;
    std::size_t warnings = 0;
    std::size_t failed = 0;  // files that fail under the --fail-on policy (error: = files - files_ok)
    void add(const BatchItem& item, FailOn fail_on);
};

// "3 files checked (profile iso6582): 2 ok, 1 with errors; 1 error, 4 warnings; 0.012 s"
// (+ ", 1 unreadable" after the files when some could not be read)
[[nodiscard]] std::string batch_summary_line(const BatchTotals& totals, std::string_view profile_name, double seconds,
                                             Lang lang = Lang::En);

// Text output of one file: its diagnostics (and a note when some were cut), then its stats line. quiet: only
// errors and warnings, no stats line.
[[nodiscard]] std::string text_file_block(const BatchItem& item, bool quiet, Lang lang = Lang::En);

// --- GitHub Actions workflow commands ---------------------------------------------------------------------
// Escaping of a command's message (% CR LF) and of a property value (also : and ,).
[[nodiscard]] std::string github_escape_data(std::string_view s);
[[nodiscard]] std::string github_escape_property(std::string_view s);
// "::error file=a.esi,line=3,col=1,title=E301::message" lines for the file's diagnostics (notes as ::notice).
[[nodiscard]] std::string github_file_block(const BatchItem& item, Lang lang = Lang::En);

// One <testsuite> with one <testcase> per file (name and file = the path, classname "essi.check"); a file that
// fails under fail_on gets a <failure> with its diagnostics, an unreadable file an <error>.
[[nodiscard]] std::string junit_report(std::span<const BatchItem> items, std::string_view profile_name, double seconds,
                                       FailOn fail_on, Lang lang = Lang::En);

// --- SARIF 2.1.0 ------------------------------------------------------------------------------------------
// Default base of the documentation links (helpUri = base + "diagnostics.md#e301"); --docs-url changes it.
constexpr std::string_view kDefaultDocsUrl = "https://essikit.invalid/docs/";
// A relative path as a URI reference (forward slashes, percent-encoded); absolute paths as file:// URIs.
[[nodiscard]] std::string path_to_uri(std::string_view path);
// The rule of every diagnostic code (id, help text from essi::code_summary, helpUri, default level).
[[nodiscard]] nlohmann::json sarif_rules(std::string_view docs_url, Lang lang = Lang::En);
[[nodiscard]] nlohmann::json sarif_report(std::span<const BatchItem> items, std::string_view profile_name,
                                          std::string_view docs_url, Lang lang = Lang::En);

// --- GitLab Code Quality (Code Climate issues) -------------------------------------------------------------
// GitLab's severity of a diagnostic: an error is "critical" (the tape cannot be cut as it is), a warning "minor",
// a note "info".
[[nodiscard]] std::string_view codeclimate_severity(Severity s);
// [{"type": "issue", "description", "check_name" (the code), "categories", "fingerprint", "severity",
// "location": {"path", "lines": {"begin"}}}, ...]: every diagnostic of every file read (an unreadable file is one
// "blocker" issue, check_name "unreadable"). The fingerprint is the SHA-256 of the path, the code, the line and the
// English message: the same finding has the same fingerprint in every run, whatever --lang.
[[nodiscard]] nlohmann::json codeclimate_report(std::span<const BatchItem> items, Lang lang = Lang::En);

}  // namespace essi::native
