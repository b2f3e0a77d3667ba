// essi: the command-line tool. check / stats / trace / profile (docs/cli.md).
// Exit codes: 0 no errors, 1 a tape has errors, 2 usage or I/O problem.
#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "essi/diagnostics.hpp"
#include "essi/profile.hpp"
#include "essi/report.hpp"
#include "essi/trace.hpp"
#include "serve.hpp"
#include "file_io.hpp"
#include "pipelined_check.hpp"
#include "report_json.hpp"
#include "text_report.hpp"

#ifndef ESSIKIT_VERSION
#define ESSIKIT_VERSION "0.1.0"
#endif

namespace {

using essi::native::FileReport;

constexpr int kExitOk = 0;
constexpr int kExitTapeErrors = 1;
constexpr int kExitUsage = 2;  // bad arguments, unreadable file or profile, output failure

constexpr int kJsonIndent = 2;

void out(std::string_view s) { std::fwrite(s.data(), 1, s.size(), stdout); }

void err(std::string_view s) {
    std::fwrite(s.data(), 1, s.size(), stderr);
}

std::string join(const std::vector<std::string>& v, std::string_view sep) {
    std::string s;
    for (const std::string& x : v) {
        if (!s.empty()) s += sep;
        s += x;
    }
    return s;
}

// A built-in profile name, or else a JSON profile file. Prints the problem and returns nullopt when
// neither works. An empty argument is the default profile.
std::optional<essi::Profile> resolve_profile(const std::string& arg) {
    const std::string name = arg.empty() ? std::string("iso6582") : arg;
    if (auto p = essi::builtin_profile(name)) return p;

    const essi::native::ReadResult file = essi::native::read_whole_file(name);
    if (!file.ok) {
        err("essi: unknown profile '" + name + "': not a built-in profile (" +
            join(essi::builtin_profile_names(), ", ") + ") and cannot read it as a file: " + file.error + "\n");
        return std::nullopt;
    }
    essi::ProfileResult parsed = essi::parse_profile(file.bytes);
    for (const essi::Diagnostic& d : parsed.diagnostics) err(essi::native::diagnostic_line(name, d) + "\n");
    if (!parsed.profile) {
        err("essi: cannot use profile " + name + "\n");
        return std::nullopt;
    }
    return parsed.profile;
}

// Tape files below a directory, by extension, in a stable (sorted) order.
constexpr std::array<std::string_view, 5> kTapeExtensions = {".esi", ".essi", ".ess", ".nc", ".txt"};

std::vector<std::string> expand_paths(const std::vector<std::string>& paths, bool& io_failed) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    for (const std::string& path : paths) {
        std::error_code ec;
        if (path == "-" || !fs::is_directory(path, ec)) {
            files.push_back(path);
            continue;
        }
        std::vector<std::string> found;
        for (fs::recursive_directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
            std::error_code entry_ec;
            if (!it->is_regular_file(entry_ec)) continue;
            std::string ext = it->path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
            if (std::find(kTapeExtensions.begin(), kTapeExtensions.end(), ext) != kTapeExtensions.end())
                found.push_back(it->path().string());
        }
        if (ec) {
            err("essi: cannot read " + path + ": " + ec.message() + "\n");
            io_failed = true;
        }
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

// Reads and checks every path (directories: the tape files below them). Unreadable files are reported on
// stderr and skipped (io_failed set).
std::vector<FileReport> check_files(const std::vector<std::string>& args, const essi::Profile& profile,
                                    bool& io_failed) {
    const std::vector<std::string> paths = expand_paths(args, io_failed);
    std::vector<FileReport> reports;
    reports.reserve(paths.size());
    for (const std::string& path : paths) {
        essi::native::ReadResult file = essi::native::read_whole_file(path);
        if (!file.ok) {
            err("essi: cannot read " + path + ": " + file.error + "\n");
            io_failed = true;
            continue;
        }
        reports.push_back({path, essi::native::check_tape_pipelined(file.bytes, profile)});
        // The bytes go out of scope here: only one tape is in memory at a time.
    }
    return reports;
}

bool any_errors(const std::vector<FileReport>& reports) {
    for (const FileReport& r : reports)
        if (!r.result.ok()) return true;
    return false;
}

int finish(int code) {
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        err(std::string("essi: cannot write output: ") + std::strerror(errno) + "\n");
        return kExitUsage;
    }
    return code;
}

int run_check(const std::vector<std::string>& paths, const std::string& format, const std::string& profile_arg) {
    const auto profile = resolve_profile(profile_arg);
    if (!profile) return kExitUsage;
    bool io_failed = false;

    if (format == "json") {
        const auto reports = check_files(paths, *profile, io_failed);
        out(essi::native::report_to_json(reports, profile->name).dump(kJsonIndent));
        out("\n");
        return finish(io_failed ? kExitUsage : any_errors(reports) ? kExitTapeErrors : kExitOk);
    }

    // Text: each file as soon as it is checked; keep only what the summary needs.
    std::vector<FileReport> summary;
    for (const std::string& path : expand_paths(paths, io_failed)) {
        std::vector<FileReport> one = check_files({path}, *profile, io_failed);
        if (one.empty()) continue;
        FileReport& r = one.front();
        std::string text;
        for (const essi::Diagnostic& d : r.result.diagnostics) {
            text += essi::native::diagnostic_line(r.path, d);
            text += '\n';
        }
        text += essi::native::file_stats_line(r);
        text += '\n';
        out(text);
        r.result.diagnostics.erase(
            std::remove_if(r.result.diagnostics.begin(), r.result.diagnostics.end(),
                           [](const essi::Diagnostic& d) { return d.severity == essi::Severity::Note; }),
            r.result.diagnostics.end());
        for (essi::Diagnostic& d : r.result.diagnostics) d.message.clear();  // counts are all we need now
        summary.push_back(std::move(r));
    }
    out(essi::native::summary_line(summary, profile->name) + "\n");
    return finish(io_failed ? kExitUsage : any_errors(summary) ? kExitTapeErrors : kExitOk);
}

void report_errors_briefly(const std::vector<FileReport>& reports) {
    for (const FileReport& r : reports) {
        const std::size_t n = r.result.count(essi::Severity::Error);
        if (n > 0)
            err("essi: " + r.path + " has " + std::to_string(n) + (n == 1 ? " error" : " errors") +
                " (see essi check " + r.path + ")\n");
    }
}

int run_stats(const std::vector<std::string>& paths, const std::string& format, const std::string& profile_arg) {
    const auto profile = resolve_profile(profile_arg);
    if (!profile) return kExitUsage;
    bool io_failed = false;
    const auto reports = check_files(paths, *profile, io_failed);
    if (format == "json") {
        out(essi::native::stats_report_to_json(reports, profile->name).dump(kJsonIndent));
        out("\n");
    } else {
        bool first = true;
        for (const FileReport& r : reports) {
            if (!first) out("\n");
            first = false;
            out(essi::native::stats_block(r));
        }
    }
    report_errors_briefly(reports);
    return finish(io_failed ? kExitUsage : any_errors(reports) ? kExitTapeErrors : kExitOk);
}

int run_trace(const std::string& path, const std::string& profile_arg) {
    const auto profile = resolve_profile(profile_arg);
    if (!profile) return kExitUsage;
    const essi::native::ReadResult file = essi::native::read_whole_file(path);
    if (!file.ok) {
        err("essi: cannot read " + path + ": " + file.error + "\n");
        return kExitUsage;
    }
    // The trace of a big tape is hundreds of MB: it is streamed in chunks, never held whole.
    const auto diagnostics =
        essi::trace_tape(file.bytes, *profile, [](std::string_view piece) { out(piece); });
    const bool errors = std::any_of(diagnostics.begin(), diagnostics.end(),
                                    [](const essi::Diagnostic& d) { return d.severity == essi::Severity::Error; });
    return finish(errors ? kExitTapeErrors : kExitOk);
}

int run_profile_show(const std::string& arg) {
    const auto profile = resolve_profile(arg);
    if (!profile) return kExitUsage;
    std::string text = essi::profile_to_json(*profile);
    if (text.empty() || text.back() != '\n') text += '\n';
    out(text);
    return finish(kExitOk);
}

int run_profile_list() {
    for (const std::string& name : essi::builtin_profile_names()) out(name + "\n");
    return finish(kExitOk);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"essi: check, measure and trace ESSI cutting tapes (ISO 6582)", "essi"};
    app.set_version_flag("--version", std::string("essi ") + ESSIKIT_VERSION);
    app.require_subcommand(1);

