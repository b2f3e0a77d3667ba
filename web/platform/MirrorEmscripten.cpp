// The page's title and its text for screen readers (app/PageMirror.hpp): handed to window.essikitMirror (index.html
// puts it in the title and the elements beside the canvas) as JSON, when it changed.
#include <emscripten.h>

#include <nlohmann/json.hpp>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void Platform::show_mirror(const PageMirror& m) {
    const nlohmann::json j = {{"lang", m.lang},         {"title", m.title},   {"label", m.label},
                              {"heading", m.heading},   {"status", m.status}, {"problems_heading", m.problems_heading},
                              {"problems", m.problems}, {"more", m.more}};
    const std::string text = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    // clang-format off
    EM_ASM({ window.essikitMirror && window.essikitMirror(JSON.parse(UTF8ToString($0))); }, text.c_str());
    // clang-format on
}

}  // namespace essi::viewer::platform
