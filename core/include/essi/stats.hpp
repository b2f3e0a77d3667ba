// The statistics of docs/semantics.md §9, accumulated from the motion stream. Defined here, inline, because
// the interpreter feeds them directly (not through the MotionSink's virtual calls) when they are its only
// sink: a call per motion and per function block of every tape that is checked.
#pragma once

#include <optional>

#include "essi/cost.hpp"
#include "essi/function_codes.hpp"
#include "essi/geom.hpp"
#include "essi/kerf.hpp"
#include "essi/machine_time.hpp"
#include "essi/motion.hpp"
#include "essi/placement.hpp"
#include "essi/profile.hpp"
#include "essi/wire.hpp"

namespace essi {

struct Stats {
    double cut_length_mm = 0;
    double cut_length_compensated_mm = 0;  // the torch's path while cutting (kerf compensation, §8)
    double mark_length_mm = 0;
    double travel_length_mm = 0;  // rapid and other tool-off motion
    double rapid_length_mm = 0;   // the rapid part of travel_length_mm
    unsigned long long pierces = 0;
    unsigned long long blocks = 0;  // program blocks read (comment lines and empty lines excluded)
    unsigned long long motions = 0;
    double estimated_time_s = 0;  // along the compensated path
    Box cut_bbox;                 // empty when nothing is cut (program coordinates)
    Box motion_bbox;              // all motion (program coordinates)
    Box machine_cut_bbox;         // the same in machine coordinates (§12: zero offset, plate rotation, tool offsets)
    Box machine_motion_bbox;      // ... and where the carriage goes when a tool offset is selected
    Point end_position;           // machine position at the end (head 1)
    std::optional<MachineTime> machine_time;   // with the profile's accel_mm_s2 (§9)
    std::optional<Cost> cost;                  // with the profile's costs
    std::optional<ConsumableUse> consumables;  // with the profile's consumables
};

// Statistics as bytes (essi/wire.hpp), and read back: false when the bytes end before them. (A new field of
// Stats, Cost or the others goes into stats_wire.cpp too: its test compares every field through the report.)
void save_stats(WireWriter& out, const Stats& s);
[[nodiscard]] bool restore_stats(WireReader& in, Stats& s);

// The time a motion of `length_mm` takes at `feed_mm_min` (none without a feed): what the statistics estimate
// along the compensated path.
[[nodiscard]] constexpr double motion_time_s(double length_mm, double feed_mm_min) {
    return feed_mm_min > 0 ? length_mm / feed_mm_min * 60.0 : 0.0;
}

// The statistics' time: the machine time with the profile's accel_mm_s2 (§9), else the estimate. What the cost is
// reckoned from, what the viewer's Statistics panel shows and what its playback lasts.
[[nodiscard]] inline double statistics_time_s(const Stats& s) {
    return s.machine_time ? s.machine_time->total_s : s.estimated_time_s;
}

// Where the pierces fall in the motion stream. A pierce is made when a cutting tool comes on (starts_cutting: the
// statistics count it and its time then); it is at the first motion after that, when that motion cuts (the
// viewer's marker). Tools that go off before any motion leave the pierce at none.
class PierceTracker {
public:
    // The tools on after an event: true when it makes a pierce.
    bool on_tools(std::uint8_t tools_after) {
        const bool pierce = starts_cutting(tools_, tools_after);
        tools_ = tools_after;
        if (pierce) [[unlikely]]
            pending_ = true;
        return pierce;
    }
    // A motion with `tools` on: true when it is where the pierce made before it is (the cutting tools still on).
    bool at_motion(std::uint8_t tools) {
        const bool here = pending_ && (tools & tools_ & kCuttingTools) != 0;
        pending_ = false;
        return here;
    }

private:
    std::uint8_t tools_ = 0;  // on before the current event
    bool pending_ = false;    // a pierce made, no motion since
};

// Accumulates statistics from the motion stream. The programmed motions give the lengths and boxes; their
// compensated path (a KerfPath inside, §8) gives the time and the compensated cut length. Call finish() after the
// last motion.
class StatsSink final : public MotionSink {
public:
    // `time_trace`: every part of the statistics' time (statistics_time_s) appended to it as it is counted, on the
    // source line it comes from: each motion of the torch's path (as the planner runs it with the profile's
    // accel_mm_s2, else at its feed), each pierce and each dwell (their peak_mm_min 0). Not in line order (the
    // planner's motions come when they are planned); the seconds add up to the statistics' time.
    explicit StatsSink(const Profile& profile, std::vector<PlannedMotion>* time_trace = nullptr)
        : profile_(profile), timed_(profile.accel_mm_s2 || profile.consumables || time_trace), torch_path_(stats_),
          machine_path_(*this), cutting_path_(*this),
          kerf_(profile.accel_mm_s2                 ? static_cast<MotionSink&>(machine_path_)
                : profile.consumables || time_trace ? static_cast<MotionSink&>(cutting_path_)
                                                    : torch_path_,
                profile.chord_tolerance_mm),
          placement_(profile), plain_(!placement_.turns()), time_trace_(time_trace) {
        if (profile.accel_mm_s2) [[unlikely]] {
            timer_.emplace(*profile.accel_mm_s2, profile.junction_deviation_mm);
            timer_->trace_into(time_trace);
        }
    }
    StatsSink(const StatsSink&) = delete;
    StatsSink& operator=(const StatsSink&) = delete;

