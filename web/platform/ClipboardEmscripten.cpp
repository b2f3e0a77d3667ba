// Browser clipboard: navigator.clipboard. Ctrl+V reaches the page as a `paste` event (index.html loads the
// text); the Paste button asks navigator.clipboard.readText, which the browser may refuse.
#include <emscripten.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void Platform::copy_text(const std::string& text) {
    // clang-format off
    EM_ASM({ window.essikitCopy && window.essikitCopy(UTF8ToString($0)); }, text.c_str());
    // clang-format on
}

void Platform::paste() {
    // clang-format off
    EM_ASM({ window.essikitPasteButton && window.essikitPasteButton(); });
    // clang-format on
}

}  // namespace essi::viewer::platform
