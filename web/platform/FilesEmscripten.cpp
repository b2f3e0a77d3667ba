// Browser files: the page (index.html) opens its <input type=file> in the click on the Open button (whose
// place this file tells it) or on Ctrl+O, inside the user's gesture as browsers require; drops and pastes
// are handled by the page too, which writes the bytes into essi_load_buffer and commits them (ApiEmscripten.cpp).
#include <emscripten.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

// The page has already opened the picker in the click or key event (a picker opened from a later frame
// is refused once the gesture has expired).
void Platform::open_file_dialog() {}

void Platform::open_button_at(float x, float y, float width, float height) {
    static float last[4] = {-1, -1, -1, -1};
    if (last[0] == x && last[1] == y && last[2] == width && last[3] == height) return;
    last[0] = x;
    last[1] = y;
    last[2] = width;
    last[3] = height;
    // (no commas inside the JavaScript: the EM_ASM macro would split its argument there)
    // clang-format off
    EM_ASM({
        const b = window.essikitOpenButton || (window.essikitOpenButton = {});
        b.x = $0; b.y = $1; b.w = $2; b.h = $3;
    }, x, y, width, height);
    // clang-format on
}

void Platform::save_file(const std::string& name, const std::string& text) {
    // (no commas inside the JavaScript: the EM_ASM macro would split its argument there)
    // clang-format off
    EM_ASM({
        const blob = new Blob([HEAPU8.slice($1, $1 + $2)], {type: 'application/octet-stream'});
        const a = document.createElement('a');
        a.href = URL.createObjectURL(blob);
        a.download = UTF8ToString($0);
        document.body.appendChild(a);
        a.click();
        setTimeout(function() { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
    }, name.c_str(), text.data(), static_cast<int>(text.size()));
    // clang-format on
}

bool Platform::show_html(const std::string& name, const std::string& html) {
    // A blob: page in a new tab (under the viewer's Content Security Policy, which allows the sheet's style sheet);
    // window.essikitLastPrintView keeps its address (the tests read it). The URL is kept while the page lives: the
    // tab may be reloaded.
    // (no commas inside the JavaScript: the EM_ASM macro would split its argument there)
    // clang-format off
    const int opened = EM_ASM_INT({
        const blob = new Blob([HEAPU8.slice($0, $0 + $1)], {type: 'text/html;charset=utf-8'});
        const url = URL.createObjectURL(blob);
        window.essikitLastPrintView = url;
        return window.open(url, '_blank') ? 1 : 0;
    }, html.data(), static_cast<int>(html.size()));
    // clang-format on
    if (opened) return true;
    save_file(name, html);
    return false;
}

void Platform::open_example(const std::string& name) {
    // clang-format off
    EM_ASM({ window.essikitOpenExample(UTF8ToString($0)); }, name.c_str());
    // clang-format on
}

void Platform::save_view_png(const std::string& name, PixelRect a) {
    // Right after the frame is drawn (the WebGL canvas still holds it): its drawing area onto a 2D canvas, a PNG
    // of it downloaded; window.essikitLastPng keeps its data URL (the tests read it).
    // (no commas inside the JavaScript: the EM_ASM macro would split its argument there)
    // clang-format off
    EM_ASM({
        const src = Module.canvas;
        const c = document.createElement('canvas');
        c.width = Math.round($2); c.height = Math.round($3);
        c.getContext('2d').drawImage(src, $0, $1, $2, $3, 0, 0, c.width, c.height);
        window.essikitLastPng = c.toDataURL('image/png');
        const a = document.createElement('a');
        a.href = window.essikitLastPng;
        a.download = UTF8ToString($4);
        document.body.appendChild(a);
        a.click();
        a.remove();
    }, a.x, a.y, a.w, a.h, name.c_str());
    // clang-format on
}

}  // namespace essi::viewer::platform
