// essi: the command-line tool. check / stats / trace / profile (docs/cli.md).
// Exit codes: 0 no errors, 1 a tape has errors, 2 usage or I/O problem.
// ESSI_NO_SERVE (the npm package's build, npm/CMakeLists.txt): everything but `essi serve`.
#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "essi/diagnostics.hpp"
#include "essi/dxf.hpp"
#include "essi/profile.hpp"
#include "essi/write.hpp"
#include "essi/pipeline.hpp"
#include "essi/trace.hpp"
#include "batch.hpp"
#include "essi_version.hpp"
#include "formats.hpp"
#include "essi/render_svg.hpp"
#include "essi/text.hpp"
#include "tape_request.hpp"
#include "terminal_text.hpp"
#include "completions.hpp"
#ifndef ESSI_NO_SERVE
#include "serve.hpp"
#endif
#include "thread_pool.hpp"
#include "file_io.hpp"
#include "pipelined_check.hpp"
#include "essi/report_json.hpp"
#include "essi/diff.hpp"
#include "essi/text_report.hpp"


extern char** environ;

namespace {

// The language of every message and report (--lang, else the environment): set once in main().
essi::Lang g_lang = essi::Lang::En;

using essi::FileReport;

constexpr int kExitOk = 0;
constexpr int kExitTapeErrors = 1;
constexpr int kExitUsage = 2;  // bad arguments, unreadable file or profile, output failure

constexpr int kJsonIndent = 2;

// The transform of every SIZE option (--max-size, --max-body, --max-store, --min-transfer-rate): a whole number
// of bytes with an optional 1024-based suffix (B, K/KB/KiB, M/MB/MiB, G/GB/GiB, T, P, E; any case), rewritten as
// the number of bytes. A sign, a fraction or a value over 2^64 - 1 is an error (CLI11's AsSizeValue read "-1" and
// "18446744073709551616" as the largest value: no limit).
std::string parse_size_option(std::string& text) {
    const std::string usage = "'" + essi::display_text(text.substr(0, 40)) +
                              "' is not a size: expected a whole number of bytes up to 18446744073709551615, "
                              "with an optional suffix KB, MB, GB, TB, PB or EB (1024-based)";
    std::size_t i = 0;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    std::uint64_t value = 0;
    const std::size_t digits_at = i;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
        const unsigned digit = static_cast<unsigned>(text[i] - '0');
        if (value > (UINT64_MAX - digit) / 10) return usage;
        value = value * 10 + digit;
    }
    if (i == digits_at) return usage;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    std::string unit;
    for (; i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])); ++i) unit += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i != text.size()) return usage;
    static constexpr std::string_view kPrefixes = "kmgtpe";
    int shift = 0;
    if (!unit.empty() && unit != "b") {
        const std::size_t p = kPrefixes.find(unit[0]);
        const std::string_view rest = std::string_view(unit).substr(1);
        if (p == std::string_view::npos || !(rest.empty() || rest == "b" || rest == "i" || rest == "ib")) return usage;
        shift = 10 * static_cast<int>(p + 1);
    }
    if (shift > 0 && value > (UINT64_MAX >> shift)) return usage;
    text = std::to_string(value << shift);
    return {};
}

// The terminal's charset (UTF-8, or GB 18030 / GBK / GB 2312 by the locale): what people read is written in it.
const essi::native::TerminalText g_terminal(std::getenv("LC_ALL"), std::getenv("LC_CTYPE"), std::getenv("LANG"));

// Output as it is: JSON, SARIF, JUnit, GitHub annotations, tapes, traces, pictures (UTF-8 or bytes by their format).
void out(std::string_view s) { std::fwrite(s.data(), 1, s.size(), stdout); }
// Output for people (the text formats): in the terminal's charset.
void out_text(std::string_view s) {
    const std::string t = g_terminal(s);
    std::fwrite(t.data(), 1, t.size(), stdout);
}

void err(std::string_view s) {
    const std::string t = g_terminal(s);
    std::fwrite(t.data(), 1, t.size(), stderr);
}

std::string join(const std::vector<std::string>& v, std::string_view sep) {
    std::string s;
    for (const std::string& x : v) {
        if (!s.empty()) s += sep;
        s += x;
    }
    return s;
}

// What --input and --to accept: the core's names of the formats (in the enum's order), then `more`.
template <class Format, std::size_t N>
std::vector<std::string> format_names(const Format (&formats)[N], const char* (*name)(Format),
                                      std::vector<std::string> more = {}) {
    std::vector<std::string> names;
    for (const Format f : formats) names.emplace_back(name(f));
    names.insert(names.end(), more.begin(), more.end());
    return names;
}

