#include "serve_security.hpp"

#if defined(ESSI_HAVE_HTTPLIB)
#include <algorithm>
#include <cctype>
#include <regex>
#include <set>

#include "essi/text.hpp"
#include "sha256.hpp"

namespace essi::native {

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
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

void set_if_absent(httplib::Response& res, const char* name, const char* value) {
    if (!res.has_header(name)) res.set_header(name, value);
}

std::string base64_of_hex(const std::string& hex) {
    static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string bytes;
    for (std::size_t i = 0; i + 1 < hex.size(); i += 2) bytes.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
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

Refusal check_request(const httplib::Request& req, const HostPolicy& hosts) {
    if (!is_clean_text(req.path) || !params_clean(req)) {
        return {400, "the path or a query parameter is not valid UTF-8 or contains a NUL byte"};
    }
    if (!req.has_header("Host")) return {400, "a Host header is required"};
    if (!host_allowed(req, hosts)) {
        return {403, "Host '" + host_name(req.get_header_value("Host")) + "' is not served here (--allowed-host NAME allows it)"};
    }
    if (is_write(req.method) && cross_origin(req)) {
        return {403, "cross-origin writes are refused: " + req.method + " only from this server's own pages"};
    }
    if (req.method == "POST" && !content_type_ok(req)) {
        return {415, "POST needs Content-Type: application/octet-stream (or text/plain); the body is the tape"};
    }
    return {};
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
           handler_hashes(html) + "; style-src 'self'" + inline_hashes(html, "style") +
           "; img-src 'self' data: blob:; connect-src 'self'; base-uri 'none'; form-action 'none'; "
           "frame-ancestors 'none'";
}

}  // namespace essi::native
#endif
