// The machine time as a machine with a path acceleration runs the torch's path (docs/semantics.md §9, "Machine
// time"): a look-ahead planner as grbl's and LinuxCNC's, over the motion stream in order.
//
//   - every motion accelerates and decelerates at `accel_mm_s2` along its path; its top speed is its feed (a
//     rapid's: the rapid speed), on an arc or a parabola also sqrt(a · r) at its smallest radius of curvature r;
//   - between two motions without a stop the speed is at most grbl's junction-deviation speed
//     v = sqrt(a · δ · s / (1 − s)), s = sqrt((1 − cos θ) / 2), cos θ = −(u_in · u_out), capped by both top speeds;
//   - the machine stands still where stop() is called (the caller's rules: the start and end of the program, a
//     tool on or off, dwells, stops, the end of every block while block stops are on);
//   - over each run of motions between two standstills a backward and a forward pass give every junction its
//     speed, then each motion is a trapezoid (or a triangle) of speed over its length.
//
// Memory: at most kMachineTimeWindow motions wait for their plan. A motion's plan is final once the motions after
// it can brake to a standstill from any speed the motion might end at; when the window is full and that is not so
// for half of it, that half is planned to stop at the window's end, as a machine with that much look-ahead would.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "essi/motion.hpp"

namespace essi {

// Motions that wait for their plan at most: 1024 × 48 bytes.
constexpr std::size_t kMachineTimeWindow = 1024;
// Motions shorter than this (mm) take no time and change no direction.
constexpr double kMachineTimeMinLength = 1e-9;
// |cos θ| beyond this is a straight junction (no limit) or a reversal (a standstill), as grbl's.
constexpr double kJunctionCosLimit = 0.999999;

// The machine time and where it goes (seconds). cutting + marking + rapid + travel + pierce + dwell = total.
struct MachineTime {
    double total_s = 0;
    double cutting_s = 0;       // motions while a cutting tool is on
    double marking_s = 0;       // motions while a marking tool is on, no cutting tool
    double rapid_s = 0;         // rapid traverse (5) with the tools off
    double travel_s = 0;        // other motion with the tools off (at the feed)
    double pierce_s = 0;
    double dwell_s = 0;
    double acceleration_s = 0;  // of the motions' time: how much longer they take than at their feed
    double torch_cutting_s = 0; // cutting_s once per torch that cuts (for the consumables)
};

class MachineTimer {
public:
    MachineTimer(double accel_mm_s2, double junction_deviation_mm);

    // A motion of the torch's path, in order. `block` tells the blocks apart for block stops.
    void motion(const MotionRecord& m);
    // A straight motion of its own block (what the statistics get without a record).
    void line(MotionKind kind, Point start, Point end, double length_mm, double feed_mm_min);
    // The machine stands still here.
    void stop();
    // While on, the machine stands still at the end of every block (ISO 6582 function 17, until 18).
    void set_block_stops(bool on);
    void add_pierce(double seconds) { time_.pierce_s += seconds; }
    void add_dwell(double seconds) { time_.dwell_s += seconds; }
    // The end of the program: a standstill, and the total.
    void finish();

    [[nodiscard]] const MachineTime& time() const { return time_; }

private:
    // A motion waiting for its plan (speeds in mm/s).
    struct Pending {
        double length_mm;
        double top;         // its top speed
        double feed;        // its feed (the time without acceleration is length / feed)
        double entry_max;   // the most its entry may be: the junction's speed, both top speeds; 0 after a stop
        MotionKind kind;
        std::uint8_t torches;
    };
    void add(MotionKind kind, double length_mm, double feed_mm_min, double top_mm_s, Point start_dir, Point end_dir,
             std::uint8_t torches, int head, std::int64_t block);
    [[nodiscard]] double junction_speed(Point in, Point out) const;
    // Plans the window: commits the motions whose plan is final (all of them at a standstill, `stops`), and
    // when the window is full at least half of it.
    void plan(bool stops);
    void commit(const Pending& p, double entry, double exit);
    [[nodiscard]] double trapezoid_s(double length_mm, double v0, double v1, double top) const;

    double accel_;
    double deviation_;
    MachineTime time_;
    std::vector<Pending> window_;
    std::vector<double> lowest_;  // the backward pass: entry speeds if the machine stops after the window
    double entry_ = 0;            // the speed at the start of window_[0] (the last committed motion's exit)
    bool standing_ = true;        // no motion since the last standstill
    bool block_stops_ = false;
    Point last_dir_;              // the direction of travel at the end of the last motion
    double last_top_ = 0;
    int last_head_ = 1;
    std::int64_t last_block_ = -1;
};

}  // namespace essi
