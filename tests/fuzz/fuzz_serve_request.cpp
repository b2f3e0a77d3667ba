// Fuzz target: `essi serve`'s request handling, fed any bytes as what a client sends on one connection
// (HardenedServer::handle_bytes: cpp-httplib's parser, the request guard (Host, Origin, content type, NUL and
// invalid UTF-8), the API (/api/check, /api/share ...) and the static files, with no socket). Native only (the
// server is): essi_fuzz_serve_request (libFuzzer, `make fuzz`, dictionary serve_request.dict) and
// essi_fuzz_replay_serve_request (ctest `fuzz_replay_serve_request`, every file of tests/fuzz/corpus/serve_request).
//
// Checks besides "no crash": every response is a well-formed HTTP/1.1 response with a status; never a 500 (the
// server's answer to an exception, i.e. a bug); at most one Cache-Control; every error (4xx) is JSON.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

#include <unistd.h>

#include "serve.hpp"
#include "serve_socket.hpp"
#include "share_store.hpp"

namespace {

namespace fs = std::filesystem;
using essi::native::HardenedServer;

[[noreturn]] void fail(const char* what, std::string_view response) {
    std::fprintf(stderr, "fuzz_serve_request: %s\n--- response ---\n%.*s\n", what,
                 static_cast<int>(std::min<std::size_t>(response.size(), 2000)), response.data());
    std::abort();
}

// The server, set up once: a web root with a stand-in viewer, one example, a share store in a temporary folder.
HardenedServer& server() {
    static std::unique_ptr<HardenedServer> s = [] {
        const fs::path root = fs::temp_directory_path() / ("essi_fuzz_serve_" + std::to_string(::getpid()));
        fs::create_directories(root / "web");
        fs::create_directories(root / "examples");
        std::ofstream(root / "web" / "index.html") << "<!doctype html><title>stand-in viewer</title>";
        std::ofstream(root / "examples" / "a.esi") << "7\n+100+0\n8\n64\n";
        essi::native::ServeOptions o;
        o.web_root = (root / "web").string();
        o.examples_dir = (root / "examples").string();
        o.data_dir = (root / "data").string();
        o.max_body = 1 << 16;
        o.max_store = 1 << 20;
        o.share_rate = 0;
        std::string error;
        std::shared_ptr<essi::native::ShareStore> store =
            essi::native::ShareStore::open(o.data_dir, error, essi::native::StoreLimits{o.share_ttl_s, o.max_store});
        if (!store) fail("cannot open the share store", error);
        auto server = std::make_unique<HardenedServer>(essi::native::ConnectionLimits{});
        essi::native::configure_server(*server, o, store);
        server->set_logger(httplib::Logger());  // (the log of every refused request would be most of the run's time)
        return server;
    }();
    return *s;
}

// Checks each response in `out` (keep-alive: one after the other, each with its Content-Length).
void check_responses(std::string_view out) {
    while (!out.empty()) {
        if (out.substr(0, 9) != "HTTP/1.1 " || out.size() < 12) fail("a response that is not HTTP/1.1", out);
        const int status = std::atoi(std::string(out.substr(9, 3)).c_str());
        if (status < 100 || status > 599) fail("a response without a status", out);
        if (status == 500) fail("a 500: a handler threw", out);
        const std::size_t head_end = out.find("\r\n\r\n");
        if (head_end == std::string_view::npos) fail("a response without the end of its headers", out);
        const std::string_view head = out.substr(0, head_end);
        std::size_t cache = 0, length = 0;
        bool json = false;
        for (std::size_t p = head.find("\r\n"); p != std::string_view::npos; p = head.find("\r\n", p + 2)) {
            const std::string_view line = head.substr(p + 2, head.find("\r\n", p + 2) - (p + 2));
            if (line.substr(0, 14) == "Cache-Control:") ++cache;
            if (line.substr(0, 15) == "Content-Length:")
                length = std::strtoul(std::string(line.substr(15)).c_str(), nullptr, 10);
            if (line.substr(0, 13) == "Content-Type:" && line.find("application/json") != std::string_view::npos)
                json = true;
        }
        if (cache > 1) fail("more than one Cache-Control", out);
        if (status >= 400 && status < 500 && !json && length > 0) fail("an error that is not JSON", out);
        // A HEAD response announces a length it does not send: the next response follows the headers at once.
        const bool bodiless = out.substr(head_end + 4, 9) == "HTTP/1.1 ";
        const std::size_t next = head_end + 4 + (bodiless ? 0 : length);
        if (next > out.size()) return;
        out.remove_prefix(next);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string out = server().handle_bytes(std::string_view(reinterpret_cast<const char*>(data), size));
    if (std::getenv("ESSI_FUZZ_DUMP")) std::fwrite(out.data(), 1, out.size(), stderr);  // (to look at a failure)
    check_responses(out);
    return 0;
}
