// The trace: the motion stream as text, one record a line, for `essi trace`, golden tests and people.
#pragma once

#include <string>
#include <string_view>

#include "essi/motion.hpp"
#include "essi/profile.hpp"

namespace essi {

// One line (no newline) for a motion:
//   "12 cut arc (10.000,0.000)->(0.000,10.000) c=(0.000,0.000) r=10.000 ccw sweep=90.000 len=15.708 tools=oxygen feed=1000"
[[nodiscard]] std::string trace_line(const MotionRecord& m);
// One line for an event: "3 fn 7 Oxygen ON tools=oxygen"
[[nodiscard]] std::string trace_line(const MachineEvent& e);

// The whole trace of a tape (events and motions, then the diagnostics as "# E301 line 7 col 1: ...").
[[nodiscard]] std::string trace_tape(std::string_view bytes, const Profile& profile);

}  // namespace essi
