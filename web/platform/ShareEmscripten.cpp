// Browser share links: index.html compresses the tape (CompressionStream 'deflate-raw'), base64url-encodes
// it into the URL fragment with the view, copies the URL and calls essi_share_done.
#include <emscripten.h>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {

bool Platform::has_share_links() const { return true; }

void Platform::share(const std::string& name, std::string_view bytes, const std::string& view_query) {
    // clang-format off
    EM_ASM({ window.essikitShare(UTF8ToString($0), $1, $2, UTF8ToString($3)); }, name.c_str(), bytes.data(),
           static_cast<int>(bytes.size()), view_query.c_str());
    // clang-format on
}

}  // namespace essi::viewer::platform
