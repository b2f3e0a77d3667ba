// essi completions SHELL (hidden: no group): the shell's completion script, made from the command line's own
// definition (completions.hpp), so it never differs from what essi accepts.
#include <memory>
#include <string>

#include "cli/cli_io.hpp"
#include "cli/commands.hpp"
#include "completions.hpp"
#include "essi/profile.hpp"

namespace essi::cli {

Subcommand define_completions(CLI::App& essi) {
    auto shell = std::make_shared<std::string>();
    CLI::App* completions = essi.add_subcommand("completions", "Print the completion script of a shell")->group("");
    completions->add_option("SHELL", *shell, "bash, zsh or fish")
        ->required()
        ->check(CLI::IsMember({"bash", "zsh", "fish"}));
    return {completions, [&essi, shell] {
                out(native::completion_script(*shell, native::completion_spec(essi, builtin_profile_names())));
                return finish(kExitOk);
            }};
}

}  // namespace essi::cli
