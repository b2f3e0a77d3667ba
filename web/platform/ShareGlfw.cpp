// Desktop share links: not made here (the link opens the browser viewer, which compresses the tape with the
// browser's CompressionStream).
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

bool Platform::has_share_links() const { return false; }

void Platform::share(const std::string&, std::string_view, const std::string&) { notify(Msg::UiShareBrowserOnly); }

}  // namespace essi::viewer::platform
