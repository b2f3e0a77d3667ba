// The machine time with acceleration: a look-ahead planner over the torch's path (essi/machine_time.hpp).
#include "essi/machine_time.hpp"

#include <algorithm>
#include <cmath>

#include "essi/geom.hpp"

namespace essi {
namespace {

// The radius of curvature a curve's top speed is taken at when it is smaller (mm): a compensated arc whose
// radius shrinks to 0 at one end (E306) still has a speed.
constexpr double kMinCurvatureRadiusMm = 1e-3;

}  // namespace

MachineTimer::MachineTimer(double accel_mm_s2, double junction_deviation_mm)
    : accel_(accel_mm_s2), accel_deviation_(accel_mm_s2 * junction_deviation_mm),
      half_inverse_accel_(0.5 / accel_mm_s2), window_(kMachineTimeWindow), lowest_(kMachineTimeWindow + 1) {}

// An arc or a parabola: its top speed is also √(a·r) at its smallest radius of curvature r.
void MachineTimer::curve(const MotionRecord& m, std::uint8_t torches) {
    if (m.curve != CurveKind::Arc) return parabola(m, torches);
    const double r = std::max(std::min(m.radius, m.end_radius), kMinCurvatureRadiusMm);  // (min_curvature_radius)
    add(m.kind, m.length_mm, std::min(m.feed_mm_min / 60, std::sqrt(accel_ * r)),
        arc_tangent(m.start, m.centre, m.ccw, m.radius), arc_tangent(m.end, m.centre, m.ccw, m.end_radius), torches,
        m.head, m.block, m.line);
}

void MachineTimer::parabola(const MotionRecord& m, std::uint8_t torches) {
    const double r = std::max(min_curvature_radius(m), kMinCurvatureRadiusMm);
    add(m.kind, m.length_mm, std::min(m.feed_mm_min / 60, std::sqrt(accel_ * r)), start_tangent(m), end_tangent(m),
        torches, m.head, m.block, m.line);
}

void MachineTimer::line(MotionKind kind, Point start, Point end, double length_mm, double feed_mm_min,
                        std::uint32_t line) {
    if (!(length_mm > kMachineTimeMinLength)) return;
    const double k = 1 / length_mm;
    const Point dir{(end.x - start.x) * k, (end.y - start.y) * k};
    add(kind, length_mm, feed_mm_min / 60, dir, dir, 1, 1, -1, line);
}

// A motion from speed v0 to v1 (mm/s): a trapezoid (accelerate, cruise at the top speed, decelerate) or, when the
// top is not reached, a triangle. The trapezoid's time is L/top plus what the two ramps lose against the top speed:
// (L + ((top − v0)² + (top − v1)²) / (2a)) / top.
[[gnu::always_inline]] inline void MachineTimer::commit(const Pending& p, double v0, double v1, double v0_squared,
                                                        double v1_squared) {
    const double peak_squared = accel_ * p.length_mm + 0.5 * (v0_squared + v1_squared);
    double t, peak;
    if (peak_squared >= p.top * p.top) {
        const double up = p.top - v0, down = p.top - v1;
        t = (p.length_mm + (up * up + down * down) * half_inverse_accel_) / p.top;
        peak = p.top;
    } else {
        peak = std::max({std::sqrt(peak_squared), v0, v1});
        t = (2 * peak - v0 - v1) / accel_;
    }
    if (trace_) [[unlikely]]
        trace_->push_back({p.line, static_cast<float>(t), static_cast<float>(peak * 60), p.kind});
    kind_s_[static_cast<int>(p.kind)] += t;
    if (p.torches > 1) [[unlikely]]
        extra_torches_s_ += t * (p.torches - 1);
}

// The backward pass gives each junction i the most its speed may be when the machine can still brake to the end
// of the window: lowest_ when it stops there, `high` when it may go on at the last motion's top speed. Where
// both agree (at the latest at a standstill) the rest of the tape cannot change it, and they agree at every
// junction before. The forward pass then gives each committed motion its entry and exit: a motion is committed
// when the junction at its end is final, or when the window is full and fewer than half of its motions are (then
// they are planned as if the machine stopped after the window). The passes work on squared speeds.
void MachineTimer::plan(bool stops) {
    const std::size_t n = pending_;
    if (n == 0) return;
    const double two_a = 2 * accel_;
    double low = 0, high = stops ? 0.0 : window_[n - 1].top * window_[n - 1].top;
    lowest_[n] = 0;
    std::size_t i = n;
    for (; i > 0 && low != high; --i) {  // until the two agree
        const Pending& p = window_[i - 1];
        low = std::min(p.entry_max_squared, low + two_a * p.length_mm);
        high = std::min(p.entry_max_squared, high + two_a * p.length_mm);
        lowest_[i - 1] = low;
    }
    std::size_t count = low == high ? i : 0;  // motions 0 .. count-1 end at a final junction
    for (; i > 0; --i) {
        const Pending& p = window_[i - 1];
        low = std::min(p.entry_max_squared, low + two_a * p.length_mm);
        lowest_[i - 1] = low;
    }
    if (!stops && n >= kMachineTimeWindow) count = std::max(count, n / 2);
    if (count == 0) return;
    double v = entry_, v_squared = v * v;
    for (std::size_t k = 0; k < count; ++k) {
        const Pending& p = window_[k];
        const double exit_squared = std::min(lowest_[k + 1], v_squared + two_a * p.length_mm);
        const double exit = std::sqrt(exit_squared);
        commit(p, v, exit, v_squared, exit_squared);
        v = exit;
        v_squared = exit_squared;
    }
    entry_ = v;
    std::copy(window_.begin() + static_cast<std::ptrdiff_t>(count), window_.begin() + static_cast<std::ptrdiff_t>(n),
              window_.begin());
    pending_ = n - count;
}

void MachineTimer::finish(double estimated_time_s) {
    plan(true);
    time_.rapid_s = kind_s_[static_cast<int>(MotionKind::Rapid)];
    time_.travel_s = kind_s_[static_cast<int>(MotionKind::Travel)];
    time_.cutting_s = kind_s_[static_cast<int>(MotionKind::Cut)];
    time_.marking_s = kind_s_[static_cast<int>(MotionKind::Mark)];
    time_.torch_cutting_s = time_.cutting_s + extra_torches_s_;
    const double motions_s = time_.cutting_s + time_.marking_s + time_.rapid_s + time_.travel_s;
    time_.acceleration_s = std::max(motions_s - (estimated_time_s - time_.pierce_s - time_.dwell_s), 0.0);
    time_.total_s = motions_s + time_.pierce_s + time_.dwell_s;
}

}  // namespace essi
