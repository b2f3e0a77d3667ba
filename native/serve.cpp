#include "serve.hpp"

// Debian's cpp-httplib 0.11 is a compiled library (libcpp-httplib.so, pkg-config `cpp-httplib`): the server is
// built only when CMake links it and defines ESSI_HAVE_HTTPLIB (see native/CMakeLists.txt); otherwise
// run_serve says so. This keeps the CLI building on machines without the library.
#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>
#endif

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include "share_store.hpp"

#if defined(ESSI_HAVE_HTTPLIB)
#include "embedded_web.hpp"
#include "serve_api.hpp"
#include "serve_security.hpp"
#include "serve_socket.hpp"
#include "serve_static.hpp"
#endif

namespace essi::native {

namespace fs = std::filesystem;

#if !defined(ESSI_HAVE_HTTPLIB)
int run_serve(const ServeOptions&) {
    std::fprintf(stderr, "essi serve: this essi was built without cpp-httplib (apt-get install libcpp-httplib-dev)\n");
    return 2;
}
#else
namespace {

bool viewer_built(const std::string& web_root) {
    if (web_root.empty()) return find_embedded_web_file("index.html") != nullptr;
    std::error_code ec;
    return fs::exists(fs::path(web_root) / "index.html", ec) && fs::exists(fs::path(web_root) / "essi_viewer.wasm", ec);
}

// A request path for the log: control and non-ASCII bytes as \xNN (no log injection), at most 200 bytes.
std::string loggable(const std::string& s) {
    std::string out;
    for (unsigned char c : s.substr(0, 200)) {
        char hex[5];
        std::snprintf(hex, sizeof hex, "\\x%02x", c);
        out += c >= 0x20 && c < 0x7f ? std::string(1, static_cast<char>(c)) : std::string(hex);
    }
    return out;
}

ConnectionLimits connection_limits(const ServeOptions& o) {
    ConnectionLimits l;
    l.max_connections = std::max<std::size_t>(o.max_connections, 1);
    l.max_client_connections = std::max<std::size_t>(o.max_client_connections, 1);
    l.threads = static_cast<std::size_t>(std::max(o.threads, 1));
    l.request_timeout_s = std::max(o.request_timeout_s, 1);
    l.min_rate = static_cast<double>(std::max<std::uint64_t>(o.min_transfer_rate, 1));
    l.body_timeout_s = std::max(o.body_timeout_s, 1);
    return l;
}

HostPolicy host_policy(const ServeOptions& o) {
    HostPolicy p;
    p.bound_host = o.host;
    for (const std::string& h : o.allowed_hosts) p.allowed.push_back(host_name(h));
    return p;
}

// Checks before routing, the headers of every response, and errors without a body as JSON (a handler's
// exception becomes a generic 500: its text stays in the server's log, never in the response).
void add_policies(HardenedServer& server, const ServeOptions& o) {
    // The error response of a refused request (its body, if any, is not read), or 0.
    const auto refuse = [hosts = host_policy(o)](const httplib::Request& req, httplib::Response& res) {
        const Refusal r = check_request(req, hosts, method_refusal);
        if (r.status == 0) return 0;
        json_error(res, r.status, r.message);
        if (!r.allow.empty()) res.set_header("Allow", r.allow);
        close_connection_after_response();
        return r.status;
    };
    server.set_request_guard([refuse](const httplib::Request& req, httplib::Response& res) {
        return refuse(req, res) ? httplib::Server::HandlerResponse::Handled
                                : httplib::Server::HandlerResponse::Unhandled;
    });
    // `Expect: 100-continue` (curl, bodies over 1 MB): refused before the client sends the body.
    server.set_expect_100_continue_handler([refuse](const httplib::Request& req, httplib::Response& res) {
        const int status = refuse(req, res);
        return status ? status : 100;
    });
    server.set_request_setup(normalize_request);
    server.set_response_finisher([](const httplib::Request&, httplib::Response& res) { add_security_headers(res); });
    server.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
        std::string what = "unknown exception";
        try {
            std::rethrow_exception(ep);
        } catch (const std::exception& e) {
            what = e.what();
        } catch (...) {
        }
        std::fprintf(stderr, "essi serve: %s %s: internal error: %s\n", req.method.c_str(), loggable(req.path).c_str(),
                     what.c_str());
        res.headers.clear();
        json_error(res, 500, "internal error");
        close_connection_after_response();  // the request's body may be unread
    });
    server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (!res.body.empty()) return;
        if (const auto failure = read_failure()) {  // the request line or headers hit a limit
            json_error(res, failure->status, failure->message);
            return;
        }
        const int s = res.status;
        json_error(res, s,
                   s == 404   ? "not found"
                   : s == 400 ? "bad request"
                   : s == 413 ? "request too large"
                              : "HTTP error " + std::to_string(s));
    });
    server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
        if (res.status >= 400)
            std::fprintf(stderr, "essi serve: %s %s -> %d\n", loggable(req.method).c_str(), loggable(req.path).c_str(),
                         res.status);
    });
}

