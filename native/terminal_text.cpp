// Text in the terminal's charset (terminal_text.hpp), through the C library's iconv.
#include "terminal_text.hpp"

#include <iconv.h>

#include <algorithm>
#include <cctype>
#include <cerrno>

namespace essi::native {

namespace {

// "zh_CN.GB18030@euro" -> "gb18030"; "" when the locale names no charset.
std::string codeset_of(std::string_view locale) {
    const std::size_t dot = locale.find('.');
    if (dot == std::string_view::npos) return {};
    std::string_view cs = locale.substr(dot + 1);
    cs = cs.substr(0, cs.find('@'));
    std::string out;
    for (char c : cs)
        if (c != '-' && c != '_') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

TerminalText::TerminalText(const char* lc_all, const char* lc_ctype, const char* lang) {
    const char* locale = nullptr;
    for (const char* v : {lc_all, lc_ctype, lang}) {
        if (v != nullptr && *v != '\0') {
            locale = v;
            break;
        }
    }
    const std::string cs = locale ? codeset_of(locale) : std::string();
    if (cs == "gb18030") charset_ = "GB18030";
    else if (cs == "gbk" || cs == "cp936") charset_ = "GBK";
    else if (cs == "gb2312" || cs == "euccn") charset_ = "GB2312";
}

std::string TerminalText::operator()(std::string_view utf8) const {
    if (charset_.empty() || std::all_of(utf8.begin(), utf8.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }))
        return std::string(utf8);
    iconv_t cd = iconv_open(charset_.c_str(), "UTF-8");
    if (cd == reinterpret_cast<iconv_t>(-1)) return std::string(utf8);  // (no converter: as it is)
    std::string out(utf8.size() * 2 + 16, '\0');
    char* in = const_cast<char*>(utf8.data());
    std::size_t in_left = utf8.size();
    char* o = out.data();
    std::size_t out_left = out.size();
    while (in_left > 0) {
        if (iconv(cd, &in, &in_left, &o, &out_left) != static_cast<std::size_t>(-1)) break;
        if (errno == E2BIG) {  // (grow the output and go on)
            const std::size_t used = static_cast<std::size_t>(o - out.data());
            out.resize(out.size() * 2);
            o = out.data() + used;
            out_left = out.size() - used;
            continue;
        }
        // A character the charset has no code for (or bytes that are not UTF-8): '?' and past it.
        std::size_t skip = 1;
        while (skip < in_left && (static_cast<unsigned char>(in[skip]) & 0xC0) == 0x80) ++skip;
        *o++ = '?';
        --out_left;
        in += skip;
        in_left -= skip;
        iconv(cd, nullptr, nullptr, nullptr, nullptr);
    }
    iconv_close(cd);
    out.resize(static_cast<std::size_t>(o - out.data()));
    return out;
}

}  // namespace essi::native
