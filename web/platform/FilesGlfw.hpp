// The desktop's files for its main loop (MainLoopGlfw.cpp): a file read whole, the window's drop handler.
#pragma once

#include <GLFW/glfw3.h>

#include <string>

#include "app/AppCallbacks.hpp"

namespace essi::viewer::platform {

// The file's bytes into `out`; false when it cannot be read.
bool read_file(const std::string& path, std::string& out);
// Files dropped on the window are loaded by `app` (the first of them; a message when it cannot be read).
void install_drop_handler(GLFWwindow* window, AppCallbacks& app);

}  // namespace essi::viewer::platform
