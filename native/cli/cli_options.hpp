// The options several subcommands of `essi` share, defined once: --max-size and the other SIZE options, --input,
// --profile and --format (docs/cli.md).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace essi::cli {

constexpr const char* kProfileHelp =
    "Built-in profile name (see `essi profile list`), a JSON profile file, or auto (the dialect the tape's "
    "evidence shows); default iso6582";

// The transform of every SIZE option (--max-size, --max-body, --max-store, --min-transfer-rate): a whole number
// of bytes with an optional 1024-based suffix (B, K/KB/KiB, M/MB/MiB, G/GB/GiB, T, P, E; any case), rewritten as
// the number of bytes. A sign, a fraction or a value over 2^64 - 1 is an error (CLI11's AsSizeValue read "-1" and
// "18446744073709551616" as the largest value: no limit). Returns the error, or "" after rewriting `text`.
[[nodiscard]] std::string parse_size_option(std::string& text);

// A SIZE option `name` into `value` (parse_size_option).
CLI::Option* add_size_option(CLI::App* sub, const char* name, std::uint64_t& value, const std::string& help);
// --max-size: the largest input read.
void add_max_size_option(CLI::App* sub, std::uint64_t& value);
// --input essi|eia|auto.
void add_input_option(CLI::App* sub, std::string& value);
// --profile NAME|FILE|auto.
void add_profile_option(CLI::App* sub, std::string& value);
// --format text|json.
void add_text_or_json_option(CLI::App* sub, std::string& value);

[[nodiscard]] std::string join(const std::vector<std::string>& v, std::string_view sep);

// What --input and --to accept: the core's names of the formats (in the enum's order), then `more`.
template <class Format, std::size_t N>
std::vector<std::string> format_names(const Format (&formats)[N], const char* (*name)(Format),
                                      std::vector<std::string> more = {}) {
    std::vector<std::string> names;
    for (const Format f : formats) names.emplace_back(name(f));
    names.insert(names.end(), more.begin(), more.end());
    return names;
}

}  // namespace essi::cli
