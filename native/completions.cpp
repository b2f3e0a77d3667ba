// Shell completions made from the CLI's definition (completions.hpp).
#include "completions.hpp"

#include <algorithm>
#include <cctype>

#include <CLI/CLI.hpp>

namespace essi::native {

namespace {

// Help text as every shell's completion syntax takes it: one line, no quotes, brackets, colons or `$`.
std::string plain(std::string_view s) {
    std::string out;
    for (char c : s) {
        if (c == '\n' || c == '\t') c = ' ';
        if (c == '\'' || c == '"' || c == '[' || c == ']' || c == ':' || c == '$' || c == '`' || c == '\\') continue;
        out += c;
    }
    return out.size() > 80 ? out.substr(0, 77) + "..." : out;
}

bool is_choice(std::string_view token) {
    return !token.empty() && std::all_of(token.begin(), token.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    });
}

CompletionOption option_of(const CLI::Option& o, const std::vector<std::string>& profiles) {
    CompletionOption c;
    for (const std::string& s : o.get_snames()) c.names.push_back("-" + s);
    for (const std::string& l : o.get_lnames()) c.names.push_back("--" + l);
    c.help = plain(o.get_description());
    c.takes_value = o.get_items_expected_max() != 0;  // (0: a flag)
    if (!c.takes_value) return c;
    const std::string type_name = o.get_type_name();
    std::string_view type = type_name;
    type = type.substr(0, type.find_first_of(": "));  // (CLI11 appends its checks: "a|b:{a,b}")
    while (!type.empty()) {  // "NAME|FILE|auto": the choices, and what the upper-case words stand for
        const std::string_view token = type.substr(0, type.find('|'));
        if (token == "FILE" || token == "DIR" || token == "PATH") c.files = true;
        else if (token == "NAME" && std::find(c.names.begin(), c.names.end(), "--profile") != c.names.end())
            c.choices.insert(c.choices.end(), profiles.begin(), profiles.end());
        else if (is_choice(token)) c.choices.emplace_back(token);
        type.remove_prefix(std::min(type.size(), token.size() + 1));
    }
    return c;
}

void add_commands(const CLI::App& app, std::vector<std::string> path, const std::vector<std::string>& profiles,
                  std::vector<CompletionCommand>& out) {
    const auto every = [](const CLI::App* a) { return !a->get_group().empty(); };  // (an empty group: hidden)
    for (const CLI::App* sub : app.get_subcommands(every)) {
        CompletionCommand c;
        c.path = path;
        c.path.push_back(sub->get_name());
        c.help = plain(sub->get_description());
        for (const CLI::Option* o : sub->get_options()) {
            if (o->get_positional()) c.files = true;
            else c.options.push_back(option_of(*o, profiles));
        }
        for (const CLI::App* nested : sub->get_subcommands(every)) c.subcommands.push_back(nested->get_name());
        out.push_back(c);
        add_commands(*sub, c.path, profiles, out);
    }
}

std::string joined(const std::vector<std::string>& v, std::string_view sep = " ") {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : std::string(sep)) + x;
    return s;
}

std::vector<std::string> top_level(const std::vector<CompletionCommand>& commands) {
    std::vector<std::string> names;
    for (const CompletionCommand& c : commands)
        if (c.path.size() == 1) names.push_back(c.path[0]);
    return names;
}

// bash: the command is the first word that is not an option (and for `profile`, the next one).
std::string bash_script(const std::vector<CompletionCommand>& commands) {
    std::string s =
        "# bash completion for essi (made by `essi completions bash`)\n"
        "_essi() {\n"
        "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} cmd=\"\" i w\n"
        "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
        "        w=${COMP_WORDS[i]}\n"
        "        [[ $w == -* ]] && continue\n"
        "        if [[ -z $cmd ]]; then cmd=$w; elif [[ $cmd == profile && $w != */* ]]; then cmd=\"profile $w\"; "
        "break; fi\n"
        "    done\n"
        "    COMPREPLY=()\n"
        "    case \"$cmd\" in\n"
        "        \"\") COMPREPLY=($(compgen -W \"" +
        joined(top_level(commands)) + " --help --version\" -- \"$cur\")); return ;;\n";
    for (const CompletionCommand& c : commands) {
        std::vector<std::string> names;
        for (const CompletionOption& o : c.options) names.insert(names.end(), o.names.begin(), o.names.end());
        s += "        \"" + joined(c.path) + "\")\n            case \"$prev\" in\n";
        for (const CompletionOption& o : c.options) {
            if (!o.takes_value) continue;
            std::vector<std::string> body;
            if (!o.choices.empty())
                body.push_back("COMPREPLY=($(compgen -W \"" + joined(o.choices) + "\" -- \"$cur\"))");
            if (o.files) body.push_back("COMPREPLY+=($(compgen -f -- \"$cur\"))");
            body.emplace_back("return");  // (a value of its own: nothing else to offer)
            s += "                " + joined(o.names, "|") + ") " + joined(body, "; ") + " ;;\n";
        }
        s += "            esac\n";
        s += "            if [[ $cur == -* ]]; then COMPREPLY=($(compgen -W \"" + joined(names) + "\" -- \"$cur\"))\n";
        if (!c.subcommands.empty())
            s += "            else COMPREPLY=($(compgen -W \"" + joined(c.subcommands) + "\" -- \"$cur\"))\n";
        else if (c.files) s += "            else COMPREPLY=($(compgen -f -- \"$cur\"))\n";
        s += "            fi ;;\n";
    }
    s += "    esac\n}\ncomplete -o filenames -F _essi essi\n";
    return s;
}

