// The playback: the drawing limited to the motions before a position that moves in machine time times a speed
// factor, with the tool drawn where the position is. The machine time is the statistics' (essi::statistics_time_s:
// planned with the profile's accelerations, else at the feeds), motion by motion as the core gives it
// (essi::motion_seconds, MotionTimes): the whole playback lasts what the Statistics panel says. One type for the
// keyboard shortcuts and the Playback panel's buttons.
#pragma once

#include <cstddef>
#include <vector>

namespace essi::viewer {

struct Document;

// The seconds of each motion of a tape (essi::motion_seconds) and the time before every kStride-th motion: the
// time at any position is then at most kStride motions' seconds away.
class MotionTimes {
public:
    MotionTimes() = default;
    explicit MotionTimes(std::vector<float> seconds);
    [[nodiscard]] std::size_t size() const { return seconds_.size(); }
    [[nodiscard]] double seconds(std::size_t motion) const { return seconds_[motion]; }
    // From the start to the start of `motion` (<= size()).
    [[nodiscard]] double before(std::size_t motion) const;

private:
    static constexpr std::size_t kStride = 256;
    std::vector<float> seconds_;
    std::vector<double> before_;  // [k]: the time before motion k * kStride
};

// Where the playback gets the open tape's MotionTimes (TapeFacts: made when first asked, for the tape open then);
// null while no tape is open.
class MotionTimesSource {
public:
    virtual ~MotionTimesSource() = default;
    [[nodiscard]] virtual const MotionTimes* motion_times() const = 0;
};

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
    void stop();                       // a new tape: no limit, paused
    // The frame's time while playing: the position moves on by `seconds` x factor of machine time, each motion
    // taking its seconds.
    void advance(float seconds, const MotionTimes& times);

    // Motions drawn: [0, limit).
    [[nodiscard]] std::size_t limit(std::size_t n) const;
    // The motion at the position (n > 0) and how far along it the tool is (0..1).
    struct At {
        std::size_t motion;
        double fraction;
    };
    [[nodiscard]] At at(std::size_t n) const;

    // Machine time (s) from the start to the position (the motions' times asked for only while the position is
    // before the end), and of the whole program: the statistics' time.
    [[nodiscard]] double elapsed_s(const Document& doc, const MotionTimesSource& times) const;
    [[nodiscard]] static double total_s(const Document& doc);
};

}  // namespace essi::viewer
