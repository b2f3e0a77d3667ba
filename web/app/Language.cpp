#include "app/Language.hpp"

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
    const std::string text = tr(id, {"\x01"});
    std::string out;
    for (const char c : text) {
        if (c == '\x01') out += spec;
        else if (c == '%') out += "%%";
        else out += c;
    }
    return out;
}

}  // namespace essi::viewer
