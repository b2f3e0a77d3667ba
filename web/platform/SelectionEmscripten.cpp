// The selection told to the page: window.essikitSelected(line, motion) when the page defines it (the npm package's
// <essi-viewer> does, and fires essi-select).
#include <emscripten.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void Platform::selection_changed(std::uint32_t line, long long motion) {
    // clang-format off
    EM_ASM({ window.essikitSelected && window.essikitSelected($0, $1); }, line, static_cast<double>(motion));
    // clang-format on
}

}  // namespace essi::viewer::platform
