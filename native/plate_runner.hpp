// The cut plan's plates analysed on a thread of their own (essi::PlateRunner), while the caller's thread goes on
// interpreting the tape: the pipelined check's third party.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include "essi/plan.hpp"

namespace essi::native {

class ThreadPlateRunner final : public PlateRunner {
public:
    // At most `max_waiting` plates wait for the thread; run() waits for room beyond that (a tape of many plates
    // does not pile up in memory when the thread falls behind).
    explicit ThreadPlateRunner(std::size_t max_waiting = kMaxWaitingPlates);
    ~ThreadPlateRunner() override;
    ThreadPlateRunner(const ThreadPlateRunner&) = delete;
    ThreadPlateRunner& operator=(const ThreadPlateRunner&) = delete;

    void run(std::function<void()> job) override;
    void wait() override;

    static constexpr std::size_t kMaxWaitingPlates = 8;

private:
    void work();

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::function<void()>> jobs_;
    std::size_t running_ = 0;
    std::size_t max_waiting_;
    bool stopping_ = false;
    std::thread thread_;  // (last: started once the rest is ready)
};

}  // namespace essi::native
