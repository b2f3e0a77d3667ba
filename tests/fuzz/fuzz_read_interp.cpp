// Fuzz target: the whole pipeline (read -> interp -> check -> stats) through essi::check_tape, once with
// each built-in profile. Built two ways (tests/CMakeLists.txt):
//   essi_fuzz         libFuzzer + ASan + UBSan (clang++-14, `make fuzz`)
//   essi_fuzz_replay  replay_main.cpp feeds it every file of tests/fuzz/corpus (ctest `fuzz_replay`)
//
// Besides "does not crash, does not throw", it checks the contract of CheckResult (report.hpp) and aborts
// when it is broken, so both the fuzzer and the replay report it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

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

    // ok() means "no error".
    if (r.ok() != (r.count(essi::Severity::Error) == 0)) fail("ok() disagrees with count(Error)", name);

    // Lengths are never negative or NaN.
    const essi::Stats& s = r.stats;
    if (!(s.cut_length_mm >= 0) || !(s.mark_length_mm >= 0) || !(s.travel_length_mm >= 0) ||
        !(s.rapid_length_mm >= 0))
        fail("a length in Stats is negative or NaN", name);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    check_one(bytes, "iso6582");
    check_one(bytes, "woyda");
    return 0;
}
