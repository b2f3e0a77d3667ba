// The problems list (docs/viewer.md, "Problems"): the diagnostics in rows, where the findings of a code with many of
// them are one row that opens to show them (the kept ones and the core's summary of those the max_per_code cap left
// out); "next problem" and "previous problem" in the list's order; a page of the list for state().
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "essi/diagnostics.hpp"

namespace essi::viewer {

// A code with more findings than this is one row of the list (a group) instead of one row each.
inline constexpr std::size_t kGroupFindingsAbove = 5;

// The findings of one code.
struct ProblemGroup {
    DiagCode code = DiagCode::E101_InvalidCharacter;
    Severity severity = Severity::Note;  // the worst of them
    std::vector<std::size_t> members;    // the diagnostics of the code (indices in the list), the cap's summary too
    std::uint64_t total = 0;             // the findings: those kept and those the cap left out
};

// One row of the list: a diagnostic, or a group (open or not), or a member of an open group.
struct ProblemRow {
    enum class Kind : std::uint8_t { Diagnostic, Group, Member };
    Kind kind = Kind::Diagnostic;
    std::size_t index = 0;  // the diagnostic's index (Diagnostic, Member), or the group's (Group)
};

class ProblemList {
public:
    // The rows of `diagnostics` (sorted as the core sorts them): a code with more than kGroupFindingsAbove findings
    // (kept or left out by the cap) is a group at the place of its first; the others are rows of their own.
    void build(const std::vector<Diagnostic>& diagnostics);
    [[nodiscard]] const std::vector<ProblemGroup>& groups() const { return groups_; }
    // The rows shown, with the groups whose index is in `open` opened.
    [[nodiscard]] std::vector<ProblemRow> rows(const std::vector<bool>& open) const;
    // The group a diagnostic belongs to (npos: none).
    [[nodiscard]] std::size_t group_of(std::size_t diagnostic) const;
    static constexpr std::size_t npos = ~std::size_t(0);

private:
    std::vector<ProblemRow> top_;  // the rows with every group closed
    std::vector<ProblemGroup> groups_;
    std::vector<std::size_t> group_of_;  // by diagnostic
};

// The diagnostic after (step 1) or before (step -1) `current` that has a place on the tape (a line), going round;
// from none (npos) the first or the last. npos when none has a place.
[[nodiscard]] std::size_t step_problem(const std::vector<Diagnostic>& diagnostics, std::size_t current, int step);

// A page of the list for state(): [offset, offset + limit) of `total`, cut to the list.
struct ProblemPage {
    std::size_t offset = 0, limit = 0;
    [[nodiscard]] std::size_t end(std::size_t total) const;
};
// The page asked for: a missing or negative offset is 0, a missing or negative limit kStateProblemsPage, a limit
// above kStateProblemsMax that.
inline constexpr std::size_t kStateProblemsPage = 100;   // state()'s problems without a page asked for
inline constexpr std::size_t kStateProblemsMax = 10000;  // at most in one page
[[nodiscard]] ProblemPage problem_page(long long offset, long long limit);

}  // namespace essi::viewer
