// How `essi`'s subcommands get their tapes and profiles: --profile and --input resolved, files read within
// --max-size, directories expanded. Every problem is said on stderr here; the callers only see what failed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "batch.hpp"
#include "essi/pipeline.hpp"
#include "essi/profile.hpp"
#include "essi/report_json.hpp"
#include "file_io.hpp"
#include "tape_request.hpp"

namespace essi::cli {

// A built-in profile name, or else a JSON profile file; an empty argument is the default profile. Nullopt after
// the message when neither works.
[[nodiscard]] std::optional<Profile> resolve_profile(const std::string& arg);

// --profile and --input: "auto" leaves the choice to each tape's content (essi/dialect.hpp).
[[nodiscard]] std::optional<native::TapeRequest> resolve_request(const std::string& profile_arg,
                                                                 const std::string& input_arg);

// One tape file read and set up as --profile and --input say (trace, render, convert, diff). Built in place: `file`
// views its own bytes, so it is never moved.
struct LoadedTape {
    LoadedTape(const std::string& path, std::uint64_t max_size);
    native::ReadResult file;
    TapeSetup setup;
};
// Null after the message (a bad --profile/--input, a file that cannot be read).
[[nodiscard]] std::unique_ptr<LoadedTape> load_tape(const std::string& path, const std::string& profile_arg,
                                                    const std::string& input_arg, std::uint64_t max_size);

// The files named by `paths` (directories: the tape files below them); a directory that cannot be read is said
// and sets `io_failed`.
[[nodiscard]] std::vector<std::string> expand_paths(const std::vector<std::string>& paths, bool& io_failed,
                                                    const native::ExpandOptions& options = {});

// Reads and checks every path, one tape in memory at a time. Unreadable files are said and skipped (io_failed set).
[[nodiscard]] std::vector<FileReport> check_files(const std::vector<std::string>& paths,
                                                  const native::TapeRequest& request, std::uint64_t max_size,
                                                  bool& io_failed);

[[nodiscard]] bool any_errors(const std::vector<FileReport>& reports);

// "essi: NAME has N errors" on stderr for each report with errors.
void report_errors_briefly(const std::vector<FileReport>& reports);

}  // namespace essi::cli
