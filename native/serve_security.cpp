#include "serve_security.hpp"

#if defined(ESSI_HAVE_HTTPLIB)
#include <algorithm>
#include <cctype>
#include <optional>
#include <regex>
#include <set>

#include "essi/job_sheet.hpp"
#include "essi/sha256.hpp"
#include "essi/text.hpp"

namespace essi::native {

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

bool params_clean(const httplib::Request& req) {
    return std::all_of(req.params.begin(), req.params.end(),
                       [](const auto& kv) { return is_clean_text(kv.first) && is_clean_text(kv.second); });
}

bool host_allowed(const httplib::Request& req, const HostPolicy& hosts) {
    const std::string name = host_name(req.get_header_value("Host"));
    static const std::set<std::string> kLoopback = {"localhost", "127.0.0.1", "::1"};
    std::string local = lower(req.local_addr);
    if (local.rfind("::ffff:", 0) == 0) local.erase(0, 7);  // an IPv4 client of a dual-stack socket
    if (kLoopback.count(name) || name == lower(hosts.bound_host) || name == local) return true;
    return std::find(hosts.allowed.begin(), hosts.allowed.end(), name) != hosts.allowed.end();
}

bool is_write(const std::string& method) {
    return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

// A write from another site: an Origin that is not http://HOST, or Fetch Metadata saying so.
bool cross_origin(const httplib::Request& req) {
    const std::string site = lower(req.get_header_value("Sec-Fetch-Site"));
    if (!site.empty() && site != "same-origin" && site != "none") return true;
    if (!req.has_header("Origin")) return false;
    return lower(req.get_header_value("Origin")) != "http://" + lower(req.get_header_value("Host"));
}

bool content_type_ok(const httplib::Request& req) {
    std::string type = lower(req.get_header_value("Content-Type"));
    type = type.substr(0, type.find(';'));
    type.erase(std::remove_if(type.begin(), type.end(), [](unsigned char c) { return std::isspace(c); }), type.end());
    return type == "application/octet-stream" || type == "text/plain" || type == "application/x-www-form-urlencoded";
}

bool all_digits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return c >= '0' && c <= '9'; });
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// qvalue = ( "0" [ "." 0*3DIGIT ] ) / ( "1" [ "." 0*3("0") ] )   (RFC 9110 §12.4.2)
bool valid_qvalue(std::string_view v) {
    if (v.empty() || (v[0] != '0' && v[0] != '1')) return false;
    if (v.size() == 1) return true;
    const std::string_view decimals = v.substr(2);
    if (v[1] != '.' || decimals.size() > 3) return false;
    if (!decimals.empty() && !all_digits(decimals)) return false;
    return v[0] == '0' || decimals.find_first_not_of('0') == std::string_view::npos;
}

// The problem with how the request's body is delimited (RFC 9112 §6), or "" (request smuggling, ambiguity).
std::string framing_problem(const httplib::Request& req) {
    const auto lengths = req.headers.equal_range("Content-Length");
    for (auto it = lengths.first; it != lengths.second; ++it) {
        if (!all_digits(it->second) || it->second.size() > 18)
            return "Content-Length '" + it->second.substr(0, 40) + "' is not a number of bytes";
        if (it->second != lengths.first->second) return "conflicting Content-Length headers";
    }
    if (req.headers.count("Transfer-Encoding") > 1) return "more than one Transfer-Encoding header";
    if (req.has_header("Transfer-Encoding") && req.has_header("Content-Length"))
        return "both Content-Length and Transfer-Encoding";
    return {};
}

void set_if_absent(httplib::Response& res, const char* name, const char* value) {
    if (!res.has_header(name)) res.set_header(name, value);
}

std::string base64_of_hex(const std::string& hex) {
    static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string bytes;
    for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
        bytes.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
    }
    return out;
}

std::string hash_source(std::string_view text) { return "'sha256-" + base64_of_hex(sha256_hex(text)) + "'"; }

// The hashes of the inline contents of <TAG ...>...</TAG> elements without a src attribute.
std::string inline_hashes(const std::string& html, const std::string& tag) {
    std::string out;
    for (std::size_t at = html.find("<" + tag); at != std::string::npos; at = html.find("<" + tag, at + 1)) {
        const std::size_t open_end = html.find('>', at);
        const std::size_t close = html.find("</" + tag + ">", open_end);
        if (open_end == std::string::npos || close == std::string::npos) break;
        if (html.substr(at, open_end - at).find(" src=") != std::string::npos) continue;
        out += " " + hash_source(std::string_view(html).substr(open_end + 1, close - open_end - 1));
    }
    return out;
}

// The hashes of on...="..." event handler attributes (they need 'unsafe-hashes').
std::string handler_hashes(const std::string& html) {
    std::string out;
    static const std::regex kHandler(R"re(\son[a-z]+="([^"]*)")re");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), kHandler); it != std::sregex_iterator(); ++it) {
        out += " " + hash_source((*it)[1].str());
    }
    return out.empty() ? out : " 'unsafe-hashes'" + out;
}

}  // namespace

bool is_clean_text(std::string_view s) {
    return s.find('\0') == std::string_view::npos && is_valid_utf8(s);  // (essi/text.hpp)
}

