// Statistics over the motion stream (§9) and the whole check pipeline: read -> interp -> stats.
#include "essi/report.hpp"

#include <algorithm>

#include "essi/interp.hpp"
#include "essi/read.hpp"

namespace essi {

void StatsSink::on_motion(const MotionRecord& m) {
    ++stats_.motions;
    switch (m.kind) {
        case MotionKind::Cut:
            stats_.cut_length_mm += m.length_mm;
            stats_.cut_bbox.add(bounding_box(m));
            break;
        case MotionKind::Mark: stats_.mark_length_mm += m.length_mm; break;
        case MotionKind::Rapid:
            stats_.rapid_length_mm += m.length_mm;
            stats_.travel_length_mm += m.length_mm;
            break;
        case MotionKind::Travel: stats_.travel_length_mm += m.length_mm; break;
    }
    if (m.curve == CurveKind::Line) {
        stats_.motion_bbox.add(m.start);
        stats_.motion_bbox.add(m.end);
    } else {
        stats_.motion_bbox.add(bounding_box(m));
    }
    if (m.feed_mm_min > 0) stats_.estimated_time_s += m.length_mm / m.feed_mm_min * 60.0;
    if (m.head == 1) stats_.end_position = m.end;
}

void StatsSink::on_event(const MachineEvent& e) {
    if (e.kind == EventKind::Dwell) stats_.estimated_time_s += e.value;
    const bool was_cutting = (tools_ & kCuttingTools) != 0;
    const bool cutting = (e.tools_after & kCuttingTools) != 0;
    if (!was_cutting && cutting) {
        ++stats_.pierces;
        stats_.estimated_time_s += profile_.pierce_time_s;
    }
    tools_ = e.tools_after;
}

bool CheckResult::ok() const { return count(Severity::Error) == 0; }

std::size_t CheckResult::count(Severity s) const {
    return static_cast<std::size_t>(
        std::count_if(diagnostics.begin(), diagnostics.end(), [&](const Diagnostic& d) { return d.severity == s; }));
}

unsigned long long count_program_blocks(const Tape& tape) {
    unsigned long long n = 0;
    const std::size_t end = tape.end_block();
    for (std::size_t i = 0; i < end; ++i)
        if (tape.block(i).kind != BlockKind::Comment) ++n;
    return n;
}

void sort_diagnostics(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        if (a.line != b.line) return a.line < b.line;
        return a.column < b.column;
    });
}

CheckResult check_tape(std::string_view bytes, const Profile& profile) {
    CheckResult result;
    const Tape tape = read_tape(bytes, profile);
    result.diagnostics = tape.diagnostics();
    StatsSink sink(profile);
    interpret(tape, bytes, profile, sink, result.diagnostics);
    result.stats = sink.stats();
    result.stats.blocks = count_program_blocks(tape);
    sort_diagnostics(result.diagnostics);
    return result;
}

}  // namespace essi
