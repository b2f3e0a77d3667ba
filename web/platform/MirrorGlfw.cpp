// The desktop viewer has no page: its window's title names the tape and its verdict (app/PageMirror.hpp).
#include <GLFW/glfw3.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void Platform::show_mirror(const PageMirror& m) {
    if (GLFWwindow* window = glfwGetCurrentContext()) glfwSetWindowTitle(window, m.title.c_str());
}

}  // namespace essi::viewer::platform
