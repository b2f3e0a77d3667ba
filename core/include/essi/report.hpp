// Phase 5, report: the result of checking one tape (its statistics, §9, and diagnostics). essi/pipeline.hpp
// makes it (check_tape, TapeChecker).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/parts.hpp"
#include "essi/read.hpp"
#include "essi/stats.hpp"

namespace essi {

struct CheckResult {
    Stats stats;
    std::vector<Diagnostic> diagnostics;  // sorted by line, column
    // How the tape was read (check_tape with a TapeSetup): its format, the profile, and for a profile chosen by
    // the evidence (--profile auto) that evidence.
    InputFormat input = InputFormat::Essi;
    std::string profile;
    bool auto_profile = false;
    std::vector<std::string> dialect_evidence;
    // Diagnostics left out by a limit on their number (limit_diagnostics, --max-diagnostics), by severity: the
    // verdict and the counts include them.
    std::size_t omitted_errors = 0, omitted_warnings = 0, omitted_notes = 0;
    // The parts and plates (essi/parts.hpp), when they were asked for (`essi check --parts`, `essi parts`, the job
    // sheet): the check alone does not make them.
    std::optional<PartsList> parts;
    [[nodiscard]] bool ok() const;                      // no error, listed or left out
    [[nodiscard]] std::size_t count(Severity s) const;  // listed and left out
    [[nodiscard]] std::size_t omitted() const { return omitted_errors + omitted_warnings + omitted_notes; }
};

// Keeps the first `max` diagnostics of `r` (in their order) and counts the rest in its omitted_*.
void limit_diagnostics(CheckResult& r, std::size_t max);

// Orders diagnostics by line, then column (stable).
void sort_diagnostics(std::vector<Diagnostic>& diagnostics);

}  // namespace essi
