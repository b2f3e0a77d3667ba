#include "thread_pool.hpp"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace essi::native {

unsigned hardware_jobs() {
    if (!kHaveThreads) return 1;
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : n;
}

void for_each_ordered(std::size_t n, unsigned jobs, const std::function<void(std::size_t)>& work,
                      const std::function<void(std::size_t)>& emit, std::size_t window) {
    if (jobs <= 1 || n <= 1 || !kHaveThreads) {
        for (std::size_t i = 0; i < n; ++i) {
            work(i);
            emit(i);
        }
        return;
    }
    const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(jobs, n));
    if (window == 0) window = std::max<std::size_t>(64, 8u * workers);

    std::mutex mutex;
    std::condition_variable taken_cv;  // workers wait here for room in the window
    std::condition_variable done_cv;   // the emitter waits here for the next item
    std::vector<char> done(n, 0);
    std::size_t next = 0;     // next item to take
    std::size_t emitted = 0;  // items emitted so far

    std::vector<std::thread> threads;
    threads.reserve(workers);
    for (unsigned t = 0; t < workers; ++t) {
        threads.emplace_back([&] {
            for (;;) {
                std::size_t i;
                {
                    std::unique_lock lock(mutex);
                    taken_cv.wait(lock, [&] { return next >= n || next < emitted + window; });
                    if (next >= n) return;
                    i = next++;
                }
                work(i);
                {
                    std::lock_guard lock(mutex);
                    done[i] = 1;
                }
                done_cv.notify_one();
            }
        });
    }
    for (std::size_t i = 0; i < n; ++i) {
        {
            std::unique_lock lock(mutex);
            done_cv.wait(lock, [&] { return done[i] != 0; });
        }
        emit(i);
        {
            std::lock_guard lock(mutex);
            emitted = i + 1;
        }
        taken_cv.notify_all();
    }
    for (std::thread& t : threads) t.join();
}

}  // namespace essi::native
