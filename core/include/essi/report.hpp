// Phase 5, report: statistics (§9) and the result of checking one tape. `check_tape` runs the whole
// pipeline (read -> interp -> check -> stats) on bytes and never throws.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
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

class Tape;
// Program blocks of a read tape: blocks up to the end, comment lines inside 3/4 excluded.
[[nodiscard]] unsigned long long count_program_blocks(const Tape& tape);
// Orders diagnostics by line, then column (stable).
void sort_diagnostics(std::vector<Diagnostic>& diagnostics);

}  // namespace essi