std::string host_name(std::string_view host_header) {
    std::string h = lower(host_header);
    if (!h.empty() && h[0] == '[') {
        const std::size_t close = h.find(']');
        return close == std::string::npos ? h : h.substr(1, close - 1);
    }
    const std::size_t colon = h.find(':');
    if (colon != std::string::npos && h.find(':', colon + 1) == std::string::npos) h.resize(colon);
    return h;
}

Refusal check_request(const httplib::Request& req, const HostPolicy& hosts, MethodPolicy methods) {
    if (!is_clean_text(req.path) || !params_clean(req)) {
        return {400, "the path or a query parameter is not valid UTF-8 or contains a NUL byte"};
    }
    if (!req.has_header("Host")) return {400, "a Host header is required"};
    if (!host_allowed(req, hosts)) {
        return {403, "Host '" + host_name(req.get_header_value("Host")) +
                         "' is not served here (--allowed-host NAME allows it)"};
    }
    if (methods) {
        if (Refusal r = methods(req); r.status != 0) return r;
    }
    if (is_write(req.method) && cross_origin(req)) {
        return {403, "cross-origin writes are refused: " + req.method + " only from this server's own pages"};
    }
    if (const std::string problem = framing_problem(req); !problem.empty()) return {400, "bad request: " + problem};
    if (req.has_header("Transfer-Encoding") && lower(trim(req.get_header_value("Transfer-Encoding"))) != "chunked") {
        return {501, "Transfer-Encoding '" + req.get_header_value("Transfer-Encoding").substr(0, 40) +
                         "' is not supported: only chunked"};
    }
    if (req.method == "POST" && !content_type_ok(req)) {
        return {415, "POST needs Content-Type: application/octet-stream (or text/plain); the body is the tape"};
    }
    return {};
}

bool accepts_gzip(std::string_view accept_encoding) {
    std::optional<bool> gzip, any;  // what the gzip (x-gzip) and * elements say
    while (!accept_encoding.empty()) {
        const std::size_t comma = accept_encoding.find(',');
        std::string_view element = accept_encoding.substr(0, comma);
        accept_encoding = comma == std::string_view::npos ? std::string_view() : accept_encoding.substr(comma + 1);
        const std::size_t semi = element.find(';');
        const std::string coding = lower(trim(element.substr(0, semi)));
        bool wanted = true;  // no q: 1
        if (semi != std::string_view::npos) {
            std::string_view params = element.substr(semi + 1);
            const std::size_t eq = params.find('=');
            const std::string name = lower(trim(params.substr(0, eq)));
            const std::string_view value =
                eq == std::string_view::npos ? std::string_view() : trim(params.substr(eq + 1));
            if (name != "q" || !valid_qvalue(value)) continue;  // an element with another parameter is ignored
            wanted = value.find_first_not_of("0.") != std::string_view::npos;
        }
        if (coding == "gzip" || coding == "x-gzip") gzip = wanted;
        else if (coding == "*") any = wanted;
    }
    return gzip ? *gzip : any.value_or(false);
}

void normalize_request(httplib::Request& req) {
    std::string accepted;  // every Accept-Encoding header, as one list
    const auto values = req.headers.equal_range("Accept-Encoding");
    for (auto it = values.first; it != values.second; ++it) accepted += (accepted.empty() ? "" : ",") + it->second;
    const bool gzip = accepts_gzip(accepted);
    req.headers.erase("Accept-Encoding");
    if (gzip) req.headers.emplace("Accept-Encoding", "gzip");
    req.headers.erase("Range");
    req.ranges.clear();
}

void add_security_headers(httplib::Response& res) {
    set_if_absent(res, "Content-Security-Policy", "default-src 'none'; frame-ancestors 'none'");
    set_if_absent(res, "X-Content-Type-Options", "nosniff");
    set_if_absent(res, "X-Frame-Options", "DENY");
    set_if_absent(res, "Referrer-Policy", "no-referrer");
    set_if_absent(res, "Cross-Origin-Opener-Policy", "same-origin");
    set_if_absent(res, "Cross-Origin-Embedder-Policy", "require-corp");
    set_if_absent(res, "Cross-Origin-Resource-Policy", "same-origin");
    set_if_absent(res, "Cache-Control", "no-cache");  // a rebuilt viewer must not be mixed with a cached one
}

std::string viewer_csp(std::string_view html_in) {
    // The HTML parser turns CR LF and CR into LF before scripts see their text: hash what the browser hashes.
    std::string html;
    for (std::size_t i = 0; i < html_in.size(); ++i) {
        if (html_in[i] == '\r') {
            html += '\n';
            if (i + 1 < html_in.size() && html_in[i + 1] == '\n') ++i;
        } else {
            html += html_in[i];
        }
    }
    return "default-src 'none'; script-src 'self' 'wasm-unsafe-eval'" + inline_hashes(html, "script") +
           handler_hashes(html) + "; style-src 'self'" + inline_hashes(html, "style") + " " +
           hash_source(job_sheet_css()) +  // (the job sheet's print view: a blob: page under this policy)
           "; img-src 'self' data: blob:; connect-src 'self'; base-uri 'none'; form-action 'none'; "
           "frame-ancestors 'none'";
}

}  // namespace essi::native
#endif
