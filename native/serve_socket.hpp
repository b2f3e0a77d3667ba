// The connection layer of `essi serve` (cpp-httplib 0.11): what a slow, idle or greedy client can hold.
//   - every connection has its own thread (ConnectionThreads), at most max_connections at once; more wait in
//     the kernel's accept queue. A slow client therefore blocks only its own thread, never the others.
//   - the request line and headers must arrive within request_timeout_s, in at most kMaxHeadBytes and
//     kMaxHeadLines lines (else 408 or 431, and the connection is closed).
//   - a body must arrive at min_rate on average after a grace of request_timeout_s (the deadline is
//     request_timeout_s + received / min_rate from the moment the server is ready to read it), and whole
//     within body_timeout_s (else 408, closed): a large-body slot is held at most
//     min(body_timeout_s, request_timeout_s + max_body / min_rate).
//   - a response must be taken at min_rate too (request_timeout_s + written / min_rate), else the connection is
//     dropped: a client reading slowly holds its worker slot for a bounded time.
//   - a connection is kept for the next request only when this one was routed and its body read to the end: the
//     bytes after a request httplib refused itself (400, 414, 416) or a body left unread are never read as a
//     request.
//   - when all max_connections threads are taken, a new connection closes the one that has waited longest (at
//     least kEvictAfterMs) for its request or in its request line and headers (WaitingConnections): slow
//     senders of headers cannot keep new clients out, only delay them by about kEvictAfterMs.
//   - at most max_client_connections connections per client address; the next one gets a 429 and is closed.
//   - at most `threads` requests are handled at once; a handler gives its slot back while it waits for and
//     reads its body (BodyReading), so slow uploads do not hold them.
//   - the listening socket has SO_REUSEADDR but never SO_REUSEPORT: a port in use is an error at start-up.
#pragma once

#if defined(ESSI_HAVE_HTTPLIB)
#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <mutex>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "serve_limits.hpp"

namespace essi::native {

struct ConnectionLimits {
    std::size_t max_connections = 256;
    std::size_t max_client_connections = 32;
    std::size_t threads = 8;
    int request_timeout_s = 10;
    int keep_alive_timeout_s = 5;
    double min_rate = 1024.0 * 1024;  // bytes per second of a body or a response, after request_timeout_s
    int body_timeout_s = 120;         // a whole body
};

inline constexpr int kEvictAfterMs = 1000;               // a connection waiting this long may be closed for a new one
inline constexpr std::size_t kMaxHeadBytes = 64 * 1024;  // the request line and headers together
inline constexpr std::size_t kMaxHeadLines = 128;        // the request line, the headers and the blank line
inline constexpr std::size_t kMaxLineBytes = 64 * 1024;  // any line read (a chunk size too)
// A lingering close (after an answer given before the request's body was read): the body still coming is read and
// dropped for at most this long and this many bytes, so that the client reads the answer instead of a reset.
inline constexpr int kLingerMs = 2000;
inline constexpr std::size_t kLingerBytes = 4 * 1024 * 1024;

// The connections waiting for a request or still reading its head, by socket, with the time they began to wait.
class WaitingConnections {
public:
    void wait(socket_t sock);   // from now, `sock` waits for a request (or its head)
    void busy(socket_t sock);   // its request was read: it may no longer be closed for a new connection
    void leave(socket_t sock);  // before the socket is closed
    // Shuts down the connection waiting longest (at least kEvictAfterMs); true when one was, or is still going.
    bool evict_one();

private:
    struct Entry {
        std::chrono::steady_clock::time_point since;
        bool waiting = true;
        bool evicted = false;
    };
    std::mutex mutex_;
    std::map<socket_t, Entry> entries_;
};

class HardenedServer : public httplib::Server {
public:
    explicit HardenedServer(const ConnectionLimits& limits);
    // Runs before routing, on the request's thread, after taking one of the `threads` slots.
    void set_request_guard(HandlerWithResponse guard) { guard_ = std::move(guard); }
    // Runs on every response just before it is written (headers common to all responses).
    void set_response_finisher(Handler finisher) { finisher_ = std::move(finisher); }
    // Runs on every request once its headers are read, before anything else (may rewrite headers).
    void set_request_setup(std::function<void(httplib::Request&)> setup) { setup_ = std::move(setup); }
    // After bind: a listen backlog of SOMAXCONN instead of cpp-httplib 0.11's 5, so that a burst of connections
    // waits in the kernel's queue instead of having its SYNs dropped (each retried only after 1 s, then 3 s).
    void widen_backlog();
    // Handles the requests in `bytes` as if a client at 127.0.0.1 had sent them on one connection (keep-alive: one
    // after the other, until the bytes end or the server closes), without a socket, and returns what the server
    // wrote back. For the request-handling fuzz target and tests: the same guard, routes and finisher.
    std::string handle_bytes(std::string_view bytes);

private:
    bool process_and_close_socket(socket_t sock) override;
    void serve_connection(socket_t sock);
    // One request from `strm` (the last of the connection when `last`); false when the connection ends.
    bool serve_request(httplib::Stream& strm, bool last);
    ConnectionLimits limits_;
    WaitingConnections waiting_;
    ClientSlots slots_;
    Semaphore workers_;
    HandlerWithResponse guard_;
    Handler finisher_;
    std::function<void(httplib::Request&)> setup_;
};

// Ends the connection after the current response (a request refused before its body was read).
void close_connection_after_response();
// The request's body has been read to its end (else the connection ends after the response).
void body_read_to_end();

// Why the current connection's last read failed, as an HTTP error: 408 (the headers or the body too slow),
// 431 (headers too large), 400 (a line too long); nullopt when no limit was hit (the client closed, or bad bytes).
struct ReadFailure {
    int status = 0;
    std::string message;
};
[[nodiscard]] std::optional<ReadFailure> read_failure();

// While a handler waits for and reads its body, the request gives its worker slot back (a slow upload must not
// hold one of the `threads`); start_clock() starts the body's deadlines once the handler is ready to read (time
// spent waiting for a slot is not the client's); done() (or the destructor) takes a worker slot again.
class BodyReading {
public:
    BodyReading();
    ~BodyReading() { done(); }
    void start_clock();
    void done();
    BodyReading(const BodyReading&) = delete;
    BodyReading& operator=(const BodyReading&) = delete;

private:
    Semaphore* worker_;
};

// The `socket_options` of the listening socket: SO_REUSEADDR only (no SO_REUSEPORT).
void exclusive_socket_options(socket_t sock);

}  // namespace essi::native
#endif
