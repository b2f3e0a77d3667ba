// Request checks and response headers of `essi serve` against hostile pages and clients (native only):
//   - paths and query parameters: valid UTF-8 without NUL, else 400
//   - Host: a loopback name, the bound address, the connection's local address or an --allowed-host name
//     (DNS rebinding), else 403
//   - writes (POST, PUT, PATCH, DELETE): an Origin header, when sent, must be this server's own origin
//     (http://HOST); no CORS headers are ever sent, so a cross-origin page cannot read or write
//   - POST needs a Content-Type: application/octet-stream, text/plain or application/x-www-form-urlencoded
//     (the body is never parsed as form parameters), else 415
//   - the body's framing is unambiguous: Content-Length digits only, repeated only with the same value, never
//     beside Transfer-Encoding, which may only be `chunked` (else 400, or 501 for another coding)
//   - Accept-Encoding is read as RFC 9110 says (tokens and q-values): only `gzip` (or `x-gzip`, or `*`) with a
//     q above 0 gets gzip; a Range header is ignored (the whole body, 200)
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
    std::string bound_host;            // --host
    std::vector<std::string> allowed;  // --allowed-host (lower-case, without port)
};

// The problem with the request as an error (status, message); status 0 when the request may be routed.
struct Refusal {
    Refusal() = default;
    Refusal(int s, std::string m, std::string a = {}) : status(s), message(std::move(m)), allow(std::move(a)) {}
    int status = 0;
    std::string message;
    std::string allow;  // the Allow header of a 405
};
// `methods` (the routes' methods, serve_api.hpp) is asked after the Host check and before the others.
using MethodPolicy = Refusal (*)(const httplib::Request&);
[[nodiscard]] Refusal check_request(const httplib::Request& req, const HostPolicy& hosts,
                                    MethodPolicy methods = nullptr);

// Whether an Accept-Encoding value accepts gzip: a `gzip` or `x-gzip` element (or `*` when gzip is not named)
// with a q-value above 0. "gzip;q=0", "x-gzip-nope" and "identity" do not.
[[nodiscard]] bool accepts_gzip(std::string_view accept_encoding);

// Rewrites a request's headers before anything reads them: Accept-Encoding becomes "gzip" when the client takes
// it (for cpp-httplib's compression of responses, which only looks for the substring) and is removed otherwise;
// Range is dropped (every response is whole: many ranges of one large body would each be a copy of it).
void normalize_request(httplib::Request& req);

// The host name of a Host header value, lower-case, without the port ("[::1]:80" -> "::1").
[[nodiscard]] std::string host_name(std::string_view host_header);

// The headers every response gets; `csp` replaces the default (which allows nothing: API responses).
void add_security_headers(httplib::Response& res);
// The Content-Security-Policy of the viewer's page: 'self' plus the SHA-256 of each inline <script>, <style>
// and on...= attribute of `html`, and 'wasm-unsafe-eval' for the WebAssembly module.
[[nodiscard]] std::string viewer_csp(std::string_view html);

}  // namespace essi::native
#endif
