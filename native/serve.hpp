// `essi serve`: a small HTTP server (cpp-httplib) for the browser viewer and the example tapes.
// Native only: sockets never enter core/ or the WASM build.
#pragma once

#include <string>

namespace essi::native {

// Serves `web_root` (the wasm build's web/ folder: index.html, essi_viewer.js, essi_viewer.wasm) at /,
// and `examples_dir` at /examples/ (with /examples/index.json listing its *.esi files), on host:port.
// Port 0 picks a free port. Prints "essi serve: http://HOST:PORT/" on stdout once listening, then blocks
// until the process is stopped. Returns 2 (with a message on stderr) when the viewer is not built or the
// address cannot be bound.
int run_serve(const std::string& host, int port, const std::string& web_root, const std::string& examples_dir);

}  // namespace essi::native

// The same function at global scope, for callers that do not use the namespace.
using essi::native::run_serve;
