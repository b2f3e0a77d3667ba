// `essi serve`: a small HTTP server (cpp-httplib) for the browser viewer, the example tapes and an API:
//   POST   /api/check?profile=NAME[&name=FILE]  body: a tape -> the JSON report of `essi check --format json`
//   POST   /api/share                           body: a tape -> {"id","url","size","created","delete_token",...}
//   GET    /api/share/ID                        the stored tape (404 JSON error when unknown or expired)
//   DELETE /api/share/ID                        with X-Delete-Token (or ?token=): 204; wrong token 403
//   GET    /api/health                          {"ok":true,"version","max_body","profiles":[...]}
// The limits against hostile clients and pages are in serve_socket.hpp, serve_security.hpp and docs/security.md.
// Native only: sockets never enter core/ or the WASM build.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace essi::native {

constexpr std::uint64_t kDefaultMaxBody = 64ull << 20;  // 64 MiB
constexpr std::uint64_t kLargeBody = 1ull << 20;        // bodies over 1 MiB count against max_large_requests

struct ServeOptions {
    std::string host = "127.0.0.1";
    int port = 8080;             // 0 picks a free port
    std::string web_root;        // the wasm build's web/ folder (index.html, essi_viewer.js/.wasm)
    std::string examples_dir;    // served at /examples/ ("" = none)
    std::string share_store_js;  // web/share_store.js of the source tree: served at /share_store.js when the
                                 // web root has none (older viewer builds copy only index.html)
    std::string data_dir;        // the share store (SQLite); "" = default_data_dir()
    std::uint64_t max_body = kDefaultMaxBody;
    int threads = 8;                         // requests handled at once
    std::vector<std::string> allowed_hosts;  // --allowed-host: Host names served besides loopback and --host
    std::int64_t share_ttl_s = 30ll * 24 * 3600;
    std::uint64_t max_store = 1ull << 30;
    unsigned share_rate = 30;  // uploads per minute per client address (0 = no limit)
    std::size_t max_connections = 256;
    std::size_t max_client_connections = 32;
    int request_timeout_s = 10;                    // the request line and headers; the grace before min_transfer_rate
    std::uint64_t min_transfer_rate = 1ull << 20;  // bytes per second of a body or a response (on average)
    int body_timeout_s = 120;                      // a whole body; also the longest wait for a slot (then 503)
    std::size_t max_large_requests = 2;            // requests with a body over kLargeBody handled at once
    std::size_t max_checks = 2;                    // checks and conversions running at once, whatever their size
    std::size_t max_diagnostics = 10000;           // diagnostics in an /api/check or /api/convert answer
};

// Serves until the process is stopped. Prints "essi serve: http://HOST:PORT/ ..." on stdout once listening.
// Returns 2 (with a message on stderr) when the viewer is not built, the store cannot be opened or the address
// cannot be bound (also when another process listens on the port).
int run_serve(const ServeOptions& options);

#if defined(ESSI_HAVE_HTTPLIB)
class HardenedServer;
class ShareStore;
// Sets `server` up as `essi serve` does: the request policies (Host, Origin, ...), the security headers, the JSON
// errors, the API with `store`, and the static files (run_serve; the request-handling fuzz target).
void configure_server(HardenedServer& server, const ServeOptions& options, std::shared_ptr<ShareStore> store);
#endif

}  // namespace essi::native
