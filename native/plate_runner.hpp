// The cut plan's plates (essi::PlateRunner) queued for whichever thread of the pipelined check has time: the reading
// thread analyses one whenever it would otherwise wait for the interpreter (run_one), and wait() analyses what is
// left on the caller's thread. It starts no thread of its own: on two cores a third thread slows the two that read
// and interpret.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>

#include "essi/plan.hpp"

namespace essi::native {

class SharedPlateRunner final : public PlateRunner {
public:
    // At most `max_waiting` plates, of at most kMaxWaitingMotions cutting motions together, wait in the queue;
    // run() analyses a plate beyond that at once, on its caller's thread (a tape of many or large plates does not
    // pile up in memory when the reader has no time for them).
    explicit SharedPlateRunner(std::size_t max_waiting = kMaxWaitingPlates) : max_waiting_(max_waiting) {}
    void run(std::function<void()> job, std::size_t motions) override;
    // Runs every plate queued, then waits for those another thread is running.
    void wait() override;
    // Runs the oldest plate queued, if any; false when none was.
    bool run_one();

    static constexpr std::size_t kMaxWaitingPlates = 8;
    static constexpr std::size_t kMaxWaitingMotions = kPlanMaxPlateMotions;

private:
    struct Job {
        std::function<void()> run;
        std::size_t motions;
    };
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Job> jobs_;
    std::size_t waiting_motions_ = 0;
    std::size_t running_ = 0;
    std::size_t max_waiting_;
};

}  // namespace essi::native
