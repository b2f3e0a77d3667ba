// The playback: the drawing limited to the motions before a position that moves in machine time (each motion at
// its programmed feed, rapid at the profile's rapid speed, a pierce with the profile's pierce time: the
// statistics' time estimate along the programmed path) times a speed factor, with the tool drawn where the
// position is. One type for the keyboard shortcuts and the Playback panel's buttons.
#pragma once

#include <cstddef>
#include <vector>

namespace essi::viewer {

struct Document;

class Playback {
public:
    bool active = false;   // the drawing is limited to the position
    bool playing = false;  // the position moves
    double position = 0;   // in motions
    float factor = 10;     // machine seconds per second of playback (1-1000)
    static constexpr float kMinFactor = 1, kMaxFactor = 1000;

    // Space, Play / Pause: plays (from the start when not active or at the end) or pauses.
    void toggle(std::size_t n);
    void step_forward(std::size_t n);  // Right, ">": the next whole motion, paused
    void step_back();                  // Left, "<": the motion before, paused
    void rewind();                     // Home: back to the start (a running playback goes on)
    void show_all(std::size_t n);      // End, "All": no limit
    void seek(double motion);          // the scrubber
    void stop();                       // a new tape: no limit, paused, the machine times forgotten
    // The frame's time while playing: the position moves on by `seconds` x factor of machine time.
    void advance(float seconds, const Document& doc);

    // Motions drawn: [0, limit).
    [[nodiscard]] std::size_t limit(std::size_t n) const;
    // The motion at the position (n > 0) and how far along it the tool is (0..1).
    struct At {
        std::size_t motion;
        double fraction;
    };
    [[nodiscard]] At at(std::size_t n) const;

    // Machine time (s) from the start to the position, and of the whole program.
    [[nodiscard]] double elapsed_s(const Document& doc) const;
    [[nodiscard]] double total_s(const Document& doc) const;

private:
    // Machine time before every kTimeStride-th motion, made at the first question after a new tape: the time at
    // any position is then at most kTimeStride durations away.
    static constexpr std::size_t kTimeStride = 256;
    void make_times(const Document& doc) const;
    mutable std::vector<double> time_before_;  // [k]: the time before motion k * kTimeStride; last: the total
};

}  // namespace essi::viewer
