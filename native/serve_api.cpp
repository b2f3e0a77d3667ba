#include "serve_api.hpp"
#include "essi_version.hpp"
#include "tape_request.hpp"

#if defined(ESSI_HAVE_HTTPLIB)
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "essi/profile.hpp"
#include "essi/pipeline.hpp"
#include "essi/report_json.hpp"
#include "essi/sha256.hpp"
#include "essi/share_link.hpp"
#include "essi/text_encoding.hpp"
#include "essi/write.hpp"
#include "pipelined_check.hpp"
#include "serve.hpp"
#include "serve_socket.hpp"

namespace essi::native {

namespace {

using Reader = httplib::ContentReader;

std::string dump(const nlohmann::json& j, int indent = -1) {
    return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

// The length of the body the request declares: its Content-Length, nullopt for a chunked body (unknown until
// read), 0 when it declares neither (RFC 9112: no body). check_request refused every other framing.
std::optional<std::uint64_t> declared_length(const httplib::Request& req) {
    if (req.has_header("Transfer-Encoding")) return std::nullopt;
    if (!req.has_header("Content-Length")) return 0;
    return std::strtoull(req.get_header_value("Content-Length").c_str(), nullptr, 10);
}

void too_large(httplib::Response& res, std::uint64_t max_body) {
    json_error(res, 413, "request body too large: the limit is " + std::to_string(max_body) + " bytes (--max-body)");
    close_connection_after_response();
}

// A slot that stayed taken for as long as a request may wait: 503 with Retry-After, the body left unread.
void busy(httplib::Response& res, const std::string& slots, std::chrono::milliseconds waited) {
    res.set_header("Retry-After", "5");
    json_error(res, 503,
               "server busy: every slot for " + slots + " stayed taken for " +
                   std::to_string(std::chrono::duration_cast<std::chrono::seconds>(waited).count()) +
                   " s; retry later");
    close_connection_after_response();
}

// Whether the body may be large: then it waits for one of the max_large_requests slots.
bool is_large(const httplib::Request& req) {
    const auto n = declared_length(req);
    return !n || *n > kLargeBody;
}

// The body, read here (not parsed); nullopt with the error response set when it is over max_body, too slow or
// cut short.
std::optional<std::string> read_body(const httplib::Request& req, httplib::Response& res, const Reader& reader,
                                     std::uint64_t max_body) {
    const auto n = declared_length(req);
    if (n && *n > max_body) {
        too_large(res, max_body);
        return std::nullopt;
    }
    std::string body;
    if (n && *n == 0) {
        body_read_to_end();
        return body;
    }
    if (n) {
        body.reserve(static_cast<std::size_t>(*n));
    } else {
        // A chunked body of unknown length: room for the largest allowed (up to 1 GB) is reserved without being
        // touched (buffers over 1 MB are mmapped: only the pages written count), so it never grows by copies.
        try {
            body.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(max_body, 1ull << 30)));
        } catch (const std::exception&) {  // (no address space for it: grow as it comes)
        }
    }
    bool over = false;
    const bool ok = reader([&](const char* data, std::size_t len) {
        over = body.size() + len > max_body;
        if (!over) body.append(data, len);
        return !over;
    });
    if (over || res.status == 413) {
        too_large(res, max_body);
        return std::nullopt;
    }
    if (!ok) {
        const auto why = read_failure();
        json_error(res, why ? why->status : 400, why ? why->message : "the request body was cut short");
        close_connection_after_response();
        return std::nullopt;
    }
    body_read_to_end();
    return body;
}

// What a request holds until its answer is written: its large-body and check slots (held() or not).
struct Slots {
    std::unique_ptr<SemaphoreHold> large, running;
};
using Keep = std::shared_ptr<Slots>;

// The response's body without a copy (Response::set_content copies its string). An answer over kLargeBody is
// sent from `text` held with `keep` until it is written (or the connection drops): the slots the request took stay
// taken while the answer is in memory, so the answers of big conversions count against --max-checks, not only
// their work (such an answer is sent uncompressed).
void set_body(httplib::Response& res, std::string&& text, const char* type, const Keep& keep = nullptr) {
    if (!keep || text.size() <= kLargeBody) {
        res.body = std::move(text);
        res.set_header("Content-Type", type);
        return;
    }
    auto held = std::make_shared<std::pair<std::string, Keep>>(std::move(text), keep);
    res.set_content_provider(held->first.size(), type,
                             [held](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 return sink.write(held->first.data() + offset, std::min<std::size_t>(length, 1 << 20));
                             });
}

std::string param_or(const httplib::Request& req, const char* key, const char* fallback) {
    return req.has_param(key) ? req.get_param_value(key) : std::string(fallback);
}

// The reading a request asks for: ?profile=NAME|auto (built-in profiles only: a request never names a file on the
// server) and ?input=essi|eia|auto, as the CLI's --profile and --input. nullopt with the 400 set when unknown.
std::optional<TapeRequest> tape_request(const httplib::Request& req, httplib::Response& res) {
    TapeRequest r;
    r.profile_name = param_or(req, "profile", "iso6582");
    if (r.profile_name != kAutoProfile) {
        r.profile = builtin_profile(r.profile_name);
        if (!r.profile) {
            std::string known(kAutoProfile);
            for (const std::string& n : builtin_profile_names()) known += ", " + n;
            json_error(res, 400, "unknown profile '" + r.profile_name + "'; expected one of: " + known);
            return std::nullopt;
        }
    }
    if (!parse_input_choice(param_or(req, "input", "auto"), r.input)) {
        json_error(res, 400, "unknown input '" + param_or(req, "input", "auto") + "'; expected essi, eia or auto");
        return std::nullopt;
    }
    if (req.has_param("max_per_code")) {
        const std::string v = req.get_param_value("max_per_code");
        const bool digits = !v.empty() && v.size() <= 10 && v.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || std::stoull(v) > kMaxPerCodeLimit) {
            json_error(res, 400,
                       "max_per_code='" + v + "': expected a whole number from 0 to " +
                           std::to_string(kMaxPerCodeLimit) + " (0: no limit)");
            return std::nullopt;
        }
        r.max_per_code = static_cast<std::size_t>(std::stoull(v));
    }
    return r;
}