// Binds --host:--port (0: a free port); the bound port, or 0 with a message on stderr.
int bind_server(HardenedServer& server, const ServeOptions& o) {
    if (o.port == 0) {
        const int bound = server.bind_to_any_port(o.host.c_str());
        if (bound > 0) return bound;
        std::fprintf(stderr, "essi serve: cannot listen on %s\n", o.host.c_str());
        return 0;
    }
    if (server.bind_to_port(o.host.c_str(), o.port)) return o.port;
    std::fprintf(stderr, "essi serve: cannot listen on %s:%d (in use by another process? try --port)\n", o.host.c_str(),
                 o.port);
    return 0;
}

}  // namespace

void configure_server(HardenedServer& server, const ServeOptions& o, std::shared_ptr<ShareStore> store) {
    server.set_payload_max_length(static_cast<std::size_t>(o.max_body));
    server.set_tcp_nodelay(true);  // no 40 ms Nagle + delayed-ACK stall between the headers and the body
    add_policies(server, o);
    ApiLimits limits;
    limits.max_body = o.max_body;
    limits.max_large_requests = std::max<std::size_t>(o.max_large_requests, 1);
    limits.max_checks = std::max<std::size_t>(o.max_checks, 1);
    limits.max_diagnostics = o.max_diagnostics;
    limits.share_rate = o.share_rate;
    limits.slot_wait = std::chrono::seconds(std::max(o.body_timeout_s, 1));
    add_api_routes(server, std::make_shared<ApiContext>(std::move(store), limits));
    add_static_routes(server, StaticFiles{o.web_root, o.examples_dir, o.share_store_js});
}

int run_serve(const ServeOptions& o) {
    if (!viewer_built(o.web_root)) {
        std::fprintf(stderr,
                     "essi serve: the viewer is not built in %s (build it with: emcmake cmake --preset wasm && "
                     "cmake --build --preset wasm --target essi_viewer, or make run)\n",
                     o.web_root.empty() ? "this essi (--web-root names none)" : o.web_root.c_str());
        return 2;
    }
    const std::string data_dir = o.data_dir.empty() ? default_data_dir() : o.data_dir;
    std::string store_error;
    std::shared_ptr<ShareStore> store =
        ShareStore::open(data_dir, store_error, StoreLimits{o.share_ttl_s, o.max_store});
    if (!store) {
        std::fprintf(stderr, "essi serve: %s\n", store_error.c_str());
        return 2;
    }

    // Buffers over 1 MB (request bodies) are mmapped and given back when freed. Without this glibc raises its mmap
    // threshold after the first free and keeps such buffers in each thread's arena: the RSS then grows with the
    // number of threads that ever held a large body, not with the number of large bodies at once.
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(kLargeBody));
    HardenedServer server(connection_limits(o));
    configure_server(server, o, store);

    const int bound = bind_server(server, o);
    if (bound == 0) return 2;
    server.widen_backlog();
    const std::string shown = o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host;
    std::printf("essi serve: http://%s:%d/  (viewer %s, examples %s, data %s; Ctrl+C stops)\n", shown.c_str(), bound,
                o.web_root.empty() ? "built in" : o.web_root.c_str(),
                o.examples_dir.empty() ? "-" : o.examples_dir.c_str(), store->path().c_str());
    std::fflush(stdout);
    return server.listen_after_bind() ? 0 : 2;
}
#endif

}  // namespace essi::native
