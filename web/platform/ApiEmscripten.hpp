// window.essikit's calls (ApiEmscripten.cpp's exported functions) go to the app's Automation: the page calls them by
// name with no context, so the main loop names the Automation once, at start.
#pragma once

#include "app/Automation.hpp"

namespace essi::viewer::platform {

void serve_page_api(Automation& automation);

}  // namespace essi::viewer::platform
