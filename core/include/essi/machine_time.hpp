// The machine time as a machine with a path acceleration runs the torch's path (docs/semantics.md §9, "Machine
// time"): a look-ahead planner as grbl's and LinuxCNC's, over the motion stream in order.
//
//   - every motion accelerates and decelerates at `accel_mm_s2` along its path; its top speed is its feed (a
//     rapid's: the rapid speed), on an arc or a parabola also sqrt(a · r) at its smallest radius of curvature r;
//   - between two motions without a stop the speed is at most grbl's junction-deviation speed
//     v = sqrt(a · δ · s / (1 − s)), s = sqrt((1 − cos θ) / 2), cos θ = −(u_in · u_out), capped by both top speeds;
//   - the machine stands still where the caller pauses it (its rules: the start and end of the program, a
//     tool on or off, dwells, stops, the end of every block while block stops are on): a junction of speed 0;
//   - a backward and a forward pass give every junction its speed, then each motion is a trapezoid (or a triangle)
//     of speed over its length.
//
// Memory: at most kMachineTimeWindow motions wait for their plan. A motion's plan is final once the motions after
// it can brake to a standstill from any speed the motion might end at (at the latest: a standstill after it);
// when the window is full and that is not so for half of it, that half is planned to stop at the window's end, as
// a machine with that much look-ahead would.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "essi/motion.hpp"

namespace essi {

// Motions that wait for their plan at most: 1024 × 32 bytes, and 1025 × 8 for the backward pass.
constexpr std::size_t kMachineTimeWindow = 1024;
// Motions shorter than this (mm) take no time and change no direction.
constexpr double kMachineTimeMinLength = 1e-9;
// |cos θ| beyond this is a straight junction (no limit) or a reversal (a standstill), as grbl's.
constexpr double kJunctionCosLimit = 0.999999;

// The machine time and where it goes (seconds). cutting + marking + rapid + travel + pierce + dwell = total.
struct MachineTime {
    double total_s = 0;
    double cutting_s = 0;  // motions while a cutting tool is on
    double marking_s = 0;  // motions while a marking tool is on, no cutting tool
    double rapid_s = 0;    // rapid traverse (5) with the tools off
    double travel_s = 0;   // other motion with the tools off (at the feed)
    double pierce_s = 0;
    double dwell_s = 0;
    double acceleration_s = 0;   // of the motions' time: how much longer they take than at their feed
    double torch_cutting_s = 0;  // cutting_s once per torch that cuts (for the consumables)
};
template <>
struct WireFloats<MachineTime> : std::true_type {};

// One motion as the planner runs it (MachineTimer::trace_into): its source line, how long it takes and the highest
// speed it reaches. Motions shorter than kMachineTimeMinLength have none.
struct PlannedMotion {
    std::uint32_t line = 0;
    float seconds = 0;
    float peak_mm_min = 0;
    MotionKind kind = MotionKind::Travel;
};

class MachineTimer {
public:
    MachineTimer(double accel_mm_s2, double junction_deviation_mm);
    // Every motion's plan appended to `out` as it is made (in order), or none (null).
    void trace_into(std::vector<PlannedMotion>* out) { trace_ = out; }

    // A motion of the torch's path, in order. `block` tells the blocks apart for block stops. (Inline, as what it
    // calls for a line: the statistics give it every motion of the compensated path.)
    [[gnu::always_inline]] void motion(const MotionRecord& m) {
        if (!(m.length_mm > kMachineTimeMinLength)) return;
        const std::uint8_t torches = m.kind == MotionKind::Cut ? m.torches : 1;
        if (m.curve != CurveKind::Line) return curve(m, torches);
        const double k = 1 / m.length_mm;
        const Point d{(m.end.x - m.start.x) * k, (m.end.y - m.start.y) * k};
        add(m.kind, m.length_mm, m.feed_mm_min / 60, d, d, torches, m.head, m.block, m.line);
    }
    // A straight motion of its own block, source line `line` (what the statistics get without a record).
    void line(MotionKind kind, Point start, Point end, double length_mm, double feed_mm_min, std::uint32_t line);
    // What the events between two motions do: the machine stands still there (`stop`), and from there on it stops
    // at the end of every block or not (`block_stops`: ISO 6582 function 17, until 18). It takes effect before the
    // next motion, or, with `after_block` >= 0, before the first motion of a later block (the events came while
    // the compensated path's piece of that block was open). Pauses before one motion add up.
    void pause(bool stop, bool block_stops, std::int64_t after_block) {
        if (after_block < 0 && !pause_.pending) {
            standing_ = standing_ || stop;
            block_stops_ = block_stops;
            watch_head_ = block_stops ? -1 : last_head_;
            return;
        }
        if (!pause_.pending) pause_.after_block = after_block;
        pause_.pending = true;
        pause_.stop = pause_.stop || stop;
        pause_.block_stops = block_stops;
        watch_head_ = -1;
    }
    void add_pierce(double seconds) { time_.pierce_s += seconds; }
    void add_dwell(double seconds) { time_.dwell_s += seconds; }
    // The end of the program: a standstill, and the total. `estimated_time_s`: the estimate of the same path (its
    // motions at their feeds, the same pierces and dwells), for the time lost to acceleration.
    void finish(double estimated_time_s);

