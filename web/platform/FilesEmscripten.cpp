// Browser files: the Open button clicks the page's <input type=file>; drops and pastes are handled by the
// page (index.html), which passes the bytes to essi_load (ApiEmscripten.cpp).
#include <emscripten.h>

#include "app/App.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

bool has_file_dialog() { return true; }

void open_file_dialog(App&) {
    EM_ASM({
        const input = document.getElementById('file');
        if (input) input.click();
    });
}

}  // namespace essi::viewer::platform
