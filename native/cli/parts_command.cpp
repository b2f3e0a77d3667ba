// essi parts: the parts a tape makes, grouped by shape, and its plates' utilisation and remnant, as text, JSON or
// CSV (essi/parts.hpp, docs/cli.md).
#include <memory>
#include <string>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/parts.hpp"
#include "essi/parts_report.hpp"
#include "essi/report_json.hpp"
#include "essi/text.hpp"

namespace essi::cli {
namespace {

struct PartsOptions {
    std::string path;
    std::string format = "text";
    std::string profile;
    std::string input = "auto";
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

int run_parts(const PartsOptions& o) {
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;
    const PartsList parts = tape_parts(tape->file.bytes, tape->setup.profile, tape->setup.format);
    if (o.format == "json") {
        nlohmann::json j = parts_to_json(parts);
        j["path"] = display_text(o.path);
        j["profile"] = tape->setup.profile.name;
        out(j.dump(kJsonIndent));
        out("\n");
    } else if (o.format == "csv") {
        out(parts_csv(parts));
    } else {
        out_text(parts_text(parts, lang()));
    }
    return finish(kExitOk);
}

}  // namespace

Subcommand define_parts(CLI::App& essi) {
    auto o = std::make_shared<PartsOptions>();
    CLI::App* parts = essi.add_subcommand(
        "parts", "The parts a tape makes, grouped by shape: count, area, size, mass; plates' utilisation and remnant");
    parts->add_option("PATH", o->path, "Tape file ('-' reads standard input)")->required();
    parts->add_option("--format", o->format, "Output format")
        ->check(CLI::IsMember({"text", "json", "csv"}))
        ->type_name("text|json|csv")
        ->capture_default_str();
    add_profile_option(parts, o->profile);
    add_input_option(parts, o->input);
    add_max_size_option(parts, o->max_size);
    return {parts, [o] { return run_parts(*o); }};
}

}  // namespace essi::cli