    [[nodiscard]] const MachineTime& time() const { return time_; }

private:
    // A motion waiting for its plan. Speeds in mm/s; the passes work on their squares (no square root).
    struct Pending {
        double length_mm;
        double top;                // its top speed
        double entry_max_squared;  // the most its entry may be: the junction's speed, both top speeds; 0 after a stop
        MotionKind kind;
        std::uint8_t torches;
        std::uint32_t line;  // its source line (the trace's)
    };
    // A motion with its top speed (above 0: every feed is) and its directions at both ends; `block` < 0: a block
    // of its own.
    [[gnu::always_inline]] void add(MotionKind kind, double length_mm, double top, Point start_dir, Point end_dir,
                                    std::uint8_t torches, int head, std::int64_t block, std::uint32_t line) {
        if (head != watch_head_) [[unlikely]] {  // another head; a pause waiting; under block stops, another block?
            if (pause_.pending && block > pause_.after_block) {
                standing_ = standing_ || pause_.stop;
                block_stops_ = pause_.block_stops;
                pause_ = {};
            }
            if (head != last_head_ || (block_stops_ && (block < 0 || block != last_block_))) standing_ = true;
            last_head_ = head;
            last_block_ = block;
            watch_head_ = block_stops_ || pause_.pending ? -1 : head;
        }
        const double top_squared = top * top;
        double entry_max_squared = 0;
        if (!standing_) {
            entry_max_squared =
                std::min(std::min(last_top_squared_, top_squared), junction_speed_squared(last_dir_, start_dir));
        }
        window_[pending_++] = {length_mm, top, entry_max_squared, kind, torches, line};
        last_dir_ = end_dir;
        last_top_squared_ = top_squared;
        standing_ = false;
        if (pending_ == kMachineTimeWindow) [[unlikely]]
            plan(false);
    }
    [[gnu::noinline]] void curve(const MotionRecord& m, std::uint8_t torches);
    [[gnu::noinline]] void parabola(const MotionRecord& m, std::uint8_t torches);
    // grbl's junction deviation: the speed at which a circle of deviation δ, tangent to both motions, is run at
    // the centripetal acceleration a: v² = a · δ · s / (1 − s). (A motion without a direction, an arc of radius 0,
    // meets its neighbours at a right angle.)
    [[nodiscard]] double junction_speed_squared(Point in, Point out) const {
        const double cos_theta = -(in.x * out.x + in.y * out.y);
        if (cos_theta < -kJunctionCosLimit) return std::numeric_limits<double>::infinity();  // straight on
        if (cos_theta > kJunctionCosLimit) return 0;                                         // a reversal
        const double s = std::sqrt(0.5 * (1 - cos_theta));
        return accel_deviation_ * s / (1 - s);
    }
    // Plans the window: commits the motions whose plan is final (all of them at the end, `stops`), and when the
    // window is full at least half of it.
    [[gnu::noinline]] void plan(bool stops);
    void commit(const Pending& p, double v0, double v1, double v0_squared, double v1_squared);

    double accel_;
    double accel_deviation_;     // a · δ
    double half_inverse_accel_;  // 1 / (2a)
    MachineTime time_;
    double kind_s_[4] = {};        // the motions' time by MotionKind
    double extra_torches_s_ = 0;   // the cutting time once more for each torch beyond the first
    std::vector<Pending> window_;  // kMachineTimeWindow long; the first `pending_` wait
    std::vector<double> lowest_;   // the backward pass: squared entry speeds if the machine stops after the window
    std::size_t pending_ = 0;
    double entry_ = 0;      // the speed at the start of window_[0] (the last committed motion's exit)
    bool standing_ = true;  // the machine stands still before the next motion
    bool block_stops_ = false;
    Point last_dir_;  // the direction of travel at the end of the last motion
    double last_top_squared_ = 0;
    int last_head_ = 1;
    int watch_head_ = 1;  // last_head_, or -1 under block stops or with a pause waiting: a motion of
                          // another head is looked at
    struct Pause {
        bool pending = false;
        bool stop = false;
        bool block_stops = false;
        std::int64_t after_block = -1;
    } pause_;  // a pause waiting for the first motion of a block after `after_block`
    std::int64_t last_block_ = -1;
    std::vector<PlannedMotion>* trace_ = nullptr;
};

}  // namespace essi