    void on_motion(const MotionRecord& m) override {
        kerf_.motion(m);
        if (!plain_) [[unlikely]]
            add_machine_boxes(m);
        if (m.torches > 1 && m.kind == MotionKind::Cut) [[unlikely]] {
            add_torch_copies(m);
            return;
        }
        if (m.curve == CurveKind::Line) {
            add_programmed_line(m.kind, m.head, m.start, m.end, m.length_mm);
            return;
        }
        count_motion(m.kind, m.head, m.end, m.length_mm);
        // The exact box of a curve costs more than a line's: computed once, used for both boxes. An arc
        // inside the boxes so far (its ends and its whole circle are) changes neither: its exact box (the
        // extremes inside the sweep) is needed only when it may reach further.
        const bool cut = m.kind == MotionKind::Cut;
        if (m.curve == CurveKind::Arc) {
            const Box reach = arc_reach(m);
            if (stats_.motion_bbox.contains(reach) && (!cut || stats_.cut_bbox.contains(reach))) return;
        }
        add_box(bounding_box(m), cut);
    }
    // A straight line without compensation while none is open (kerf_open() false): what on_motion counts of
    // one. The interpreter calls it directly for the lines of a tape that is only checked, without their records;
    // `line`: its source line.
    [[gnu::always_inline]] void add_line(MotionKind kind, int head, Point start, Point end, double length_mm,
                                         double feed_mm_min, std::uint32_t line) {
        if (!plain_) [[unlikely]]
            add_machine_line(kind, start, end);
        add_programmed_line(kind, head, start, end, length_mm);
        TorchPath::add(stats_, kind, length_mm, feed_mm_min, 1);
        if (timed_) [[unlikely]]
            time_line(kind, start, end, length_mm, feed_mm_min, line);
    }
    void on_event(const MachineEvent& e) override {
        count_event(e.kind, e.value, e.tools_after, e.torches_after);
        if (timed_) [[unlikely]]
            time_event(e);
    }
    // What on_event counts of an event: the interpreter calls it directly, without making the event.
    // Several torches pierce together: each pierce counts, the pierce time once.
    void count_event(EventKind kind, double value, std::uint8_t tools_after, std::uint8_t torches = 1) {
        if (kind == EventKind::Dwell) stats_.estimated_time_s += value;
        if (pierces_.on_tools(tools_after)) {
            stats_.pierces += torches;
            stats_.estimated_time_s += profile_.pierce_time_s;
        }
    }
    // Whether the statistics follow the machine time or the consumables (the profile's accel_mm_s2 or
    // consumables): then every event, in order, goes to time_event besides count_event.
    [[nodiscard]] bool timed() const { return timed_; }
    // The machine time's and the consumables' side of an event, in the tape's order (time_change).
    void time_event(const MachineEvent& e) {
        if (affects_time(e.kind, e.code, timed_tools_, e.tools_after)) time_change(e);
    }
    // Whether an event can change the machine time or the consumables: all but a function that switches no tool,
    // other than 17, 18, 63 and 64 (most events). `tools_before`: the tools of the event before.
    [[nodiscard]] static bool affects_time(EventKind kind, unsigned code, std::uint8_t tools_before,
                                           std::uint8_t tools_after) {
        constexpr std::uint8_t kTools = kCuttingTools | kMarkingTools;
        return kind != EventKind::Function || ((tools_after ^ tools_before) & kTools) != 0 ||
               code - fn::kAccelerationControlOn <= 1u || code - fn::kCancelFunctions <= 1u;  // (17, 18; 63, 64)
    }

