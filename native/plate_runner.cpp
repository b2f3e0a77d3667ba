#include "plate_runner.hpp"

namespace essi::native {

void SharedPlateRunner::run(std::function<void()> job, std::size_t motions) {
    {
        std::lock_guard lock(mutex_);
        if (jobs_.size() < max_waiting_ && waiting_motions_ + motions <= kMaxWaitingMotions) {
            jobs_.push_back({std::move(job), motions});
            waiting_motions_ += motions;
            return;
        }
    }
    job();
}

bool SharedPlateRunner::run_one() {
    Job job;
    {
        std::lock_guard lock(mutex_);
        if (jobs_.empty()) return false;
        job = std::move(jobs_.front());
        jobs_.pop_front();
        waiting_motions_ -= job.motions;
        ++running_;
    }
    job.run();
    {
        std::lock_guard lock(mutex_);
        --running_;
    }
    changed_.notify_all();
    return true;
}

void SharedPlateRunner::wait() {
    while (run_one()) {
    }
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return running_ == 0 && jobs_.empty(); });
}

}  // namespace essi::native
