// Request checks and response headers of `essi serve` against hostile pages and clients (native only):
//   - paths and query parameters: valid UTF-8 without NUL, else 400
//   - Host: a loopback name, the bound address, the connection's local address or an --allowed-host name
//     (DNS rebinding), else 403
//   - writes (POST, PUT, PATCH, DELETE): an Origin header, when sent, must be this server's own origin
//     (http://HOST); no CORS headers are ever sent, so a cross-origin page cannot read or write
//   - POST needs a Content-Type: application/octet-stream, text/plain or application/x-www-form-urlencoded
//     (the body is never parsed as form parameters), else 415
//   - every response: nosniff, X-Frame-Options DENY, Referrer-Policy no-referrer, COOP/COEP/CORP, a CSP
#pragma once

#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>

#include <string>
#include <string_view>
#include <vector>

namespace essi::native {

// True when `s` is valid UTF-8 (no overlongs, no surrogates) and has no NUL byte.
[[nodiscard]] bool is_clean_text(std::string_view s);

struct HostPolicy {
    std::string bound_host;               // --host
    std::vector<std::string> allowed;     // --allowed-host (lower-case, without port)
};

// The problem with the request as an error (status, message); status 0 when the request may be routed.
struct Refusal {
    int status = 0;
    std::string message;
};
[[nodiscard]] Refusal check_request(const httplib::Request& req, const HostPolicy& hosts);

// The host name of a Host header value, lower-case, without the port ("[::1]:80" -> "::1").
[[nodiscard]] std::string host_name(std::string_view host_header);

// The headers every response gets; `csp` replaces the default (which allows nothing: API responses).
void add_security_headers(httplib::Response& res);
// The Content-Security-Policy of the viewer's page: 'self' plus the SHA-256 of each inline <script>, <style>
// and on...= attribute of `html`, and 'wasm-unsafe-eval' for the WebAssembly module.
[[nodiscard]] std::string viewer_csp(std::string_view html);

}  // namespace essi::native
#endif
