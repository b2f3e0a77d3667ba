// The loading progress as its bar shows it: moved on at most every kEverySeconds. Every change of the bar redraws
// the page, and a redraw under a software GPU (SwiftShader: a whole-canvas blit and the panels) takes a core for
// about 50 ms: at every 2 % step, that was a core taken from the reading worker for as long as it read.
#pragma once

namespace essi::viewer {

class ShownProgress {
public:
    static constexpr double kEverySeconds = 0.25;

    // What the bar shows at `now_s` (seconds, any clock that only goes forward) for `progress`: the progress itself
    // when it went back (another load) or the bar last moved kEverySeconds ago or more, else what it showed.
    float update(float progress, double now_s) {
        if (progress != shown_ && (shown_ < 0 || progress < shown_ || now_s - moved_at_s_ >= kEverySeconds)) {
            shown_ = progress;
            moved_at_s_ = now_s;
        }
        return shown_;
    }

private:
    float shown_ = -1;  // none yet
    double moved_at_s_ = 0;
};

}  // namespace essi::viewer
