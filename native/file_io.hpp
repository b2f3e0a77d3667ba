// Reading whole files into memory for the CLI (and later the server). Core never touches files.
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace essi::native {

// A file's bytes: mapped into memory for regular files (no copy, no page clearing), read into `owned`
// for streams. `bytes` views whichever holds them and stays valid while the ReadResult lives.
struct ReadResult {
    bool ok = false;
    std::string_view bytes;  // the whole file
    std::string error;       // "No such file or directory" when !ok
    std::string owned;       // the bytes of a stream (or a file that could not be mapped)
    std::shared_ptr<const void> mapping;  // unmaps on destruction
};

// Reads the whole file at `path` with one read when its size is known (regular files), in chunks
// otherwise (pipes, devices). "-" reads standard input. Never throws.
[[nodiscard]] ReadResult read_whole_file(const std::string& path);

}  // namespace essi::native
