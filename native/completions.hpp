// Shell completions of `essi` (bash, zsh, fish), made from the command line's own definition: its subcommands,
// their options and the values an option takes (CLI11's type names: "text|json" are the choices, FILE and DIR
// complete file names, NAME of a profile the built-in profiles). They cannot drift from the CLI:
// `essi completions bash|zsh|fish` prints them, and the build writes them next to the binary.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace essi::native {

struct CompletionOption {
    std::vector<std::string> names;  // "--format", "-j" ...
    std::string help;
    bool takes_value = false;
    std::vector<std::string> choices;  // the values it takes, when they are a list
    bool files = false;                // a file or folder name is one of its values
};

struct CompletionCommand {
    std::vector<std::string> path;  // {"check"}, {"profile", "show"}
    std::string help;
    std::vector<CompletionOption> options;
    std::vector<std::string> subcommands;  // its own (profile: show, list)
    bool files = false;                    // takes file names after its options
};

// Every subcommand of `app` (nested ones too), with its options; `profiles`: the names NAME stands for.
[[nodiscard]] std::vector<CompletionCommand> completion_spec(const CLI::App& app,
                                                             const std::vector<std::string>& profiles);

// The completion script for `shell` ("bash", "zsh" or "fish"); empty for another shell.
[[nodiscard]] std::string completion_script(std::string_view shell, const std::vector<CompletionCommand>& commands);

}  // namespace essi::native
