// Tapes and profiles for `essi`'s subcommands (cli_tapes.hpp).
#include "cli/cli_tapes.hpp"

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "essi/diagnostics.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "pipelined_check.hpp"

namespace essi::cli {
namespace {

// A tape file (or '-') within --max-size, as its text (native::read_tape_file); the problem on stderr when it cannot
// be read.
native::ReadResult read_tape_file(const std::string& path, std::uint64_t max_size) {
    native::ReadResult file = native::read_tape_file(path, max_size, lang());
    if (!file.ok) err("essi: cannot read " + display_text(path) + ": " + file.error + "\n");
    return file;
}

}  // namespace

std::optional<Profile> resolve_profile(const std::string& arg) {
    const std::string name = arg.empty() ? std::string("iso6582") : arg;
    if (auto p = builtin_profile(name)) return p;

    const native::ReadResult file = native::read_whole_file(name, native::kMaxProfileBytes);
    if (!file.ok) {
        err("essi: unknown profile '" + display_text(name) + "': not a built-in profile (" +
            join(builtin_profile_names(), ", ") + ") and cannot read it as a file: " + file.error + "\n");
        return std::nullopt;
    }
    ProfileResult parsed = parse_profile(file.bytes);
    for (const Diagnostic& d : parsed.diagnostics) err(diagnostic_line(name, d, lang()) + "\n");
    if (!parsed.profile) {
        err("essi: cannot use profile " + name + "\n");
        return std::nullopt;
    }
    return parsed.profile;
}

std::optional<native::TapeRequest> resolve_request(const std::string& profile_arg, const std::string& input_arg) {
    native::TapeRequest r;
    if (!parse_input_choice(input_arg, r.input)) {
        err("essi: unknown --input '" + display_text(input_arg) + "'; expected essi, eia or auto\n");
        return std::nullopt;
    }
    if (profile_arg == kAutoProfile) {
        r.profile_name = std::string(kAutoProfile);
        return r;
    }
    r.profile = resolve_profile(profile_arg);
    if (!r.profile) return std::nullopt;
    r.profile_name = r.profile->name;
    return r;
}

LoadedTape::LoadedTape(const std::string& path, std::uint64_t max_size) : file(read_tape_file(path, max_size)) {}

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
                                      const native::ExpandOptions& options) {
    std::vector<std::string> errors;
    std::vector<std::string> files = native::expand_paths(paths, options, errors);
    for (const std::string& e : errors) {
        err("essi: " + e + "\n");
        io_failed = true;
    }
    return files;
}

std::vector<FileReport> check_files(const std::vector<std::string>& paths, const native::TapeRequest& request,
                                    std::uint64_t max_size, bool& io_failed) {
    std::vector<FileReport> reports;
    for (const std::string& path : expand_paths(paths, io_failed)) {
        native::ReadResult file = read_tape_file(path, max_size);
        if (!file.ok) {
            io_failed = true;
            continue;
        }
        reports.push_back({path, native::check_tape_pipelined(file.bytes, request.setup(file.bytes))});
        // The bytes go out of scope here: only one tape is in memory at a time.
    }
    return reports;
}

bool any_errors(const std::vector<FileReport>& reports) {
    for (const FileReport& r : reports)
        if (!r.result.ok()) return true;
    return false;
}

void report_errors_briefly(const std::vector<FileReport>& reports) {
    for (const FileReport& r : reports) {
        const std::size_t n = r.result.count(Severity::Error);
        if (n > 0) err("essi: " + format_message(Msg::ReportHasErrors, lang(), {r.display_path(), n}) + "\n");
    }
}

}  // namespace essi::cli
