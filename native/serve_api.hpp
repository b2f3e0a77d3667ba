// The JSON API of `essi serve` (see serve.hpp for the endpoints). Request bodies are read inside the handlers
// (never parsed as form parameters; parameters come from the query string only), with at most
// `max_large_requests` bodies over kLargeBody in memory at once and at most `max_checks` checks or conversions
// running at once, each report cut to `max_diagnostics` diagnostics. A request waits at most `slot_wait` for
// either kind of slot, then gets 503.
#pragma once

#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "serve_limits.hpp"
#include "serve_security.hpp"
#include "share_store.hpp"

namespace essi::native {

struct ApiLimits {
    std::uint64_t max_body = 0;
    std::size_t max_large_requests = 2;
    std::size_t max_checks = 2;
    std::size_t max_diagnostics = 10000;
    unsigned share_rate = 30;
    std::chrono::milliseconds slot_wait{60000};
};

struct ApiContext {
    std::shared_ptr<ShareStore> store;
    ApiLimits limits;
    Semaphore large_bodies;
    Semaphore checks;
    RateLimit share_rate;
    ApiContext(std::shared_ptr<ShareStore> s, const ApiLimits& l)
        : store(std::move(s)), limits(l), large_bodies(l.max_large_requests), checks(l.max_checks),
          share_rate(l.share_rate) {}
};

void add_api_routes(httplib::Server& server, const std::shared_ptr<ApiContext>& ctx);

// The methods each path takes, checked before routing: 405 with an Allow header for another method on an API
// endpoint or a file, 404 for a path under /api/ that is no endpoint; status 0 when the request may be routed.
[[nodiscard]] Refusal method_refusal(const httplib::Request& req);

// A JSON error body {"error","status"}; never throws on bytes that are not UTF-8 (they become U+FFFD).
void json_error(httplib::Response& res, int status, const std::string& message);

}  // namespace essi::native
#endif