// The body as a tape's text (essi::decode_tape_text, as `essi check` reads a file): the body itself, or its UTF-16
// (with a byte order mark) decoded into `decoded`; null with a 400 answer when it is UTF-16 that is no text.
const std::string* tape_text(const std::string& body, std::string& decoded, httplib::Response& res) {
    TapeText text = decode_tape_text(body);
    if (!text.ok()) {
        json_error(res, 400, text.problem.text(Lang::En));
        return nullptr;
    }
    if (!text.decoded) return &body;
    decoded = std::move(*text.decoded);
    return &decoded;
}

void check_tape(const ApiLimits& limits, const httplib::Request& req, httplib::Response& res, const std::string& bytes,
                const Keep& keep) {
    const auto request = tape_request(req, res);
    if (!request) return;
    std::string decoded;
    const std::string* text_of_tape = tape_text(bytes, decoded, res);
    if (!text_of_tape) return;
    const std::string& body = *text_of_tape;
    FileReport report;
    report.path = param_or(req, "name", "-");
    report.result = check_tape_pipelined(body, request->setup(body), limits.max_diagnostics);
    limit_diagnostics(report.result, limits.max_diagnostics);  // (with the setup's note)
    const FileReport one[] = {std::move(report)};
    std::string text = dump(report_to_json(one, request->profile_name), 2);
    text += '\n';
    set_body(res, std::move(text), "application/json", keep);
}

