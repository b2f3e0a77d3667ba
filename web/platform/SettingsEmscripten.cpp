// Viewer settings in the browser's localStorage (a key "essikit.NAME"): kept across sessions of the page; the
// browser's languages.
#include <emscripten.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

std::optional<std::string> Platform::load_setting(const char* name) {
    // Its length first (-1: none; a page without storage, e.g. a private window that refuses it, has none), then
    // its bytes into a string of that length.
    // clang-format off
    const int len = EM_ASM_INT({
        try {
            const s = window.localStorage.getItem('essikit.' + UTF8ToString($0));
            return s === null ? -1 : lengthBytesUTF8(s);
        } catch (e) {
            return -1;
        }
    }, name);
    // clang-format on
    if (len < 0) return std::nullopt;
    std::string value(static_cast<std::size_t>(len) + 1, '\0');
    // clang-format off
    EM_ASM({
        try {
            stringToUTF8(window.localStorage.getItem('essikit.' + UTF8ToString($0)) || "", $1, $2);
        } catch (e) {
        }
    }, name, value.data(), len + 1);
    // clang-format on
    value.resize(std::strlen(value.c_str()));
    return value;
}

void Platform::save_setting(const char* name, const std::string& value) {
    // clang-format off
    EM_ASM({
        try {
            window.localStorage.setItem('essikit.' + UTF8ToString($0), UTF8ToString($1));
        } catch (e) {
        }
    }, name, value.c_str());
    // clang-format on
}

// navigator.languages in the user's order (else navigator.language): the first one essikit has.
Lang Platform::system_language() {
    // clang-format off
    const int len = EM_ASM_INT({
        const tags = (navigator.languages && navigator.languages.length) ? navigator.languages : [navigator.language || ""];
        return lengthBytesUTF8(tags.join(' '));
    });
    // clang-format on
    std::string tags(static_cast<std::size_t>(len) + 1, '\0');
    // clang-format off
    EM_ASM({
        const tags = (navigator.languages && navigator.languages.length) ? navigator.languages : [navigator.language || ""];
        stringToUTF8(tags.join(' '), $0, $1);
    }, tags.data(), len + 1);
    // clang-format on
    tags.resize(std::strlen(tags.c_str()));
    std::size_t at = 0;
    while (at < tags.size()) {
        const std::size_t end = std::min(tags.find(' ', at), tags.size());
        if (const auto lang = parse_lang(std::string_view(tags).substr(at, end - at))) return *lang;
        at = end + 1;
    }
    return Lang::En;
}

void Platform::show_language(Lang lang) {
    // (no commas inside the JavaScript: the EM_ASM macro would split its argument there)
    // clang-format off
    EM_ASM({
        document.documentElement.lang = UTF8ToString($0);
        const drop = document.getElementById('drop');
        if (drop) drop.textContent = UTF8ToString($1);
    }, std::string(lang_code(lang)).c_str(), c_text(Msg::UiDropHere, lang));
    // clang-format on
}

}  // namespace essi::viewer::platform
