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
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "essi/profile.hpp"
#include "essi/report.hpp"
#include "pipelined_check.hpp"
#include "essi/report_json.hpp"
#include "share_store.hpp"
#include "sha256.hpp"

#ifndef ESSIKIT_VERSION
#define ESSIKIT_VERSION "0.1.0"
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

void json_error(httplib::Response& res, int status, const std::string& message) {
    res.status = status;
    res.set_content(nlohmann::json{{"error", message}, {"status", status}}.dump(), "application/json");
}

}  // namespace

int run_serve(const ServeOptions& o) {
    std::error_code ec;
    if (!fs::exists(fs::path(o.web_root) / "index.html", ec) || !fs::exists(fs::path(o.web_root) / "essi_viewer.wasm", ec)) {
        std::fprintf(stderr,
                     "essi serve: the viewer is not built in %s (build it with: emcmake cmake --preset wasm && "
                     "cmake --build --preset wasm --target essi_viewer, or make run)\n",
                     o.web_root.c_str());
        return 2;
    }
    const std::string data_dir = o.data_dir.empty() ? default_data_dir() : o.data_dir;
    std::string store_error;
    std::shared_ptr<ShareStore> store = ShareStore::open(data_dir, store_error);
    if (!store) {
        std::fprintf(stderr, "essi serve: %s\n", store_error.c_str());
        return 2;
    }

    httplib::Server server;
    if (o.threads > 0) {
        const int n = o.threads;
        server.new_task_queue = [n] { return new httplib::ThreadPool(static_cast<size_t>(n)); };
    }
    server.set_payload_max_length(static_cast<size_t>(o.max_body));
    server.set_tcp_nodelay(true);  // no 40 ms Nagle + delayed-ACK stall between the headers and the body
    server.set_file_extension_and_mimetype_mapping("wasm", "application/wasm");
    server.set_file_extension_and_mimetype_mapping("js", "text/javascript");
    server.set_file_extension_and_mimetype_mapping("esi", "text/plain; charset=us-ascii");
    server.set_file_extension_and_mimetype_mapping("json", "application/json");
    // Always revalidate: a rebuilt viewer must not be mixed with a cached one.
    server.set_default_headers({{"Cache-Control", "no-cache"}, {"X-Content-Type-Options", "nosniff"}});

    // ---- API ----------------------------------------------------------------------------------------------
    const std::uint64_t max_body = o.max_body;
    server.Get("/api/health", [max_body](const httplib::Request&, httplib::Response& res) {
        res.set_content(nlohmann::json{{"ok", true},
                                       {"version", ESSIKIT_VERSION},
                                       {"max_body", max_body},
                                       {"profiles", builtin_profile_names()}}
                            .dump(),
                        "application/json");
    });
    server.Post("/api/check", [](const httplib::Request& req, httplib::Response& res) {
        const std::string name = req.has_param("profile") ? req.get_param_value("profile") : std::string("iso6582");
        // Built-in profiles only: a request never names a file on the server.
        const auto profile = builtin_profile(name);
        if (!profile) {
            std::string known;
            for (const std::string& n : builtin_profile_names()) known += (known.empty() ? "" : ", ") + n;
            json_error(res, 400, "unknown profile '" + name + "'; expected one of: " + known);
            return;
        }
        FileReport report;
        report.path = req.has_param("name") ? req.get_param_value("name") : std::string("-");
        report.result = check_tape_pipelined(req.body, *profile);
        const FileReport one[] = {std::move(report)};
        res.set_content(report_to_json(one, profile->name).dump(2) + "\n", "application/json");
    });
    server.Post("/api/share", [store](const httplib::Request& req, httplib::Response& res) {
        if (req.body.empty()) {
            json_error(res, 400, "empty body: POST the tape's bytes");
            return;
        }
        const ShareStore::PutResult put = store->put(req.body);
        if (!put.ok) {
            json_error(res, 500, "cannot store the tape: " + put.error);
            return;
        }
        res.status = put.created ? 201 : 200;
        res.set_header("Location", "/api/share/" + put.id);
        res.set_content(nlohmann::json{{"id", put.id},
                                       {"url", "/#share=" + put.id},
                                       {"api_url", "/api/share/" + put.id},
                                       {"size", req.body.size()},
                                       {"created", put.created}}
                            .dump(),
                        "application/json");
    });
    server.Get(R"(/api/share/([^/]*))", [store](const httplib::Request& req, httplib::Response& res) {
        const std::string id = req.matches[1];
        if (!is_sha256_hex(id)) {
            json_error(res, 400, "bad share id '" + id + "': expected 64 lower-case hex digits (SHA-256)");
            return;
        }
        auto tape = store->get(id);
        if (!tape) {
            json_error(res, 404, "no shared tape " + id);
            return;
        }
        res.set_header("Cache-Control", "public, max-age=31536000, immutable");  // content-addressed
        res.set_content(std::move(*tape), "text/plain; charset=us-ascii");
    });
    // Wrong methods and unknown API paths: JSON errors, never the viewer's files.
    const auto method_not_allowed = [](const char* allowed) {
        return [allowed](const httplib::Request& req, httplib::Response& res) {
            res.set_header("Allow", allowed);
            json_error(res, 405, req.method + " is not allowed on " + req.path + "; use " + allowed);
        };
    };
    server.Get("/api/check", method_not_allowed("POST"));
    server.Put("/api/check", method_not_allowed("POST"));
    server.Delete("/api/check", method_not_allowed("POST"));
    server.Get("/api/share", method_not_allowed("POST"));
    server.Post(R"(/api/share/.*)", method_not_allowed("GET"));
    server.Delete(R"(/api/share/.*)", method_not_allowed("GET"));
    server.Get(R"(/api/.*)", [](const httplib::Request& req, httplib::Response& res) {
        json_error(res, 404, "no API endpoint " + req.path);
    });
    server.Post(R"(/.*)", [](const httplib::Request& req, httplib::Response& res) {
        json_error(res, 404, "no API endpoint " + req.path);
    });

    // ---- static files -------------------------------------------------------------------------------------
    const std::string examples_dir = o.examples_dir;
    server.Get("/examples/index.json", [examples_dir](const httplib::Request&, httplib::Response& res) {
        res.set_content(nlohmann::json(example_names(examples_dir)).dump(), "application/json");
    });
    if (!examples_dir.empty() && fs::is_directory(examples_dir, ec)) server.set_mount_point("/examples", examples_dir);
    if (!server.set_mount_point("/", o.web_root)) {
        std::fprintf(stderr, "essi serve: cannot serve %s\n", o.web_root.c_str());
        return 2;
    }

    const std::string share_js = o.share_store_js;
    server.Get("/share_store.js", [share_js](const httplib::Request&, httplib::Response& res) {
        std::FILE* f = share_js.empty() ? nullptr : std::fopen(share_js.c_str(), "rb");
        if (!f) {
            json_error(res, 404, "not found");
            return;
        }
        std::string text;
        char buf[8192];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
        std::fclose(f);
        res.set_content(std::move(text), "text/javascript");
    });

    // Errors without a body (404 of a missing file, 413 of a too big body, 400 of a bad request): JSON.
    server.set_error_handler([max_body](const httplib::Request&, httplib::Response& res) {
        if (!res.body.empty()) return;
        std::string msg;
        switch (res.status) {
            case 413: msg = "request body too large: the limit is " + std::to_string(max_body) + " bytes (--max-body)"; break;
            case 404: msg = "not found"; break;
            case 400: msg = "bad request"; break;
            default: msg = "HTTP error " + std::to_string(res.status); break;
        }
        json_error(res, res.status, msg);
    });
    server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
        if (res.status >= 400) std::fprintf(stderr, "essi serve: %s %s -> %d\n", req.method.c_str(), req.path.c_str(), res.status);
    });

    int bound = o.port;
    if (o.port == 0) {
        bound = server.bind_to_any_port(o.host.c_str());
        if (bound <= 0) {
            std::fprintf(stderr, "essi serve: cannot listen on %s\n", o.host.c_str());
            return 2;
        }
    } else if (!server.bind_to_port(o.host.c_str(), o.port)) {
        std::fprintf(stderr, "essi serve: cannot listen on %s:%d (in use? try --port)\n", o.host.c_str(), o.port);
        return 2;
    }
    const std::string shown = o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host;
    std::printf("essi serve: http://%s:%d/  (viewer %s, examples %s, data %s; Ctrl+C stops)\n", shown.c_str(), bound,
                o.web_root.c_str(), o.examples_dir.empty() ? "-" : o.examples_dir.c_str(), store->path().c_str());
    std::fflush(stdout);
    return server.listen_after_bind() ? 0 : 2;
}
#endif

}  // namespace essi::native
