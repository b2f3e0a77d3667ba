// The calls the platform makes into the viewer besides the frame loop (App) and the page's API (Automation): a file
// the user opened, dropped or pasted, and how a platform service went. App implements them; the platform is given
// them once the app is made (platform::Platform::connect).
#pragma once

#include <string>

#include "essi/i18n.hpp"

namespace essi::viewer {

class AppCallbacks {
public:
    virtual ~AppCallbacks() = default;
    // A file's bytes as read: a tape to read (or to compare, in compare mode), or a profile (`.json`).
    virtual void load(std::string name, std::string bytes) = 0;
    // A short message in the toolbar (written, cannot read, no file chosen ...).
    virtual void notify(Msg id, const MessageArgs& args = {}) = 0;
};

}  // namespace essi::viewer
