#!/usr/bin/env python3
"""`essi serve` with 8 request threads against 64 slow clients (headers sent a byte at a time, from 32 loopback
addresses) and one greedy client (40 idle connections from one address): a normal client still gets
GET /api/health answered in under a second, the slow clients are cut off after --request-timeout, and the
greedy client's connections beyond --max-client-connections get 429. Loopback only; stops by itself (60 s alarm).
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


def open_slow(port, n):
    socks = []
    for i in range(n):
        s = socket.create_connection(("127.0.0.1", port), timeout=2, source_address=(f"127.0.0.{2 + i % 32}", 0))
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


def main(essi):
    signal.alarm(60)
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
        greedy = [socket.create_connection(("127.0.0.1", port), timeout=2, source_address=("127.0.0.200", 0))
                  for _ in range(GREEDY)]
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
    return report.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
