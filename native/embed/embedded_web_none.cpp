// embedded_web_files of a build without ESSI_EMBED_WEB_DIR: no viewer compiled in.
#include "embedded_web.hpp"

namespace essi::native {

std::span<const EmbeddedFile> embedded_web_files() { return {}; }

}  // namespace essi::native
