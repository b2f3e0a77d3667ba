#!/usr/bin/env python3
"""`essi serve` with 8 request threads against 64 slow clients (48 send their headers a byte at a time, 16 their
body; from 32 loopback addresses) and one greedy client (40 idle connections from one address): a normal client still gets
GET /api/health answered in under a second, the slow clients are cut off after --request-timeout (so are a slow
body and, after 5 s, an idle kept-alive connection), and the greedy client's connections beyond --max-client-connections get 429; with every connection taken by slow
senders of headers, a new client is still answered (the one waiting longest is closed for it). Loopback only;
stops by itself (80 s alarm).
Usage: slow_clients.py PATH/TO/essi"""
import signal
import socket
import sys
import time

from serve_common import Report, start_server, stop_server, timed_get

SLOW_CLIENTS = 64
GREEDY = 40
PER_CLIENT = 16
TIMEOUT_S = 3


SLOW_BODIES = 16  # of the slow clients: whole headers of a POST at once, then the body a byte at a time


def open_slow(port, n):
    socks = []
    for i in range(n):
        s = socket.create_connection(("127.0.0.1", port), timeout=2, source_address=(f"127.0.0.{2 + i % 32}", 0))
        if i < SLOW_BODIES:
            s.sendall(f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/octet-stream\r\n"
                      f"Content-Length: 100000\r\n\r\n".encode())
        s.setblocking(False)
        socks.append(s)
    return socks


class Trickle:
    """Sends `request` to every socket, one byte each per step (it is long enough never to be complete)."""

    def __init__(self, socks, request):
        self.socks, self.request, self.pos = socks, request, 0

    def run(self, seconds, step):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline and self.pos < len(self.request):
            for s in self.socks:
                try:
                    s.send(self.request[self.pos:self.pos + 1])
                except OSError:
                    pass  # the server closed it
            self.pos += 1
            time.sleep(step)


def closed_by_server(s):
    try:
        s.recv(4096)  # EOF or an answer: the server gave up on it
        return True
    except BlockingIOError:
        return False
    except OSError:
        return True


def at_eof(s):
    """True once the server closed `s` (data still arriving is read and ignored)."""
    try:
        return s.recv(4096) == b""
    except BlockingIOError:
        return False
    except OSError:
        return True


def count_429(socks, wait_s):
    """How many of `socks` got a 429 within `wait_s` seconds."""
    got = set()
    deadline = time.monotonic() + wait_s
    while time.monotonic() < deadline and len(got) < len(socks):
        for i, s in enumerate(socks):
            if i in got:
                continue
            try:
                if s.recv(4096).startswith(b"HTTP/1.1 429"):
                    got.add(i)
            except (BlockingIOError, OSError):
                pass
        time.sleep(0.05)
    return len(got)


def idle_and_slow_body(port, report):
    """A kept-alive connection left idle and a body sent at 500 B/s: both closed by the server in time."""
    idle = socket.create_connection(("127.0.0.1", port), timeout=2)
    idle.sendall(f"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n".encode())
    answer = idle.recv(4096)
    body = socket.create_connection(("127.0.0.1", port), timeout=2)
    body.sendall((f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/octet-stream\r\n"
                  f"Content-Length: 1000000\r\n\r\n").encode())
    for s in (idle, body):
        s.setblocking(False)
    t0 = time.monotonic()
    closed = {}
    while time.monotonic() - t0 < 8 and len(closed) < 2:
        try:
            body.send(b"+100+0\n" * 14)
        except OSError:
            pass
        for name, s in (("idle", idle), ("slow body", body)):
            if name not in closed and at_eof(s):
                closed[name] = time.monotonic() - t0
        time.sleep(0.2)
    report.check(answer.startswith(b"HTTP/1.1 200") and 4.0 < closed.get("idle", 99) < 6.5,
                 f"idle kept-alive connection closed after {closed.get('idle', -1):.1f} s (keep-alive 5 s)")
    report.check(TIMEOUT_S - 0.5 < closed.get("slow body", 99) < TIMEOUT_S + 1.5,
                 f"body at 500 B/s cut off after {closed.get('slow body', -1):.1f} s (--request-timeout {TIMEOUT_S})")
    idle.close()
    body.close()


