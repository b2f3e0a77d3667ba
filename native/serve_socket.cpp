#include "serve_socket.hpp"

#include <cstdio>
#include <cstring>

#if defined(ESSI_HAVE_HTTPLIB)
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace essi::native {

namespace {

using Clock = std::chrono::steady_clock;

std::string address_of(const sockaddr_storage& sa, int& port) {
    char buf[INET6_ADDRSTRLEN] = "";
    if (sa.ss_family == AF_INET) {
        const auto* in = reinterpret_cast<const sockaddr_in*>(&sa);
        inet_ntop(AF_INET, &in->sin_addr, buf, sizeof buf);
        port = ntohs(in->sin_port);
    } else if (sa.ss_family == AF_INET6) {
        const auto* in6 = reinterpret_cast<const sockaddr_in6*>(&sa);
        inet_ntop(AF_INET6, &in6->sin6_addr, buf, sizeof buf);
        port = ntohs(in6->sin6_port);
    }
    return buf;
}

struct Endpoint {
    std::string ip;
    int port = -1;
};

Endpoint endpoint(socket_t sock, bool peer) {
    sockaddr_storage sa{};
    socklen_t len = sizeof sa;
    Endpoint e;
    const int rc = peer ? getpeername(sock, reinterpret_cast<sockaddr*>(&sa), &len)
                        : getsockname(sock, reinterpret_cast<sockaddr*>(&sa), &len);
    if (rc == 0) e.ip = address_of(sa, e.port);
    return e;
}

bool wait_for(socket_t sock, short events, int timeout_ms) {
    if (timeout_ms <= 0) return false;
    pollfd p{sock, events, 0};
    int rc;
    while ((rc = poll(&p, 1, timeout_ms)) < 0 && errno == EINTR) {
    }
    return rc > 0;
}

std::string seconds_text(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", s);
    return buf;
}

// A socket stream with the deadlines of serve_socket.hpp: the head (request line and headers) and the body of a
// request share the reads, each with its own deadline and size limits; the response's writes have theirs.
class DeadlineStream : public httplib::Stream {
public:
    enum class Failure { none, head_timeout, head_too_large, line_too_long, body_too_slow, body_timeout };

    DeadlineStream(socket_t sock, const ConnectionLimits& limits)
        : sock_(sock), limits_(limits), remote_(endpoint(sock, true)), local_(endpoint(sock, false)) {}
    void begin_request() {
        phase_ = Phase::head;
        start_ = Clock::now();
        bytes_ = lines_ = line_ = 0;
        failure_ = Failure::none;
    }
    void begin_body() {
        phase_ = Phase::body;
        start_ = Clock::now();
        bytes_ = line_ = 0;
    }
    bool is_readable() const override { return wait_for(sock_, POLLIN, remaining_ms()); }
    bool is_writable() const override { return wait_for(sock_, POLLOUT, remaining_ms()); }
    ssize_t read(char* ptr, size_t size) override {
        if (phase_ == Phase::head) {
            if (bytes_ >= kMaxHeadBytes) return fail(Failure::head_too_large);
            size = std::min(size, kMaxHeadBytes - bytes_);
        }
        ssize_t n;
        if (buffered()) {
            n = static_cast<ssize_t>(std::min(size, buf_len_ - buf_pos_));
            std::memcpy(ptr, buf_ + buf_pos_, static_cast<std::size_t>(n));
            buf_pos_ += static_cast<std::size_t>(n);
        } else {
            if (!is_readable()) {
                if (phase_ == Phase::head) return fail(Failure::head_timeout);
                return fail(total_deadline() <= rate_deadline() ? Failure::body_timeout : Failure::body_too_slow);
            }
            // Small reads (cpp-httplib reads lines a byte at a time) are served from one recv of up to 4 KB.
            char* into = size >= sizeof buf_ ? ptr : buf_;
            while ((n = recv(sock_, into, size >= sizeof buf_ ? size : sizeof buf_, 0)) < 0 && errno == EINTR) {
            }
            if (n <= 0) return n;
            if (into == buf_) {
                buf_len_ = static_cast<std::size_t>(n);
                n = static_cast<ssize_t>(std::min(size, buf_len_));
                std::memcpy(ptr, buf_, static_cast<std::size_t>(n));
                buf_pos_ = static_cast<std::size_t>(n);
            }
        }
        bytes_ += static_cast<std::size_t>(n);
        // cpp-httplib reads lines (the request line, headers, chunk sizes) a byte at a time, into a string that
        // grows until the line ends: a line is cut at kMaxLineBytes, the head at kMaxHeadLines lines.
        if (size == 1) {
            if (*ptr != '\n') {
                if (++line_ > kMaxLineBytes) return fail(Failure::line_too_long);
            } else {
                line_ = 0;
                if (phase_ == Phase::head && ++lines_ > kMaxHeadLines) return fail(Failure::head_too_large);
            }
        }
        return n;
    }
    ssize_t write(const char* ptr, size_t size) override {
        if (phase_ != Phase::write) {
            phase_ = Phase::write;
            start_ = Clock::now();
            bytes_ = 0;
        }
        if (!is_writable()) return -1;
        ssize_t n;
        while ((n = send(sock_, ptr, size, MSG_NOSIGNAL)) < 0 && errno == EINTR) {
        }
        if (n > 0) bytes_ += static_cast<std::size_t>(n);
        return n;
    }
    void get_remote_ip_and_port(std::string& ip, int& port) const override { ip = remote_.ip, port = remote_.port; }
    void get_local_ip_and_port(std::string& ip, int& port) const override { ip = local_.ip, port = local_.port; }
    socket_t socket() const override { return sock_; }
    const std::string& remote_ip() const { return remote_.ip; }
    [[nodiscard]] Failure failure() const { return failure_; }
    // Bytes received and not read yet (the start of a next request on the connection).
    [[nodiscard]] bool buffered() const { return buf_pos_ < buf_len_; }
    [[nodiscard]] const ConnectionLimits& limits() const { return limits_; }

private:
    enum class Phase { head, body, write };
    ssize_t fail(Failure f) {
        failure_ = f;
        return -1;
    }
    // The head's deadline, or the minimum rate's (request_timeout_s + bytes / min_rate) of a body or a response.
    Clock::time_point rate_deadline() const {
        Clock::time_point deadline = start_ + std::chrono::seconds(limits_.request_timeout_s);
        if (phase_ == Phase::head) return deadline;
        return deadline +
               std::chrono::milliseconds(static_cast<long long>(static_cast<double>(bytes_) / limits_.min_rate * 1000));
    }
    Clock::time_point total_deadline() const { return start_ + std::chrono::seconds(limits_.body_timeout_s); }
    int remaining_ms() const {
        using ms = std::chrono::milliseconds;
        const Clock::time_point deadline =
            phase_ == Phase::body ? std::min(rate_deadline(), total_deadline()) : rate_deadline();
        return static_cast<int>(
            std::min<long long>(std::chrono::duration_cast<ms>(deadline - Clock::now()).count(), 1 << 30));
    }
    socket_t sock_;
    const ConnectionLimits& limits_;
    Endpoint remote_, local_;
    Phase phase_ = Phase::head;
    Clock::time_point start_ = Clock::now();
    std::size_t bytes_ = 0;  // read in this phase, or written
    std::size_t lines_ = 0;  // lines of the head
    std::size_t line_ = 0;   // bytes of the line being read a byte at a time
    Failure failure_ = Failure::none;
    char buf_[4096];
    std::size_t buf_pos_ = 0, buf_len_ = 0;
};

// One thread per connection, at most `max` at once: enqueue() waits for a free one, which stops the accept
// loop (the kernel's backlog holds the next connections) instead of queueing sockets without bound.
// When all are taken, `evict` is asked to close a waiting connection (WaitingConnections::evict_one).
class ConnectionThreads : public httplib::TaskQueue {
public:
    ConnectionThreads(std::size_t max, std::function<bool()> evict) : max_(max), evict_(std::move(evict)) {}
    void enqueue(std::function<void()> fn) override {
        std::unique_lock lock(mutex_);
        while (running_ >= max_) {
            lock.unlock();
            const bool freeing = evict_ && evict_();
            lock.lock();
            cv_.wait_for(lock, std::chrono::milliseconds(freeing ? 20 : 200), [this] { return running_ < max_; });
        }
        ++running_;
        std::thread([this, fn = std::move(fn)] {
            fn();
            std::lock_guard done(mutex_);
            --running_;
            cv_.notify_all();
        }).detach();
    }
    void shutdown() override {
        std::unique_lock lock(mutex_);
        cv_.wait(lock, [this] { return running_ == 0; });
    }

private:
    std::mutex mutex_;
    std::condition_variable cv_;
    std::size_t running_ = 0;
    std::size_t max_;
    std::function<bool()> evict_;
};

void refuse(socket_t sock) {
    static const std::string kBody = R"({"error":"too many connections from this address; retry later","status":429})";
    static const std::string kBusy =
        "HTTP/1.1 429 Too Many Requests\r\nContent-Type: application/json\r\nRetry-After: 1\r\nConnection: close\r\n"
        "Content-Length: " +
        std::to_string(kBody.size()) + "\r\n\r\n" + kBody;
    [[maybe_unused]] const ssize_t n = send(sock, kBusy.data(), kBusy.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
}

thread_local bool t_close_after = false;
thread_local bool t_routed = false;               // the request reached the routes (not refused by httplib itself)
thread_local bool t_body_unread = false;          // the request declared a body not read to its end
thread_local Semaphore* t_worker = nullptr;       // the worker slot this thread holds, if any
thread_local DeadlineStream* t_stream = nullptr;  // the connection this thread serves

}  // namespace

HardenedServer::HardenedServer(const ConnectionLimits& limits)
    : limits_(limits), slots_(limits.max_connections, limits.max_client_connections), workers_(limits.threads) {
    const std::size_t max = limits.max_connections;
    new_task_queue = [this, max] { return new ConnectionThreads(max, [this] { return waiting_.evict_one(); }); };
    set_keep_alive_timeout(limits.keep_alive_timeout_s);
    set_socket_options(exclusive_socket_options);
    set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (!t_worker) workers_.acquire();
        t_worker = &workers_;
        t_routed = true;
        if (t_stream) waiting_.busy(t_stream->socket());
        t_body_unread = req.has_header("Transfer-Encoding") ||
                        (req.has_header("Content-Length") && req.get_header_value("Content-Length") != "0");
        return guard_ ? guard_(req, res) : HandlerResponse::Unhandled;
    });
    set_post_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (finisher_) finisher_(req, res);
    });
}