// POST /api/convert?to=essi|eia|gcode&profile=P|auto&to_profile=Q&absolute=1&input=...&format=json: the
// converted program as text/plain (the count of warnings in X-Essi-Warnings), or with format=json
// {"text", "diagnostics"}; 422 with the diagnostics when the tape has errors (as `essi convert` exits 1), unless
// force=1 (then the text of what the machine would run, with X-Essi-Errors). At most --max-diagnostics
// diagnostics, the rest counted in "diagnostics_omitted".
void convert(const ApiLimits& limits, const httplib::Request& req, httplib::Response& res, const std::string& bytes,
             const Keep& keep) {
    const auto request = tape_request(req, res);
    if (!request) return;
    std::string decoded;
    const std::string* text_of_tape = tape_text(bytes, decoded, res);
    if (!text_of_tape) return;
    const std::string& body = *text_of_tape;
    const std::string to = param_or(req, "to", "");
    ConvertOptions options;
    if (const auto format = parse_output_format(to)) options.to = *format;
    else
        return json_error(
            res, 400, "to=" + std::string(to.empty() ? "(none)" : "'" + to + "'") + ": expected essi, eia or gcode");
    const TapeSetup setup = request->setup(body);
    options.target = setup.profile;
    if (req.has_param("to_profile")) {
        const auto target = builtin_profile(req.get_param_value("to_profile"));
        if (!target) return json_error(res, 400, "unknown to_profile '" + req.get_param_value("to_profile") + "'");
        options.target = *target;
    }
    options.absolute = param_or(req, "absolute", "0") == "1";
    options.force = param_or(req, "force", "0") == "1";
    ConvertResult r = convert_tape(body, setup, options);
    const auto errors = std::count_if(r.diagnostics.begin(), r.diagnostics.end(),
                                      [](const Diagnostic& d) { return d.severity == Severity::Error; });
    const std::size_t all = r.diagnostics.size();
    if (all > limits.max_diagnostics) r.diagnostics.resize(limits.max_diagnostics);  // (sorted: the first ones)
    nlohmann::json out{{"diagnostics", diagnostics_to_json(r.diagnostics)}};
    if (all > limits.max_diagnostics) out["diagnostics_omitted"] = all - limits.max_diagnostics;
    if (r.refused) {
        res.status = 422;
        out["error"] = "the tape has errors";
        return set_body(res, dump(out), "application/json", keep);
    }
    if (errors > 0) res.set_header("X-Essi-Errors", std::to_string(errors));
    if (param_or(req, "format", "text") == "json") {
        out["text"] = std::move(r.text);
        return set_body(res, dump(out), "application/json", keep);
    }
    res.set_header("X-Essi-Warnings", std::to_string(all));
    set_body(res, std::move(r.text), "text/plain; charset=us-ascii", keep);
}

void share_tape(ShareStore& store, httplib::Response& res, const std::string& body) {
    if (body.empty()) return json_error(res, 400, "empty body: POST the tape's bytes");
    const ShareStore::PutResult put = store.put(body);
    if (put.too_large) return json_error(res, 507, put.error);
    if (!put.ok) return json_error(res, 500, "cannot store the tape");
    res.status = put.created ? 201 : 200;
    res.set_header("Location", "/api/share/" + put.id);
    nlohmann::json j{{"id", put.id},        {"url", "/#share=" + put.id}, {"api_url", "/api/share/" + put.id},
                     {"size", body.size()}, {"created", put.created},     {"expires_unix", put.expires_unix}};
    if (put.created) j["delete_token"] = put.delete_token;
    res.set_content(dump(j), "application/json");
}

// Runs `handle` on the body read within the limits: a large body waits for a large-body slot before it is read,
// and `work` (the check slots, or null) is taken once it is read; neither wait holds a worker slot. The slots
// are released when the handler returns, or once its answer is written when set_body keeps them.
template <class Handle>
void with_body(ApiContext& ctx, const httplib::Request& req, httplib::Response& res, const Reader& reader,
               Semaphore* work, Handle handle) {
    const ApiLimits& l = ctx.limits;
    BodyReading reading;  // no worker slot while waiting for a slot or for the client's bytes
    const Keep slots = std::make_shared<Slots>();
    slots->large = std::make_unique<SemaphoreHold>(is_large(req) ? &ctx.large_bodies : nullptr, l.slot_wait);
    if (!slots->large->held())
        return busy(res, "large requests (--max-large-requests " + std::to_string(l.max_large_requests) + ")",
                    l.slot_wait);
    reading.start_clock();
    std::optional<std::string> body = read_body(req, res, reader, l.max_body);
    if (!body) return;
    slots->running = std::make_unique<SemaphoreHold>(work, l.slot_wait);
    if (!slots->running->held())
        return busy(res, "checks (--max-checks " + std::to_string(l.max_checks) + ")", l.slot_wait);
    reading.done();
    handle(*body, slots);
}

bool valid_id(const std::string& id, httplib::Response& res) {
    if (is_store_id(id)) return true;
    json_error(res, 400, "bad share id '" + id + "': expected 64 lower-case hex digits (SHA-256)");
    return false;
}

// The tape is streamed from the store in pieces of 64 KB (never whole in memory); a share deleted or evicted
// while it is sent ends the connection before its Content-Length.
void get_share(const std::shared_ptr<ShareStore>& store, const httplib::Request& req, httplib::Response& res) {
    const std::string id = req.matches[1];
    if (!valid_id(id, res)) return;
    const auto size = store->size_of(id);
    if (!size) return json_error(res, 404, "no shared tape " + id + " (never stored, expired or deleted)");
    res.set_header("Cache-Control", "private, no-cache");  // content-addressed, but it can expire or be deleted
    constexpr const char* kType = "text/plain; charset=us-ascii";
    if (*size == 0) return res.set_content("", kType);
    res.set_content_provider(static_cast<std::size_t>(*size), kType,
                             [store, id](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 std::vector<char> buf(std::min<std::size_t>(length, 64 * 1024));
                                 const std::int64_t n = store->read(id, offset, buf.data(), buf.size());
                                 return n > 0 && sink.write(buf.data(), static_cast<std::size_t>(n));
                             });
}

