// Running a tape again for one more sink: replay_tape, and the machine-time planner's motions (planned_motions).
#include "essi/interp.hpp"
#include "essi/stats.hpp"

namespace essi {

void replay_tape(std::string_view bytes, const Profile& profile, InputFormat format, MotionSink& sink) {
    std::vector<Diagnostic> ignored;  // (the check has them)
    Interpreter interpreter(bytes, profile, sink, ignored);
    TapeReader reader(bytes, profile, format);
    Tape chunk;
    while (reader.read_chunk(chunk, kReplayChunkBlocks)) interpreter.run(chunk);
    interpreter.finish();
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

}  // namespace essi