// The answer went out before the request's body was read (413, 503, a 4xx): the client may still be sending it.
// Closing now would make the kernel answer its next bytes with a reset, which can destroy the answer before the
// client has read it (curl: "Broken pipe", "Connection reset by peer"). So the server says it has written all
// (FIN), then reads and drops what comes until the client closes, for at most kLingerMs and kLingerBytes.
namespace {
void linger(socket_t sock) {
    ::shutdown(sock, SHUT_WR);
    const Clock::time_point until = Clock::now() + std::chrono::milliseconds(kLingerMs);
    char scratch[16384];
    std::size_t dropped = 0;
    while (dropped < kLingerBytes) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
        if (left <= 0 || !wait_for(sock, POLLIN, static_cast<int>(left))) break;
        const ssize_t n = recv(sock, scratch, sizeof scratch, 0);
        if (n <= 0) break;
        dropped += static_cast<std::size_t>(n);
    }
}
}  // namespace

bool HardenedServer::process_and_close_socket(socket_t sock) {
    const std::string client = client_key(endpoint(sock, true).ip);
    if (slots_.enter(client)) {
        serve_connection(sock);
        if (t_body_unread) linger(sock);
        slots_.leave(client);
    } else {
        refuse(sock);
    }
    shutdown(sock, SHUT_RDWR);
    close(sock);
    return true;
}

