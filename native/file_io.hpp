// Reading whole files into memory for the CLI (and later the server). Core never touches files.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "essi/i18n.hpp"

namespace essi::native {

// A file's bytes: read into `storage` for regular files (one read, no page clearing), into `owned` for streams.
// `bytes` views whichever holds them and stays valid while the ReadResult lives.
struct ReadResult {
    bool ok = false;
    std::string_view bytes;                 // the whole file
    std::string error;                      // "No such file or directory" when !ok
    std::string owned;                      // the bytes of a stream (or a file that could not be mapped)
    std::shared_ptr<const char[]> storage;  // the bytes of a regular file
};

// The largest input the CLI reads by default (`--max-size`): far above any real tape, far below the memory of
// the machines it runs on. Memory of `essi check` is about the input plus a constant (docs/security.md).
constexpr std::uint64_t kDefaultMaxInputBytes = 1ull << 30;  // 1 GiB
// Profile files are small: a larger one is not a profile.
constexpr std::uint64_t kMaxProfileBytes = 1ull << 20;  // 1 MiB

// Reads the whole file at `path` with one read when its size is known (regular files), in chunks
// otherwise (pipes, devices). "-" reads standard input. Never throws. A file of more than `max_bytes` is not
// read (a regular file is not even mapped): ok is false and the error says the size and the limit; a stream
// is read up to the limit and then refused the same way.
[[nodiscard]] ReadResult read_whole_file(const std::string& path, std::uint64_t max_bytes = kDefaultMaxInputBytes);

// A tape file as read_whole_file reads it, as its text (essi::decode_tape_text: UTF-16 with a byte order mark becomes
// UTF-8); UTF-16 that is no text is not read (ok false, the error in `lang` says where).
[[nodiscard]] ReadResult read_tape_file(const std::string& path, std::uint64_t max_bytes, Lang lang);

// "the file has more than 1 GiB (--max-size 1GB)": the error of a file beyond `max_bytes`.
[[nodiscard]] std::string too_large_text(std::uint64_t size, std::uint64_t max_bytes, bool size_known);

}  // namespace essi::native