void delete_share(ShareStore& store, const httplib::Request& req, httplib::Response& res) {
    const std::string id = req.matches[1];
    if (!valid_id(id, res)) return;
    const std::string token =
        req.has_header("X-Delete-Token") ? req.get_header_value("X-Delete-Token") : param_or(req, "token", "");
    switch (store.remove(id, token)) {
        case ShareStore::Removal::removed: res.status = 204; return;
        case ShareStore::Removal::missing: return json_error(res, 404, "no shared tape " + id);
        case ShareStore::Removal::wrong_token:
            return json_error(res, 403, "wrong or missing delete token (X-Delete-Token)");
        case ShareStore::Removal::failed: return json_error(res, 500, "cannot delete the tape");
    }
}

}  // namespace

void json_error(httplib::Response& res, int status, const std::string& message) {
    res.status = status;
    res.set_content(dump(nlohmann::json{{"error", message}, {"status", status}}), "application/json");
}

void add_api_routes(httplib::Server& server, const std::shared_ptr<ApiContext>& ctx) {
    server.Get("/api/health", [ctx](const httplib::Request&, httplib::Response& res) {
        res.set_content(dump({{"ok", true},
                              {"version", kVersion},
                              {"max_body", ctx->limits.max_body},
                              {"profiles", builtin_profile_names()}}),
                        "application/json");
    });
    server.Post("/api/check", [ctx](const httplib::Request& req, httplib::Response& res, const Reader& reader) {
        with_body(*ctx, req, res, reader, &ctx->checks,
                  [&](const std::string& body, const Keep& keep) { check_tape(ctx->limits, req, res, body, keep); });
    });
    server.Post("/api/convert", [ctx](const httplib::Request& req, httplib::Response& res, const Reader& reader) {
        with_body(*ctx, req, res, reader, &ctx->checks,
                  [&](const std::string& body, const Keep& keep) { convert(ctx->limits, req, res, body, keep); });
    });
    server.Post("/api/share", [ctx](const httplib::Request& req, httplib::Response& res, const Reader& reader) {
        if (const unsigned wait = ctx->share_rate.try_take(client_key(req.remote_addr))) {
            res.set_header("Retry-After", std::to_string(wait));
            json_error(res, 429,
                       "too many shares from this address (--share-rate); retry in " + std::to_string(wait) + " s");
            return close_connection_after_response();
        }
        with_body(*ctx, req, res, reader, nullptr,
                  [&](const std::string& body, const Keep&) { share_tape(*ctx->store, res, body); });
    });
    server.Get(R"(/api/share/([^/]*))",
               [ctx](const httplib::Request& req, httplib::Response& res) { get_share(ctx->store, req, res); });
    server.Delete(R"(/api/share/([^/]*))", [ctx](const httplib::Request& req, httplib::Response& res, const Reader&) {
        delete_share(*ctx->store, req, res);
        close_connection_after_response();  // a DELETE body (if any) is not read
    });
}

Refusal method_refusal(const httplib::Request& req) {
    const std::string& p = req.path;
    const auto only = [&req](std::initializer_list<const char*> methods, const char* allow) -> Refusal {
        for (const char* m : methods)
            if (req.method == m) return {};
        return {405, req.method + " is not allowed on " + req.path + "; use " + allow, allow};
    };
    if (p == "/api/health") return only({"GET", "HEAD"}, "GET, HEAD");
    if (p == "/api/check" || p == "/api/convert" || p == "/api/share") return only({"POST"}, "POST");
    if (p.rfind("/api/share/", 0) == 0 && p.find('/', 11) == std::string::npos)
        return only({"GET", "HEAD", "DELETE"}, "GET, HEAD, DELETE");
    if (p == "/api" || p.rfind("/api/", 0) == 0) return {404, "no API endpoint " + p, ""};
    return only({"GET", "HEAD"}, "GET, HEAD");  // the viewer's files and the examples
}

}  // namespace essi::native
#endif
