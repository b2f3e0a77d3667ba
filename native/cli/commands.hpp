// `essi`'s subcommands (docs/cli.md). Each is defined by a function that adds it to the command line with its
// options and returns what runs it once parsed; main() holds the table of them.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace essi::cli {

struct Subcommand {
    CLI::App* app = nullptr;   // selected after parsing when *app is true
    std::function<int()> run;  // the exit code
};

using DefineSubcommand = Subcommand (*)(CLI::App& essi);

Subcommand define_check(CLI::App& essi);        // check_command.cpp
Subcommand define_stats(CLI::App& essi);        // stats_command.cpp
Subcommand define_parts(CLI::App& essi);        // parts_command.cpp: the parts list, plates and remnants
Subcommand define_diff(CLI::App& essi);         // diff_command.cpp
Subcommand define_trace(CLI::App& essi);        // trace_command.cpp
Subcommand define_convert(CLI::App& essi);      // convert_command.cpp
Subcommand define_render(CLI::App& essi);       // render_command.cpp
Subcommand define_report(CLI::App& essi);       // report_command.cpp: the job sheet (PDF, HTML)
Subcommand define_profile(CLI::App& essi);      // profile_command.cpp: profile show, profile list
Subcommand define_serve(CLI::App& essi);        // serve_command.cpp (not in the npm package's build)
Subcommand define_completions(CLI::App& essi);  // completions_command.cpp: hidden; the shells' scripts

}  // namespace essi::cli