    // The tool offset in force from now on (11, 114, 12: the interpreter calls it): the carriage moves at once.
    void set_tool_offset(Point offset) {
        if (offset == tool_offset_) return;
        go_explicit();
        tool_offset_ = offset;
        if (stats_.motions > 0) add_machine_box(Box::of(machine_end(), machine_end()), false);
    }
    // The planner's motions appended to `out` as they are planned (MachineTimer::trace_into); none without the
    // profile's accel_mm_s2.
    void trace_machine_time(std::vector<PlannedMotion>* out) {
        if (timer_) timer_->trace_into(out);
    }
    // The end of the program: the compensated path's last piece; the machine boxes when they are the program's
    // moved.
    void finish() {
        kerf_.finish();
        if (plain_) {
            stats_.machine_cut_bbox = placement_.moved(stats_.cut_bbox, {});
            stats_.machine_motion_bbox = placement_.moved(stats_.motion_bbox, {});
        }
        if (timer_) [[unlikely]] {
            timer_->finish(stats_.estimated_time_s);
            stats_.machine_time = timer_->time();
        }
        if (profile_.costs || profile_.consumables) [[unlikely]]
            reckon_costs();  // (after the machine time)
    }
    // Whether a compensated piece is open: a line without compensation must then come as a record (it is the
    // exit from compensation).
    [[nodiscard]] bool kerf_open() const { return kerf_.open(); }
    [[nodiscard]] bool has_gouges() const { return kerf_.has_gouges(); }
    [[nodiscard]] std::vector<KerfGouge> take_gouges() { return kerf_.take_gouges(); }

    [[nodiscard]] const Stats& stats() const { return stats_; }
    Stats& stats() { return stats_; }

private:
    // The compensated path: its time and its cut length (each torch's).
    class TorchPath final : public MotionSink {
    public:
        explicit TorchPath(Stats& stats) : stats_(stats) {}
        void on_motion(const MotionRecord& m) override {
            add(stats_, m.kind, m.length_mm, m.feed_mm_min, m.kind == MotionKind::Cut ? m.torches : 1);
        }
        // Returns the motion's time.
        static double add(Stats& s, MotionKind kind, double length_mm, double feed_mm_min, int torches) {
            if (kind == MotionKind::Cut) s.cut_length_compensated_mm += length_mm * torches;
            const double t = motion_time_s(length_mm, feed_mm_min);
            s.estimated_time_s += t;
            return t;
        }
        // A part of the time, appended to `out` (the time trace).
        static void traced(std::vector<PlannedMotion>* out, MotionKind kind, double feed_mm_min, std::uint32_t line,
                           double seconds) {
            out->push_back({line, static_cast<float>(seconds), static_cast<float>(feed_mm_min), kind});
        }

    private:
        Stats& stats_;
    };
    // The compensated path for the machine time (the profile's accel_mm_s2): its motions go to the timer too.
    class MachineTorchPath final : public MotionSink {
    public:
        explicit MachineTorchPath(StatsSink& owner) : owner_(owner) {}
        void on_motion(const MotionRecord& m) override {
            TorchPath::add(owner_.stats_, m.kind, m.length_mm, m.feed_mm_min,
                           m.kind == MotionKind::Cut ? m.torches : 1);
            owner_.timer_->motion(m);
        }

    private:
        StatsSink& owner_;
    };
    // The compensated path for the consumables or the time trace without a machine time: the cutting time at the
    // feed, once per torch.
    class CuttingTimeTorchPath final : public MotionSink {
    public:
        explicit CuttingTimeTorchPath(StatsSink& owner) : owner_(owner) {}
        void on_motion(const MotionRecord& m) override {
            const int torches = m.kind == MotionKind::Cut ? m.torches : 1;
            const double t = TorchPath::add(owner_.stats_, m.kind, m.length_mm, m.feed_mm_min, torches);
            if (m.kind == MotionKind::Cut) owner_.torch_cutting_s_ += t * torches;
            if (owner_.time_trace_) [[unlikely]]
                TorchPath::traced(owner_.time_trace_, m.kind, m.feed_mm_min, m.line, t);
        }

