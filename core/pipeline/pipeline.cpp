// The check pipeline (essi/pipeline.hpp): read -> interp (statistics) -> plan -> report.
#include "essi/pipeline.hpp"

#include <algorithm>
#include <memory>

#include "essi/lines.hpp"

namespace essi {

namespace {

// The cut plan's diagnostics name a block by its line: their column is where the block begins (the line's first
// byte that is not a blank). The lines are walked once, up to the last such diagnostic's, in the order of their
// lines (LineIndex::line's rule, without an index: a tape with a finding on every part has one a few lines apart).
void block_columns(std::string_view bytes, std::vector<Diagnostic>& diagnostics) {
    std::vector<std::uint64_t> wanted;  // the diagnostics without a column: line << 32 | index
    for (std::size_t k = 0; k < diagnostics.size(); ++k)
        if (diagnostics[k].line > 0 && diagnostics[k].column == 0)
            wanted.push_back(std::uint64_t{diagnostics[k].line} << 32 | k);
    std::sort(wanted.begin(), wanted.end());
    std::uint32_t line = 1;
    std::size_t at = 0;  // where `line` starts (bytes.size(): past the last line)
    for (const std::uint64_t key : wanted) {
        Diagnostic& d = diagnostics[static_cast<std::size_t>(key & 0xFFFFFFFFu)];
        for (; line < d.line && at < bytes.size(); ++line) {
            at = find_line_end(bytes, at);
            if (at >= bytes.size()) break;
            const char end = bytes[at++];
            if (at < bytes.size() && is_line_end_pair(end, bytes[at])) ++at;
        }
        const std::string_view text =
            line < d.line || at >= bytes.size() ? std::string_view{} : bytes.substr(at, find_line_end(bytes, at) - at);
        const std::size_t first = text.find_first_not_of(" \t");
        d.column = static_cast<std::uint32_t>(first == std::string_view::npos ? 0 : first) + 1;
    }
}

}  // namespace

// ---- TapeChecker ----

TapeChecker::TapeChecker(std::string_view bytes, const Profile& profile, MotionSink* also)
    : bytes_(bytes), profile_(profile), cap_(profile.max_per_code), stats_(profile), plan_(profile),
      both_(also ? std::make_unique<PlanThenAlso>(plan_, *also) : nullptr),
      interpreter_(bytes, profile, stats_, &plan_then_also(), result_.diagnostics) {}

TapeChecker::~TapeChecker() = default;

void TapeChecker::check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures) {
    const std::size_t first = result_.diagnostics.size();
    result_.diagnostics.insert(result_.diagnostics.end(), chunk.diagnostics().begin(), chunk.diagnostics().end());
    interpreter_.run(chunk, measures);
    blocks_ += chunk.program_blocks();
    if (result_.diagnostics.size() > first) [[unlikely]]
        keep_diagnostics_from(first);
}

void TapeChecker::check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures, MotionBuffer& plan_input) {
    plan_input.clear();
    interpreter_.send_also_to(plan_input);
    check_chunk(chunk, measures);
    interpreter_.send_also_to(plan_then_also());
}

void TapeChecker::feed_plan(const MotionBuffer& plan_input) { plan_input.replay(plan_then_also()); }

// The chunk's diagnostics (from `first` on) through max_per_code; past twice max_kept_ the list is sorted and cut
// back to max_kept_: a stable sort keeps equal positions in the order found, so the first max_kept_ stay what they
// would be had every diagnostic been kept until the end.
void TapeChecker::keep_diagnostics_from(std::size_t first) {
    cap_.filter(result_.diagnostics, first);
    if (result_.diagnostics.size() / 2 >= max_kept_ && result_.diagnostics.size() - max_kept_ >= max_kept_) {
        sort_diagnostics(result_.diagnostics);
        limit_diagnostics(result_, max_kept_);
    }
}

void TapeChecker::finish_diagnostics() {
    cap_.append_summaries(result_.diagnostics);
    sort_diagnostics(result_.diagnostics);
    limit_diagnostics(result_, max_kept_);
}

void TapeChecker::finish_reading() {
    interpreter_.finish();
    plan_.end_input();
    result_.stats = stats_.stats();
    result_.stats.blocks = blocks_;
}

void TapeChecker::find_parts() {
    parts_ = std::make_unique<PartsFinder>(profile_);
    plan_.keep_plate_motions(parts_.get());
}

CheckResult TapeChecker::finish() {
    finish_reading();
    std::vector<Diagnostic> plan = plan_findings();
    result_.diagnostics.insert(result_.diagnostics.end(), std::make_move_iterator(plan.begin()),
                               std::make_move_iterator(plan.end()));
    if (parts_) result_.parts = parts_->finish();
    finish_diagnostics();
    return std::move(result_);
}

CheckResult TapeChecker::finish_before_plan() {
    finish_reading();
    finish_diagnostics();
    return std::move(result_);
}

std::vector<Diagnostic> TapeChecker::plan_findings() {
    std::vector<Diagnostic> plan = plan_.finish();
    block_columns(bytes_, plan);
    return plan;
}

CheckResult check_tape(std::string_view bytes, const Profile& profile, InputFormat format, std::size_t max_diagnostics,
                       bool parts) {
    // A chunk at a time: each chunk is interpreted while it is still in cache, and the whole tape is
    // never held (a 100 MB tape would cost some 200 MB of blocks).
    TapeChecker checker(bytes, profile);
    checker.set_max_diagnostics(max_diagnostics);
    if (parts) checker.find_parts();
    TapeReader reader(bytes, profile, format);
    Tape chunk;
    // The chunk's room at once (the next chunks reuse it): a small tape's blocks and words are not copied over
    // while they grow.
    const std::size_t blocks = std::min(kCheckChunkBlocks, bytes.size() / kMinBlockBytes + 1);
    chunk.reserve(blocks, blocks * kChunkWordsPerBlock);
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

CheckResult check_tape(std::string_view bytes, const TapeSetup& setup, std::size_t max_diagnostics, bool parts) {
    CheckResult r = check_tape(bytes, setup.profile, setup.format, max_diagnostics, parts);
    record_setup(r, setup);
    return r;
}

}  // namespace essi