// fish: one `complete` line per subcommand and per option, under the condition that its subcommand was given.
std::string fish_script(const std::vector<CompletionCommand>& commands) {
    std::string s = "# fish completion for essi (made by `essi completions fish`)\ncomplete -c essi -f\n";
    const std::string tops = joined(top_level(commands));
    for (const CompletionCommand& c : commands) {
        std::string when;
        if (c.path.size() == 1) {
            s += "complete -c essi -n 'not __fish_seen_subcommand_from " + tops + "' -a " + c.path[0] + " -d '" +
                 c.help + "'\n";
            when = "__fish_seen_subcommand_from " + c.path[0];
            if (!c.subcommands.empty()) {
                s += "complete -c essi -n '" + when + "; and not __fish_seen_subcommand_from " + joined(c.subcommands) +
                     "' -a '" + joined(c.subcommands) + "'\n";
                when += "; and not __fish_seen_subcommand_from " + joined(c.subcommands);
            }
        } else {
            when = "__fish_seen_subcommand_from " + c.path[0] + "; and __fish_seen_subcommand_from " + c.path.back();
        }
        for (const CompletionOption& o : c.options) {
            s += "complete -c essi -n '" + when + "'";
            for (const std::string& n : o.names)
                s += n.rfind("--", 0) == 0 ? " -l " + n.substr(2) : " -s " + n.substr(1);
            if (o.takes_value) s += o.files ? " -r -F" : " -x";
            if (!o.choices.empty()) s += " -a '" + joined(o.choices) + "'";
            s += " -d '" + o.help + "'\n";
        }
        if (c.files && c.subcommands.empty()) s += "complete -c essi -n '" + when + "' -F\n";
    }
    return s;
}

// zsh: _arguments per subcommand, the words shifted past the subcommand.
std::string zsh_script(const std::vector<CompletionCommand>& commands) {
    std::string s =
        "#compdef essi\n# zsh completion for essi (made by `essi completions zsh`)\n_essi() {\n"
        "    local -a commands\n    commands=(\n";
    for (const CompletionCommand& c : commands)
        if (c.path.size() == 1) s += "        '" + c.path[0] + ":" + c.help + "'\n";
    s += "    )\n    if (( CURRENT == 2 )); then _describe 'command' commands; return; fi\n"
         "    local cmd=$words[2]\n"
         "    [[ $cmd == profile && CURRENT -gt 3 ]] && cmd=\"profile $words[3]\"\n"
         "    shift words; (( CURRENT-- ))\n"
         "    [[ $cmd == profile\\ * ]] && { shift words; (( CURRENT-- )); }\n"
         "    case $cmd in\n";
    for (const CompletionCommand& c : commands) {
        s += "        '" + joined(c.path) + "') _arguments";
        for (const CompletionOption& o : c.options) {
            const std::string names = o.names.size() == 1 ? o.names[0] : "{" + joined(o.names, ",") + "}";
            std::string action;
            if (o.takes_value) {
                action = ":value:";
                if (!o.choices.empty()) action += "(" + joined(o.choices) + ")";
                else if (o.files) action += "_files";
                else action += " ";
            }
            s += " \\\n            " + (o.names.size() == 1 ? "'" + names + "[" + o.help + "]" + action + "'"
                                                            : names + "'[" + o.help + "]" + action + "'");
        }
        if (!c.subcommands.empty()) s += " \\\n            '1:command:(" + joined(c.subcommands) + ")'";
        else if (c.files) s += " \\\n            '*:file:_files'";
        s += " ;;\n";
    }
    s += "    esac\n}\n_essi \"$@\"\n";
    return s;
}

}  // namespace

std::vector<CompletionCommand> completion_spec(const CLI::App& app, const std::vector<std::string>& profiles) {
    std::vector<CompletionCommand> out;
    add_commands(app, {}, profiles, out);
    return out;
}

std::string completion_script(std::string_view shell, const std::vector<CompletionCommand>& commands) {
    if (shell == "bash") return bash_script(commands);
    if (shell == "zsh") return zsh_script(commands);
    if (shell == "fish") return fish_script(commands);
    return {};
}

}  // namespace essi::native
