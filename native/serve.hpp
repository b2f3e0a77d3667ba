// `essi serve`: a small HTTP server (cpp-httplib) for the browser viewer, the example tapes and an API:
//   POST /api/check?profile=NAME[&name=FILE]   body: a tape -> the JSON report of `essi check --format json`
//   POST /api/share                            body: a tape -> {"id","url","size","created"} (stored by SHA-256)
//   GET  /api/share/ID                         the stored tape (404 JSON error when unknown)
//   GET  /api/health                           {"ok":true,"version","max_body","profiles":[...]}
// Native only: sockets never enter core/ or the WASM build.
#pragma once

#include <cstdint>
#include <string>

namespace essi::native {

constexpr std::uint64_t kDefaultMaxBody = 64ull << 20;  // 64 MiB

struct ServeOptions {
    std::string host = "127.0.0.1";
    int port = 8080;                 // 0 picks a free port
    std::string web_root;            // the wasm build's web/ folder (index.html, essi_viewer.js/.wasm)
    std::string examples_dir;        // served at /examples/ ("" = none)
    std::string share_store_js;      // web/share_store.js of the source tree: served at /share_store.js when the
                                     // web root has none (older viewer builds copy only index.html)
    std::string data_dir;            // the share store (SQLite); "" = default_data_dir()
    std::uint64_t max_body = kDefaultMaxBody;
    int threads = 0;                 // request threads; 0 = cpp-httplib's default
};

// Serves until the process is stopped. Prints "essi serve: http://HOST:PORT/ ..." on stdout once listening.
// Returns 2 (with a message on stderr) when the viewer is not built, the store cannot be opened or the address
// cannot be bound.
int run_serve(const ServeOptions& options);

}  // namespace essi::native
