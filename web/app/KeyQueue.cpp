#include "app/KeyQueue.hpp"

#include <algorithm>

namespace essi::viewer {

void KeyQueue::push(const KeyEvent& e) {
    if (queue_.size() >= kMaxQueued) queue_.pop_front();
    queue_.push_back(e);
}

std::vector<KeyEvent> KeyQueue::take_frame() {
    std::vector<KeyEvent> taken;
    while (!queue_.empty()) {
        const KeyEvent& e = queue_.front();
        const bool changed = std::any_of(taken.begin(), taken.end(), [&](const KeyEvent& t) { return t.key == e.key; });
        if (changed) break;  // (a second change of a key this frame: it waits, and so does all that follows it)
        taken.push_back(e);
        queue_.pop_front();
    }
    return taken;
}

}  // namespace essi::viewer
