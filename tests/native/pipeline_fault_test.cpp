// The two-thread check (native/pipelined_check.cpp) when one of its threads throws: the exception comes out of
// check_tape_pipelined, on the caller's thread, once both threads are done; nothing calls std::terminate, nothing
// waits for ever, and the next check is whole. The failure is an allocation refused on demand: this test binary
// replaces operator new (so it is a program of its own: every other test keeps the library's).
#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "../bench/nest_generator.hpp"
#include "../unit/test_util.hpp"
#include "essi/pipeline.hpp"
#include "pipelined_check.hpp"

namespace {

// What operator new does with allocations of at least kBigBytes (a chunk's blocks, the interpreter's buffers):
// count them, or refuse the one after `g_skip` more, once, on the thread chosen.
constexpr std::size_t kBigBytes = 64 * 1024;
enum class Mode { Off, Count, FailCaller, FailOther };
std::atomic<Mode> g_mode{Mode::Off};
std::atomic<long> g_skip{0};
std::atomic<long> g_counted{0};
std::thread::id g_caller;  // the thread that called the check (the interpreting thread)

bool refuse(std::size_t n) {
    const Mode mode = g_mode.load(std::memory_order_acquire);
    if (mode == Mode::Off || n < kBigBytes) return false;
    const bool caller = std::this_thread::get_id() == g_caller;
    if (mode == Mode::Count) {
        if (caller) g_counted.fetch_add(1);
        return false;
    }
    if (caller != (mode == Mode::FailCaller)) return false;
    if (g_skip.fetch_sub(1) > 0) return false;
    g_mode.store(Mode::Off, std::memory_order_release);  // (once)
    return true;
}

}  // namespace

void* operator new(std::size_t n) {
    if (refuse(n)) throw std::bad_alloc();
    if (void* p = std::malloc(n > 0 ? n : 1)) return p;
    throw std::bad_alloc();
}
// (g++ takes the replaced operator delete's free() for a mismatch with new: it is this operator new's malloc())
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

using essi::native::check_tape_pipelined;
using essi::native::kPipelineMinBytes;

const std::string& tape() {
    static const std::string t = essi::bench::generate_nest_tape(4 * kPipelineMinBytes, 5);
    return t;
}

// The big allocations the calling thread makes in one check of the tape.
long caller_allocations() {
    g_caller = std::this_thread::get_id();
    g_counted = 0;
    g_mode = Mode::Count;
    (void)check_tape_pipelined(tape(), essi::Profile{});
    g_mode = Mode::Off;
    return g_counted.load();
}

// One check with the big allocation after `skip` more refused on the thread `mode` names: the call throws
// std::bad_alloc once both threads are done, an allocation was refused indeed, and the next check is whole.
void expect_refused(Mode mode, long skip) {
    g_caller = std::this_thread::get_id();
    g_skip = skip;
    g_mode = mode;
    EXPECT_THROW((void)check_tape_pipelined(tape(), essi::Profile{}), std::bad_alloc);
    EXPECT_EQ(g_mode.load(), Mode::Off) << "no allocation was refused: the test did not test";
    g_mode = Mode::Off;
    const essi::Profile profile;
    essi_test::expect_same_result(check_tape_pipelined(tape(), profile), essi::check_tape(tape(), profile),
                                  "the check after the failed one");
}

TEST(PipelineFault, TheReadingThreadFailsInTheMiddle) {
    for (const long skip : {0L, 2L, 5L}) {  // its first chunk, the third, the sixth
        SCOPED_TRACE("allocations let through first: " + std::to_string(skip));
        expect_refused(Mode::FailOther, skip);
    }
}

TEST(PipelineFault, TheInterpretingThreadFailsInTheMiddle) {
    const long big = caller_allocations();
    ASSERT_GE(big, 4) << "the interpreting thread's big allocations: too few to fail one in the middle";
    for (const long skip : {big / 4, big / 2}) {
        SCOPED_TRACE("allocations let through first: " + std::to_string(skip) + " of " + std::to_string(big));
        expect_refused(Mode::FailCaller, skip);
    }
}

}  // namespace
