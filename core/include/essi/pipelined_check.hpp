// Checking one tape on two threads (where the build has them: essi/threads.hpp). A thread of its own reads chunks of
// blocks while the caller's thread interprets the chunks already read (TapeChecker::check_chunk, its stream for the
// cut plan kept in a MotionBuffer); the reading thread also feeds those streams to the cut plan and the checker's
// `also` sink (TapeChecker::feed_plan), in chunk order, and either thread runs the caller's `idle` work (the plan's
// plates) while it would wait for the other. The same core steps as check_tape, so the same result to the bit.
// `essi check --jobs N`, `essi serve` (native/pipelined_check.hpp) and the viewer's loader (web/app/DocumentLoader)
// run it.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

#include "essi/interp.hpp"
#include "essi/pipeline.hpp"
#include "essi/read.hpp"
#include "essi/threads.hpp"

namespace essi {

// Tapes smaller than this are checked on one thread (a thread costs more than it saves).
inline constexpr std::size_t kPipelineMinBytes = std::size_t(1) << 20;
// Chunks of blocks handed between the threads, and in flight.
inline constexpr std::size_t kPipelineChunkBlocks = 16384;
inline constexpr int kPipelineChunks = 4;
// Chunks' streams for the cut plan in flight (from the interpreting thread to the reading thread, which feeds the
// plan): the one the interpreter fills and the one the reader feeds. Each holds a chunk's motions and events, up to
// 208 bytes a block (a tape of parabolas: 3.4 MB), so more cost memory (docs/hostile-input.md).
inline constexpr int kPipelinePlanChunks = 2;

class PipelinedCheck {
public:
    struct Hooks {
        // On the caller's thread, each chunk read, before it is interpreted; `before` is the reader as it was
        // before the chunk (with keep_readers: the hook may take it), else null.
        std::function<void(const Tape& chunk, std::optional<TapeReader>& before)> chunk_read;
        // On the reading thread, before each chunk's stream goes to the plan and `also`.
        std::function<void(const MotionBuffer& stream)> before_feed;
        // On either thread while it would wait for the other: one piece of work, false when there was none.
        std::function<bool()> idle;
        bool keep_readers = false;
    };

    // Starts the reading thread on `reader`'s chunks of `chunk_blocks` blocks for `checker` (set up, no chunk checked
    // yet; it must outlive this). Only where kHaveThreads.
    PipelinedCheck(TapeChecker& checker, TapeReader reader, Hooks hooks,
                   std::size_t chunk_blocks = kPipelineChunkBlocks);
    // Stops the reading thread where it is (a check dropped before its end).
    ~PipelinedCheck();
    PipelinedCheck(const PipelinedCheck&) = delete;
    PipelinedCheck& operator=(const PipelinedCheck&) = delete;

    // Interprets chunks until every one is interpreted and fed and the reading thread is done (true; the checker's
    // finish() may follow), or until `in_time` says false after a chunk (false: call again). An exception of either
    // thread (no memory for a chunk, say) comes out here, once the reading thread has stopped: never
    // std::terminate, never a thread left waiting for the other.
    bool run(const std::function<bool()>& in_time = {});

private:
    // A chunk's slot: the reader fills slot k, the interpreter empties it, in order. It changes hands through its
    // atomic `full` flag (wait_while/wake_one, essi/threads.hpp: a short spin, then a futex), so a thread that is only
    // a little ahead does not go to sleep at every chunk. (Each slot on cache lines of its own: the thread filling one
    // writes its vectors' ends at every item, and must not take the lines of the slot the other thread is reading.)
    struct alignas(64) Slot {
        Tape chunk;
        std::vector<MotionMeasure> measures;  // worked out by the reading thread (arcs: radii, sweeps)
        std::optional<TapeReader> before;     // (Hooks::keep_readers)
        bool last = false;                    // the reader is done: this slot holds nothing
        std::atomic<std::uint32_t> full{0};   // (0 or 1: a futex word, essi/threads.hpp)
    };
    // The other way: the interpreter's stream for the cut plan, a chunk's in each slot.
    struct alignas(64) PlanSlot {
        MotionBuffer stream;
        std::atomic<std::uint32_t> full{0};  // (0 or 1: a futex word, essi/threads.hpp)
    };
    void read_all(TapeReader& reader);
    bool feed_plan();
    void wake_reader();
    void release_interpreter();
    void stop_reader();
    bool interpret_chunks(const std::function<bool()>& in_time);

    TapeChecker& checker_;
    Hooks hooks_;
    std::size_t chunk_blocks_;
    std::array<Slot, kPipelineChunks> slots_;
    std::array<PlanSlot, kPipelinePlanChunks> plan_slots_;
    std::size_t next_chunk_ = 0;  // the chunk the interpreter takes next
    std::size_t next_plan_ = 0;   // the plan slot the reader feeds next
    // Bumped (and notified) whenever the reading thread may have work: a chunk's slot emptied, a plan slot filled,
    // the interpreter done, the check stopped.
    std::atomic<std::uint32_t> reader_wake_{0};
    std::atomic<bool> interpreted_{false};    // every plan slot the interpreter fills is filled
    std::atomic<bool> reader_failed_{false};  // the reading thread threw: reader_error_
    std::atomic<bool> stop_reading_{false};   // the interpreting thread threw, or the check was dropped
    std::exception_ptr reader_error_;
    std::thread reader_thread_;
};

}  // namespace essi
