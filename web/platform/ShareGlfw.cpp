// Desktop share links: not made here (the link opens the browser viewer, which compresses the tape with the
// browser's CompressionStream).
#include "app/App.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::platform {

bool has_share_links() { return false; }

void share(App& app, const std::string&, std::string_view, const std::string&) {
    app.notify(Msg::UiShareBrowserOnly);
}

}  // namespace essi::viewer::platform
