#include "pipelined_check.hpp"

#include "plate_runner.hpp"
#include "thread_pool.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include "essi/pipeline.hpp"

namespace essi::native {

namespace {
// What a thread writing a line takes from another core's cache (x86-64 and most others).
constexpr std::size_t kCacheLineBytes = 64;
}  // namespace

CheckResult check_tape_pipelined(std::string_view bytes, const TapeSetup& setup, std::size_t max_diagnostics,
                                 bool parts) {
    CheckResult r = check_tape_pipelined(bytes, setup.profile, setup.format, max_diagnostics, parts);
    record_setup(r, setup);
    return r;
}

CheckResult check_tape_pipelined(std::string_view bytes, const Profile& profile, InputFormat format,
                                 std::size_t max_diagnostics, bool parts) {
    // (without threads, e.g. under Emscripten without pthreads: the same check on this thread)
    if (bytes.size() < kPipelineMinBytes || !kHaveThreads)
        return check_tape(bytes, profile, format, max_diagnostics, parts);

    // A ring of chunks: the reader fills slot k, the checker empties it, in order. A slot changes hands through
    // its atomic `full` flag (C++20 wait/notify: a short spin, then a futex), so a thread that is only a little
    // ahead does not go to sleep and wait to be woken at every chunk.
    // (each slot on cache lines of its own: the thread filling one writes its vectors' ends at every item, and must
    // not take the lines of the slot the other thread is reading from it)
    struct alignas(kCacheLineBytes) Slot {
        Tape chunk;
        std::vector<MotionMeasure> measures;  // worked out by the reading thread (arcs: radii, sweeps)
        bool last = false;                    // the reader is done: this slot holds nothing
        std::atomic<bool> full{false};
    };
    std::array<Slot, kPipelineChunks> slots;
    // A second ring, the other way: the interpreter's stream for the cut plan, a chunk's in each slot, which the
    // reading thread feeds to the plan (TapeChecker::feed_plan) between its chunks.
    struct alignas(kCacheLineBytes) PlanSlot {
        MotionBuffer stream;
        std::atomic<bool> full{false};
    };
    std::array<PlanSlot, kPipelinePlanChunks> plan_slots;
    // Bumped (and notified) by the interpreting thread whenever the reading thread may have work: a chunk's slot
    // emptied, a plan slot filled, the interpreter done.
    std::atomic<std::uint32_t> reader_wake{0};
    std::atomic<bool> interpreted{false};  // every plan slot the interpreter fills is filled
    const auto wake_reader = [&] {
        reader_wake.fetch_add(1, std::memory_order_release);
        reader_wake.notify_one();
    };
    // A thread that throws (no memory for a chunk, say) ends the check on both, and its exception comes out of this
    // call once the reading thread is joined: never std::terminate, never a thread left waiting for the other
    // (essi serve answers the request with an error and goes on).
    std::atomic<bool> reader_failed{false};  // the reading thread threw: `reader_error`
    std::atomic<bool> stop_reading{false};   // the interpreting thread threw: the reading thread returns
    std::exception_ptr reader_error;
    // The reading thread, failed: every empty chunk slot says "last" and every plan slot is empty, so that the
    // interpreting thread, waiting for either or coming to them, sees `reader_failed` and stops.
    const auto release_interpreter = [&] {
        reader_failed.store(true, std::memory_order_release);
        for (Slot& s : slots) {
            if (s.full.load(std::memory_order_acquire)) continue;
            s.last = true;
            s.full.store(true, std::memory_order_release);
            s.full.notify_one();
        }
        for (PlanSlot& p : plan_slots) {
            p.full.store(false, std::memory_order_release);
            p.full.notify_one();
        }
    };
    // The cut plan's plates, analysed by whichever thread would otherwise wait for the other.
    SharedPlateRunner plates;

    TapeChecker checker(bytes, profile);
    checker.set_max_diagnostics(max_diagnostics);
    checker.set_plate_runner(&plates);
    if (parts) checker.find_parts();

    const auto read_all = [&] {
        TapeReader reader(bytes, profile, format);
        std::size_t next_plan = 0;  // the plan slot to feed next
        // Feeds the plan slots filled, in order; false when none was.
        const auto feed_plan = [&] {
            bool fed = false;
            for (;; ++next_plan, fed = true) {
                PlanSlot& p = plan_slots[next_plan % plan_slots.size()];
                if (!p.full.load(std::memory_order_acquire)) return fed;
                checker.feed_plan(p.stream);
                p.full.store(false, std::memory_order_release);
                p.full.notify_one();
            }
        };
        bool reading = true;
        for (std::size_t k = 0;;) {
            const std::uint32_t seen = reader_wake.load(std::memory_order_acquire);
            if (stop_reading.load(std::memory_order_acquire)) return;
            if (feed_plan()) continue;  // (first: the interpreter may be waiting for a plan slot)
            if (!reading) {
                if (!interpreted.load(std::memory_order_acquire)) {
                    if (!plates.run_one()) reader_wake.wait(seen, std::memory_order_acquire);
                    continue;
                }
                feed_plan();  // (what was filled before `interpreted` was set)
                return;
            }
            Slot& slot = slots[k % slots.size()];
            if (slot.full.load(std::memory_order_acquire)) {
                if (!plates.run_one()) reader_wake.wait(seen, std::memory_order_acquire);
                continue;
            }
            const bool more = reader.read_chunk(slot.chunk, kPipelineChunkBlocks);
            // The arcs' square roots and atan2s, off the interpreting thread, but only while a chunk waits for
            // it besides the one it is checking (this thread is ahead): else the chunk goes at once and the
            // interpreter measures its arcs itself (the same formula, the same numbers). The two threads
            // balance their work so, whichever is faster on the machine.
            std::size_t full = 0;
            for (const Slot& s : slots) full += s.full.load(std::memory_order_relaxed) ? 1 : 0;
            if (full >= 2) measure_motions(slot.chunk, slot.measures);
            else slot.measures.clear();
            slot.last = !more;
            slot.full.store(true, std::memory_order_release);
            slot.full.notify_one();
            ++k;
            reading = more;
        }
    };
    std::thread reader_thread([&] {
        try {
            read_all();
        } catch (...) {
            reader_error = std::current_exception();
            release_interpreter();
        }
    });

    const auto interpret_all = [&] {
        for (std::size_t k = 0;; ++k) {
            Slot& slot = slots[k % slots.size()];
            while (!slot.full.load(std::memory_order_acquire) && plates.run_one()) {
            }
            slot.full.wait(false, std::memory_order_acquire);
            const bool last = slot.last;
            if (!last) {
                PlanSlot& plan = plan_slots[k % plan_slots.size()];
                while (plan.full.load(std::memory_order_acquire) && plates.run_one()) {
                }
                plan.full.wait(true, std::memory_order_acquire);
                if (reader_failed.load(std::memory_order_acquire)) return;
                checker.check_chunk(slot.chunk, slot.measures, plan.stream);
                plan.full.store(true, std::memory_order_release);
            }
            slot.full.store(false, std::memory_order_release);
            slot.full.notify_one();
            if (last) return;
            wake_reader();
        }
    };
    try {
        interpret_all();
    } catch (...) {
        stop_reading.store(true, std::memory_order_release);
        wake_reader();
        reader_thread.join();
        throw;
    }
    interpreted.store(true, std::memory_order_release);
    wake_reader();
    reader_thread.join();
    if (reader_error) std::rethrow_exception(reader_error);
    CheckResult r = checker.finish();
    r.input = format;
    r.profile = profile.name;
    return r;
}

}  // namespace essi::native
