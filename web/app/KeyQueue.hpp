// Key presses and releases queued between frames, so that none is lost. ImGui 1.86 reads the keys' state once a
// frame: a key pressed and released within one frame (a quick tap, several arrows typed at once) would never be seen
// down. The platform pushes every key event as it comes and hands ImGui, before each frame, the events up to the
// first one that would change a key already changed in that frame; the rest wait for the next frames (a tap: down in
// one frame, up in the next).
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

namespace essi::viewer {

struct KeyEvent {
    int key = 0;  // the platform's key code (GLFW_KEY_*)
    int scancode = 0;
    int action = 0;  // 0 released, 1 pressed, 2 repeated (GLFW_RELEASE, GLFW_PRESS, GLFW_REPEAT)
    int mods = 0;
};

class KeyQueue {
public:
    // Events beyond this many wait no more: the oldest are handed over (a key held down repeats forever).
    static constexpr std::size_t kMaxQueued = 256;

    void push(const KeyEvent& e);
    // The events this frame takes, in order: each key changes at most once.
    [[nodiscard]] std::vector<KeyEvent> take_frame();
    [[nodiscard]] std::size_t queued() const { return queue_.size(); }

private:
    std::deque<KeyEvent> queue_;
};

}  // namespace essi::viewer
