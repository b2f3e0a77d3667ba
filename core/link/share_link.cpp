// Share link fragments (essi/share_link.hpp).
#include "essi/share_link.hpp"
#include "essi/profile.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "essi/text.hpp"

namespace essi {
namespace {

constexpr std::string_view kBase64Url = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
constexpr std::size_t kQuoteBytes = 24;  // what a problem quotes of a value

constexpr std::array<std::int8_t, 256> make_base64url_values() {
    std::array<std::int8_t, 256> v{};
    for (auto& x : v) x = -1;
    for (std::size_t i = 0; i < kBase64Url.size(); ++i)
        v[static_cast<unsigned char>(kBase64Url[i])] = static_cast<std::int8_t>(i);
    return v;
}
constexpr std::array<std::int8_t, 256> kBase64UrlValues = make_base64url_values();

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// application/x-www-form-urlencoded, as the page's URLSearchParams reads it: '+' is a space, %XX a byte (a '%'
// without two hex digits stays as it is).
std::string form_decode(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '+') {
            out += ' ';
        } else if (s[i] == '%' && i + 2 < s.size() && hex_value(s[i + 1]) >= 0 && hex_value(s[i + 2]) >= 0) {
            out += static_cast<char>(hex_value(s[i + 1]) * 16 + hex_value(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// form_decode's inverse: letters, digits and - _ . ~ as they are, every other byte as %XX (so '+' is "%2B").
std::string form_encode(std::string_view s) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(s.size());
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
            c == '.' || c == '~') {
            out += ch;
        } else {
            out += '%';
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    return out;
}

// A finite number written in full (no trailing text), as "12.5" or "-3e2".
std::optional<double> parse_number(const std::string& s) {
    if (s.empty() || s.size() > 32) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<ShareView> parse_view(const std::string& v) {
    ShareView view;
    double* parts[] = {&view.x, &view.y, &view.zoom};
    std::size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const std::size_t comma = k < 2 ? v.find(',', start) : v.size();
        if (comma == std::string::npos) return std::nullopt;
        const auto n = parse_number(v.substr(start, comma - start));
        if (!n) return std::nullopt;
        *parts[k] = *n;
        start = comma + 1;
    }
    if (!(view.zoom > 0)) return std::nullopt;
    return view;
}

// A problem, in English and as a message.
void add_problem(ShareLink& link, Message m) {
    link.problems.push_back(m.text(Lang::En));
    link.problem_messages.push_back(std::move(m));
}

// The field `key` with its decoded value, into `link`.
void read_field(std::string_view key, const std::string& value, ShareLink& link) {
    // `msg` (a row of core/i18n/messages/link.def) with `before` and then the value quoted.
    const auto problem = [&](Msg msg, std::optional<std::size_t> before = std::nullopt) {
        const std::string quote = display_text(excerpt(value, kQuoteBytes));
        add_problem(link, before ? Message{msg, {*before, quote}} : Message{msg, {quote}});
    };
    if (key == "c") {
        link.view = parse_view(value);
        if (!link.view) problem(Msg::LinkBadView);
    } else if (key == "l") {
        const auto n = parse_number(value);
        if (n && *n >= 0 && *n <= 4294967295.0 && *n == std::floor(*n)) link.line = static_cast<std::uint32_t>(*n);
        else problem(Msg::LinkBadLine);
    } else if (key == "n") {
        link.name = value;
        if (link.name.size() > kMaxShareNameBytes) {
            link.name = excerpt(value, kMaxShareNameBytes);
            problem(Msg::LinkNameTooLong, kMaxShareNameBytes);
        }
    } else if (key == "share") {
        if (is_store_id(value)) link.store_id = value;
        else problem(Msg::LinkBadStoreId);
    } else if (key == "t") {
        auto bytes = base64url_decode(value);
        if (bytes && !bytes->empty()) link.packed = std::move(*bytes);
        else problem(Msg::LinkBadTape);
    } else if (key == "p") {
        if (is_valid_profile_name(value)) link.profile = value;
        else problem(Msg::LinkBadProfile);
    } else if (key == "pj") {
        auto bytes = base64url_decode(value);
        if (bytes && !bytes->empty() && bytes->size() <= kMaxShareProfileBytes) link.profile_json = std::move(*bytes);
        else problem(Msg::LinkBadProfileJson, kMaxShareProfileBytes);
    } else if (key == "i") {
        link.input = parse_input_format(value);
        if (!link.input) problem(Msg::LinkBadInput);
    } else if (key == "b") {
        const auto n = parse_number(value);
        if (n && *n >= 0 && *n <= 1e15 && *n == std::floor(*n)) link.tape_bytes = static_cast<std::uint64_t>(*n);
        else problem(Msg::LinkBadLength);
    }
}

}  // namespace

bool is_store_id(std::string_view s) {
    if (s.size() != kStoreIdDigits) return false;
    for (char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

ShareLink parse_share_fragment(std::string_view fragment) {
    ShareLink link;
    if (!fragment.empty() && fragment.front() == '#') fragment.remove_prefix(1);
    if (fragment.size() > kMaxShareFragmentBytes) {
        add_problem(link, {Msg::LinkTooLong, {fragment.size(), kMaxShareFragmentBytes}});
        return link;
    }
    std::size_t pos = 0;
    while (pos <= fragment.size()) {
        std::size_t amp = fragment.find('&', pos);
        if (amp == std::string_view::npos) amp = fragment.size();
        const std::string_view field = fragment.substr(pos, amp - pos);
        pos = amp + 1;
        if (field.empty()) continue;
        const std::size_t eq = field.find('=');
        const std::string key = form_decode(field.substr(0, eq));
        const std::string value = eq == std::string_view::npos ? std::string() : form_decode(field.substr(eq + 1));
        read_field(key, value, link);
    }
    return link;
}

std::string share_view_query(const ShareView& view, std::uint32_t line) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "c=%.6g,%.6g,%.6g&l=%u", view.x, view.y, view.zoom, line);
    return buf;
}

std::string share_reading_query(std::string_view profile, std::string_view profile_json,
                                std::optional<InputFormat> input) {
    std::string q = "p=" + form_encode(profile);  // ("iso6582+custom": the '+' would be read as a space)
    if (!profile_json.empty()) q += "&pj=" + base64url_encode(profile_json);
    if (input) q += "&i=" + form_encode(input_format_name(*input));
    return q;
}

std::string base64url_encode(std::string_view bytes) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const auto v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
        for (int s = 18; s >= 0; s -= 6) out += kBase64Url[(v >> s) & 63];
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += kBase64Url[(v >> 18) & 63];
        out += kBase64Url[(v >> 12) & 63];
        if (rest == 2) out += kBase64Url[(v >> 6) & 63];
    }
    return out;
}

std::optional<std::string> base64url_decode(std::string_view text) {
    if (text.size() % 4 == 1) return std::nullopt;  // no whole byte in the last character
    std::string out;
    out.reserve(text.size() / 4 * 3 + 2);
    unsigned acc = 0;
    int bits = 0;
    for (char c : text) {
        const int v = kBase64UrlValues[static_cast<unsigned char>(c)];
        if (v < 0) return std::nullopt;
        acc = (acc << 6) | static_cast<unsigned>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += static_cast<char>((acc >> bits) & 0xFF);
        }
    }
    return out;
}

}  // namespace essi
