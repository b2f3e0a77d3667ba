// essi: the command-line tool (docs/cli.md). One subcommand a file in native/cli/; this file holds their table.
// Exit codes: 0 no errors, 1 a tape has errors, 2 usage or I/O problem.
// ESSI_NO_SERVE (the npm package's build, npm/CMakeLists.txt): everything but `essi serve`.
#include <cstdlib>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_io.hpp"
#include "cli/commands.hpp"
#include "essi/i18n.hpp"
#include "essi/text.hpp"
#include "essi_version.hpp"
#include "process_memory.hpp"

namespace {

using namespace essi::cli;

// In the order `essi --help` lists them. (completions comes last, after --lang is given to these.)
constexpr DefineSubcommand kSubcommands[] = {
    define_check,   define_stats,  define_parts,  define_diff,    define_trace,
    define_convert, define_render, define_report, define_profile,
#ifndef ESSI_NO_SERVE
    define_serve,
#endif
};

// --lang on every command and its nested commands: the language of the messages and reports.
void add_lang_options(CLI::App& essi, std::string& lang_arg) {
    const auto every = [](CLI::App*) { return true; };
    const auto add = [&lang_arg](CLI::App* cmd) {
        cmd->add_option("--lang", lang_arg,
                        "Language of messages and reports: en, de or zh (default: from LC_ALL, LC_MESSAGES or LANG)")
            ->type_name("en|de|zh");
    };
    for (CLI::App* sub : essi.get_subcommands(every)) {
        add(sub);
        for (CLI::App* nested : sub->get_subcommands(every)) add(nested);
    }
}

// --lang, else the POSIX environment's language; false after the message for a language essikit has not.
bool choose_lang(const std::string& lang_arg) {
    if (lang_arg.empty()) {
        set_lang(essi::lang_from_environment(std::getenv("LC_ALL"), std::getenv("LC_MESSAGES"), std::getenv("LANG")));
    } else if (const auto lang = essi::parse_lang(lang_arg)) {
        set_lang(*lang);
    } else {
        err("essi: --lang " + essi::display_text(lang_arg) + " is not a language essikit has; expected en, de or zh\n");
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App essi{"essi: check, measure and trace ESSI cutting tapes (ISO 6582)", "essi"};
    essi.set_version_flag("--version",
                          std::string("essi ") + essi::native::kVersion + " (commit " + essi::native::kGitCommit + ")");
    essi.require_subcommand(1);

    std::vector<Subcommand> subcommands;
    for (const DefineSubcommand define : kSubcommands) subcommands.push_back(define(essi));
    std::string lang_arg;
    add_lang_options(essi, lang_arg);
    subcommands.push_back(define_completions(essi));

    try {
        essi.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return essi.exit(e) == 0 ? kExitOk : kExitUsage;
    }
    if (!choose_lang(lang_arg)) return kExitUsage;
    for (const Subcommand& sub : subcommands) {
        if (!*sub.app) continue;
        if (sub.app->get_name() != "serve") essi::native::keep_freed_memory();  // (a server gives memory back)
        return sub.run();
    }
    return kExitUsage;
}
