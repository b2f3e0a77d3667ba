// The short message in the toolbar (copied, written, paste ignored ...): shown for kMessageSeconds, in the language
// of the moment it is drawn.
#pragma once

#include "app/Language.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer {

class Notices {
public:
    static constexpr double kMessageSeconds = 4;

    explicit Notices(UiFonts& fonts) : fonts_(fonts) {}

    void notify(Msg id, const MessageArgs& args = {});
    // The last message (state().message), and whether it is still shown.
    [[nodiscard]] const Phrase& message() const { return message_; }
    [[nodiscard]] bool shown() const;

private:
    UiFonts& fonts_;
    Phrase message_;
    double until_ = 0;  // glfwGetTime()
};

}  // namespace essi::viewer
