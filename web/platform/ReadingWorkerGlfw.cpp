// The desktop has no reading worker: the viewer reads every tape itself (LoadController's slices).
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

ReadingWorker* Platform::reading_worker() { return nullptr; }

}  // namespace essi::viewer::platform
