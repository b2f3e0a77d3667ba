// Viewer settings in the browser's localStorage (a key "essikit.NAME"): kept across sessions of the page.
#include <emscripten.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

std::optional<int> load_setting(const char* name) {
    // (-2147483648: none; a page without storage, e.g. a private window that refuses it, has none)
    const int v = EM_ASM_INT({
        try {
            const s = window.localStorage.getItem('essikit.' + UTF8ToString($0));
            return s === null ? -2147483648 : (parseInt(s, 10) | 0);
        } catch (e) {
            return -2147483648;
        }
    }, name);
    if (v == -2147483647 - 1) return std::nullopt;
    return v;
}

void save_setting(const char* name, int value) {
    EM_ASM({
        try {
            window.localStorage.setItem('essikit.' + UTF8ToString($0), String($1));
        } catch (e) {
        }
    }, name, value);
}

}  // namespace essi::viewer::platform