// A built-in profile name, or else a JSON profile file. Prints the problem and returns nullopt when
// neither works. An empty argument is the default profile.
std::optional<essi::Profile> resolve_profile(const std::string& arg) {
    const std::string name = arg.empty() ? std::string("iso6582") : arg;
    if (auto p = essi::builtin_profile(name)) return p;

    const essi::native::ReadResult file = essi::native::read_whole_file(name, essi::native::kMaxProfileBytes);
    if (!file.ok) {
        err("essi: unknown profile '" + essi::display_text(name) + "': not a built-in profile (" +
            join(essi::builtin_profile_names(), ", ") + ") and cannot read it as a file: " + file.error + "\n");
        return std::nullopt;
    }
    essi::ProfileResult parsed = essi::parse_profile(file.bytes);
    for (const essi::Diagnostic& d : parsed.diagnostics) err(essi::diagnostic_line(name, d, g_lang) + "\n");
    if (!parsed.profile) {
        err("essi: cannot use profile " + name + "\n");
        return std::nullopt;
    }
    return parsed.profile;
}

// A tape file (or '-') within --max-size; the problem on stderr when it cannot be read.
essi::native::ReadResult read_tape_file(const std::string& path, std::uint64_t max_size) {
    essi::native::ReadResult file = essi::native::read_whole_file(path, max_size);
    if (!file.ok) err("essi: cannot read " + essi::display_text(path) + ": " + file.error + "\n");
    return file;
}

// --profile and --input: "auto" leaves the choice to each tape's content (essi/dialect.hpp).
std::optional<essi::native::TapeRequest> resolve_request(const std::string& profile_arg, const std::string& input_arg) {
    essi::native::TapeRequest r;
    if (!essi::parse_input_choice(input_arg, r.input)) {
        err("essi: unknown --input '" + essi::display_text(input_arg) + "'; expected essi, eia or auto\n");
        return std::nullopt;
    }
    if (profile_arg == essi::kAutoProfile) {
        r.profile_name = std::string(essi::kAutoProfile);
        return r;
    }
    r.profile = resolve_profile(profile_arg);
    if (!r.profile) return std::nullopt;
    r.profile_name = r.profile->name;
    return r;
}

// One tape file read and set up as --profile and --input say (trace, render, convert). Built in place: `file`
// views its own bytes, so it is never moved.
struct LoadedTape {
    LoadedTape(const std::string& path, std::uint64_t max_size) : file(read_tape_file(path, max_size)) {}
    essi::native::ReadResult file;
    essi::TapeSetup setup;
};
// Null after the message (a bad --profile/--input, a file that cannot be read).
std::unique_ptr<LoadedTape> load_tape(const std::string& path, const std::string& profile_arg,
                                      const std::string& input_arg, std::uint64_t max_size) {
    const auto request = resolve_request(profile_arg, input_arg);
    if (!request) return nullptr;
    auto tape = std::make_unique<LoadedTape>(path, max_size);
    if (!tape->file.ok) return nullptr;
    tape->setup = request->setup(tape->file.bytes);
    return tape;
}

std::vector<std::string> expand_paths(const std::vector<std::string>& paths, bool& io_failed,
                                      const essi::native::ExpandOptions& options = {}) {
    std::vector<std::string> errors;
    std::vector<std::string> files = essi::native::expand_paths(paths, options, errors);
    for (const std::string& e : errors) {
        err("essi: " + e + "\n");
        io_failed = true;
    }
    return files;
}

