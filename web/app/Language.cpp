#include "app/Language.hpp"

#include "app/App.hpp"
#include "platform/Platform.hpp"

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

// The user's choice (the setting), else what the browser or the environment asks for.
Lang App::startup_language() {
    if (const auto setting = platform::load_text_setting(kLanguageSetting))
        if (const auto lang = parse_lang(*setting)) return *lang;
    return platform::system_language();
}

void App::set_language(Lang lang, bool remember) {
    set_ui_lang(lang);
    if (remember) platform::save_text_setting(kLanguageSetting, std::string(lang_code(lang)));
    platform::show_language(lang);
}

}  // namespace essi::viewer
