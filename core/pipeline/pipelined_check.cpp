// Checking one tape on two threads (essi/pipelined_check.hpp).
#include "essi/pipelined_check.hpp"

namespace essi {

PipelinedCheck::PipelinedCheck(TapeChecker& checker, TapeReader reader, Hooks hooks, std::size_t chunk_blocks)
    : checker_(checker), hooks_(std::move(hooks)), chunk_blocks_(chunk_blocks) {
    reader_thread_ = std::thread(
        [this](TapeReader r) {
            try {
                read_all(r);
            } catch (...) {
                reader_error_ = std::current_exception();
                release_interpreter();
            }
        },
        std::move(reader));
}

PipelinedCheck::~PipelinedCheck() {
    if (reader_thread_.joinable()) stop_reader();
}

void PipelinedCheck::wake_reader() {
    reader_wake_.fetch_add(1, std::memory_order_release);
    wake_one(reader_wake_);
}

// The interpreting thread is done with (or has given up on) the check: the reading thread returns where it is.
void PipelinedCheck::stop_reader() {
    stop_reading_.store(1, std::memory_order_release);
    wake_reader();
    reader_thread_.join();
}

// The reading thread failed: every empty chunk slot says "last" and every plan slot is empty, so that the interpreting
// thread, waiting for either or coming to them, sees reader_failed_ and stops.
void PipelinedCheck::release_interpreter() {
    reader_failed_.store(1, std::memory_order_release);
    for (Slot& s : slots_) {
        if (s.full.load(std::memory_order_acquire)) continue;
        s.last = true;
        s.full.store(1, std::memory_order_release);
        wake_one(s.full);
    }
    for (PlanSlot& p : plan_slots_) {
        p.full.store(0, std::memory_order_release);
        wake_one(p.full);
    }
}

// Feeds the plan slots filled, in order; false when none was.
bool PipelinedCheck::feed_plan() {
    bool fed = false;
    for (;; ++next_plan_, fed = true) {
        PlanSlot& p = plan_slots_[next_plan_ % plan_slots_.size()];
        if (!p.full.load(std::memory_order_acquire)) return fed;
        if (hooks_.before_feed) hooks_.before_feed(p.stream);
        checker_.feed_plan(p.stream);
        p.full.store(0, std::memory_order_release);
        wake_one(p.full);
    }
}

void PipelinedCheck::read_all(TapeReader& reader) {
    const auto idle = [this] { return hooks_.idle && hooks_.idle(); };
    bool reading = true;
    for (std::size_t k = 0;;) {
        const std::uint32_t seen = reader_wake_.load(std::memory_order_acquire);
        if (stop_reading_.load(std::memory_order_acquire)) return;
        if (feed_plan()) continue;  // (first: the interpreter may be waiting for a plan slot)
        if (!reading) {
            if (!interpreted_.load(std::memory_order_acquire)) {
                if (!idle()) wait_while(reader_wake_, seen);
                continue;
            }
            feed_plan();  // (what was filled before `interpreted_` was set)
            return;
        }
        Slot& slot = slots_[k % slots_.size()];
        if (slot.full.load(std::memory_order_acquire)) {
            if (!idle()) wait_while(reader_wake_, seen);
            continue;
        }
        if (hooks_.keep_readers) slot.before = reader;
        const bool more = reader.read_chunk(slot.chunk, chunk_blocks_);
        // The arcs' square roots and atan2s, off the interpreting thread, but only while a chunk waits for it besides
        // the one it is checking (this thread is ahead): else the chunk goes at once and the interpreter measures its
        // arcs itself (the same formula, the same numbers). The two threads balance their work so, whichever is
        // faster on the machine.
        std::size_t full = 0;
        for (const Slot& s : slots_) full += s.full.load(std::memory_order_relaxed) ? 1 : 0;
        if (full >= 2) measure_motions(slot.chunk, slot.measures);
        else slot.measures.clear();
        slot.last = !more;
        slot.full.store(1, std::memory_order_release);
        wake_one(slot.full);
        ++k;
        reading = more;
    }
}

// The chunks in order until the last (true) or until `in_time` says false after one.
bool PipelinedCheck::interpret_chunks(const std::function<bool()>& in_time) {
    const auto idle = [this] { return hooks_.idle && hooks_.idle(); };
    for (;;) {
        const std::size_t k = next_chunk_;
        Slot& slot = slots_[k % slots_.size()];
        while (!slot.full.load(std::memory_order_acquire) && idle()) {
        }
        wait_while(slot.full, 0);
        const bool last = slot.last;
        if (!last) {
            PlanSlot& plan = plan_slots_[k % plan_slots_.size()];
            while (plan.full.load(std::memory_order_acquire) && idle()) {
            }
            wait_while(plan.full, 1);
            if (reader_failed_.load(std::memory_order_acquire)) return true;
            if (hooks_.chunk_read) hooks_.chunk_read(slot.chunk, slot.before);
            checker_.check_chunk(slot.chunk, slot.measures, plan.stream);
            plan.full.store(1, std::memory_order_release);
        }
        slot.full.store(0, std::memory_order_release);
        wake_one(slot.full);
        if (last) return true;
        ++next_chunk_;
        wake_reader();
        if (in_time && !in_time()) return false;
    }
}

bool PipelinedCheck::run(const std::function<bool()>& in_time) {
    try {
        if (!interpret_chunks(in_time)) return false;
    } catch (...) {
        stop_reader();
        throw;
    }
    interpreted_.store(1, std::memory_order_release);
    wake_reader();
    reader_thread_.join();
    if (reader_error_) std::rethrow_exception(reader_error_);
    return true;
}

}  // namespace essi
