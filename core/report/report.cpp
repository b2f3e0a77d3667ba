// Statistics over the motion stream (§9) and the whole check pipeline: read -> interp -> stats.
#include "essi/report.hpp"

#include <algorithm>

#include "essi/interp.hpp"
#include <memory>
#include "essi/read.hpp"

namespace essi {

void StatsSink::on_motion(const MotionRecord& m) {
    ++stats_.motions;
    // A line's box is its end points; the exact box of a curve costs more: computed once, used twice.
    if (m.curve == CurveKind::Line) {
        stats_.motion_bbox.add(m.start);
        stats_.motion_bbox.add(m.end);
        if (m.kind == MotionKind::Cut) {
            stats_.cut_bbox.add(m.start);
            stats_.cut_bbox.add(m.end);
        }
    } else {
        const Box box = bounding_box(m);
        stats_.motion_bbox.add(box);
        if (m.kind == MotionKind::Cut) stats_.cut_bbox.add(box);
    }
    switch (m.kind) {
        case MotionKind::Cut:
            stats_.cut_length_mm += m.length_mm;
            break;
        case MotionKind::Mark: stats_.mark_length_mm += m.length_mm; break;
        case MotionKind::Rapid:
            stats_.rapid_length_mm += m.length_mm;
            stats_.travel_length_mm += m.length_mm;
            break;
        case MotionKind::Travel: stats_.travel_length_mm += m.length_mm; break;
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

void sort_diagnostics(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        if (a.line != b.line) return a.line < b.line;
        return a.column < b.column;
    });
}

// ---- TapeChecker ----

// Sends every record to the statistics and, when asked, to one more sink (the viewer's buffers).
class TapeChecker::Tee : public MotionSink {
public:
    Tee(const Profile& profile, MotionSink* also) : stats(profile), also_(also) {}
    // Where the interpreter sends its records: the statistics alone need no hop through the tee.
    MotionSink& target() { return also_ ? static_cast<MotionSink&>(*this) : stats; }
    void on_motion(const MotionRecord& m) override {
        stats.on_motion(m);
        if (also_) also_->on_motion(m);
    }
    void on_event(const MachineEvent& e) override {
        stats.on_event(e);
        if (also_) also_->on_event(e);
    }
    StatsSink stats;
private:
    MotionSink* also_;
};

TapeChecker::TapeChecker(std::string_view bytes, const Profile& profile, MotionSink* also)
    : tee_(std::make_unique<Tee>(profile, also)), interpreter_(bytes, profile, tee_->target(), result_.diagnostics) {}

TapeChecker::~TapeChecker() = default;

void TapeChecker::check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures) {
    result_.diagnostics.insert(result_.diagnostics.end(), chunk.diagnostics().begin(), chunk.diagnostics().end());
    interpreter_.run(chunk, measures);
    blocks_ += chunk.program_blocks();
}

CheckResult TapeChecker::finish() {
    interpreter_.finish();
    result_.stats = tee_->stats.stats();
    result_.stats.blocks = blocks_;
    sort_diagnostics(result_.diagnostics);
    return std::move(result_);
}

CheckResult check_tape(std::string_view bytes, const Profile& profile) {
    // A chunk at a time: each chunk is interpreted while it is still in cache, and the whole tape is
    // never held (a 100 MB tape would cost some 200 MB of blocks).
    TapeChecker checker(bytes, profile);
    TapeReader reader(bytes, profile);
    Tape chunk;
    while (reader.read_chunk(chunk, kCheckChunkBlocks)) checker.check_chunk(chunk);
    return checker.finish();
}

}  // namespace essi