    std::string format = "text";
    std::string profile_arg;
    std::vector<std::string> paths;
    std::string trace_path;
    std::string show_arg;

    const auto add_profile_option = [&](CLI::App* sub) {
        sub->add_option("--profile", profile_arg,
                        "Built-in profile name (see `essi profile list`) or a JSON profile file; default iso6582")
            ->type_name("NAME|FILE");
    };
    const auto add_format_option = [&](CLI::App* sub) {
        sub->add_option("--format", format, "Output format: text or json")
            ->check(CLI::IsMember({"text", "json"}))
            ->type_name("text|json")
            ->capture_default_str();
    };

    CLI::App* check = app.add_subcommand("check", "Check tapes: diagnostics, statistics and a summary");
    add_format_option(check);
    add_profile_option(check);
    check->add_option("PATH", paths, "Tape files ('-' reads standard input)")->required();

    CLI::App* stats = app.add_subcommand("stats", "Statistics of tapes: lengths, pierces, time, extent");
    add_format_option(stats);
    add_profile_option(stats);
    stats->add_option("PATH", paths, "Tape files ('-' reads standard input)")->required();

    CLI::App* trace = app.add_subcommand("trace", "Print the motion stream of a tape, one record a line");
    add_profile_option(trace);
    trace->add_option("PATH", trace_path, "Tape file ('-' reads standard input)")->required();

