// essi trace: the motion stream of a tape, one record a line (essi/trace.hpp; docs/cli.md).
#include <algorithm>
#include <memory>
#include <string>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/trace.hpp"

namespace essi::cli {
namespace {

struct TraceOptions {
    std::string path;
    std::string profile;
    std::string input = "auto";
    int decimals = kTraceDecimals;
    TraceView view;
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

int run_trace(const TraceOptions& o) {
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;
    // The trace of a big tape is hundreds of MB: it is written a piece at a time, never held whole.
    const TapeSetup& setup = tape->setup;
    const auto diagnostics = trace_tape(
        tape->file.bytes, setup.profile, [](std::string_view piece) { out(piece); }, setup.format, o.decimals, o.view);
    const bool errors = std::any_of(diagnostics.begin(), diagnostics.end(),
                                    [](const Diagnostic& d) { return d.severity == Severity::Error; });
    return finish(errors ? kExitTapeErrors : kExitOk);
}

}  // namespace

Subcommand define_trace(CLI::App& essi) {
    auto o = std::make_shared<TraceOptions>();
    CLI::App* trace = essi.add_subcommand("trace", "Print the motion stream of a tape, one record a line");
    add_profile_option(trace, o->profile);
    add_input_option(trace, o->input);
    trace->add_option("--decimals", o->decimals, "Decimals of lengths and coordinates (default 3)")
        ->check(CLI::Range(0, 9))
        ->type_name("N");
    trace->add_flag("--kerf", o->view.kerf,
                    "The torch's path: the kerf-compensated motion stream (29/30/38), same record format");
    trace->add_flag("--machine", o->view.machine,
                    "Machine coordinates: zero offset + plate rotation . program - tool offset (the profile's "
                    "placement)");
    add_max_size_option(trace, o->max_size);
    trace->add_option("PATH", o->path, "Tape file ('-' reads standard input)")->required();
    return {trace, [o] { return run_trace(*o); }};
}

}  // namespace essi::cli