// Reads and checks every path (directories: the tape files below them). Unreadable files are reported on
// stderr and skipped (io_failed set).
std::vector<FileReport> check_files(const std::vector<std::string>& args, const essi::native::TapeRequest& request,
                                    std::uint64_t max_size, bool& io_failed) {
    const std::vector<std::string> paths = expand_paths(args, io_failed);
    std::vector<FileReport> reports;
    reports.reserve(paths.size());
    for (const std::string& path : paths) {
        essi::native::ReadResult file = essi::native::read_whole_file(path, max_size);
        if (!file.ok) {
            err("essi: cannot read " + essi::display_text(path) + ": " + file.error + "\n");
            io_failed = true;
            continue;
        }
        reports.push_back({path, essi::native::check_tape_pipelined(file.bytes, request.setup(file.bytes))});
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

struct CheckOptions {
    std::string format = "text";
    std::string profile;
    std::string input = "auto";
    std::string ext;             // --ext LIST ("" = the defaults)
    bool no_sniff = false;
    unsigned jobs = 0;           // 0 = all cores
    std::string fail_on = "error";
    long long max_diagnostics = -1;  // -1 = all
    long long max_per_code = -1;     // -1 = the profile's max_per_code
    bool quiet = false;
    std::string docs_url = std::string(essi::native::kDefaultDocsUrl);
    std::uint64_t max_size = essi::native::kDefaultMaxInputBytes;
};

int run_check(const std::vector<std::string>& paths, const CheckOptions& o) {
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
    const std::vector<std::string> files = expand_paths(paths, io_failed, expand);

    BatchOptions batch;
    batch.jobs = o.jobs == 0 ? hardware_jobs() : o.jobs;
    if (o.max_diagnostics >= 0) batch.max_diagnostics = static_cast<std::size_t>(o.max_diagnostics);
    batch.max_size = o.max_size;
    const FailOn fail_on = o.fail_on == "warning" ? FailOn::Warning : o.fail_on == "never" ? FailOn::Never : FailOn::Error;

    BatchTotals totals;
    std::vector<BatchItem> kept;       // json, junit, sarif: the whole report is written at the end
    const bool streamed = o.format == "text" || o.format == "github";
    check_batch(files, *request, batch, [&](BatchItem&& item) {
        totals.add(item, fail_on);
        if (!item.read_ok) {
            err("essi: " + essi::format_message(essi::Msg::ReportCannotRead, g_lang, {item.report.display_path(), item.error}) + "\n");
            io_failed = true;
        }
        if (o.format == "text") {
            if (item.read_ok) out_text(text_file_block(item, o.quiet, g_lang));
        } else if (o.format == "github") {
            out(github_file_block(item, g_lang));
        } else {
            kept.push_back(std::move(item));
        }
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    if (o.format == "json") {
        std::vector<FileReport> reports;
        reports.reserve(kept.size());
        for (BatchItem& it : kept)
            if (it.read_ok) reports.push_back(std::move(it.report));
        out(report_to_json(reports, profile_name, g_lang).dump(kJsonIndent));
        out("\n");
    } else if (o.format == "junit") {
        out(junit_report(kept, profile_name, seconds, fail_on, g_lang));
    } else if (o.format == "sarif") {
        out(sarif_report(kept, profile_name, o.docs_url, g_lang).dump(kJsonIndent));
        out("\n");
    } else if (o.format == "codeclimate") {
        out(codeclimate_report(kept, g_lang).dump(kJsonIndent));
        out("\n");
    }
    const std::string summary = batch_summary_line(totals, profile_name, seconds, g_lang) + "\n";
    if (streamed) (o.format == "text" ? out_text : out)(summary);
    else if (!o.quiet) err(summary);

    if (io_failed) return finish(kExitUsage);
    if (fail_on == FailOn::Never) return finish(kExitOk);
    return finish(totals.failed > 0 ? kExitTapeErrors : kExitOk);
}

bool write_file(const std::string& path, std::string_view bytes) {
    if (path == "-") {
        out(bytes);
        return true;
    }
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    return std::fclose(f) == 0 && ok;
}

// Runs `argv` (looked up on PATH) and waits; true when it exits with 0. Under Emscripten (the npm package) there are
// no processes: false, and `render --png` says it needs rsvg-convert.
bool run_program(const std::vector<std::string>& args) {
#ifdef __EMSCRIPTEN__
    (void)args;
    return false;
#else
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
#endif
}

struct RenderCliOptions {
    std::string path;
    std::string output;
    std::string format;  // svg (default) or dxf; "" = by the output's extension
    std::string profile;
    std::string input = "auto";
    bool png = false;
    bool no_travel = false;
    bool problems_only = false;
    double width = 1200;
    std::uint64_t max_size = essi::native::kDefaultMaxInputBytes;
};

int run_render(const RenderCliOptions& o) {
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;
    const essi::native::ReadResult& file = tape->file;
    const essi::TapeSetup& setup = tape->setup;
    essi::RenderOptions options;
    options.title = o.path == "-" ? std::string("-") : essi::display_text(std::filesystem::path(o.path).filename().string());
    options.width_px = o.width;
    options.show_travel = !o.no_travel;
    options.problems_only = o.problems_only;
    const auto ends_with = [](const std::string& s, const char* ext) {
        const std::size_t n = std::strlen(ext);
        return s.size() > n && s.compare(s.size() - n, n, ext) == 0;
    };
    const bool png = o.png || ends_with(o.output, ".png");
    const auto say = [](essi::Msg m, essi::MessageArgs args) { err("essi render: " + essi::format_message(m, g_lang, args) + "\n"); };
    const auto cannot_write = [&](const std::string& path) {
        say(essi::Msg::CliCannotWrite, {essi::display_text(path), std::strerror(errno)});
        return kExitUsage;
    };
    if (o.format == "dxf" || (o.format.empty() && ends_with(o.output, ".dxf"))) {
        if (png) {
            say(essi::Msg::RenderDxfIsNoPicture, {o.png ? std::string("--png") : essi::display_text(o.output)});
            return kExitUsage;
        }
        const essi::DxfResult dxf = essi::render_dxf(file.bytes, setup);
        std::string output = o.output;
        if (output.empty()) output = (o.path == "-" ? std::string("stdin") : std::filesystem::path(o.path).filename().string()) + ".dxf";
        if (!write_file(output, dxf.text)) return cannot_write(output);
        if (output != "-") say(essi::Msg::RenderWrote, {essi::display_text(output)});
        const bool errors = std::any_of(dxf.diagnostics.begin(), dxf.diagnostics.end(),
                                        [](const essi::Diagnostic& d) { return d.severity == essi::Severity::Error; });
        return finish(errors ? kExitTapeErrors : kExitOk);
    }
    const essi::RenderResult r = essi::render_svg(file.bytes, setup.profile, options, setup.format);
    std::string output = o.output;
    if (output.empty()) {
        const std::string base = o.path == "-" ? std::string("stdin") : std::filesystem::path(o.path).filename().string();
        output = base + (png ? ".png" : ".svg");
    }
    if (png) {
        if (output == "-") {
            say(essi::Msg::RenderPngNeedsFile, {});
            return kExitUsage;
        }
        const std::string tmp = output + ".tmp.svg";
        if (!write_file(tmp, r.svg)) return cannot_write(tmp);
        const bool ok = run_program({"rsvg-convert", "--background-color=white", "-o", output, tmp});
        std::remove(tmp.c_str());
        if (!ok) {
            std::remove(output.c_str());  // (no empty or partial picture left behind)
            say(essi::Msg::RenderNoRsvg, {});
            return kExitUsage;
        }
        std::error_code ec;
        if (std::filesystem::file_size(output, ec) == 0 || ec) {
            std::remove(output.c_str());
            say(essi::Msg::RenderPngEmpty, {essi::display_text(output)});
            return kExitUsage;
        }
    } else if (!write_file(output, r.svg)) {
        return cannot_write(output);
    }
    if (output != "-") say(essi::Msg::RenderWrote, {essi::display_text(output)});
    return finish(r.result.ok() ? kExitOk : kExitTapeErrors);
}

void report_errors_briefly(const std::vector<FileReport>& reports) {
    for (const FileReport& r : reports) {
        const std::size_t n = r.result.count(essi::Severity::Error);
        if (n > 0)
            err("essi: " + essi::format_message(essi::Msg::ReportHasErrors, g_lang, {r.display_path(), n}) + "\n");
    }
}

struct ConvertCliOptions {
    std::string path;
    std::string output = "-";
    std::string to;
    std::string profile;
    std::string to_profile;
    std::string input = "auto";
    bool absolute = false;
    bool incremental = false;
    bool force = false;
    std::uint64_t max_size = essi::native::kDefaultMaxInputBytes;
};

// essi convert: the tape read as --input/--profile say, checked as essi check does, run, and written in --to for
// --to-profile (default: the profile it was read with). Warnings and errors on stderr; a tape with errors exits 1
// and nothing is written, unless --force (then what the machine would run of it is written, and it still exits 1).
int run_convert(const ConvertCliOptions& o) {
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;
    const essi::TapeSetup& setup = tape->setup;
    essi::ConvertOptions options;
    options.to = essi::parse_output_format(o.to).value_or(essi::OutputFormat::Essi);  // (--to is checked: one of them)
    options.absolute = o.absolute;
    options.force = o.force;
    if (o.to_profile.empty()) {
        options.target = setup.profile;
    } else {
        const auto target = resolve_profile(o.to_profile);
        if (!target) return kExitUsage;
        options.target = *target;
    }
    const essi::ConvertResult r = essi::convert_tape(tape->file.bytes, setup, options);
    for (const essi::Diagnostic& d : r.diagnostics) err(essi::diagnostic_line(o.path, d, g_lang) + "\n");
    if (r.refused) {
        err("essi convert: " + essi::format_message(essi::Msg::ConvertRefused, g_lang, {essi::display_text(o.path)}) + "\n");
        return finish(kExitTapeErrors);
    }
    if (!write_file(o.output, r.text)) {
        err("essi convert: cannot write " + essi::display_text(o.output) + ": " + std::strerror(errno) + "\n");
        return kExitUsage;
    }
    return finish(r.ok() ? kExitOk : kExitTapeErrors);
}

int run_stats(const std::vector<std::string>& paths, const std::string& format, const std::string& profile_arg,
              const std::string& input_arg, std::uint64_t max_size) {
    const auto request = resolve_request(profile_arg, input_arg);
    if (!request) return kExitUsage;
    bool io_failed = false;
    const auto reports = check_files(paths, *request, max_size, io_failed);
    if (format == "json") {
        out(essi::stats_report_to_json(reports, request->profile_name).dump(kJsonIndent));
        out("\n");
    } else {
        bool first = true;
        for (const FileReport& r : reports) {
            if (!first) out("\n");
            first = false;
            out_text(essi::stats_block(r, g_lang));
        }
    }
    report_errors_briefly(reports);
    return finish(io_failed ? kExitUsage : any_errors(reports) ? kExitTapeErrors : kExitOk);
}

int run_trace(const std::string& path, const std::string& profile_arg, const std::string& input_arg,
              std::uint64_t max_size, int decimals, essi::TraceView view) {
    const auto tape = load_tape(path, profile_arg, input_arg, max_size);
    if (!tape) return kExitUsage;
    // The trace of a big tape is hundreds of MB: it is written a piece at a time, never held whole.
    const essi::TapeSetup& setup = tape->setup;
    const auto diagnostics =
        essi::trace_tape(tape->file.bytes, setup.profile, [](std::string_view piece) { out(piece); }, setup.format, decimals,
                         view);
    const bool errors = std::any_of(diagnostics.begin(), diagnostics.end(),
                                    [](const essi::Diagnostic& d) { return d.severity == essi::Severity::Error; });
    return finish(errors ? kExitTapeErrors : kExitOk);
}

// essi diff A B: two revisions compared contour by contour (essi/diff.hpp). Exit 0 when they cut the same, 1 when
// they differ, 2 for a usage problem or a file that cannot be read.
int run_diff(const std::vector<std::string>& paths, const std::string& format, const std::string& profile_arg,
             const std::string& input_arg, std::uint64_t max_size) {
    const auto a = load_tape(paths[0], profile_arg, input_arg, max_size);
    const auto b = a ? load_tape(paths[1], profile_arg, input_arg, max_size) : nullptr;
    if (!a || !b) return kExitUsage;
    const essi::TapeContours ca = essi::tape_contours(a->file.bytes, a->setup);
    const essi::TapeContours cb = essi::tape_contours(b->file.bytes, b->setup);
    const essi::TapeDiff d = essi::diff_contours(ca.contours, cb.contours);
    const essi::DiffSide sa{paths[0], &ca}, sb{paths[1], &cb};
    if (format == "json") out(essi::diff_json(sa, sb, d));
    else out_text(essi::diff_text(sa, sb, d, g_lang));
    return finish(d.same() ? kExitOk : kExitTapeErrors);
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
    app.set_version_flag("--version", std::string("essi ") + essi::native::kVersion + " (commit " +
                                              essi::native::kGitCommit + ")");
    app.require_subcommand(1);

    std::string format = "text";
    std::string profile_arg;
    std::string input_arg = "auto";
    std::vector<std::string> paths;
    std::string trace_path;
    std::string show_arg;
    std::uint64_t max_size = essi::native::kDefaultMaxInputBytes;  // stats and trace (check and render: their options)
    const auto add_max_size_option = [](CLI::App* sub, std::uint64_t& value) {
        sub->add_option("--max-size", value,
                        "Largest input read, file or standard input (suffixes KB MB GB: 1024-based; default 1GB)")
            ->transform(CLI::Validator(parse_size_option, "", ""))
            ->type_name("SIZE");
    };

    constexpr const char* kProfileHelp =
        "Built-in profile name (see `essi profile list`), a JSON profile file, or auto (the dialect the tape's "
        "evidence shows); default iso6582";
    constexpr const char* kInputHelp = "Tape format: essi, eia, or auto (from the content; the default)";
    const std::vector<std::string> input_names = format_names(essi::kInputFormats, essi::input_format_name, {"auto"});
    const auto add_input_option = [&input_names](CLI::App* sub, std::string& value) {
        sub->add_option("--input", value, kInputHelp)
            ->check(CLI::IsMember(input_names))
            ->type_name(join(input_names, "|"))
            ->capture_default_str();
    };
    const auto add_profile_option = [&](CLI::App* sub) {
        sub->add_option("--profile", profile_arg, kProfileHelp)->type_name("NAME|FILE|auto");
        add_input_option(sub, input_arg);
    };
    const auto add_format_option = [&](CLI::App* sub) {
        sub->add_option("--format", format, "Output format: text or json")
            ->check(CLI::IsMember({"text", "json"}))
            ->type_name("text|json")
            ->capture_default_str();
    };

    CheckOptions check_opts;
    CLI::App* check = app.add_subcommand("check", "Check tapes: diagnostics, statistics and a summary");
    check->add_option("--format", check_opts.format, "Output format")
        ->check(CLI::IsMember({"text", "json", "junit", "sarif", "github", "codeclimate"}))
        ->type_name("text|json|junit|sarif|github|codeclimate")
        ->capture_default_str();
    check->add_option("--profile", check_opts.profile, kProfileHelp)->type_name("NAME|FILE|auto");
    add_input_option(check, check_opts.input);
    check->add_option("--ext", check_opts.ext,
                      "File extensions that count in directories (default: .esi,.essi,.ess,.nc,.txt)")
        ->type_name("LIST");
    check->add_flag("--no-sniff", check_opts.no_sniff,
                    "In directories, do not look into files with other extensions for ESSI content");
    check->add_option("-j,--jobs", check_opts.jobs, "Files checked in parallel (default: all cores)")
        ->check(CLI::Range(1u, 1024u));
    check->add_option("--fail-on", check_opts.fail_on, "Exit code 1 on: error, warning or never")
        ->check(CLI::IsMember({"error", "warning", "never"}))
        ->type_name("error|warning|never")
        ->capture_default_str();
    check->add_option("--max-diagnostics", check_opts.max_diagnostics,
                      "At most N diagnostics per file (the rest are counted in a note)")
        ->check(CLI::Range(0LL, 1LL << 40))
        ->type_name("N");
    check->add_option("--max-per-code", check_opts.max_per_code,
                      "At most N diagnostics of one code per file, then one that counts the rest (default: the "
                      "profile's max_per_code, 1000; 0: no limit)")
        ->check(CLI::Range(0LL, static_cast<long long>(essi::kMaxPerCodeLimit)))
        ->type_name("N");
    check->add_flag("-q,--quiet", check_opts.quiet,
                    "Text: only errors, warnings and the summary; json/junit/sarif: no summary on stderr");
    check->add_option("--docs-url", check_opts.docs_url,
                      "Base URL of the docs/ folder for SARIF help links (helpUri = URL/diagnostics.md#e301)")
        ->capture_default_str();
    add_max_size_option(check, check_opts.max_size);
    check->add_option("PATH", paths, "Tape files or directories ('-' reads standard input)")->required();

    CLI::App* stats = app.add_subcommand("stats", "Statistics of tapes: lengths, pierces, time, extent");
    add_format_option(stats);
    add_profile_option(stats);
    add_max_size_option(stats, max_size);
    stats->add_option("PATH", paths, "Tape files ('-' reads standard input)")->required();

    std::vector<std::string> diff_paths;
    CLI::App* diff = app.add_subcommand("diff", "Compare two revisions of a tape: contours same, moved, changed, "
                                                "removed, added, and the statistics before and after");
    add_format_option(diff);
    add_profile_option(diff);
    add_max_size_option(diff, max_size);
    diff->add_option("A B", diff_paths, "The two tape files")->required()->expected(2);

    CLI::App* trace = app.add_subcommand("trace", "Print the motion stream of a tape, one record a line");
    add_profile_option(trace);
    int trace_decimals = essi::kTraceDecimals;
    trace->add_option("--decimals", trace_decimals, "Decimals of lengths and coordinates (default 3)")
        ->check(CLI::Range(0, 9))
        ->type_name("N");
    essi::TraceView trace_view;
    trace->add_flag("--kerf", trace_view.kerf,
                    "The torch's path: the kerf-compensated motion stream (29/30/38), same record format");
    trace->add_flag("--machine", trace_view.machine,
                    "Machine coordinates: zero offset + plate rotation . program - tool offset (the profile's placement)");
    add_max_size_option(trace, max_size);
    trace->add_option("PATH", trace_path, "Tape file ('-' reads standard input)")->required();

    ConvertCliOptions convert_opts;
    CLI::App* convert = app.add_subcommand("convert", "Write a tape as ESSI, EIA (RS-274) or G-code for LinuxCNC");
    convert->add_option("--to", convert_opts.to, "Target format")
        ->required()
        ->check(CLI::IsMember(format_names(essi::kOutputFormats, essi::output_format_name)))
        ->type_name(join(format_names(essi::kOutputFormats, essi::output_format_name), "|"));
    convert->add_option("--profile", convert_opts.profile, kProfileHelp)->type_name("NAME|FILE|auto");
    convert->add_option("--to-profile", convert_opts.to_profile,
                        "The dialect written (units, end code, EIA table): a built-in name or a JSON profile file; "
                        "default: the profile the tape is read with")
        ->type_name("NAME|FILE");
    add_input_option(convert, convert_opts.input);
    auto* absolute_flag = convert->add_flag("--absolute", convert_opts.absolute, "Absolute coordinates (82, G90)");
    convert->add_flag("--incremental", convert_opts.incremental, "Incremental coordinates (81, G91; the default)")
        ->excludes(absolute_flag);
    convert->add_flag("--force", convert_opts.force,
                      "Write the tape even when it has errors (what the machine would run of it; the exit code is "
                      "still 1)");
    add_max_size_option(convert, convert_opts.max_size);
    convert->add_option("-o,--output", convert_opts.output, "Output file ('-' = stdout, the default)");
    convert->add_option("FILE", convert_opts.path, "Tape file ('-' reads standard input)")->required();

    RenderCliOptions render_opts;
    CLI::App* render = app.add_subcommand("render", "Draw a tape as SVG (or PNG): motion, pierces, errors, a legend");
    render->add_option("PATH", render_opts.path, "Tape file ('-' reads standard input)")->required();
    add_max_size_option(render, render_opts.max_size);
    render->add_option("-o,--output", render_opts.output, "Output file ('-' = stdout; default NAME.svg)");
    render->add_option("--profile", render_opts.profile, kProfileHelp)->type_name("NAME|FILE|auto");
    add_input_option(render, render_opts.input);
    render->add_option("--format", render_opts.format, "svg (default) or dxf (R12: layers CUT, MARK, TRAVEL, DIAGNOSTICS; also when OUT ends in .dxf)")
        ->check(CLI::IsMember({"svg", "dxf"}))
        ->type_name("svg|dxf");
    render->add_flag("--png", render_opts.png, "Write PNG (through rsvg-convert; also when OUT ends in .png)");
    render->add_flag("--no-travel", render_opts.no_travel, "Leave out travel and rapid motion");
    render->add_flag("--problems-only", render_opts.problems_only,
                     "Draw what the diagnostics concern in full and everything else faint");
    render->add_option("--width", render_opts.width, "Width of the picture in pixels")
        ->check(CLI::Range(16.0, 100000.0))
        ->capture_default_str();

    CLI::App* profile = app.add_subcommand("profile", "Show machine and dialect profiles");
    profile->require_subcommand(1);
    CLI::App* show = profile->add_subcommand("show", "Print a profile as JSON (every key)");
    show->add_option("PROFILE", show_arg, "Built-in profile name or JSON profile file")
        ->required()
        ->type_name("NAME|FILE");
    CLI::App* list = profile->add_subcommand("list", "List the built-in profiles");

#ifndef ESSI_NO_SERVE
    essi::native::ServeOptions serve_opts;
    serve_opts.web_root = ESSI_DEFAULT_WEB_ROOT;
    serve_opts.examples_dir = ESSI_DEFAULT_EXAMPLES_DIR;
    serve_opts.share_store_js = ESSI_DEFAULT_SHARE_STORE_JS;
    CLI::App* serve = app.add_subcommand("serve", "Serve the browser viewer, the example tapes and the check/share API");
    serve->add_option("--host", serve_opts.host, "Address to listen on")->capture_default_str();
    serve->add_option("--port", serve_opts.port, "Port (0 picks a free one)")->check(CLI::Range(0, 65535))->capture_default_str();
    serve->add_option("--web-root", serve_opts.web_root,
                      "The built viewer (index.html, essi_viewer.js/.wasm); empty: the viewer compiled into essi (make dist)")
        ->capture_default_str();
    serve->add_option("--examples", serve_opts.examples_dir, "Folder of example tapes served at /examples/")->capture_default_str();
    serve->add_option("--data", serve_opts.data_dir,
                      "Folder of the share store (SQLite); default $XDG_DATA_HOME/essikit, else ./essi-data")
        ->type_name("DIR");
    const auto size_option = [serve](const char* name, std::uint64_t& value, const char* help) {
        serve->add_option(name, value, help)->transform(CLI::Validator(parse_size_option, "", ""))->type_name("SIZE")->capture_default_str();
    };
    size_option("--max-body", serve_opts.max_body, "Largest request body in bytes (suffixes KB MB GB: 1024-based)");
    size_option("--max-store", serve_opts.max_store, "Largest total size of the stored shares (oldest go first)");
    size_option("--min-transfer-rate", serve_opts.min_transfer_rate,
                "Slowest average rate, per second, of a request body or a response after the first --request-timeout "
                "seconds (default 1MB)");
    const auto limit_option = [serve](const char* name, auto& value, int max, const char* help) {
        serve->add_option(name, value, help)->check(CLI::Range(1, max))->capture_default_str();
    };
    limit_option("--threads", serve_opts.threads, 1024, "Requests handled at once (each connection waits in its own thread)");
    limit_option("--max-connections", serve_opts.max_connections, 100000, "Connections open at once (more wait to be accepted)");
    limit_option("--max-client-connections", serve_opts.max_client_connections, 100000,
                 "Connections open at once from one client address (more get 429)");
    limit_option("--request-timeout", serve_opts.request_timeout_s, 3600,
                 "Seconds a client has to send its request line and headers (and the grace before --min-transfer-rate)");
    limit_option("--body-timeout", serve_opts.body_timeout_s, 86400,
                 "Seconds a request body may take in all; also the longest wait for a slot (then 503)");
    limit_option("--max-large-requests", serve_opts.max_large_requests, 1024,
                 "Requests with a body over 1 MB handled at once (bounds the server's memory)");
    limit_option("--max-checks", serve_opts.max_checks, 1024,
                 "Checks and conversions running at once, whatever the size of their tape (bounds the server's memory)");
    limit_option("--max-diagnostics", serve_opts.max_diagnostics, 100000000,
                 "Diagnostics in an /api/check or /api/convert answer (the rest are counted: diagnostics_omitted)");
    serve->add_option("--allowed-host", serve_opts.allowed_hosts,
                      "A Host name served besides localhost, 127.0.0.1, ::1 and --host (repeatable; DNS rebinding)")
        ->type_name("NAME");
    const std::map<std::string, std::int64_t> seconds_per{{"s", 1}, {"m", 60}, {"h", 3600}, {"d", 86400}};
    serve->add_option("--share-ttl", serve_opts.share_ttl_s, "How long a share lives (suffixes s m h d; default 30d)")
        ->transform(CLI::AsNumberWithUnit(seconds_per, CLI::AsNumberWithUnit::CASE_SENSITIVE))
        ->check(CLI::PositiveNumber)
        ->type_name("DURATION");
    serve->add_option("--share-rate", serve_opts.share_rate, "Uploads per minute per client address (0: no limit)")
        ->capture_default_str();
#endif

    // --lang on every command: the language of the messages and reports (else the POSIX environment's).
    std::string lang_arg;
    const auto add_lang = [&](CLI::App* cmd) {
        cmd->add_option("--lang", lang_arg,
                        "Language of messages and reports: en, de or zh (default: from LC_ALL, LC_MESSAGES or LANG)")
            ->type_name("en|de|zh");
    };
    const auto every = [](CLI::App*) { return true; };
    for (CLI::App* sub : app.get_subcommands(every)) {
        add_lang(sub);
        for (CLI::App* nested : sub->get_subcommands(every)) add_lang(nested);
    }

    // Hidden (no group): the shell completions, made from the definition above (completions.hpp).
    std::string completion_shell;
    CLI::App* completions = app.add_subcommand("completions", "Print the completion script of a shell")->group("");
    completions->add_option("SHELL", completion_shell, "bash, zsh or fish")
        ->required()
        ->check(CLI::IsMember({"bash", "zsh", "fish"}));

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int rc = app.exit(e);
        return rc == 0 ? kExitOk : kExitUsage;
    }
    if (lang_arg.empty()) {
        g_lang = essi::lang_from_environment(std::getenv("LC_ALL"), std::getenv("LC_MESSAGES"), std::getenv("LANG"));
    } else if (const auto lang = essi::parse_lang(lang_arg)) {
        g_lang = *lang;
    } else {
        err("essi: --lang " + essi::display_text(lang_arg) + " is not a language essikit has; expected en, de or zh\n");
        return kExitUsage;
    }

    if (*check) return run_check(paths, check_opts);
    if (*stats) return run_stats(paths, format, profile_arg, input_arg, max_size);
    if (*trace)
        return run_trace(trace_path, profile_arg, input_arg, max_size, trace_decimals, trace_view);
    if (*render) return run_render(render_opts);
    if (*diff) return run_diff(diff_paths, format, profile_arg, input_arg, max_size);
    if (*convert) return run_convert(convert_opts);
    if (*show) return run_profile_show(show_arg);
    if (*list) return run_profile_list();
#ifndef ESSI_NO_SERVE
    if (*serve) return essi::native::run_serve(serve_opts);
#endif
    if (*completions) {
        out(essi::native::completion_script(completion_shell,
                                            essi::native::completion_spec(app, essi::builtin_profile_names())));
        return kExitOk;
    }
    return kExitUsage;
}
