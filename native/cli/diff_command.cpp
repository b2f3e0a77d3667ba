// essi diff A B: two revisions compared contour by contour (essi/diff.hpp). Exit 0 when they cut the same, 1 when
// they differ, 2 for a usage problem or a file that cannot be read.
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_io.hpp"
#include "cli/cli_options.hpp"
#include "cli/cli_tapes.hpp"
#include "cli/commands.hpp"
#include "essi/diff.hpp"

namespace essi::cli {
namespace {

struct DiffOptions {
    std::vector<std::string> paths;  // A and B
    std::string format = "text";
    std::string profile;
    std::string input = "auto";
    std::uint64_t max_size = native::kDefaultMaxInputBytes;
};

int run_diff(const DiffOptions& o) {
    const auto a = load_tape(o.paths[0], o.profile, o.input, o.max_size);
    const auto b = a ? load_tape(o.paths[1], o.profile, o.input, o.max_size) : nullptr;
    if (!a || !b) return kExitUsage;
    const TapeContours ca = tape_contours(a->file.bytes, a->setup);
    const TapeContours cb = tape_contours(b->file.bytes, b->setup);
    const TapeDiff d = diff_contours(ca.contours, cb.contours);
    const DiffSide sa{o.paths[0], &ca}, sb{o.paths[1], &cb};
    if (o.format == "json") out(diff_json(sa, sb, d));
    else out_text(diff_text(sa, sb, d, lang()));
    return finish(d.same() ? kExitOk : kExitTapeErrors);
}

}  // namespace

Subcommand define_diff(CLI::App& essi) {
    auto o = std::make_shared<DiffOptions>();
    CLI::App* diff = essi.add_subcommand("diff",
                                         "Compare two revisions of a tape: contours same, moved, changed, "
                                         "removed, added, and the statistics before and after");
    add_text_or_json_option(diff, o->format);
    add_profile_option(diff, o->profile);
    add_input_option(diff, o->input);
    add_max_size_option(diff, o->max_size);
    diff->add_option("A B", o->paths, "The two tape files")->required()->expected(2);
    return {diff, [o] { return run_diff(*o); }};
}

}  // namespace essi::cli
