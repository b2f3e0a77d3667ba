#include "app/ProblemList.hpp"

#include <algorithm>

#include "essi/diagnostic_cap.hpp"

namespace essi::viewer {

void ProblemList::build(const std::vector<Diagnostic>& diagnostics) {
    top_.clear();
    groups_.clear();
    group_of_.assign(diagnostics.size(), npos);
    // The findings of each code: those kept, and those its summary says were left out.
    std::vector<std::uint64_t> findings;
    for (const Diagnostic& d : diagnostics) {
        const auto code = static_cast<std::size_t>(d.code);
        if (code >= findings.size()) findings.resize(code + 1);
        const std::uint64_t omitted = cap_omitted(d);
        findings[code] += omitted > 0 ? omitted : 1;
    }
    std::vector<std::size_t> group_by_code(findings.size(), npos);
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
        const Diagnostic& d = diagnostics[i];
        const auto code = static_cast<std::size_t>(d.code);
        if (findings[code] <= kGroupFindingsAbove) {
            top_.push_back({ProblemRow::Kind::Diagnostic, i});
            continue;
        }
        std::size_t& g = group_by_code[code];
        if (g == npos) {
            g = groups_.size();
            groups_.push_back({d.code, d.severity, {}, findings[code]});
            top_.push_back({ProblemRow::Kind::Group, g});
        }
        ProblemGroup& group = groups_[g];
        group.severity = std::max(group.severity, d.severity);
        group.members.push_back(i);
        group_of_[i] = g;
    }
}

std::vector<ProblemRow> ProblemList::rows(const std::vector<bool>& open) const {
    std::vector<ProblemRow> rows;
    rows.reserve(top_.size());
    for (const ProblemRow& r : top_) {
        rows.push_back(r);
        if (r.kind != ProblemRow::Kind::Group || r.index >= open.size() || !open[r.index]) continue;
        for (const std::size_t m : groups_[r.index].members) rows.push_back({ProblemRow::Kind::Member, m});
    }
    return rows;
}

std::size_t ProblemList::group_of(std::size_t diagnostic) const {
    return diagnostic < group_of_.size() ? group_of_[diagnostic] : npos;
}

std::size_t step_problem(const std::vector<Diagnostic>& diagnostics, std::size_t current, int step) {
    const std::size_t n = diagnostics.size();
    if (n == 0) return ProblemList::npos;
    // (from none: one step before the first, or after the last)
    std::size_t at = current < n ? current : (step > 0 ? n - 1 : 0);
    for (std::size_t k = 0; k < n; ++k) {
        at = step > 0 ? (at + 1) % n : (at + n - 1) % n;
        if (diagnostics[at].line > 0) return at;
    }
    return ProblemList::npos;
}

std::size_t ProblemPage::end(std::size_t total) const {
    return offset >= total ? total : offset + std::min(limit, total - offset);
}

ProblemPage problem_page(long long offset, long long limit) {
    ProblemPage p;
    p.offset = offset > 0 ? static_cast<std::size_t>(offset) : 0;
    p.limit = limit < 0 ? kStateProblemsPage : std::min(static_cast<std::size_t>(limit), kStateProblemsMax);
    return p;
}

}  // namespace essi::viewer
