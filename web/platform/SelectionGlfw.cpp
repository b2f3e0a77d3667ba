// The desktop viewer has no page to tell of the selection.
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

void Platform::selection_changed(std::uint32_t, long long) {}

}  // namespace essi::viewer::platform
