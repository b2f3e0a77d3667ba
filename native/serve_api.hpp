// The JSON API of `essi serve` (see serve.hpp for the endpoints). Request bodies are read inside the handlers
// (never parsed as form parameters; parameters come from the query string only), with at most
// `max_large_requests` bodies over kLargeBody in memory at once.
#pragma once

#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>

#include <cstdint>
#include <memory>
#include <string>

#include "serve_limits.hpp"
#include "serve_security.hpp"
#include "share_store.hpp"

namespace essi::native {

struct ApiContext {
    std::shared_ptr<ShareStore> store;
    std::uint64_t max_body = 0;
    Semaphore large_bodies{2};
    RateLimit share_rate{30};
    ApiContext(std::shared_ptr<ShareStore> s, std::uint64_t body, std::size_t large, unsigned rate)
        : store(std::move(s)), max_body(body), large_bodies(large), share_rate(rate) {}
};

void add_api_routes(httplib::Server& server, const std::shared_ptr<ApiContext>& ctx);

// The methods each path takes, checked before routing: 405 with an Allow header for another method on an API
// endpoint or a file, 404 for a path under /api/ that is no endpoint; status 0 when the request may be routed.
[[nodiscard]] Refusal method_refusal(const httplib::Request& req);

// A JSON error body {"error","status"}; never throws on bytes that are not UTF-8 (they become U+FFFD).
void json_error(httplib::Response& res, int status, const std::string& message);

}  // namespace essi::native
#endif
