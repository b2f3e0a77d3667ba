// Whether this build can start threads: natively yes; under Emscripten only when built with pthreads (the viewer's
// reading worker essi_reader_mt, web/CMakeLists.txt), not in the page's program, the npm package's CLI or the
// unit tests under node, where everything runs on the calling thread. And a thread's wait for another's word.
#pragma once

#include <atomic>
#include <cstdint>

#if defined(__EMSCRIPTEN_PTHREADS__)
#include <emscripten/threading.h>

#include <cmath>
#endif

namespace essi {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kHaveThreads = false;
#else
inline constexpr bool kHaveThreads = true;
#endif

// Waits while `a` holds `old`, and wakes a thread that waits on `a`: std::atomic's wait and notify_one, but with
// Emscripten's pthreads a futex (Atomics.wait and notify). There the C++ library's wait polls with sleeps that grow
// with the time waited and its notify does nothing, so a thread woke up milliseconds late at every chunk: the
// viewer's worker on two threads read 10 M motions no faster than on one.
inline void wait_while(const std::atomic<std::uint32_t>& a, std::uint32_t old) {
#if defined(__EMSCRIPTEN_PTHREADS__)
    while (a.load(std::memory_order_acquire) == old)
        emscripten_futex_wait(const_cast<std::atomic<std::uint32_t>*>(&a), old, INFINITY);
#else
    a.wait(old, std::memory_order_acquire);
#endif
}
inline void wake_one(std::atomic<std::uint32_t>& a) {
#if defined(__EMSCRIPTEN_PTHREADS__)
    emscripten_futex_wake(&a, 1);
#else
    a.notify_one();
#endif
}

}  // namespace essi
