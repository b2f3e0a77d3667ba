#include "plate_runner.hpp"

namespace essi::native {

ThreadPlateRunner::ThreadPlateRunner(std::size_t max_waiting)
    : max_waiting_(max_waiting), thread_([this] { work(); }) {}

ThreadPlateRunner::~ThreadPlateRunner() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void ThreadPlateRunner::run(std::function<void()> job) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.size() < max_waiting_; });
    jobs_.push_back(std::move(job));
    changed_.notify_all();
}

void ThreadPlateRunner::wait() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.empty() && running_ == 0; });
}

void ThreadPlateRunner::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;  // (stopping, nothing left)
        std::function<void()> job = std::move(jobs_.front());
        jobs_.pop_front();
        ++running_;
        changed_.notify_all();  // (room for another)
        lock.unlock();
        job();
        lock.lock();
        --running_;
        changed_.notify_all();
    }
}

}  // namespace essi::native
