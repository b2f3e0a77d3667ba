// The check pipeline: read -> interp (statistics) -> plan -> report, on a whole tape (check_tape, which never
// throws) or a chunk of blocks at a time (TapeChecker). The top of the core's layers (core/LAYERS): the outputs
// (diff, drawings, conversions) run it.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "essi/diagnostic_cap.hpp"
#include "essi/diagnostics.hpp"
#include "essi/dialect.hpp"
#include "essi/interp.hpp"
#include "essi/motion.hpp"
#include "essi/parts.hpp"
#include "essi/plan.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"
#include "essi/report.hpp"
#include "essi/stats.hpp"

namespace essi {

// `max_diagnostics`: at most that many are kept (TapeChecker::set_max_diagnostics); `parts`: the result has the
// parts list too (TapeChecker::find_parts).
[[nodiscard]] CheckResult check_tape(std::string_view bytes, const Profile& profile,
                                     InputFormat format = InputFormat::Essi,
                                     std::size_t max_diagnostics = static_cast<std::size_t>(-1), bool parts = false);
// The check of a tape as `setup` reads it (essi/dialect.hpp: format and profile given or found), with the
// setup's note (N403) among the diagnostics and the setup in the result.
[[nodiscard]] CheckResult check_tape(std::string_view bytes, const TapeSetup& setup,
                                     std::size_t max_diagnostics = static_cast<std::size_t>(-1), bool parts = false);
// The result's record of `setup` (format, profile, evidence, note): for callers that run their own TapeChecker.
void record_setup(CheckResult& result, const TapeSetup& setup);

// The check pipeline, fed a chunk of blocks at a time (from a TapeReader, in tape order): what
// check_tape does, for callers that read on another thread or also want the motion stream.
class TapeChecker {
public:
    // `also`, when given, receives every motion and event too (e.g. the viewer's document), its straight lines
    // of head 1 as MotionSink::on_line (UnitLine: units and mm, no record).
    TapeChecker(std::string_view bytes, const Profile& profile, MotionSink* also = nullptr);
    ~TapeChecker();
    TapeChecker(const TapeChecker&) = delete;
    TapeChecker& operator=(const TapeChecker&) = delete;
    // `measures`: measure_motions(chunk), when the caller worked it out ahead (on another thread).
    void check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures = {});
    // The same, the chunk's stream for the cut plan (and `also`) kept in `plan_input` (emptied first) instead of
    // fed to them: feed_plan passes it on. For a pipeline that feeds the plan on another thread.
    void check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures, MotionBuffer& plan_input);
    // A chunk's stream for the cut plan (check_chunk's `plan_input`) to the plan (and `also`): every chunk's that
    // was kept, once each, in chunk order, before the next chunk checked without a buffer and before finish(); on
    // any one thread at a time (the plan is touched by nothing else meanwhile).
    void feed_plan(const MotionBuffer& plan_input);
    // The cut plan's plates are analysed by `runner` (essi/plan.hpp; null: on this thread as they end).
    void set_plate_runner(PlateRunner* runner) { plan_.set_runner(runner); }
    // At most `max` diagnostics are kept (the first by line and column, as limit_diagnostics on the sorted
    // result would keep them; the rest counted): the memory the check's diagnostics take is bounded by it too.
    // Before the first chunk.
    void set_max_diagnostics(std::size_t max) { max_kept_ = max; }
    // finish() gives the parts list too (essi/parts.hpp), made from the cut plan's plates in this same pass.
    // Before the first chunk; not with defer_plan.
    void find_parts();
    // After the last chunk: the result (diagnostics sorted). Call once.
    [[nodiscard]] CheckResult finish();

    // The cut plan's plates kept to be analysed after the check, their motions read back from `store`
    // (CutPlan::defer_plates): for the viewer, which keeps every motion anyway and shows the drawing first.
    // Before the first chunk.
    void defer_plan(const MotionStore* store) { plan_.defer_plates(store); }
    // After the last chunk, instead of finish(): the result without the cut plan's findings (plan_findings() gives
    // them). Call once.
    [[nodiscard]] CheckResult finish_before_plan();
    // After finish_before_plan: one kept plate analysed (false when none is left), and how many are left of all.
    bool analyse_plan_plate() { return plan_.analyse_deferred_plate(); }
    [[nodiscard]] std::size_t plan_plates_left() const { return plan_.deferred_plates_left(); }
    [[nodiscard]] std::size_t plan_plates() const { return plan_.deferred_plates(); }
    // After finish_before_plan: the cut plan's diagnostics (the plates not analysed yet are analysed first),
    // unsorted. Call once.
    [[nodiscard]] std::vector<Diagnostic> plan_findings();

private:
    void finish_reading();  // the interpreter's and the plan's input ended; the statistics taken
    // What the interpreter feeds besides the statistics: the plan, or the plan and `also`.
    MotionSink& plan_then_also() { return both_ ? static_cast<MotionSink&>(*both_) : plan_; }
    void keep_diagnostics_from(std::size_t first);  // max_per_code on the new ones, then max_kept_
    void finish_diagnostics();                      // the summaries of max_per_code, sorted, cut to max_kept_
    // The cut plan, then `also`: the one more sink the interpreter feeds.
    class PlanThenAlso final : public MotionSink {
    public:
        PlanThenAlso(CutPlan& plan, MotionSink& also) : plan_(plan), also_(also) {}
        void on_motion(const MotionRecord& m) override {
            plan_.on_motion(m);
            also_.on_motion(m);
        }
        void on_event(const MachineEvent& e) override {
            plan_.on_event(e);
            also_.on_event(e);
        }
        void on_line(const UnitLine& l) override {
            plan_.on_line(l);
            also_.on_line(l);
        }

    private:
        CutPlan& plan_;
        MotionSink& also_;
    };
    std::string_view bytes_;
    const Profile& profile_;
    CheckResult result_;
    DiagnosticCap cap_;  // max_per_code for the diagnostics of the reader and the interpreter
    std::size_t max_kept_ = static_cast<std::size_t>(-1);
    StatsSink stats_;
    CutPlan plan_;                        // the cut plan's rules (essi/plan.hpp)
    std::unique_ptr<PartsFinder> parts_;  // find_parts
    std::unique_ptr<PlanThenAlso> both_;
    Interpreter interpreter_;  // feeds the statistics directly, and the plan (and `also`)
    unsigned long long blocks_ = 0;
};

// Blocks per chunk when check_tape streams a tape (about 100 KB of blocks: stays in the L2 cache).
constexpr std::size_t kCheckChunkBlocks = 8192;
// What check_tape reserves for a chunk: a block for every kMinBlockBytes bytes of the tape (a line of one
// character and its line end), up to kCheckChunkBlocks, and kChunkWordsPerBlock words each (an ESSI motion has
// two, an EIA block three or four); a chunk that needs more grows.
constexpr std::size_t kMinBlockBytes = 2;
constexpr std::size_t kChunkWordsPerBlock = 4;

}  // namespace essi