    private:
        StatsSink& owner_;
    };
    [[gnu::noinline]] void time_line(MotionKind kind, Point start, Point end, double length_mm, double feed_mm_min,
                                     std::uint32_t line) {
        if (timer_) return timer_->line(kind, start, end, length_mm, feed_mm_min, line);
        const double t = motion_time_s(length_mm, feed_mm_min);
        if (kind == MotionKind::Cut) torch_cutting_s_ += t;
        if (time_trace_) TorchPath::traced(time_trace_, kind, feed_mm_min, line, t);
    }

    // An event that may change the time (affects_time): its dwell while cutting (the consumables), its pierce and
    // dwell time, and whether the machine stands still there (every such event but an 83 and a 63/64 that
    // switches no tool off: a tool on or off, a dwell, a stop, the end, 17 and 18) and stops at the end of every
    // block from there on (17 until 18, or a 63/64 that cancels the stored functions). The timer takes those two
    // as a pause where the torch's path reaches the place: before the next motion, or, while a compensated piece
    // is open, before the first piece of a later block.
    void time_change(const MachineEvent& e) {
        constexpr std::uint8_t kTools = kCuttingTools | kMarkingTools;
        const std::uint8_t before = timed_tools_;
        timed_tools_ = e.tools_after;
        bool stop = ((e.tools_after ^ before) & kTools) != 0;
        if (e.kind == EventKind::Function) [[likely]] {
            const unsigned code = e.code;
            if (code - fn::kAccelerationControlOn <= 1u || code - fn::kCancelFunctions <= 1u) [[unlikely]] {
                const bool control = code <= fn::kAccelerationControlOff;  // (17, 18; else 63, 64)
                block_stops_ = code == fn::kAccelerationControlOn;
                stop = stop || control;
            }
        } else if (e.kind != EventKind::ZeroOffset) {
            stop = true;
            if (e.kind == EventKind::Dwell) {
                if (e.tools_after & kCuttingTools) cutting_dwell_s_ += e.value * e.torches_after;
                if (timer_) timer_->add_dwell(e.value);
                if (time_trace_) TorchPath::traced(time_trace_, MotionKind::Travel, 0, e.line, e.value);
            }
        }
        const bool pierce = starts_cutting(before, e.tools_after);  // (PierceTracker's rule)
        if (pierce && time_trace_) TorchPath::traced(time_trace_, MotionKind::Cut, 0, e.line, profile_.pierce_time_s);
        if (!timer_) return;
        if (pierce) timer_->add_pierce(profile_.pierce_time_s);
        timer_->pause(stop, block_stops_, kerf_.open() ? std::int64_t{kerf_.open_block()} : -1);
    }
    // The cost and the consumables, from the statistics (the machine time when there is one).
    void reckon_costs() {
        const bool machine = stats_.machine_time.has_value();
        if (profile_.costs) {
            stats_.cost = reckon_cost(*profile_.costs, profile_.material, profile_.plate,
                                      {statistics_time_s(stats_), machine, stats_.pierces, stats_.cut_length_mm});
        }
        if (profile_.consumables) {
            const double cutting = machine ? stats_.machine_time->torch_cutting_s : torch_cutting_s_;
            const double arc_on =
                cutting + static_cast<double>(stats_.pierces) * profile_.pierce_time_s + cutting_dwell_s_;
            stats_.consumables = consumable_use(*profile_.consumables, stats_.pierces, arc_on);
        }
    }

