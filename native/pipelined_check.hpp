// Checking one tape on two cores (essi::PipelinedCheck, essi/pipelined_check.hpp): a thread reads chunks of blocks
// while the caller's thread interprets the chunks already read; the reading thread also feeds the interpreted chunks'
// motions to the cut plan, and each thread analyses the plan's plates while it would wait for the other. The same
// core steps as essi::check_tape, so the same result to the bit.
#pragma once

#include <string_view>

#include "essi/pipeline.hpp"
#include "essi/pipelined_check.hpp"

namespace essi::native {

using essi::kPipelineMinBytes;  // (essi/pipelined_check.hpp: smaller tapes are checked on one thread)

// `parts`: the result has the parts list too (TapeChecker::find_parts).
[[nodiscard]] CheckResult check_tape_pipelined(std::string_view bytes, const Profile& profile,
                                               InputFormat format = InputFormat::Essi,
                                               std::size_t max_diagnostics = static_cast<std::size_t>(-1),
                                               bool parts = false);
// The check of a tape as `setup` reads it (check_tape(bytes, setup) on two cores).
[[nodiscard]] CheckResult check_tape_pipelined(std::string_view bytes, const TapeSetup& setup,
                                               std::size_t max_diagnostics = static_cast<std::size_t>(-1),
                                               bool parts = false);

}  // namespace essi::native
