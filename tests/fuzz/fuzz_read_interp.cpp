// Fuzz target: the whole pipeline (read -> interp -> check -> stats) through essi::check_tape, once with
// each built-in profile. Built two ways (tests/CMakeLists.txt):
//   essi_fuzz_read_interp         libFuzzer + ASan + UBSan (clang++-14, `make fuzz`, with read_interp.dict and
//                                 inputs up to 128 KB: the corpus holds whole generated tapes)
//   essi_fuzz_replay_read_interp  replay_main.cpp feeds it every file of tests/fuzz/corpus/read_interp (ctest
//                                 `fuzz_replay_read_interp`)
//
// Besides "does not crash, does not throw", it checks the contract of CheckResult (report.hpp) and aborts
// when it is broken, so both the fuzzer and the replay report it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "essi/lines.hpp"
#include "essi/report.hpp"

namespace {

[[noreturn]] void fail(const char* what, const char* profile) {
    std::fprintf(stderr, "fuzz_read_interp: %s (profile %s)\n", what, profile);
    std::abort();
}

const essi::Profile& profile_named(const char* name) {
    // builtin_profile must know both names; a missing one is a bug, not an input problem.
    static const essi::Profile iso = [] {
        auto p = essi::builtin_profile("iso6582");
        if (!p) fail("builtin_profile(\"iso6582\") is missing", "iso6582");
        return *p;
    }();
    static const essi::Profile woyda = [] {
        auto p = essi::builtin_profile("woyda");
        if (!p) fail("builtin_profile(\"woyda\") is missing", "woyda");
        return *p;
    }();
    return std::string_view(name) == "woyda" ? woyda : iso;
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
        const double ex = static_cast<double>(l.end_x) * profile_.unit_mm + profile_.setup_offset_x_mm;
        const double sy = static_cast<double>(l.start_y) * profile_.unit_mm + profile_.setup_offset_y_mm;
        units_agree = units_agree && ex == l.end.x && sy == l.start.y;
    }
private:
    const essi::Profile& profile_;
};

void check_also(std::string_view bytes, const char* name, const essi::CheckResult& want) {
    const essi::Profile& profile = profile_named(name);
    CountingSink also(profile);
    essi::TapeChecker checker(bytes, profile, &also);
    essi::TapeReader reader(bytes, profile);
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

void check_one(std::string_view bytes, const char* name) {
    const essi::Profile& profile = profile_named(name);
    // check_tape is documented never to throw: an exception escaping here terminates (= a failure).
    const essi::CheckResult r = essi::check_tape(bytes, profile);

    // Diagnostics are sorted by line, then column.
    for (std::size_t i = 1; i < r.diagnostics.size(); ++i) {
        const auto& a = r.diagnostics[i - 1];
        const auto& b = r.diagnostics[i];
        if (b.line < a.line || (b.line == a.line && b.column < a.column))
            fail("diagnostics are not sorted by line, column", name);
    }
    for (const auto& d : r.diagnostics)
        if (d.message.empty()) fail("a diagnostic has no message", name);

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
        !(s.rapid_length_mm >= 0))
        fail("a length in Stats is negative or NaN", name);

    check_also(bytes, name, r);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    check_one(bytes, "iso6582");
    check_one(bytes, "woyda");
    return 0;
}
