// Counters behind `essi serve`'s limits on hostile clients (native only, no HTTP in here):
//   ClientSlots  connections open at once, in all and per client address (--max-connections,
//                --max-client-connections)
//   Semaphore    a counting semaphore: requests handled at once (--threads), large bodies at once
//                (--max-large-requests), checks and conversions at once (--max-checks)
//   RateLimit    uploads per minute per client address (--share-rate)
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <map>
#include <mutex>
#include <string>

namespace essi::native {

// The key a client's limits are counted under: its IPv4 address, or the /64 network of an IPv6 address (one
// host commonly owns a whole /64); an IPv4-mapped IPv6 address counts as its IPv4 address.
[[nodiscard]] std::string client_key(const std::string& ip);

class ClientSlots {
public:
    ClientSlots(std::size_t max_total, std::size_t max_per_client)
        : max_total_(max_total), max_per_client_(max_per_client) {}
    // Takes a slot for `client`; false (nothing taken) when either limit is reached.
    bool enter(const std::string& client);
    void leave(const std::string& client);

private:
    std::mutex mutex_;
    std::map<std::string, std::size_t> per_client_;
    std::size_t total_ = 0;
    std::size_t max_total_;
    std::size_t max_per_client_;
};

class Semaphore {
public:
    explicit Semaphore(std::size_t count) : free_(count) {}
    void acquire();
    // acquire() waiting at most `wait`; false (nothing taken) when no slot came free in time.
    bool try_acquire_for(std::chrono::milliseconds wait);
    void release();

private:
    std::mutex mutex_;
    std::condition_variable cv_;
    std::size_t free_;
};

// Holds a Semaphore for a scope (nothing when `sem` is null). With a `wait`, gives up after it: then held() is
// false and nothing is released.
class SemaphoreHold {
public:
    explicit SemaphoreHold(Semaphore* sem) : sem_(sem) {
        if (sem_) sem_->acquire();
    }
    SemaphoreHold(Semaphore* sem, std::chrono::milliseconds wait) : sem_(sem) {
        if (sem_ && !sem_->try_acquire_for(wait)) sem_ = nullptr, held_ = false;
    }
    ~SemaphoreHold() {
        if (sem_) sem_->release();
    }
    [[nodiscard]] bool held() const { return held_; }
    SemaphoreHold(const SemaphoreHold&) = delete;
    SemaphoreHold& operator=(const SemaphoreHold&) = delete;

private:
    Semaphore* sem_;
    bool held_ = true;
};

// At most `per_minute` events per client in any 60 s window (0 = no limit).
class RateLimit {
public:
    using Clock = std::chrono::steady_clock;
    explicit RateLimit(unsigned per_minute) : per_minute_(per_minute) {}
    // 0 when the event is allowed (and counted), else the seconds until it would be.
    unsigned try_take(const std::string& client, Clock::time_point now = Clock::now());

private:
    std::mutex mutex_;
    std::map<std::string, std::deque<Clock::time_point>> events_;
    unsigned per_minute_;
};

}  // namespace essi::native
