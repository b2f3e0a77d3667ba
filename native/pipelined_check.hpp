// Checking one tape on two cores: a thread reads chunks of blocks while the caller's thread interprets
// the chunks already read; the reading thread also feeds the interpreted chunks' motions to the cut plan, and each
// thread analyses the plan's plates while it would wait for the other. The same core steps as essi::check_tape, so
// the same result to the bit.
#pragma once

#include <string_view>

#include "essi/pipeline.hpp"

namespace essi::native {

// Tapes smaller than this are checked on one thread (a thread costs more than it saves).
constexpr std::size_t kPipelineMinBytes = 1u << 20;
// Blocks per chunk handed between the threads, and chunks in flight.
constexpr std::size_t kPipelineChunkBlocks = 16384;
constexpr int kPipelineChunks = 4;
// Chunks' streams for the cut plan in flight (from the interpreting thread to the reading thread, which feeds the
// plan): the one the interpreter fills and the one the reader feeds. Each holds a chunk's motions and events, up to
// 208 bytes a block (a tape of parabolas: 3.4 MB), so more cost memory (docs/hostile-input.md).
constexpr int kPipelinePlanChunks = 2;

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