void HardenedServer::serve_connection(socket_t sock) {
    DeadlineStream strm(sock, limits_);
    t_stream = &strm;
    for (std::size_t left = keep_alive_max_count_; left > 0 && svr_sock_ != INVALID_SOCKET; --left) {
        // The first request may take request_timeout_s to begin, the next ones keep_alive_timeout_s.
        const int wait_s = left == keep_alive_max_count_ ? limits_.request_timeout_s : limits_.keep_alive_timeout_s;
        waiting_.wait(sock);
        if (!strm.buffered() && !wait_for(sock, POLLIN, wait_s * 1000)) break;
        strm.begin_request();
        if (!serve_request(strm, left == 1)) break;
    }
    waiting_.leave(sock);
    t_stream = nullptr;
}

bool HardenedServer::serve_request(httplib::Stream& strm, bool last) {
    t_close_after = t_routed = t_body_unread = false;
    bool closed = false;
    const bool ok = process_request(strm, last, closed, setup_);
    if (t_worker) t_worker->release();  // (the guard took a worker slot for the request)
    t_worker = nullptr;
    // Not routed: httplib answered by itself (a request line or headers it could not read, 414, 416), and what
    // follows on the connection is the rest of that request, not a new one; so is an unread body.
    return ok && !closed && !t_close_after && t_routed && !t_body_unread;
}

void WaitingConnections::wait(socket_t sock) {
    std::lock_guard lock(mutex_);
    Entry& e = entries_[sock];
    e.since = Clock::now();
    e.waiting = true;
}

void WaitingConnections::busy(socket_t sock) {
    std::lock_guard lock(mutex_);
    if (auto it = entries_.find(sock); it != entries_.end()) it->second.waiting = false;
}

