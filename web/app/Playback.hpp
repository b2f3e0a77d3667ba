// The playback: the drawing limited to the motions before a position that moves at `speed` motions a second, with
// the tool drawn where the position is. One type for the keyboard shortcuts and the Playback panel's buttons.
// `n` is always the document's motion count.
#pragma once

#include <cstddef>

namespace essi::viewer {

class Playback {
public:
    bool active = false;   // the drawing is limited to the position
    bool playing = false;  // the position moves
    double position = 0;   // in motions
    float speed = 20;      // motions per second

    // Space, Play / Pause: plays (from the start when not active or at the end) or pauses.
    void toggle(std::size_t n);
    void step_forward(std::size_t n);  // Right, ">": the next whole motion, paused
    void step_back();                  // Left, "<": the motion before, paused
    void rewind();                     // Home: back to the start (a running playback goes on)
    void show_all(std::size_t n);      // End, "All": no limit
    void seek(double motion);          // the scrubber
    void stop();                       // a new tape: no limit, paused
    void advance(float seconds, std::size_t n);   // the frame's time while playing

    // Motions drawn: [0, limit).
    [[nodiscard]] std::size_t limit(std::size_t n) const;
    // The motion at the position (n > 0) and how far along it the tool is (0..1).
    struct At {
        std::size_t motion;
        double fraction;
    };
    [[nodiscard]] At at(std::size_t n) const;
};

}  // namespace essi::viewer
