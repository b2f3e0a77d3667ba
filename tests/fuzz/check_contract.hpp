// The contract every parser's fuzz target checks of the whole pipeline (read -> interp -> check -> stats), shared
// by fuzz_read_interp.cpp (ESSI) and fuzz_read_eia.cpp (EIA): never a throw, diagnostics sorted and on a line of
// the tape with a column and a message, lengths never negative or NaN, the chunked check with one more sink
// equal to check_tape, every UnitLine's units its mm. A broken contract aborts (the fuzzer and the replay report
// it).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>

#include "essi/lines.hpp"
#include "essi/pipeline.hpp"

namespace essi_fuzz {

[[noreturn]] inline void fail(const char* what, const char* profile) {
    std::fprintf(stderr, "fuzz: %s (profile %s)\n", what, profile);
    std::abort();
}

// A built-in profile (a missing one is a bug, not an input problem), parsed once.
inline const essi::Profile& profile_named(const char* name) {
    static std::map<std::string, essi::Profile> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    auto p = essi::builtin_profile(name);
    if (!p) fail("a built-in profile is missing", name);
    return cache.emplace(name, *p).first->second;
}

// TapeChecker's one more sink (the viewer's document): every motion once (the straight ones of head 1 as
// UnitLines, whose units are their mm), and the statistics of check_tape.
class CountingSink : public essi::MotionSink {
public:
    explicit CountingSink(const essi::Profile& p) : profile_(p) {}
    unsigned long long motions = 0;
    bool units_agree = true;
    void on_motion(const essi::MotionRecord&) override { ++motions; }
    void on_line(const essi::UnitLine& l) override {
        ++motions;
        const double ex = static_cast<double>(l.end_x) * profile_.unit_mm;
        const double sy = static_cast<double>(l.start_y) * profile_.unit_mm;
        units_agree = units_agree && ex == l.end.x && sy == l.start.y;
    }

private:
    const essi::Profile& profile_;
};

inline void check_also(std::string_view bytes, const char* name, essi::InputFormat format,
                       const essi::CheckResult& want) {
    const essi::Profile& profile = profile_named(name);
    CountingSink also(profile);
    essi::TapeChecker checker(bytes, profile, &also);
    essi::TapeReader reader(bytes, profile, format);
    essi::Tape chunk;
    while (reader.read_chunk(chunk, 64)) checker.check_chunk(chunk);
    const essi::CheckResult got = checker.finish();
    if (got.stats.motions != want.stats.motions || also.motions != want.stats.motions)
        fail("TapeChecker with a sink counts other motions than check_tape", name);
    if (got.diagnostics.size() != want.diagnostics.size())
        fail("TapeChecker with a sink gives other diagnostics than check_tape", name);
    if (!(got.stats.cut_length_mm == want.stats.cut_length_mm) && !(std::isnan(got.stats.cut_length_mm)))
        fail("TapeChecker with a sink gives another cut length than check_tape", name);
    if (!also.units_agree) fail("a UnitLine's units are not its mm", name);
}

// Checks `bytes` read as `format` with the built-in profile `name` and aborts when the contract is broken.
inline void check_one(std::string_view bytes, const char* name, essi::InputFormat format = essi::InputFormat::Essi) {
    const essi::Profile& profile = profile_named(name);
    // check_tape is documented never to throw: an exception escaping here terminates (= a failure).
    const essi::CheckResult r = essi::check_tape(bytes, profile, format);

    // Diagnostics are sorted by line, then column.
    for (std::size_t i = 1; i < r.diagnostics.size(); ++i) {
        const auto& a = r.diagnostics[i - 1];
        const auto& b = r.diagnostics[i];
        if (b.line < a.line || (b.line == a.line && b.column < a.column))
            fail("diagnostics are not sorted by line, column", name);
    }
    for (const auto& d : r.diagnostics)
        if (essi::diagnostic_message(d, essi::Lang::En).empty()) fail("a diagnostic has no message", name);

    // Every diagnostic points at a line of the tape (the line index counts lines by the reader's rule), with a
    // column; only a tape too large to read has none.
    essi::LineIndex lines;
    lines.build(bytes);
    const std::size_t last_line = std::max<std::size_t>(lines.line_count(), 1);
    for (const auto& d : r.diagnostics) {
        if (d.code == essi::DiagCode::E117_TapeTooLarge) continue;
        if (d.line < 1 || d.line > last_line) fail("a diagnostic's line is not a line of the tape", name);
        if (d.column < 1) fail("a diagnostic has no column", name);
    }

    // Lengths are never negative or NaN.
    const essi::Stats& s = r.stats;
    if (!(s.cut_length_mm >= 0) || !(s.mark_length_mm >= 0) || !(s.travel_length_mm >= 0) ||
        !(s.rapid_length_mm >= 0) || !(s.cut_length_compensated_mm >= 0) || !(s.estimated_time_s >= 0))
        fail("a length or the time in Stats is negative or NaN", name);
    // Without compensation the torch's path is the programmed one (docs/semantics.md §8).
    if (s.cut_length_compensated_mm != s.cut_length_mm && !(s.motions > 0))
        fail("a compensated cut length without motion", name);
    // The machine boxes: with the built-in profiles (no placement) the program's.
    if (s.machine_cut_bbox.empty != s.cut_bbox.empty || s.machine_motion_bbox.empty != s.motion_bbox.empty)
        fail("a machine box where the program has none (or none where it has one)", name);

    check_also(bytes, name, format, r);
}

}  // namespace essi_fuzz