void WaitingConnections::leave(socket_t sock) {
    std::lock_guard lock(mutex_);
    entries_.erase(sock);
}

bool WaitingConnections::evict_one() {
    std::lock_guard lock(mutex_);
    const auto now = Clock::now();
    auto oldest = entries_.end();
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
        if (it->second.evicted) return true;  // one is already on its way out
        if (it->second.waiting && now - it->second.since >= std::chrono::milliseconds(kEvictAfterMs) &&
            (oldest == entries_.end() || it->second.since < oldest->second.since)) {
            oldest = it;
        }
    }
    if (oldest == entries_.end()) return false;
    oldest->second.evicted = true;
    ::shutdown(oldest->first, SHUT_RDWR);  // its poll and recv end at once; its thread closes it
    return true;
}

BodyReading::BodyReading() : worker_(t_worker) {
    if (worker_) worker_->release();
    t_worker = nullptr;
}

void BodyReading::start_clock() {
    if (t_stream) t_stream->begin_body();
}

void BodyReading::done() {
    if (!worker_) return;
    worker_->acquire();
    t_worker = worker_;
    worker_ = nullptr;
}

namespace {
// A connection in memory: reads `in`, appends what is written to `out`.
class MemoryStream : public httplib::Stream {
public:
    MemoryStream(std::string_view in, std::string& out) : in_(in), out_(out) {}
    bool is_readable() const override { return pos_ < in_.size(); }
    bool is_writable() const override { return true; }
    ssize_t read(char* ptr, size_t size) override {
        const std::size_t n = std::min(size, in_.size() - pos_);
        std::memcpy(ptr, in_.data() + pos_, n);
        pos_ += n;
        return static_cast<ssize_t>(n);
    }
    ssize_t write(const char* ptr, size_t size) override {
        out_.append(ptr, size);
        return static_cast<ssize_t>(size);
    }
    void get_remote_ip_and_port(std::string& ip, int& port) const override { ip = "127.0.0.1", port = 40000; }
    void get_local_ip_and_port(std::string& ip, int& port) const override { ip = "127.0.0.1", port = 8080; }
    socket_t socket() const override { return INVALID_SOCKET; }
    [[nodiscard]] bool done() const { return pos_ >= in_.size(); }

private:
    std::string_view in_;
    std::size_t pos_ = 0;
    std::string& out_;
};
}  // namespace

std::string HardenedServer::handle_bytes(std::string_view bytes) {
    std::string out;
    MemoryStream strm(bytes, out);
    // cpp-httplib writes a streamed body (a static file) only while the server "runs", i.e. has a listening
    // socket: a server that never listened is made to look running for the call (the number is never used).
    const socket_t listening = svr_sock_;
    if (listening == INVALID_SOCKET) svr_sock_ = 0;
    for (std::size_t left = keep_alive_max_count_; left > 0 && !strm.done(); --left)
        if (!serve_request(strm, left == 1)) break;
    svr_sock_ = listening;
    return out;
}

void HardenedServer::widen_backlog() {
    if (svr_sock_ != INVALID_SOCKET) ::listen(svr_sock_, SOMAXCONN);
}

void close_connection_after_response() { t_close_after = true; }

void body_read_to_end() { t_body_unread = false; }

std::optional<ReadFailure> read_failure() {
    if (!t_stream) return std::nullopt;
    const ConnectionLimits& l = t_stream->limits();
    const std::string timeout = std::to_string(l.request_timeout_s) + " s (--request-timeout)";
    switch (t_stream->failure()) {
        case DeadlineStream::Failure::none: return std::nullopt;
        case DeadlineStream::Failure::head_timeout:
            return ReadFailure{408, "request timeout: the request line and headers must arrive within " + timeout};
        case DeadlineStream::Failure::head_too_large:
            return ReadFailure{431, "request headers too large: at most " + std::to_string(kMaxHeadBytes) +
                                        " bytes in " + std::to_string(kMaxHeadLines) + " lines"};
        case DeadlineStream::Failure::line_too_long:
            return ReadFailure{400, "a line of the request is longer than " + std::to_string(kMaxLineBytes) + " bytes"};
        case DeadlineStream::Failure::body_too_slow:
            return ReadFailure{408, "request timeout: the body came slower than " + seconds_text(l.min_rate) +
                                        " bytes/s (--min-transfer-rate) after the first " + timeout};
        case DeadlineStream::Failure::body_timeout:
            return ReadFailure{408, "request timeout: the whole body must arrive within " +
                                        std::to_string(l.body_timeout_s) + " s (--body-timeout)"};
    }
    return std::nullopt;
}

void exclusive_socket_options(socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
}

}  // namespace essi::native
#endif
