// The bound on diagnostics of one code (profile key max_per_code, `--max-per-code`, the server's `max_per_code`):
// at most N diagnostics of a code are kept, in the order they are found; the rest are only counted, and one
// summary diagnostic of that code says how many more there are. A tape with a finding on every part, or N parts
// that all collide, then costs the report and the memory N findings a code, not one per part or per pair.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "essi/diagnostics.hpp"

namespace essi {

class DiagnosticCap {
public:
    // `max_per_code` 0: every diagnostic is kept.
    explicit DiagnosticCap(std::size_t max_per_code = 0);
    [[nodiscard]] std::size_t max_per_code() const { return max_; }
    // Counts one diagnostic of `code` (at `line`, of `severity`); true when it is to be kept.
    [[nodiscard]] bool admit(DiagCode code, std::uint32_t line, Severity severity);
    [[nodiscard]] bool admit(const Diagnostic& d) { return admit(d.code, d.line, d.severity); }
    // Counts `n` diagnostics of `code` that another cap left out, the first of them at `line`.
    void add_omitted(DiagCode code, std::uint64_t n, std::uint32_t line, Severity severity);
    // Everything `other` left out (a plate's cap folded into the tape's).
    void add_omitted(const DiagnosticCap& other);
    // Keeps the diagnostics of d[from, end) that are admitted, in their order; drops the rest.
    void filter(std::vector<Diagnostic>& d, std::size_t from = 0);
    // Moves the admitted diagnostics of `from` to the end of `to`, in their order.
    void move_admitted(std::vector<Diagnostic>& from, std::vector<Diagnostic>& to);
    // One diagnostic for each code that had some left out: "N more E605 diagnostics are not listed (at most M of a
    // code: --max-per-code)", at the line of the first left out, with that code and severity.
    void append_summaries(std::vector<Diagnostic>& out) const;

private:
    struct Count {
        std::uint64_t seen = 0;     // admitted or not
        std::uint64_t omitted = 0;  // not kept (here or by a cap folded in)
        std::uint32_t first_omitted_line = UINT32_MAX;
        Severity severity = Severity::Error;
    };
    [[nodiscard]] Count& count(DiagCode code);
    std::size_t max_;
    std::vector<Count> counts_;  // by code number
};

// How many diagnostics of its code `d` says were left out when it is a summary of append_summaries; 0 for any other.
[[nodiscard]] std::uint64_t cap_omitted(const Diagnostic& d);

}  // namespace essi
