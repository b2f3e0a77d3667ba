// essi profile show / essi profile list: the machine and dialect profiles (docs/profiles.md).
#include <memory>
#include <string>

#include "cli/cli_io.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/profile.hpp"

namespace essi::cli {
namespace {

int run_profile_show(const std::string& arg) {
    const auto profile = resolve_profile(arg);
    if (!profile) return kExitUsage;
    std::string text = profile_to_json(*profile);
    if (text.empty() || text.back() != '\n') text += '\n';
    out(text);
    return finish(kExitOk);
}

int run_profile_list() {
    for (const std::string& name : builtin_profile_names()) out(name + "\n");
    return finish(kExitOk);
}

}  // namespace

Subcommand define_profile(CLI::App& essi) {
    CLI::App* profile = essi.add_subcommand("profile", "Show machine and dialect profiles");
    profile->require_subcommand(1);
    auto show_arg = std::make_shared<std::string>();
    CLI::App* show = profile->add_subcommand("show", "Print a profile as JSON (every key)");
    show->add_option("PROFILE", *show_arg, "Built-in profile name or JSON profile file")
        ->required()
        ->type_name("NAME|FILE");
    CLI::App* list = profile->add_subcommand("list", "List the built-in profiles");
    return {profile, [show, list, show_arg] {
                if (*show) return run_profile_show(*show_arg);
                if (*list) return run_profile_list();
                return kExitUsage;
            }};
}

}  // namespace essi::cli
