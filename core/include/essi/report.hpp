// Phase 5, report: statistics (§9) and the result of checking one tape. `check_tape` runs the whole
// pipeline (read -> interp -> check -> stats) on bytes and never throws.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/interp.hpp"
#include "essi/read.hpp"
#include "essi/motion.hpp"
#include "essi/profile.hpp"

namespace essi {

struct Stats {
    double cut_length_mm = 0;
    double mark_length_mm = 0;
    double travel_length_mm = 0;   // rapid and other tool-off motion
    double rapid_length_mm = 0;    // the rapid part of travel_length_mm
    unsigned long long pierces = 0;
    unsigned long long blocks = 0; // program blocks read (comment lines and empty lines excluded)
    unsigned long long motions = 0;
    double estimated_time_s = 0;
    Box cut_bbox;                  // empty when nothing is cut
    Box motion_bbox;               // all motion
    Point end_position;            // machine position at the end (head 1)
};

struct CheckResult {
    Stats stats;
    std::vector<Diagnostic> diagnostics;  // sorted by line, column
    [[nodiscard]] bool ok() const;  // no error
    [[nodiscard]] std::size_t count(Severity s) const;
};

// Accumulates statistics from the motion stream.
class StatsSink : public MotionSink {
public:
    explicit StatsSink(const Profile& profile) : profile_(profile) {}
    void on_motion(const MotionRecord& m) override;
    void on_event(const MachineEvent& e) override;
    [[nodiscard]] const Stats& stats() const { return stats_; }
    Stats& stats() { return stats_; }
private:
    const Profile& profile_;
    Stats stats_;
    std::uint8_t tools_ = 0;  // tools on before the current event (pierce counting)
};

[[nodiscard]] CheckResult check_tape(std::string_view bytes, const Profile& profile);

// The check pipeline, fed a chunk of blocks at a time (from a TapeReader, in tape order): what
// check_tape does, for callers that read on another thread or also want the motion stream.
class TapeChecker {
public:
    // `also`, when given, receives every motion and event too (e.g. the viewer's GPU buffers).
    TapeChecker(std::string_view bytes, const Profile& profile, MotionSink* also = nullptr);
    ~TapeChecker();
    TapeChecker(const TapeChecker&) = delete;
    TapeChecker& operator=(const TapeChecker&) = delete;
    // `measures`: measure_motions(chunk), when the caller worked it out ahead (on another thread).
    void check_chunk(const Tape& chunk, std::span<const MotionMeasure> measures = {});
    // After the last chunk: the result (diagnostics sorted). Call once.
    [[nodiscard]] CheckResult finish();
private:
    class Tee;
    CheckResult result_;
    std::unique_ptr<Tee> tee_;  // the statistics, and the `also` sink when there is one
    Interpreter interpreter_;   // feeds the statistics directly when there is no `also` sink
    unsigned long long blocks_ = 0;
};

// Blocks per chunk when check_tape streams a tape (about 100 KB of blocks: stays in the L2 cache).
constexpr std::size_t kCheckChunkBlocks = 8192;

// Orders diagnostics by line, then column (stable).
void sort_diagnostics(std::vector<Diagnostic>& diagnostics);

}  // namespace essi
