// Statistics over the motion stream (§9) and the whole check pipeline: read -> interp -> stats.
#include "essi/report.hpp"

#include <algorithm>

#include "essi/interp.hpp"
#include <memory>
#include "essi/lines.hpp"
#include "essi/read.hpp"

namespace essi {

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

namespace {

// The cut plan's diagnostics name a block by its line: their column is where the block begins (the line's first
// byte that is not a blank). The lines are indexed only when there is such a diagnostic.
void block_columns(std::string_view bytes, std::vector<Diagnostic>& diagnostics) {
    if (diagnostics.empty()) return;
    LineIndex lines;
    lines.build(bytes);
    for (Diagnostic& d : diagnostics) {
        if (d.line == 0 || d.column > 0) continue;
        const std::string_view text = lines.line(bytes, d.line);
        const std::size_t first = text.find_first_not_of(" \t");
        d.column = static_cast<std::uint32_t>(first == std::string_view::npos ? 0 : first) + 1;
    }
}

}  // namespace

// ---- TapeChecker ----

TapeChecker::TapeChecker(std::string_view bytes, const Profile& profile, MotionSink* also)
    : bytes_(bytes), stats_(profile), plan_(profile), both_(also ? std::make_unique<PlanThenAlso>(plan_, *also) : nullptr),
      interpreter_(bytes, profile, stats_, both_ ? static_cast<MotionSink*>(both_.get()) : &plan_, result_.diagnostics) {}

TapeChecker::~TapeChecker() = default;

void TapeChecker::check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures) {
    result_.diagnostics.insert(result_.diagnostics.end(), chunk.diagnostics().begin(), chunk.diagnostics().end());
    interpreter_.run(chunk, measures);
    blocks_ += chunk.program_blocks();
}

void TapeChecker::finish_reading() {
    interpreter_.finish();
    plan_.end_input();
    result_.stats = stats_.stats();
    result_.stats.blocks = blocks_;
}

CheckResult TapeChecker::finish() {
    finish_reading();
    std::vector<Diagnostic> plan = plan_findings();
    result_.diagnostics.insert(result_.diagnostics.end(), std::make_move_iterator(plan.begin()),
                               std::make_move_iterator(plan.end()));
    sort_diagnostics(result_.diagnostics);
    return std::move(result_);
}

CheckResult TapeChecker::finish_before_plan() {
    finish_reading();
    sort_diagnostics(result_.diagnostics);
    return std::move(result_);
}

std::vector<Diagnostic> TapeChecker::plan_findings() {
    std::vector<Diagnostic> plan = plan_.finish();
    block_columns(bytes_, plan);
    return plan;
}

CheckResult check_tape(std::string_view bytes, const Profile& profile, InputFormat format) {
    // A chunk at a time: each chunk is interpreted while it is still in cache, and the whole tape is
    // never held (a 100 MB tape would cost some 200 MB of blocks).
    TapeChecker checker(bytes, profile);
    TapeReader reader(bytes, profile, format);
    Tape chunk;
    while (reader.read_chunk(chunk, kCheckChunkBlocks)) checker.check_chunk(chunk);
    CheckResult r = checker.finish();
    r.input = format;
    r.profile = profile.name;
    return r;
}

void record_setup(CheckResult& result, const TapeSetup& setup) {
    result.input = setup.format;
    result.profile = setup.profile.name;
    result.auto_profile = setup.auto_profile;
    if (setup.auto_profile) result.dialect_evidence = setup.evidence;
    if (setup.note) {
        result.diagnostics.push_back(*setup.note);
        sort_diagnostics(result.diagnostics);
    }
}

CheckResult check_tape(std::string_view bytes, const TapeSetup& setup) {
    CheckResult r = check_tape(bytes, setup.profile, setup.format);
    record_setup(r, setup);
    return r;
}

}  // namespace essi
