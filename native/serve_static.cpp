#include "serve_static.hpp"

#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string_view>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "embedded_web.hpp"
#include "serve_security.hpp"

namespace essi::native {

namespace fs = std::filesystem;

namespace {

// A worker runs under the policy its own script is sent with: the reading worker loads its program and compiles
// it (script-src 'self' 'wasm-unsafe-eval'), its reading thread's worker loads the same program, and neither fetches
// anything else.
constexpr const char* kReaderWorkerCsp = "default-src 'none'; script-src 'self' 'wasm-unsafe-eval'; connect-src 'self'";

struct Served {
    const char* name;
    const char* type;
};
constexpr Served kViewerFiles[] = {
    {"index.html", "text/html; charset=utf-8"},
    {"essi_viewer.js", "text/javascript"},
    {"essi_viewer.wasm", "application/wasm"},
    {"essi_viewer.data", "application/octet-stream"},
    {"share_store.js", "text/javascript"},
    {"favicon.ico", "image/x-icon"},
    {"essi_cjk.ttc", "font/collection"},  // (the CJK font, fetched only when a text needs it: web/render/UiFonts.hpp)
    // The reading worker's program (web/worker/), which the page starts in a Web Worker; a cross-origin isolated
    // page (this server's) starts the one built with threads, whose second thread runs essi_reader_mt.worker.js.
    {"essi_reader.js", "text/javascript"},
    {"essi_reader.wasm", "application/wasm"},
    {"essi_reader_mt.js", "text/javascript"},
    {"essi_reader_mt.wasm", "application/wasm"},
    {"essi_reader_mt.worker.js", "text/javascript"},
};

// The scripts that start a worker, sent with kReaderWorkerCsp.
bool is_worker_script(std::string_view name) {
    return name == "essi_reader.js" || name == "essi_reader_mt.js" || name == "essi_reader_mt.worker.js";
}

void not_found(httplib::Response& res) {
    res.status = 404;
    res.set_content(R"({"error":"not found","status":404})", "application/json");
}

// Streams the regular file `path` (404 when it is not one).
void send_file(const fs::path& path, const char* type, httplib::Response& res) {
    std::error_code ec;
    const auto size = fs::is_regular_file(path, ec) ? fs::file_size(path, ec) : 0;
    std::shared_ptr<std::FILE> f(ec ? nullptr : std::fopen(path.c_str(), "rb"), [](std::FILE* p) {
        if (p) std::fclose(p);
    });
    if (!f || ec) return not_found(res);
    res.set_content_provider(static_cast<std::size_t>(size), type,
                             [f](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 std::vector<char> buf(std::min<std::size_t>(length, 64 * 1024));
                                 if (std::fseek(f.get(), static_cast<long>(offset), SEEK_SET) != 0) return false;
                                 const std::size_t n = std::fread(buf.data(), 1, buf.size(), f.get());
                                 return n > 0 && sink.write(buf.data(), n);
                             });
}

std::string read_small_file(const fs::path& path) {
    std::string text;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
    char buf[8192];
    for (std::size_t n; f && (n = std::fread(buf, 1, sizeof buf, f.get())) > 0;) text.append(buf, n);
    return text;
}

// The page itself: read whole (20 KB) to send the CSP that allows exactly its inline scripts and styles.
void send_index(std::string html, httplib::Response& res) {
    if (html.empty()) return not_found(res);
    res.set_header("Content-Security-Policy", viewer_csp(html));
    res.set_content(std::move(html), "text/html; charset=utf-8");
}

// Sends `bytes`, which live as long as the program (the embedded files), without copying them.
void send_static_bytes(std::string_view bytes, const char* type, httplib::Response& res) {
    res.set_content_provider(bytes.size(), type,
                             [bytes](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 return sink.write(bytes.data() + offset, std::min<std::size_t>(length, 64 * 1024));
                             });
}

// A file of the viewer compiled into essi (StaticFiles::web_root empty): gzip-encoded to clients that take it.
void send_embedded_file(const Served& served, const httplib::Request& req, httplib::Response& res) {
    const EmbeddedFile* file = find_embedded_web_file(served.name);
    if (file == nullptr) return not_found(res);
    const std::string_view name = served.name;
    if (is_worker_script(name)) res.set_header("Content-Security-Policy", kReaderWorkerCsp);
    if (name == "index.html") {
        send_index(std::string(file->bytes), res);
    } else {
        res.set_header("Vary", "Accept-Encoding");
        const bool gzip = accepts_gzip(req.get_header_value("Accept-Encoding"));
        if (gzip) res.set_header("Content-Encoding", "gzip");
        send_static_bytes(gzip ? file->gzip : file->bytes, served.type, res);
    }
}

void send_viewer_file(const StaticFiles& files, const std::string& name, const httplib::Request& req,
                      httplib::Response& res) {
    const auto it =
        std::find_if(std::begin(kViewerFiles), std::end(kViewerFiles), [&](const Served& s) { return name == s.name; });
    if (it == std::end(kViewerFiles)) return not_found(res);
    if (files.web_root.empty()) return send_embedded_file(*it, req, res);
    fs::path path = fs::path(files.web_root) / name;
    std::error_code ec;
    if (name == "share_store.js" && !fs::exists(path, ec) && !files.share_store_js.empty()) path = files.share_store_js;
    if (name == "index.html") return send_index(read_small_file(path), res);
    if (is_worker_script(name)) res.set_header("Content-Security-Policy", kReaderWorkerCsp);
    // The programs' gzip twins (made by the build, web/CMakeLists.txt: 40 % of their size) for clients that take
    // them.
    if (name.ends_with(".wasm")) {
        res.set_header("Vary", "Accept-Encoding");
        const fs::path gz = path.string() + ".gz";
        if (accepts_gzip(req.get_header_value("Accept-Encoding")) && fs::is_regular_file(gz, ec)) {
            res.set_header("Content-Encoding", "gzip");
            return send_file(gz, it->type, res);
        }
    }
    send_file(path, it->type, res);
}

std::vector<std::string> example_names(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    if (dir.empty() || !fs::is_directory(dir, ec)) return names;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string ext = e.path().extension().string();
        if (e.is_regular_file(ec) && (ext == ".esi" || ext == ".eia")) names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

void add_static_routes(httplib::Server& server, const StaticFiles& files) {
    server.Get("/", [files](const httplib::Request& req, httplib::Response& res) {
        send_viewer_file(files, "index.html", req, res);
    });
    server.Get(R"(/([A-Za-z0-9_.-]+))", [files](const httplib::Request& req, httplib::Response& res) {
        send_viewer_file(files, req.matches[1], req, res);
    });
    server.Get("/examples/index.json", [files](const httplib::Request&, httplib::Response& res) {
        res.set_content(nlohmann::json(example_names(files.examples_dir)).dump(), "application/json");
    });
    // An example is served only when it is one of the listed names: no path is ever built from the request.
    server.Get(R"(/examples/([A-Za-z0-9_.-]+\.(esi|eia)))",
               [files](const httplib::Request& req, httplib::Response& res) {
                   const std::vector<std::string> names = example_names(files.examples_dir);
                   if (std::find(names.begin(), names.end(), req.matches[1].str()) == names.end())
                       return not_found(res);
                   send_file(fs::path(files.examples_dir) / req.matches[1].str(), "text/plain; charset=us-ascii", res);
               });
}

}  // namespace essi::native
#endif