def full_table(essi, report):
    """--max-connections 16, all held by clients sending their headers a byte per 0.3 s (request timeout 10 s): a
    new client gets GET /api/health answered within 3 s, because the connection waiting longest is closed for it."""
    proc, port, _ = start_server(essi, "--max-connections", "16", "--request-timeout", "10")
    try:
        slow = []
        for i in range(16):
            s = socket.create_connection(("127.0.0.1", port), timeout=2, source_address=(f"127.0.0.{2 + i % 4}", 0))
            s.setblocking(False)
            slow.append(s)
        trickle = Trickle(slow, f"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Pad: {'a' * 200}\r\n".encode())
        trickle.run(1.5, 0.3)
        status, seconds = timed_get(port, timeout=8, source="127.0.0.100")
        report.check(status.startswith("HTTP/1.1 200") and seconds < 3.0,
                     f"all 16 connections taken by slow headers: a new client answered {status!r} in {seconds:.2f} s")
        trickle.run(0.3, 0.3)
        closed = sum(1 for s in slow if closed_by_server(s))
        report.check(closed >= 1, f"{closed} of the 16 slow connections closed to make room")
        for s in slow:
            s.close()
    finally:
        stop_server(proc)


def main(essi):
    signal.alarm(80)
    report = Report()
    proc, port, _ = start_server(essi, "--threads", "8", "--request-timeout", str(TIMEOUT_S),
                                 "--max-client-connections", str(PER_CLIENT))
    try:
        request = f"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nX-Pad: {'a' * 200}\r\n".encode()
        slow = open_slow(port, SLOW_CLIENTS)
        trickle = Trickle(slow, request)
        trickle.run(0.5, 0.05)
        times = []
        for _ in range(5):
            status, seconds = timed_get(port)
            times.append(seconds)
            report.check(status.startswith("HTTP/1.1 200") and seconds < 1.0,
                         f"normal client during {SLOW_CLIENTS} slow ones: {status} in {seconds:.3f} s")
            trickle.run(0.2, 0.05)
        report.check(max(times) < 1.0, f"slowest normal answer {max(times):.3f} s < 1 s")
        # Still sending (a byte per 0.25 s), but slower than the minimum rate: cut off after the timeout.
        trickle.run(TIMEOUT_S + 1.5, 0.25)
        cut = sum(1 for s in slow if closed_by_server(s))
        report.check(cut == SLOW_CLIENTS, f"{cut}/{SLOW_CLIENTS} slow clients cut off after --request-timeout {TIMEOUT_S} s")
        for s in slow:
            s.close()
        idle_and_slow_body(port, report)
        t0 = time.monotonic()
        greedy = [socket.create_connection(("127.0.0.1", port), timeout=5, source_address=("127.0.0.200", 0))
                  for _ in range(GREEDY)]
        connect_s = time.monotonic() - t0
        report.check(connect_s < 1.0, f"{GREEDY} connections in a burst accepted in {connect_s:.3f} s (listen backlog)")
        for s in greedy:
            s.setblocking(False)
        refused = count_429(greedy, 2.0)
        report.check(refused == GREEDY - PER_CLIENT,
                     f"greedy client: {refused} of {GREEDY} connections got 429 (limit {PER_CLIENT})")
        status, seconds = timed_get(port)
        report.check(status.startswith("HTTP/1.1 200") and seconds < 1.0, f"normal client beside the greedy one: {seconds:.3f} s")
        for s in greedy:
            s.close()
    finally:
        stop_server(proc)
    full_table(essi, report)
    return report.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
