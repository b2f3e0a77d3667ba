// Desktop clipboard through GLFW.
#include <GLFW/glfw3.h>

#include "app/App.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void copy_text(const std::string& text) { glfwSetClipboardString(nullptr, text.c_str()); }

void paste(App& app) {
    const char* text = glfwGetClipboardString(nullptr);
    if (text == nullptr || *text == 0) {
        app.notify(Msg::UiClipboardEmpty);
        return;
    }
    app.load("pasted.esi", text);
}

}  // namespace essi::viewer::platform
