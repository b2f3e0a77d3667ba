#include "app/Language.hpp"

#include <string_view>

namespace essi::viewer {

namespace {
Lang g_lang = Lang::En;
}

Lang ui_lang() { return g_lang; }
void set_ui_lang(Lang lang) { g_lang = lang; }

std::string tr_id(Msg id, const char* stable_id) {
    std::string s(tr(id));
    s += "###";
    s += stable_id;
    return s;
}

std::string tr_format(Msg id, const char* spec) {
    // The argument's place marked by a character no message has (U+E000, of the private use area): a control
    // character would come back escaped, as every argument does ("\x01").
    constexpr std::string_view kMark = "\xEE\x80\x80";
    const std::string text = tr(id, {std::string(kMark)});
    std::string out;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (text.compare(k, kMark.size(), kMark) == 0) {
            out += spec;
            k += kMark.size() - 1;
        } else {
            out += text[k] == '%' ? "%%" : std::string(1, text[k]);
        }
    }
    return out;
}

}  // namespace essi::viewer
