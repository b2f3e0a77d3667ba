// The machine time with acceleration: a look-ahead planner over the torch's path (essi/machine_time.hpp).
#include "essi/machine_time.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "essi/geom.hpp"

namespace essi {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The radius of curvature a curve's top speed is taken at when it is smaller (mm): a compensated arc whose
// radius shrinks to 0 at one end (E306) still has a speed.
constexpr double kMinCurvatureRadiusMm = 1e-3;

double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
bool is_zero(Point a) { return a.x == 0 && a.y == 0; }

}  // namespace

MachineTimer::MachineTimer(double accel_mm_s2, double junction_deviation_mm)
    : accel_(accel_mm_s2), deviation_(junction_deviation_mm) {
    window_.reserve(kMachineTimeWindow);
    lowest_.reserve(kMachineTimeWindow + 1);
}

void MachineTimer::motion(const MotionRecord& m) {
    double top = m.feed_mm_min / 60;
    if (m.curve != CurveKind::Line)
        top = std::min(top, std::sqrt(accel_ * std::max(min_curvature_radius(m), kMinCurvatureRadiusMm)));
    const std::uint8_t torches = m.kind == MotionKind::Cut ? m.torches : 1;
    add(m.kind, m.length_mm, m.feed_mm_min, top, start_tangent(m), end_tangent(m), torches, m.head, m.block);
}

void MachineTimer::line(MotionKind kind, Point start, Point end, double length_mm, double feed_mm_min) {
    if (!(length_mm > kMachineTimeMinLength)) return;
    const Point dir{(end.x - start.x) / length_mm, (end.y - start.y) / length_mm};
    add(kind, length_mm, feed_mm_min, feed_mm_min / 60, dir, dir, 1, 1, -1);
}

// `block` < 0: a block of its own.
void MachineTimer::add(MotionKind kind, double length_mm, double feed_mm_min, double top_mm_s, Point start_dir,
                       Point end_dir, std::uint8_t torches, int head, std::int64_t block) {
    if (!(length_mm > kMachineTimeMinLength) || !(top_mm_s > 0)) return;
    if (head != last_head_ || (block_stops_ && (block < 0 || block != last_block_))) stop();
    last_head_ = head;
    last_block_ = block;
    const double entry_max = standing_ ? 0.0 : std::min({junction_speed(last_dir_, start_dir), last_top_, top_mm_s});
    window_.push_back({length_mm, top_mm_s, feed_mm_min / 60, entry_max, kind, torches});
    last_dir_ = end_dir;
    last_top_ = top_mm_s;
    standing_ = false;
    if (window_.size() >= kMachineTimeWindow) plan(false);
}

// grbl's junction deviation: the speed at which a circle of deviation δ, tangent to both motions, is run at the
// centripetal acceleration a.
double MachineTimer::junction_speed(Point in, Point out) const {
    if (is_zero(in) || is_zero(out)) return 0;
    const double cos_theta = -dot(in, out);
    if (cos_theta > kJunctionCosLimit) return 0;           // a reversal
    if (cos_theta < -kJunctionCosLimit) return kInfinity;  // straight on
    const double s = std::sqrt(0.5 * (1 - cos_theta));
    return std::sqrt(accel_ * deviation_ * s / (1 - s));
}

void MachineTimer::stop() {
    plan(true);
    standing_ = true;
    entry_ = 0;
}

void MachineTimer::set_block_stops(bool on) { block_stops_ = on; }

// The backward pass gives each junction i the most its speed may be when the machine can still brake to the end
// of the window: lowest_ when it stops there, `highest` when it may go on at the last motion's top speed. Where
// both agree the rest of the tape cannot change it (and they agree at every junction before). The forward pass
// then gives each committed motion its entry and exit: a motion is committed when the junction at its end is
// final, or when the window is full and fewer than half of its motions are (then they are planned as if the
// machine stopped after the window).
void MachineTimer::plan(bool stops) {
    const std::size_t n = window_.size();
    if (n == 0) return;
    lowest_.resize(n + 1);
    const double two_a = 2 * accel_;
    double low = 0, high = stops ? 0.0 : window_.back().top;
    lowest_[n] = 0;
    std::size_t final_junction = low == high ? n : 0;
    bool found = low == high;
    for (std::size_t i = n; i-- > 0;) {
        const Pending& p = window_[i];
        low = std::min(p.entry_max, std::sqrt(low * low + two_a * p.length_mm));
        high = std::min(p.entry_max, std::sqrt(high * high + two_a * p.length_mm));
        lowest_[i] = low;
        if (!found && low == high) {
            final_junction = i;
            found = true;
        }
    }
    std::size_t count = final_junction;  // motions 0 .. count-1 end at a final junction
    if (!stops && n >= kMachineTimeWindow) count = std::max(count, n / 2);
    if (count == 0) return;
    double v = entry_;
    for (std::size_t i = 0; i < count; ++i) {
        const Pending& p = window_[i];
        const double exit = std::min(lowest_[i + 1], std::sqrt(v * v + two_a * p.length_mm));
        commit(p, v, exit);
        v = exit;
    }
    entry_ = v;
    window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(count));
}

void MachineTimer::commit(const Pending& p, double entry, double exit) {
    const double t = trapezoid_s(p.length_mm, entry, exit, p.top);
    switch (p.kind) {
        case MotionKind::Cut:
            time_.cutting_s += t;
            time_.torch_cutting_s += t * p.torches;
            break;
        case MotionKind::Mark: time_.marking_s += t; break;
        case MotionKind::Rapid: time_.rapid_s += t; break;
        case MotionKind::Travel: time_.travel_s += t; break;
    }
    time_.acceleration_s += t - p.length_mm / p.feed;
}

// The time of a motion of `length_mm` from speed v0 to v1 (mm/s), at most `top`: a trapezoid (accelerate, cruise
// at the top speed, decelerate) or, when the top is not reached, a triangle.
double MachineTimer::trapezoid_s(double length_mm, double v0, double v1, double top) const {
    const double a = accel_;
    const double peak_squared = a * length_mm + 0.5 * (v0 * v0 + v1 * v1);
    if (peak_squared >= top * top) {
        const double ramps_mm = (2 * top * top - v0 * v0 - v1 * v1) / (2 * a);
        return (2 * top - v0 - v1) / a + (length_mm - ramps_mm) / top;
    }
    const double peak = std::max({std::sqrt(peak_squared), v0, v1});
    return (2 * peak - v0 - v1) / a;
}

void MachineTimer::finish() {
    stop();
    time_.acceleration_s = std::max(time_.acceleration_s, 0.0);
    time_.total_s = time_.cutting_s + time_.marking_s + time_.rapid_s + time_.travel_s + time_.pierce_s + time_.dwell_s;
}

}  // namespace essi
