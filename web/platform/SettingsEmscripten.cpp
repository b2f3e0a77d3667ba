// Viewer settings in the browser's localStorage (a key "essikit.NAME"): kept across sessions of the page.
#include <emscripten.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

std::optional<std::string> load_text_setting(const char* name) {
    // Its length first (-1: none; a page without storage, e.g. a private window that refuses it, has none), then
    // its bytes into a string of that length.
    const int len = EM_ASM_INT({
        try {
            const s = window.localStorage.getItem('essikit.' + UTF8ToString($0));
            return s === null ? -1 : lengthBytesUTF8(s);
        } catch (e) {
            return -1;
        }
    }, name);
    if (len < 0) return std::nullopt;
    std::string value(static_cast<std::size_t>(len) + 1, '\0');
    EM_ASM({
        try {
            stringToUTF8(window.localStorage.getItem('essikit.' + UTF8ToString($0)) || '', $1, $2);
        } catch (e) {
        }
    }, name, value.data(), len + 1);
    value.resize(std::strlen(value.c_str()));
    return value;
}

void save_text_setting(const char* name, const std::string& value) {
    EM_ASM({
        try {
            window.localStorage.setItem('essikit.' + UTF8ToString($0), UTF8ToString($1));
        } catch (e) {
        }
    }, name, value.c_str());
}

std::optional<int> load_setting(const char* name) {
    const auto text = load_text_setting(name);
    if (!text) return std::nullopt;
    return std::atoi(text->c_str());
}

void save_setting(const char* name, int value) { save_text_setting(name, std::to_string(value)); }

}  // namespace essi::viewer::platform
