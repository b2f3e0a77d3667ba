// Text in the terminal's charset (terminal_text.hpp), converted by essi/charset.hpp.
#include "terminal_text.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "essi/charset.hpp"

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
    if (charset_.empty() ||
        std::all_of(utf8.begin(), utf8.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }))
        return std::string(utf8);
    std::optional<std::string> text = utf8_to_charset(utf8, charset_.c_str());
    return text ? std::move(*text) : std::string(utf8);  // (no converter: as it is)
}

}  // namespace essi::native
