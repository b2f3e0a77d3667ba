// Phase 2, interp: walks the blocks with the machine state (tools, modes, transforms 21-28, 81/82/83,
// kerf, feed, heads) and emits the motion stream to a sink (docs/semantics.md §3-§10, §12).
#pragma once

#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/machine_time.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"

namespace essi {

namespace detail {
class Machine;
}
class StatsSink;

// What an arc block measures from its words alone when it is incremental (its start is the tape's (0,0)), in
// the tape frame and unit increments: two square roots and an atan2, worth working out on another thread.
// 21-28 only swap and mirror the axes: radii stay, a mirror turns the sweep's sign. The interpreter computes
// the same numbers the same way when it is not given them (and in absolute mode, where the start is not (0,0)).
struct MotionMeasure {
    double r0 = 0, r1 = 0;  // radius at the start and at the end
    double sweep = 0;       // signed angle in the tape's sense (TC), +-2 pi for a full circle
};
// The measures of a chunk's arc blocks (motions of 5 words) before its end_block(), in block order, into `out`.
void measure_motions(const Tape& chunk, std::vector<MotionMeasure>& out);

// The interpreter's formulas on integer points in unit increments (any one frame), for callers that rebuild a
// motion's numbers from its integer points (the viewer's compact document): the same numbers to the bit.
// A straight length (a line's, times the unit):
[[nodiscard]] double units_length(long long dx, long long dy);
// An arc's radii and sweep from its start (sx, sy), end and centre, `ccw` its sense in that frame:
[[nodiscard]] MotionMeasure measure_arc(long long sx, long long sy, long long ex, long long ey, long long cx,
                                        long long cy, bool ccw);

// The machine, fed a chunk of blocks at a time (TapeReader), or a whole tape. Diagnostics of
// interpretation and geometry are appended to `diagnostics` (columns computed from `source`).
class Interpreter {
public:
    Interpreter(std::string_view source, const Profile& profile, MotionSink& sink,
                std::vector<Diagnostic>& diagnostics);
    // The statistics and, when given, one more sink `also` (what TapeChecker runs): the statistics are fed
    // directly, `also` gets every motion and event, its straight lines of head 1 as MotionSink::on_line.
    Interpreter(std::string_view source, const Profile& profile, StatsSink& stats, MotionSink* also,
                std::vector<Diagnostic>& diagnostics);
    ~Interpreter();
    Interpreter(const Interpreter&) = delete;
    Interpreter& operator=(const Interpreter&) = delete;
    // Runs the program blocks of `chunk` (chunks must come in tape order). `measures`, when given, is
    // measure_motions(chunk) worked out ahead (e.g. on the reading thread): the same numbers, not computed twice.
    void run(const Tape& chunk, std::span<const MotionMeasure> measures = {});
    // After the last chunk: reports what the program opened and never closed.
    void finish();
    // From now on, what went to the one more sink `also` goes to `also` here (a checker that constructed it with
    // one: e.g. a chunk's stream for the cut plan kept in a MotionBuffer).
    void send_also_to(MotionSink& also);

private:
    std::unique_ptr<detail::Machine> machine_;
};

// Runs the program in `tape` and sends every motion and event to `sink`, in program order. Diagnostics of
// interpretation and geometry are appended to `diagnostics` (with columns computed from `source`).
void interpret(const Tape& tape, std::string_view source, const Profile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diagnostics);

// Blocks read and run at a time by replay_tape.
constexpr std::size_t kReplayChunkBlocks = 8192;

// Reads and runs a tape again, a chunk at a time, for what one more sink makes of it (the check has its
// diagnostics: they are left out here).
void replay_tape(std::string_view bytes, const Profile& profile, InputFormat format, MotionSink& sink);

// Every motion of the tape's torch path as the machine-time planner runs it (essi/machine_time.hpp), in order:
// empty when the profile has no accel_mm_s2. Reads and runs the tape again.
[[nodiscard]] std::vector<PlannedMotion> planned_motions(std::string_view bytes, const Profile& profile,
                                                         InputFormat format);

// The seconds of every motion of the tape's motion stream (what a MotionSink gets, in order) by the statistics'
// time (statistics_time_s: planned with the profile's accel_mm_s2, else at the feeds): what its source line and the
// lines without a motion before it take (its part of the torch's path, pierces, dwells); what comes after the last
// motion is the last one's. They add up to the statistics' time. Reads and runs the tape again.
[[nodiscard]] std::vector<float> motion_seconds(std::string_view bytes, const Profile& profile, InputFormat format);

// The coordinate mapping of functions 21-28 (§7): machine = M * tape.
struct AxisMapping {
    int xx = 1, xy = 0, yx = 0, yy = 1;  // machine x = xx*X + xy*Y; machine y = yx*X + yy*Y
    [[nodiscard]] bool mirrors() const { return xx * yy - xy * yx < 0; }
    [[nodiscard]] Point apply(double X, double Y) const { return {xx * X + xy * Y, yx * X + yy * Y}; }
    // The inverse (the transpose: M is orthogonal).
    [[nodiscard]] Point invert(double x, double y) const { return {xx * x + yx * y, xy * x + yy * y}; }
};
// The mapping selected by function 21..28.
[[nodiscard]] AxisMapping axis_mapping(int function_code);

}  // namespace essi
