// The trace: the motion stream as text, one record a line, for `essi trace`, golden tests and people.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "essi/diagnostics.hpp"
#include <string_view>

#include "essi/motion.hpp"
#include "essi/profile.hpp"
#include "essi/read.hpp"

namespace essi {

constexpr int kTraceDecimals = 3;

// One line (no newline) for a motion:
//   "12 cut arc (10.000,0.000)->(0.000,10.000) c=(0.000,0.000) r=10.000 ccw sweep=90.000 len=15.708 tools=oxygen
//   feed=1000"
// Lengths and coordinates to `decimals` decimals (default 3: micrometres, the golden files'; essi trace
// --decimals N).
[[nodiscard]] std::string trace_line(const MotionRecord& m, int decimals = kTraceDecimals);
// One line for an event: "3 fn 7 Oxygen ON tools=oxygen" (function names in the profile's dialect)
[[nodiscard]] std::string trace_line(const MachineEvent& e, Dialect dialect = Dialect::Iso6582);

// Receives the trace a piece at a time (whole lines, each ending in '\n').
using TraceWriter = std::function<void(std::string_view)>;

// What the trace shows: the motion stream as programmed (program coordinates), or the torch's path (the
// kerf-compensated path, docs/semantics.md §8: `essi trace --kerf`), in machine coordinates (§12: `--machine`),
// or both.
struct TraceView {
    bool kerf = false;
    bool machine = false;
};

// Streams the trace of a tape to `write`: events and motions in program order, then the diagnostics as
// "# E301 line 7 col 1: ...". Returns the diagnostics (sorted), so a caller can tell whether it had errors.
// The kerf path adds its gouges (E307).
std::vector<Diagnostic> trace_tape(std::string_view bytes, const Profile& profile, const TraceWriter& write,
                                   InputFormat format = InputFormat::Essi, int decimals = kTraceDecimals,
                                   TraceView view = {});

// The whole trace as one string (small tapes, golden tests).
[[nodiscard]] std::string trace_tape(std::string_view bytes, const Profile& profile,
                                     InputFormat format = InputFormat::Essi);

}  // namespace essi
