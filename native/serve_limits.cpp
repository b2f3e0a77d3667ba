#include "serve_limits.hpp"

#include <arpa/inet.h>

namespace essi::native {

std::string client_key(const std::string& ip) {
    in6_addr a{};
    if (ip.find(':') == std::string::npos || inet_pton(AF_INET6, ip.c_str(), &a) != 1) return ip;
    if (IN6_IS_ADDR_V4MAPPED(&a)) return ip.substr(ip.rfind(':') + 1);
    for (int i = 8; i < 16; ++i) a.s6_addr[i] = 0;
    char buf[INET6_ADDRSTRLEN] = "";
    inet_ntop(AF_INET6, &a, buf, sizeof buf);
    return std::string(buf) + "/64";
}

bool ClientSlots::enter(const std::string& client) {
    std::lock_guard lock(mutex_);
    std::size_t& mine = per_client_[client];
    if (total_ >= max_total_ || mine >= max_per_client_) {
        if (mine == 0) per_client_.erase(client);
        return false;
    }
    ++mine;
    ++total_;
    return true;
}

void ClientSlots::leave(const std::string& client) {
    std::lock_guard lock(mutex_);
    auto it = per_client_.find(client);
    if (it == per_client_.end()) return;
    if (--it->second == 0) per_client_.erase(it);
    --total_;
}

void Semaphore::acquire() {
    std::unique_lock lock(mutex_);
    cv_.wait(lock, [this] { return free_ > 0; });
    --free_;
}

bool Semaphore::try_acquire_for(std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    if (!cv_.wait_for(lock, wait, [this] { return free_ > 0; })) return false;
    --free_;
    return true;
}

void Semaphore::release() {
    {
        std::lock_guard lock(mutex_);
        ++free_;
    }
    cv_.notify_one();
}

unsigned RateLimit::try_take(const std::string& client, Clock::time_point now) {
    if (per_minute_ == 0) return 0;
    std::lock_guard lock(mutex_);
    // Forget clients whose window is empty, so that the map stays as small as the set of recent uploaders.
    for (auto it = events_.begin(); it != events_.end();) {
        while (!it->second.empty() && now - it->second.front() >= std::chrono::minutes(1)) it->second.pop_front();
        it = it->second.empty() ? events_.erase(it) : std::next(it);
    }
    std::deque<Clock::time_point>& mine = events_[client];
    if (mine.size() < per_minute_) {
        mine.push_back(now);
        return 0;
    }
    const auto wait = std::chrono::minutes(1) - (now - mine.front());
    return static_cast<unsigned>(std::chrono::ceil<std::chrono::seconds>(wait).count()) + 0u;
}

}  // namespace essi::native
