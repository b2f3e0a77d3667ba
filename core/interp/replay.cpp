// Running a tape again for one more sink: replay_tape, the machine-time planner's motions (planned_motions) and
// the seconds of each motion (motion_seconds).
#include <algorithm>

#include "essi/interp.hpp"
#include "essi/stats.hpp"

namespace essi {

namespace {

// Reads the tape a chunk at a time and runs it (the one read-and-run loop of a replay).
void run_tape(std::string_view bytes, const Profile& profile, InputFormat format, Interpreter& interpreter) {
    TapeReader reader(bytes, profile, format);
    Tape chunk;
    while (reader.read_chunk(chunk, kReplayChunkBlocks)) interpreter.run(chunk);
    interpreter.finish();
}

// The source line of every motion, in order.
class MotionLines final : public MotionSink {
public:
    void on_motion(const MotionRecord& m) override { lines.push_back(m.line); }
    void on_line(const UnitLine& l) override { lines.push_back(l.line); }
    void on_event(const MachineEvent&) override {}
    std::vector<std::uint32_t> lines;
};

}  // namespace

void replay_tape(std::string_view bytes, const Profile& profile, InputFormat format, MotionSink& sink) {
    std::vector<Diagnostic> ignored;  // (the check has them)
    Interpreter interpreter(bytes, profile, sink, ignored);
    run_tape(bytes, profile, format, interpreter);
}

std::vector<PlannedMotion> planned_motions(std::string_view bytes, const Profile& profile, InputFormat format) {
    std::vector<PlannedMotion> out;
    if (!profile.accel_mm_s2) return out;
    StatsSink stats(profile);
    stats.trace_machine_time(&out);
    replay_tape(bytes, profile, format, stats);
    stats.finish();
    return out;
}

std::vector<float> motion_seconds(std::string_view bytes, const Profile& profile, InputFormat format) {
    std::vector<PlannedMotion> parts;  // of the time, on their lines
    StatsSink stats(profile, &parts);
    MotionLines motions;
    std::vector<Diagnostic> ignored;
    Interpreter interpreter(bytes, profile, stats, &motions, ignored);
    run_tape(bytes, profile, format, interpreter);
    stats.finish();
    const std::vector<std::uint32_t>& lines = motions.lines;  // (in line order: the program runs top to bottom)
    std::vector<float> out(lines.size());
    if (lines.empty()) return out;
    for (const PlannedMotion& p : parts) {
        const auto at = static_cast<std::size_t>(std::lower_bound(lines.begin(), lines.end(), p.line) - lines.begin());
        out[std::min(at, lines.size() - 1)] += p.seconds;
    }
    return out;
}

}  // namespace essi
