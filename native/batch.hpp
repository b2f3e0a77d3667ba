// `essi check` on many tapes: which files a directory contributes (extensions, content sniffing), and the
// check of a list of files on a pool of threads with results handed back in input order.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "essi/profile.hpp"
#include "tape_request.hpp"
#include "file_io.hpp"
#include "essi/report_json.hpp"

namespace essi::native {

// ".esi .essi .ess .nc .txt"
[[nodiscard]] std::vector<std::string> default_tape_extensions();
// "esi,.NC txt" -> {".esi", ".nc", ".txt"} (commas or spaces, dot optional, lower-cased). Empty entries dropped.
[[nodiscard]] std::vector<std::string> parse_extension_list(std::string_view list);

// looks_like_essi (essi/sniff.hpp) on the first kSniffBytes of the file; false when it cannot be read.
[[nodiscard]] bool sniff_tape_file(const std::string& path);

struct ExpandOptions {
    std::vector<std::string> extensions = default_tape_extensions();  // lower case, with the dot
    bool sniff = true;  // files below a directory without one of `extensions`: sniff their content
};

// Files to check: each argument that is not a directory as given ("-" too), each directory replaced by the
// tape files below it (recursively, sorted). Directories that cannot be read add a message to `errors`.
[[nodiscard]] std::vector<std::string> expand_paths(const std::vector<std::string>& args, const ExpandOptions& options,
                                                    std::vector<std::string>& errors);

// One checked file of a batch.
struct BatchItem {
    FileReport report;     // report.path is the path as given
    bool read_ok = false;  // false: the file could not be read (`error` says why; report is empty)
    std::string error;
    double seconds = 0;  // reading and checking it
};

struct BatchOptions {
    unsigned jobs = 1;                                                      // worker threads
    std::size_t max_diagnostics = std::numeric_limits<std::size_t>::max();  // per file
    std::uint64_t max_size = kDefaultMaxInputBytes;                         // per file (--max-size)
    bool parts = false;    // each result with its parts list (--parts; essi/parts.hpp)
    Lang lang = Lang::En;  // of the reason a file cannot be read
};

// Reads and checks `files` on options.jobs threads and calls emit for each, on the calling thread, in the
// order of `files`. A single big tape (or jobs >= 2) uses the two-thread check_tape_pipelined; with jobs == 1
// everything runs on the calling thread.
void check_batch(const std::vector<std::string>& files, const TapeRequest& request, const BatchOptions& options,
                 const std::function<void(BatchItem&&)>& emit);

}  // namespace essi::native
