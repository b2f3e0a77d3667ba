// The viewer compiled into `essi` (the dist builds: ESSI_EMBED_WEB_DIR, native/CMakeLists.txt), so that the binary
// alone serves the page: each file's bytes and its gzip twin (made by the build with gzip -9), in read-only data.
// Without ESSI_EMBED_WEB_DIR the list is empty and `essi serve` reads its --web-root folder.
#pragma once

#include <span>
#include <string_view>

namespace essi::native {

struct EmbeddedFile {
    std::string_view name;   // "index.html", "essi_viewer.wasm", ...
    std::string_view bytes;  // the file as built
    std::string_view gzip;   // the same, gzip-encoded
};

// Every embedded file (empty when this build embeds none).
[[nodiscard]] std::span<const EmbeddedFile> embedded_web_files();

// The embedded file `name`, or nullptr.
[[nodiscard]] const EmbeddedFile* find_embedded_web_file(std::string_view name);

}  // namespace essi::native
