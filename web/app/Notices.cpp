#include "app/Notices.hpp"

#include <GLFW/glfw3.h>

namespace essi::viewer {

void Notices::notify(Msg id, const MessageArgs& args) {
    message_ = {id, args};
    fonts_.require_glyphs(message_.text());  // (a name in it)
    until_ = glfwGetTime() + kMessageSeconds;
}

bool Notices::shown() const { return !message_.empty() && glfwGetTime() < until_; }

}  // namespace essi::viewer
