// The shared options of `essi`'s subcommands (cli_options.hpp).
#include "cli/cli_options.hpp"

#include <cctype>

#include "essi/read.hpp"
#include "essi/text.hpp"

namespace essi::cli {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::string parse_size_option(std::string& text) {
    const std::string usage = "'" + display_text(text.substr(0, 40)) +
                              "' is not a size: expected a whole number of bytes up to 18446744073709551615, "
                              "with an optional suffix KB, MB, GB, TB, PB or EB (1024-based)";
    std::size_t i = 0;
    while (i < text.size() && is_space(text[i])) ++i;
    std::uint64_t value = 0;
    const std::size_t digits_at = i;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
        const unsigned digit = static_cast<unsigned>(text[i] - '0');
        if (value > (UINT64_MAX - digit) / 10) return usage;
        value = value * 10 + digit;
    }
    if (i == digits_at) return usage;
    while (i < text.size() && is_space(text[i])) ++i;
    std::string unit;
    for (; i < text.size() && !is_space(text[i]); ++i)
        unit += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    while (i < text.size() && is_space(text[i])) ++i;
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

CLI::Option* add_size_option(CLI::App* sub, const char* name, std::uint64_t& value, const std::string& help) {
    return sub->add_option(name, value, help)->transform(CLI::Validator(parse_size_option, "", ""))->type_name("SIZE");
}

void add_max_size_option(CLI::App* sub, std::uint64_t& value) {
    add_size_option(sub, "--max-size", value,
                    "Largest input read, file or standard input (suffixes KB MB GB: 1024-based; default 1GB)");
}

void add_input_option(CLI::App* sub, std::string& value) {
    const std::vector<std::string> names = format_names(kInputFormats, input_format_name, {"auto"});
    sub->add_option("--input", value, "Tape format: essi, eia, or auto (from the content; the default)")
        ->check(CLI::IsMember(names))
        ->type_name(join(names, "|"))
        ->capture_default_str();
}

void add_profile_option(CLI::App* sub, std::string& value) {
    sub->add_option("--profile", value, kProfileHelp)->type_name("NAME|FILE|auto");
}

void add_text_or_json_option(CLI::App* sub, std::string& value) {
    sub->add_option("--format", value, "Output format: text or json")
        ->check(CLI::IsMember({"text", "json"}))
        ->type_name("text|json")
        ->capture_default_str();
}

std::string join(const std::vector<std::string>& v, std::string_view sep) {
    std::string s;
    for (const std::string& x : v) {
        if (!s.empty()) s += sep;
        s += x;
    }
    return s;
}

}  // namespace essi::cli
