// A small pool of worker threads for the CLI's batch check: runs work(i) for i in [0, n) on up to `jobs`
// threads and hands the results back on the calling thread in index order (deterministic output).
#pragma once

#include <cstddef>
#include <functional>

#include "essi/threads.hpp"  // (kHaveThreads)

namespace essi::native {

// Calls work(i) for every i in [0, n) on `jobs` worker threads (jobs <= 1 or no threads: on the calling thread), and
// emit(i) on the calling thread in increasing i, as soon as items 0..i are done. At most `window` items
// are taken ahead of the last emitted one (bounds the memory of results waiting to be emitted).
// work must not throw (an exception terminates the program).
void for_each_ordered(std::size_t n, unsigned jobs, const std::function<void(std::size_t)>& work,
                      const std::function<void(std::size_t)>& emit, std::size_t window = 0);

// The number of hardware threads (at least 1).
[[nodiscard]] unsigned hardware_jobs();

}  // namespace essi::native
