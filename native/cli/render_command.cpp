// essi render: a tape drawn as SVG, PNG (through rsvg-convert) or DXF (essi/render_svg.hpp, essi/dxf.hpp).
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/dxf.hpp"
#include "essi/render_svg.hpp"
#include "essi/text.hpp"

extern char** environ;

namespace essi::cli {
namespace {

struct RenderOptionsCli {
    std::string path;
    std::string output;
    std::string format;  // svg (default) or dxf; "" = by the output's extension
    std::string profile;
    std::string input = "auto";
    bool png = false;
    bool no_travel = false;
    bool problems_only = false;
    bool remnant = false;
    double width = 1200;
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

// Runs `argv` (looked up on PATH) and waits; true when it exits with 0. Under Emscripten (the npm package) there are
// no processes: false, and `render --png` says it needs rsvg-convert.
bool run_program(const std::vector<std::string>& args) {
#ifdef __EMSCRIPTEN__
    (void)args;
    return false;
#else
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
#endif
}

bool ends_with(const std::string& s, const char* ext) {
    const std::size_t n = std::strlen(ext);
    return s.size() > n && s.compare(s.size() - n, n, ext) == 0;
}

void say(Msg m, MessageArgs args) { err("essi render: " + format_message(m, lang(), args) + "\n"); }

int cannot_write(const std::string& path) {
    say(Msg::CliCannotWrite, {display_text(path), std::strerror(errno)});
    return kExitUsage;
}

// -o, else the tape's file name (stdin: "stdin") with `extension`.
std::string output_path(const RenderOptionsCli& o, const char* extension) {
    if (!o.output.empty()) return o.output;
    const std::string base = o.path == "-" ? std::string("stdin") : std::filesystem::path(o.path).filename().string();
    return base + extension;
}

int render_dxf_file(const RenderOptionsCli& o, const LoadedTape& tape) {
    const DxfResult dxf = render_dxf(tape.file.bytes, tape.setup);
    const std::string output = output_path(o, ".dxf");
    if (!write_file(output, dxf.text)) return cannot_write(output);
    if (output != "-") say(Msg::RenderWrote, {display_text(output)});
    const bool errors = std::any_of(dxf.diagnostics.begin(), dxf.diagnostics.end(),
                                    [](const Diagnostic& d) { return d.severity == Severity::Error; });
    return finish(errors ? kExitTapeErrors : kExitOk);
}

// The SVG turned into `output` by rsvg-convert; no empty or partial picture is left behind.
int write_png(const std::string& svg, const std::string& output) {
    if (output == "-") {
        say(Msg::RenderPngNeedsFile, {});
        return kExitUsage;
    }
    const std::string tmp = output + ".tmp.svg";
    if (!write_file(tmp, svg)) return cannot_write(tmp);
    const bool ok = run_program({"rsvg-convert", "--background-color=white", "-o", output, tmp});
    std::remove(tmp.c_str());
    if (!ok) {
        std::remove(output.c_str());
        say(Msg::RenderNoRsvg, {});
        return kExitUsage;
    }
    std::error_code ec;
    if (std::filesystem::file_size(output, ec) == 0 || ec) {
        std::remove(output.c_str());
        say(Msg::RenderPngEmpty, {display_text(output)});
        return kExitUsage;
    }
    return kExitOk;
}

int run_render(const RenderOptionsCli& o) {
    const auto tape = load_tape(o.path, o.profile, o.input, o.max_size);
    if (!tape) return kExitUsage;
    const bool png = o.png || ends_with(o.output, ".png");
    if (o.format == "dxf" || (o.format.empty() && ends_with(o.output, ".dxf"))) {
        if (png) {
            say(Msg::RenderDxfIsNoPicture, {o.png ? std::string("--png") : display_text(o.output)});
            return kExitUsage;
        }
        return render_dxf_file(o, *tape);
    }
    RenderOptions options;
    options.title = o.path == "-" ? std::string("-") : display_text(std::filesystem::path(o.path).filename().string());
    options.width_px = o.width;
    options.show_travel = !o.no_travel;
    options.problems_only = o.problems_only;
    options.remnant = o.remnant;
    const RenderResult r = render_svg(tape->file.bytes, tape->setup.profile, options, tape->setup.format);
    const std::string output = output_path(o, png ? ".png" : ".svg");
    if (png) {
        if (const int rc = write_png(r.svg, output); rc != kExitOk) return rc;
    } else if (!write_file(output, r.svg)) {
        return cannot_write(output);
    }
    if (output != "-") say(Msg::RenderWrote, {display_text(output)});
    return finish(r.result.ok() ? kExitOk : kExitTapeErrors);
}

}  // namespace

Subcommand define_render(CLI::App& essi) {
    auto o = std::make_shared<RenderOptionsCli>();
    CLI::App* render = essi.add_subcommand("render", "Draw a tape as SVG (or PNG): motion, pierces, errors, a legend");
    render->add_option("PATH", o->path, "Tape file ('-' reads standard input)")->required();
    add_max_size_option(render, o->max_size);
    render->add_option("-o,--output", o->output, "Output file ('-' = stdout; default NAME.svg)");
    add_profile_option(render, o->profile);
    add_input_option(render, o->input);
    render
        ->add_option("--format", o->format,
                     "svg (default) or dxf (R12: layers CUT, MARK, TRAVEL, DIAGNOSTICS; also when OUT ends in .dxf)")
        ->check(CLI::IsMember({"svg", "dxf"}))
        ->type_name("svg|dxf");
    render->add_flag("--png", o->png, "Write PNG (through rsvg-convert; also when OUT ends in .png)");
    render->add_flag("--no-travel", o->no_travel, "Leave out travel and rapid motion");
    render->add_flag("--remnant", o->remnant,
                     "Outline each plate (profile plate_mm, else its parts' box) and draw its remnant");
    render->add_flag("--problems-only", o->problems_only,
                     "Draw what the diagnostics concern in full and everything else faint");
    render->add_option("--width", o->width, "Width of the picture in pixels")
        ->check(CLI::Range(16.0, 100000.0))
        ->capture_default_str();
    return {render, [o] { return run_render(*o); }};
}

}  // namespace essi::cli
