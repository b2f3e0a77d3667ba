#include "pipelined_check.hpp"

#include <array>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace essi::native {

CheckResult check_tape_pipelined(std::string_view bytes, const Profile& profile) {
    if (bytes.size() < kPipelineMinBytes) return check_tape(bytes, profile);

    // A ring of chunks: the reader fills slot k, the checker empties it, in order.
    struct Slot {
        Tape chunk;
        std::vector<MotionMeasure> measures;  // worked out by the reading thread (lengths, radii, sweeps)
        bool full = false;
        bool last = false;  // the reader is done: this slot holds nothing
    };
    std::array<Slot, kPipelineChunks> slots;
    std::mutex mutex;
    std::condition_variable changed;

    std::thread reader_thread([&] {
        TapeReader reader(bytes, profile);
        for (std::size_t k = 0;; ++k) {
            Slot& slot = slots[k % slots.size()];
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return !slot.full; });
            }
            const bool more = reader.read_chunk(slot.chunk, kPipelineChunkBlocks);
            measure_motions(slot.chunk, slot.measures);  // the square roots and atan2s, off the interpreting thread
            {
                std::lock_guard lock(mutex);
                slot.full = true;
                slot.last = !more;
            }
            changed.notify_all();
            if (!more) return;
        }
    });

    TapeChecker checker(bytes, profile);
    for (std::size_t k = 0;; ++k) {
        Slot& slot = slots[k % slots.size()];
        {
            std::unique_lock lock(mutex);
            changed.wait(lock, [&] { return slot.full; });
        }
        const bool last = slot.last;
        if (!last) checker.check_chunk(slot.chunk, slot.measures);
        {
            std::lock_guard lock(mutex);
            slot.full = false;
        }
        changed.notify_all();
        if (last) break;
    }
    reader_thread.join();
    return checker.finish();
}

}  // namespace essi::native
