// Reading whole files into memory for the CLI (and later the server). Core never touches files.
#pragma once

#include <string>

namespace essi::native {

struct ReadResult {
    bool ok = false;
    std::string bytes;   // the whole file
    std::string error;   // "No such file or directory" when !ok
};

// Reads the whole file at `path` with one read when its size is known (regular files), in chunks
// otherwise (pipes, devices). "-" reads standard input. Never throws.
[[nodiscard]] ReadResult read_whole_file(const std::string& path);

}  // namespace essi::native