    CLI::App* profile = app.add_subcommand("profile", "Show machine and dialect profiles");
    profile->require_subcommand(1);
    CLI::App* show = profile->add_subcommand("show", "Print a profile as JSON (every key)");
    show->add_option("PROFILE", show_arg, "Built-in profile name or JSON profile file")
        ->required()
        ->type_name("NAME|FILE");
    CLI::App* list = profile->add_subcommand("list", "List the built-in profiles");

    std::string host = "127.0.0.1";
    int port = 8080;
    std::string web_root = ESSI_DEFAULT_WEB_ROOT;
    std::string examples_dir = ESSI_DEFAULT_EXAMPLES_DIR;
    CLI::App* serve = app.add_subcommand("serve", "Serve the browser viewer and the example tapes over HTTP");
    serve->add_option("--host", host, "Address to listen on")->capture_default_str();
    serve->add_option("--port", port, "Port (0 picks a free one)")->check(CLI::Range(0, 65535))->capture_default_str();
    serve->add_option("--web-root", web_root, "The built viewer (index.html, essi_viewer.js/.wasm)")->capture_default_str();
    serve->add_option("--examples", examples_dir, "Folder of example tapes served at /examples/")->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int rc = app.exit(e);
        return rc == 0 ? kExitOk : kExitUsage;
    }

    if (*check) return run_check(paths, format, profile_arg);
    if (*stats) return run_stats(paths, format, profile_arg);
    if (*trace) return run_trace(trace_path, profile_arg);
    if (*show) return run_profile_show(show_arg);
    if (*list) return run_profile_list();
    if (*serve) return essi::native::run_serve(host, port, web_root, examples_dir);
    return kExitUsage;
}
