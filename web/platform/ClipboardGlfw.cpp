// Desktop clipboard through GLFW.
#include <GLFW/glfw3.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void Platform::copy_text(const std::string& text) { glfwSetClipboardString(nullptr, text.c_str()); }

void Platform::paste() {
    const char* text = glfwGetClipboardString(nullptr);
    if (text == nullptr || *text == 0) {
        notify(Msg::UiClipboardEmpty);
        return;
    }
    load("pasted.esi", text);
}

}  // namespace essi::viewer::platform
