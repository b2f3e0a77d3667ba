// essi check: tapes checked in a batch on a pool of threads, reported as text, JSON, JUnit, SARIF, GitHub
// annotations or Code Climate (docs/cli.md).
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "batch.hpp"
#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/profile.hpp"
#include "formats.hpp"
#include "thread_pool.hpp"

namespace essi::cli {
namespace {

struct CheckOptions {
    std::vector<std::string> paths;
    std::string format = "text";
    std::string profile;
    std::string input = "auto";
    std::string ext;  // --ext LIST ("" = the defaults)
    bool no_sniff = false;
    unsigned jobs = 0;  // 0 = all cores
    std::string fail_on = "error";
    long long max_diagnostics = -1;  // -1 = all
    long long max_per_code = -1;     // -1 = the profile's max_per_code
    bool quiet = false;
    bool parts = false;
    std::string docs_url = std::string(native::kDefaultDocsUrl);
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

native::FailOn fail_on_of(const std::string& name) {
    if (name == "warning") return native::FailOn::Warning;
    if (name == "never") return native::FailOn::Never;
    return native::FailOn::Error;
}

// The whole report of the formats written at the end (json, junit, sarif, codeclimate).
void write_kept_report(std::vector<native::BatchItem>& kept, const CheckOptions& o, const std::string& profile_name,
                       double seconds, native::FailOn fail_on) {
    if (o.format == "json") {
        std::vector<FileReport> reports;
        reports.reserve(kept.size());
        for (native::BatchItem& it : kept)
            if (it.read_ok) reports.push_back(std::move(it.report));
        write_report_json(reports, profile_name, lang(), kJsonIndent, [](std::string_view s) { out(s); });
        out("\n");
    } else if (o.format == "junit") {
        out(native::junit_report(kept, profile_name, seconds, fail_on, lang()));
    } else if (o.format == "sarif") {
        out(native::sarif_report(kept, profile_name, o.docs_url, lang()).dump(kJsonIndent));
        out("\n");
    } else if (o.format == "codeclimate") {
        out(native::codeclimate_report(kept, lang()).dump(kJsonIndent));
        out("\n");
    }
}

int run_check(const CheckOptions& o) {
    using namespace essi::native;
    const auto t0 = std::chrono::steady_clock::now();
    auto request = resolve_request(o.profile, o.input);
    if (!request) return kExitUsage;
    if (o.max_per_code >= 0) request->max_per_code = static_cast<std::size_t>(o.max_per_code);
    const std::string& profile_name = request->profile_name;
    bool io_failed = false;

    ExpandOptions expand;
    if (!o.ext.empty()) expand.extensions = parse_extension_list(o.ext);
    expand.sniff = !o.no_sniff;
    const std::vector<std::string> files = cli::expand_paths(o.paths, io_failed, expand);

    BatchOptions batch;
    batch.jobs = o.jobs == 0 ? hardware_jobs() : o.jobs;
    if (o.max_diagnostics >= 0) batch.max_diagnostics = static_cast<std::size_t>(o.max_diagnostics);
    batch.max_size = o.max_size;
    batch.parts = o.parts && o.format == "json";
    batch.lang = lang();
    const FailOn fail_on = fail_on_of(o.fail_on);

    BatchTotals totals;
    std::vector<BatchItem> kept;  // json, junit, sarif, codeclimate: the whole report is written at the end
    const bool streamed = o.format == "text" || o.format == "github";
    check_batch(files, *request, batch, [&](BatchItem&& item) {
        totals.add(item, fail_on);
        if (!item.read_ok) {
            err("essi: " + format_message(Msg::ReportCannotRead, lang(), {item.report.display_path(), item.error}) +
                "\n");
            io_failed = true;
        }
        if (o.format == "text") {
            if (item.read_ok) out_text(text_file_block(item, o.quiet, lang()));
        } else if (o.format == "github") {
            out(github_file_block(item, lang()));
        } else {
            kept.push_back(std::move(item));
        }
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_kept_report(kept, o, profile_name, seconds, fail_on);

    const std::string summary = batch_summary_line(totals, profile_name, seconds, lang()) + "\n";
    if (streamed) (o.format == "text" ? out_text : out)(summary);
    else if (!o.quiet) err(summary);

    if (io_failed) return finish(kExitUsage);
    if (fail_on == FailOn::Never) return finish(kExitOk);
    return finish(totals.failed > 0 ? kExitTapeErrors : kExitOk);
}

}  // namespace

Subcommand define_check(CLI::App& essi) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* check = essi.add_subcommand("check", "Check tapes: diagnostics, statistics and a summary");
    check->add_option("--format", o->format, "Output format")
        ->check(CLI::IsMember({"text", "json", "junit", "sarif", "github", "codeclimate"}))
        ->type_name("text|json|junit|sarif|github|codeclimate")
        ->capture_default_str();
    add_profile_option(check, o->profile);
    add_input_option(check, o->input);
    check->add_option("--ext", o->ext, "File extensions that count in directories (default: .esi,.essi,.ess,.nc,.txt)")
        ->type_name("LIST");
    check->add_flag("--no-sniff", o->no_sniff,
                    "In directories, do not look into files with other extensions for ESSI content");
    check->add_option("-j,--jobs", o->jobs, "Files checked in parallel (default: all cores)")
        ->check(CLI::Range(1u, 1024u));
    check->add_option("--fail-on", o->fail_on, "Exit code 1 on: error, warning or never")
        ->check(CLI::IsMember({"error", "warning", "never"}))
        ->type_name("error|warning|never")
        ->capture_default_str();
    check
        ->add_option("--max-diagnostics", o->max_diagnostics,
                     "At most N diagnostics per file (the rest are counted in a note)")
        ->check(CLI::Range(0LL, 1LL << 40))
        ->type_name("N");
    check
        ->add_option("--max-per-code", o->max_per_code,
                     "At most N diagnostics of one code per file, then one that counts the rest (default: the "
                     "profile's max_per_code, 1000; 0: no limit)")
        ->check(CLI::Range(0LL, static_cast<long long>(kMaxPerCodeLimit)))
        ->type_name("N");
    check->add_flag("--parts", o->parts,
                    "JSON: each file's parts, groups and plates too (essi parts; found in the same pass)");
    check->add_flag("-q,--quiet", o->quiet,
                    "Text: only errors, warnings and the summary; json/junit/sarif: no summary on stderr");
    check
        ->add_option("--docs-url", o->docs_url,
                     "Base URL of the docs/ folder for SARIF help links (helpUri = URL/diagnostics.md#e301)")
        ->capture_default_str();
    add_max_size_option(check, o->max_size);
    check->add_option("PATH", o->paths, "Tape files or directories ('-' reads standard input)")->required();
    return {check, [o] { return run_check(*o); }};
}

}  // namespace essi::cli
