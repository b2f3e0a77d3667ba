#include "serve.hpp"

// Debian's cpp-httplib 0.11 is a compiled library (libcpp-httplib.so, pkg-config `cpp-httplib`): the server is
// built only when CMake links it and defines ESSI_HAVE_HTTPLIB (see native/CMakeLists.txt); otherwise
// run_serve says so. This keeps the CLI building on machines without the library.
#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>
#endif

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

namespace essi::native {

namespace fs = std::filesystem;

#if !defined(ESSI_HAVE_HTTPLIB)
int run_serve(const std::string&, int, const std::string&, const std::string&) {
    std::fprintf(stderr, "essi serve: this essi was built without cpp-httplib (apt-get install libcpp-httplib-dev)\n");
    return 2;
}
#else
namespace {

// Names of the example tapes (*.esi), sorted.
std::vector<std::string> example_names(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    if (dir.empty() || !fs::is_directory(dir, ec)) return names;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        if (e.is_regular_file(ec) && e.path().extension() == ".esi") names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

int run_serve(const std::string& host, int port, const std::string& web_root, const std::string& examples_dir) {
    std::error_code ec;
    if (!fs::exists(fs::path(web_root) / "index.html", ec) || !fs::exists(fs::path(web_root) / "essi_viewer.wasm", ec)) {
        std::fprintf(stderr,
                     "essi serve: the viewer is not built in %s (build it with: emcmake cmake --preset wasm && "
                     "cmake --build --preset wasm --target essi_viewer, or make run)\n",
                     web_root.c_str());
        return 2;
    }

    httplib::Server server;
    server.set_file_extension_and_mimetype_mapping("wasm", "application/wasm");
    server.set_file_extension_and_mimetype_mapping("js", "text/javascript");
    server.set_file_extension_and_mimetype_mapping("esi", "text/plain; charset=us-ascii");
    server.set_file_extension_and_mimetype_mapping("json", "application/json");
    // Always revalidate: a rebuilt viewer must not be mixed with a cached one.
    server.set_default_headers({{"Cache-Control", "no-cache"}});

    server.Get("/examples/index.json", [examples_dir](const httplib::Request&, httplib::Response& res) {
        res.set_content(nlohmann::json(example_names(examples_dir)).dump(), "application/json");
    });
    if (!examples_dir.empty() && fs::is_directory(examples_dir, ec)) server.set_mount_point("/examples", examples_dir);
    if (!server.set_mount_point("/", web_root)) {
        std::fprintf(stderr, "essi serve: cannot serve %s\n", web_root.c_str());
        return 2;
    }
    server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
        if (res.status >= 400) std::fprintf(stderr, "essi serve: %s %s -> %d\n", req.method.c_str(), req.path.c_str(), res.status);
    });

    int bound = port;
    if (port == 0) {
        bound = server.bind_to_any_port(host.c_str());
        if (bound <= 0) {
            std::fprintf(stderr, "essi serve: cannot listen on %s\n", host.c_str());
            return 2;
        }
    } else if (!server.bind_to_port(host.c_str(), port)) {
        std::fprintf(stderr, "essi serve: cannot listen on %s:%d (in use? try --port)\n", host.c_str(), port);
        return 2;
    }
    const std::string shown = host.find(':') != std::string::npos ? "[" + host + "]" : host;
    std::printf("essi serve: http://%s:%d/  (viewer %s, examples %s; Ctrl+C stops)\n", shown.c_str(), bound,
                web_root.c_str(), examples_dir.empty() ? "-" : examples_dir.c_str());
    std::fflush(stdout);
    return server.listen_after_bind() ? 0 : 2;
}
#endif

}  // namespace essi::native