    // Machine boxes (§12). While the plate is not turned and no tool offset was ever selected ("plain"), they are
    // the program's moved by the zero offset, worked out once at the end; from the first tool offset on, every
    // motion adds its machine box.
    void go_explicit() {
        if (!plain_) return;
        plain_ = false;
        stats_.machine_cut_bbox = placement_.moved(stats_.cut_bbox, {});
        stats_.machine_motion_bbox = placement_.moved(stats_.motion_bbox, {});
    }
    [[nodiscard]] Point machine_end() const { return placement_.machine(stats_.end_position, tool_offset_); }
    void add_machine_box(const Box& b, bool cut) {
        stats_.machine_motion_bbox.add(b);
        if (cut) stats_.machine_cut_bbox.add(b);
    }
    void add_machine_line(MotionKind kind, Point start, Point end) {
        add_machine_box(Box::of(placement_.machine(start, tool_offset_), placement_.machine(end, tool_offset_)),
                        kind == MotionKind::Cut);
    }
    void add_machine_boxes(const MotionRecord& m) {
        const bool cut = m.kind == MotionKind::Cut;
        add_machine_box(placement_.machine_box(m, tool_offset_), cut);
        if (m.torches > 1 && cut) {
            MotionRecord last = m;
            const Point far = torch_copy({0, 0}, m.torch_step, m.torches - 1);
            last.start = torch_copy(m.start, far, 1);
            last.end = torch_copy(m.end, far, 1);
            last.centre = torch_copy(m.centre, far, 1);
            last.parabola.vertex = torch_copy(m.parabola.vertex, far, 1);
            add_machine_box(placement_.machine_box(last, tool_offset_), true);
        }
    }

    // A cut made by several torches at once: its length once per torch, the box of every copy.
    void add_torch_copies(const MotionRecord& m) {
        ++stats_.motions;
        stats_.cut_length_mm += m.length_mm * m.torches;
        if (m.head == 1) stats_.end_position = m.end;
        const Box b = m.curve == CurveKind::Line ? Box::of(m.start, m.end) : bounding_box(m);
        const Point far = torch_copy({0, 0}, m.torch_step, m.torches - 1);
        add_box(b, true);  // the copies lie between the first and the last
        add_box(Box{b.min_x + far.x, b.min_y + far.y, b.max_x + far.x, b.max_y + far.y, false}, true);
    }
    [[gnu::always_inline]] void add_programmed_line(MotionKind kind, int head, Point start, Point end,
                                                    double length_mm) {
        count_motion(kind, head, end, length_mm);
        add_box(Box::of(start, end), kind == MotionKind::Cut);  // a line's box is its end points
    }
    // Everything of a programmed motion but its box: the count, the length by kind, the end position.
    void count_motion(MotionKind kind, int head, Point end, double length_mm) {
        ++stats_.motions;
        switch (kind) {
            case MotionKind::Cut: stats_.cut_length_mm += length_mm; break;
            case MotionKind::Mark: stats_.mark_length_mm += length_mm; break;
            case MotionKind::Rapid:
                stats_.rapid_length_mm += length_mm;
                stats_.travel_length_mm += length_mm;
                break;
            case MotionKind::Travel: stats_.travel_length_mm += length_mm; break;
        }
        if (head == 1) stats_.end_position = end;
    }
    void add_box(const Box& box, bool cut) {
        stats_.motion_bbox.add(box);
        if (cut) stats_.cut_bbox.add(box);
    }
    // A box that holds the whole arc: its ends, and its circle at the larger of its two radii widened a little,
    // so that no rounding of the exact box's extremes (centre + radius) can pass it.
    static Box arc_reach(const MotionRecord& m) {
        constexpr double kRelativeSlack = 1e-9;
        const double r = (m.radius > m.end_radius ? m.radius : m.end_radius) * (1 + kRelativeSlack);
        Box reach = Box::of(m.start, m.end);
        reach.add(Box{m.centre.x - r, m.centre.y - r, m.centre.x + r, m.centre.y + r, false});
        return reach;
    }

    const Profile& profile_;
    Stats stats_;
    PierceTracker pierces_;
    // The machine time (with the profile's accel_mm_s2), what it follows of the events, and the consumables' times.
    bool timed_;  // accel_mm_s2, consumables or the time trace
    std::optional<MachineTimer> timer_;
    double torch_cutting_s_ = 0;  // the cutting motions at their feed, once per torch
    double cutting_dwell_s_ = 0;  // dwells while a cutting tool is on, once per torch
    std::uint8_t timed_tools_ = 0;
    bool block_stops_ = false;
    TorchPath torch_path_;
    MachineTorchPath machine_path_;
    CuttingTimeTorchPath cutting_path_;
    KerfPath kerf_;
    Placement placement_;
    bool plain_;
    Point tool_offset_;
    std::vector<PlannedMotion>* time_trace_;  // (the constructor's)
};

}  // namespace essi
