// The result of checking a tape (essi/report.hpp): its verdict, counts and order of diagnostics.
#include "essi/report.hpp"

#include <algorithm>

namespace essi {

bool CheckResult::ok() const { return count(Severity::Error) == 0; }

std::size_t CheckResult::count(Severity s) const {
    const std::size_t omitted = s == Severity::Error     ? omitted_errors
                                : s == Severity::Warning ? omitted_warnings
                                                         : omitted_notes;
    return omitted + static_cast<std::size_t>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                                            [&](const Diagnostic& d) { return d.severity == s; }));
}

void limit_diagnostics(CheckResult& r, std::size_t max) {
    if (r.diagnostics.size() <= max) return;
    for (std::size_t i = max; i < r.diagnostics.size(); ++i) {
        switch (r.diagnostics[i].severity) {
            case Severity::Error: ++r.omitted_errors; break;
            case Severity::Warning: ++r.omitted_warnings; break;
            case Severity::Note: ++r.omitted_notes; break;
        }
    }
    r.diagnostics.erase(r.diagnostics.begin() + static_cast<std::ptrdiff_t>(max), r.diagnostics.end());
}

void sort_diagnostics(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        if (a.line != b.line) return a.line < b.line;
        return a.column < b.column;
    });
}

}  // namespace essi
