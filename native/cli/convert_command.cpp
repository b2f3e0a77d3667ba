// essi convert: the tape read as --input/--profile say, checked as essi check does, run, and written in --to for
// --to-profile (default: the profile it was read with). Warnings and errors on stderr; a tape with errors exits 1
// and nothing is written, unless --force (then what the machine would run of it is written, and it still exits 1).
#include <cerrno>
#include <cstring>
#include <memory>
#include <string>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/diagnostics.hpp"
#include "essi/text.hpp"
#include "essi/text_report.hpp"
#include "essi/write.hpp"

namespace essi::cli {
namespace {

struct ConvertOptionsCli {
    std::string path;
    std::string output = "-";
    std::string to;
    std::string profile;
    std::string to_profile;
    std::string input = "auto";
    bool absolute = false;
    bool incremental = false;
    bool force = false;
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

int run_convert(const ConvertOptionsCli& o) {
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;
    const TapeSetup& setup = tape->setup;
    ConvertOptions options;
    options.to = parse_output_format(o.to).value_or(OutputFormat::Essi);  // (--to is checked: one of them)
    options.absolute = o.absolute;
    options.force = o.force;
    if (o.to_profile.empty()) {
        options.target = setup.profile;
    } else {
        const auto target = resolve_profile(o.to_profile);
        if (!target) return kExitUsage;
        options.target = *target;
    }
    const ConvertResult r = convert_tape(tape->file.bytes, setup, options);
    for (const Diagnostic& d : r.diagnostics) err(diagnostic_line(o.path, d, lang()) + "\n");
    if (r.refused) {
        err("essi convert: " + format_message(Msg::ConvertRefused, lang(), {display_text(o.path)}) + "\n");
        return finish(kExitTapeErrors);
    }
    if (!write_file(o.output, r.text)) {
        err("essi convert: cannot write " + display_text(o.output) + ": " + std::strerror(errno) + "\n");
        return kExitUsage;
    }
    return finish(r.ok() ? kExitOk : kExitTapeErrors);
}

}  // namespace

Subcommand define_convert(CLI::App& essi) {
    auto o = std::make_shared<ConvertOptionsCli>();
    CLI::App* convert = essi.add_subcommand("convert", "Write a tape as ESSI, EIA (RS-274) or G-code for LinuxCNC");
    const std::vector<std::string> targets = format_names(kOutputFormats, output_format_name);
    convert->add_option("--to", o->to, "Target format")
        ->required()
        ->check(CLI::IsMember(targets))
        ->type_name(join(targets, "|"));
    add_profile_option(convert, o->profile);
    convert
        ->add_option("--to-profile", o->to_profile,
                     "The dialect written (units, end code, EIA table): a built-in name or a JSON profile file; "
                     "default: the profile the tape is read with")
        ->type_name("NAME|FILE");
    add_input_option(convert, o->input);
    auto* absolute_flag = convert->add_flag("--absolute", o->absolute, "Absolute coordinates (82, G90)");
    convert->add_flag("--incremental", o->incremental, "Incremental coordinates (81, G91; the default)")
        ->excludes(absolute_flag);
    convert->add_flag("--force", o->force,
                      "Write the tape even when it has errors (what the machine would run of it; the exit code is "
                      "still 1)");
    add_max_size_option(convert, o->max_size);
    convert->add_option("-o,--output", o->output, "Output file ('-' = stdout, the default)");
    convert->add_option("FILE", o->path, "Tape file ('-' reads standard input)")->required();
    return {convert, [o] { return run_convert(*o); }};
}

}  // namespace essi::cli
