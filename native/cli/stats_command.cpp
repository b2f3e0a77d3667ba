// essi stats: the statistics of tapes (lengths, pierces, time, extent) as text or JSON (docs/cli.md).
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/text_report.hpp"

namespace essi::cli {
namespace {

struct StatsOptions {
    std::vector<std::string> paths;
    std::string format = "text";
    std::string profile;
    std::string input = "auto";
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

int run_stats(const StatsOptions& o) {
    const auto request = resolve_request(o.profile, o.input);
    if (!request) return kExitUsage;
    bool io_failed = false;
    const auto reports = check_files(o.paths, *request, o.max_size, io_failed);
    if (o.format == "json") {
        out(stats_report_to_json(reports, request->profile_name).dump(kJsonIndent));
        out("\n");
    } else {
        bool first = true;
        for (const FileReport& r : reports) {
            if (!first) out("\n");
            first = false;
            out_text(stats_block(r, lang()));
        }
    }
    report_errors_briefly(reports);
    return finish(io_failed ? kExitUsage : any_errors(reports) ? kExitTapeErrors : kExitOk);
}

}  // namespace

Subcommand define_stats(CLI::App& essi) {
    auto o = std::make_shared<StatsOptions>();
    CLI::App* stats = essi.add_subcommand("stats", "Statistics of tapes: lengths, pierces, time, extent");
    add_text_or_json_option(stats, o->format);
    add_profile_option(stats, o->profile);
    add_input_option(stats, o->input);
    add_max_size_option(stats, o->max_size);
    stats->add_option("PATH", o->paths, "Tape files ('-' reads standard input)")->required();
    return {stats, [o] { return run_stats(*o); }};
}

}  // namespace essi::cli
