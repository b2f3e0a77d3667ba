// Fuzz target: a profile file (essi::parse_profile, JSON). Built as essi_fuzz_profile (libFuzzer, `make fuzz`)
// and essi_fuzz_replay_profile (replays tests/fuzz/corpus/profile, ctest `fuzz_replay_profile`).
//
// Besides "does not crash, does not throw", it checks parse_profile's contract and aborts when it is broken: a
// profile comes back with no diagnostic or none comes back with at least one, every diagnostic is E402, every
// accepted profile keeps its numbers finite and in range, writes itself as JSON that parses back to the same
// JSON, and checks a small tape without a non-finite statistic.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "essi/profile.hpp"
#include "essi/pipeline.hpp"

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_profile: %s\n", what);
    std::abort();
}

void check_accepted(const essi::Profile& p) {
    const double values[] = {p.unit_mm,
                             p.arc_tolerance_units,
                             p.chord_tolerance_mm,
                             p.kerf_units,
                             p.default_dwell_s,
                             p.feed_mm_min,
                             p.rapid_mm_min,
                             p.pierce_time_s,
                             p.active_zero_offset().x,
                             p.active_zero_offset().y,
                             p.plate_rotation_deg,
                             p.marker_offset.x,
                             p.marker_offset.y,
                             p.powder_marker_offset.x,
                             p.powder_marker_offset.y};
    for (double v : values)
        if (!std::isfinite(v)) fail("an accepted profile holds a number that is not finite");
    if (!(p.unit_mm > 0) || !(p.feed_mm_min > 0) || !(p.rapid_mm_min > 0))
        fail("an accepted profile has a zero unit or speed");
    const std::string json = essi::profile_to_json(p);
    const essi::ProfileResult again = essi::parse_profile(json);
    if (!again.profile) fail("profile_to_json wrote a profile that parse_profile refuses");
    if (essi::profile_to_json(*again.profile) != json) fail("a profile does not survive its own JSON");
    const essi::CheckResult r = essi::check_tape("7\n+1000+0\n+0+1000+0+500-\n41+2\n8\n64\n", p);
    if (!std::isfinite(r.stats.cut_length_mm) || !std::isfinite(r.stats.estimated_time_s))
        fail("a tape checked under an accepted profile has a statistic that is not finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const essi::ProfileResult r = essi::parse_profile(text);
    if (r.profile.has_value() == !r.diagnostics.empty()) fail("a profile and its diagnostics disagree");
    for (const essi::Diagnostic& d : r.diagnostics) {
        if (d.code != essi::DiagCode::E402_BadProfile) fail("a profile diagnostic that is not E402");
        if (essi::diagnostic_message(d, essi::Lang::En).empty() ||
            essi::diagnostic_message(d, essi::Lang::En).size() > 400)
            fail("a profile diagnostic without a short message");
    }
    if (r.profile) check_accepted(*r.profile);
    return 0;
}
