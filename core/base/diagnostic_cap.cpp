// At most max_per_code diagnostics of a code (essi/diagnostic_cap.hpp).
#include "essi/diagnostic_cap.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace essi {

DiagnosticCap::DiagnosticCap(std::size_t max_per_code) : max_(max_per_code) {}

DiagnosticCap::Count& DiagnosticCap::count(DiagCode code) {
    const auto k = static_cast<std::size_t>(code);
    if (k >= counts_.size()) counts_.resize(k + 1);
    return counts_[k];
}

bool DiagnosticCap::admit(DiagCode code, std::uint32_t line, Severity severity) {
    if (max_ == 0) return true;
    Count& c = count(code);
    if (++c.seen <= max_) return true;
    add_omitted(code, 1, line, severity);
    return false;
}

void DiagnosticCap::add_omitted(DiagCode code, std::uint64_t n, std::uint32_t line, Severity severity) {
    if (n == 0) return;
    Count& c = count(code);
    if (c.omitted == 0) c.severity = severity;
    c.omitted += n;
    c.first_omitted_line = std::min(c.first_omitted_line, line);
}

void DiagnosticCap::add_omitted(const DiagnosticCap& other) {
    for (std::size_t k = 0; k < other.counts_.size(); ++k) {
        const Count& c = other.counts_[k];
        add_omitted(static_cast<DiagCode>(k), c.omitted, c.first_omitted_line, c.severity);
    }
}

void DiagnosticCap::filter(std::vector<Diagnostic>& d, std::size_t from) {
    if (max_ == 0) return;
    const auto kept = std::stable_partition(d.begin() + static_cast<std::ptrdiff_t>(from), d.end(),
                                            [&](const Diagnostic& x) { return admit(x); });
    d.erase(kept, d.end());
}

void DiagnosticCap::move_admitted(std::vector<Diagnostic>& from, std::vector<Diagnostic>& to) {
    for (Diagnostic& d : from)
        if (admit(d)) to.push_back(std::move(d));
    from.clear();
}

void DiagnosticCap::append_summaries(std::vector<Diagnostic>& out) const {
    for (std::size_t k = 0; k < counts_.size(); ++k) {
        const Count& c = counts_[k];
        if (c.omitted == 0) continue;
        const auto code = static_cast<DiagCode>(k);
        out.push_back(make_diagnostic(
            c.severity, code, c.first_omitted_line, 1, Msg::DiagnosticsOmittedOfCode,
            {static_cast<unsigned long long>(c.omitted), code_name(code), static_cast<unsigned long long>(max_)}));
    }
}

// (the summary's first argument is the count, written as its digits: append_summaries)
std::uint64_t cap_omitted(const Diagnostic& d) {
    if (d.msg != Msg::DiagnosticsOmittedOfCode) return 0;
    const std::string& packed = d.args.packed();
    return std::strtoull(packed.c_str(), nullptr, 10);
}

}  // namespace essi
