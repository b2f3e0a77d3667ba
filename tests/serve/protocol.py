#!/usr/bin/env python3
"""`essi serve` against malformed and greedy HTTP on raw loopback sockets (docs/security.md): after a request the
server refused by itself (400, 414), after a header timeout or an unread body the connection is closed and its
remaining bytes are never answered as a second request; headers are bounded in bytes and lines (431); a body must
arrive whole within --body-timeout even at a rate above --min-transfer-rate, so a slow sender frees its
large-request slot in time; a request that finds no check slot within --body-timeout gets 503 (an unread answer keeps
its slot); the body's framing must be unambiguous; every method an endpoint does not take gets 405 with Allow;
Accept-Encoding is read with its q-values; --max-diagnostics cuts an answer; a body refused before it is read is
drained, so the client reads the refusal (a lingering close). Loopback only; stops by itself (90 s
alarm).
Usage: protocol.py PATH/TO/essi"""
import gzip
import signal
import socket
import sys
import threading
import time

from serve_common import Report, start_server, stop_server

REQUEST_TIMEOUT_S = 2
BODY_TIMEOUT_S = 3


def exchange(port, data, wait_s=6.0):
    """Sends `data` on a new connection and reads until the server closes it (or `wait_s` passes).
    Returns (bytes received, closed by the server, seconds until the end)."""
    t0 = time.monotonic()
    with socket.create_connection(("127.0.0.1", port), timeout=wait_s) as s:
        try:
            s.sendall(data)
        except OSError:
            pass  # the server may close before taking everything
        got = b""
        s.settimeout(0.2)
        while time.monotonic() - t0 < wait_s:
            try:
                chunk = s.recv(65536)
            except socket.timeout:
                continue
            except OSError:
                return got, True, time.monotonic() - t0
            if not chunk:
                return got, True, time.monotonic() - t0
            got += chunk
        return got, False, time.monotonic() - t0


def statuses(data):
    """The status codes of the responses in `data`, one after the other (each with its Content-Length)."""
    codes = []
    while data.startswith(b"HTTP/1.1 ") and b"\r\n\r\n" in data:
        head, data = data.split(b"\r\n\r\n", 1)
        codes.append(int(head[9:12]))
        length = [int(line.split(b":", 1)[1]) for line in head.split(b"\r\n") if line.lower().startswith(b"content-length:")]
        data = data[length[0] if length else 0:]
    return codes + ([-1] if data else [])  # -1: bytes that are no response


def header(data, name):
    for line in data.split(b"\r\n\r\n", 1)[0].split(b"\r\n")[1:]:
        key, _, value = line.partition(b":")
        if key.strip().lower() == name.lower().encode():
            return value.strip().decode()
    return None


def body_of(data):
    return data.split(b"\r\n\r\n", 1)[1] if b"\r\n\r\n" in data else b""


def get(port, path, extra=""):
    return f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n{extra}\r\n".encode()


def connection_endings(port, report):
    health = get(port, "/api/health")
    # A request line httplib cannot parse (four words), then a valid request on the same connection.
    got, closed, _ = exchange(port, b"GET /x HTTP/1.1 junk\r\nHost: 127.0.0.1\r\n\r\n" + health)
    report.check(statuses(got) == [400] and closed, f"bad request line then a request: answers {statuses(got)} (one 400), closed: {closed}")
    # A request line over 8 KB (414) whose "body" is another request.
    smuggled = b"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"
    long_line = b"GET /" + b"a" * 9000 + b" HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: %d\r\n\r\n" % len(smuggled) + smuggled
    got, closed, _ = exchange(port, long_line)
    report.check(statuses(got) == [414] and closed, f"request line of 9 KB then bytes: answers {statuses(got)} (one 414), closed: {closed}")
    # A GET with a body that is another request: the body is not read, so the connection ends after the answer.
    got, closed, _ = exchange(port, get(port, "/api/health", f"Content-Length: {len(smuggled)}\r\n") + smuggled)
    report.check(statuses(got) == [200] and closed, f"GET with a body holding a request: answers {statuses(got)} (one 200), closed: {closed}")
    # Keep-alive still works for requests without a body.
    got, closed, _ = exchange(port, health + health + get(port, "/api/health", "Connection: close\r\n"))
    report.check(statuses(got) == [200, 200, 200], f"three pipelined GETs: answers {statuses(got)}")


def early_answer(port, report):
    # A body over --max-body (4 MB here) is refused from its Content-Length, before it is read, while the client is
    # still sending it. The server lingers (reads and drops what comes, kLingerMs / kLingerBytes): the client's
    # sending ends without a reset or a broken pipe (curl gives up on those, answer or not), and it reads the 413.
    head = b"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\nContent-Length: 6000000\r\n\r\n"
    send_error = None
    got = b""
    with socket.create_connection(("127.0.0.1", port), timeout=6) as s:
        try:
            s.sendall(head)
            for _ in range(48):  # 3 MB in 64 KB writes
                s.sendall(b"1" * 65536)
        except OSError as e:
            send_error = e
        try:
            while chunk := s.recv(65536):
                got += chunk
        except OSError:
            pass
    report.check(send_error is None and statuses(got) == [413] and b"request body too large" in body_of(got),
                 f"3 MB of a 6 MB body sent before reading the answer: sending ended with {send_error!r}, "
                 f"answers {statuses(got)} {body_of(got)[:50]!r} (413)")


def header_limits(port, report):
    # Headers sent in part, then nothing: 408 after --request-timeout, and the connection closed at once.
    got, closed, seconds = exchange(port, b"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n", wait_s=REQUEST_TIMEOUT_S + 4)
    report.check(statuses(got) == [408] and b"--request-timeout" in body_of(got) and closed and seconds < REQUEST_TIMEOUT_S + 1.5,
                 f"headers cut short: {statuses(got)} {body_of(got)[:90]!r}, closed after {seconds:.1f} s "
                 f"(--request-timeout {REQUEST_TIMEOUT_S})")
    lines = b"".join(b"X-Pad-%d: a\r\n" % i for i in range(200))
    got, closed, _ = exchange(port, b"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n" + lines + b"\r\n")
    report.check(statuses(got) == [431] and closed, f"200 header lines: {statuses(got)} (431), closed: {closed}")
    got, closed, _ = exchange(port, b"GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Big: " + b"a" * 100000 + b"\r\n\r\n")
    report.check(statuses(got) == [431] and closed, f"a header line of 100 KB: {statuses(got)} (431), closed: {closed}")


def framing(port, report):
    def post(headers, body=b"7\n"):
        return (f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n{headers}\r\n").encode() + body
    cases = [
        ("two different Content-Length", "Content-Length: 2\r\nContent-Length: 3\r\n", 400, b"conflicting Content-Length"),
        ("Content-Length 2x", "Content-Length: 2x\r\n", 400, b"not a number of bytes"),
        ("Content-Length -1", "Content-Length: -1\r\n", 400, b"not a number of bytes"),
        ("Content-Length and chunked", "Content-Length: 2\r\nTransfer-Encoding: chunked\r\n", 400, b"both Content-Length and Transfer-Encoding"),
        ("Transfer-Encoding gzip", "Transfer-Encoding: gzip\r\n", 501, b"only chunked"),
    ]
    for name, headers, want, text in cases:
        got, closed, _ = exchange(port, post(headers))
        report.check(statuses(got) == [want] and text in body_of(got) and closed,
                     f"{name}: {statuses(got)} {body_of(got)[:80]!r} (want {want}), closed: {closed}")
    got, closed, _ = exchange(port, post("Content-Length: 2\r\nContent-Length: 2\r\nConnection: close\r\n"))
    report.check(statuses(got) == [200], f"the same Content-Length twice: {statuses(got)} (200)")


def methods(port, report):
    cases = [("PATCH", "/api/check", "POST"), ("OPTIONS", "/api/check", "POST"), ("PUT", "/api/check", "POST"),
             ("DELETE", "/api/convert", "POST"), ("TRACE", "/api/health", "GET, HEAD"), ("POST", "/api/health", "GET, HEAD"),
             ("PUT", "/api/share/" + "0" * 64, "GET, HEAD, DELETE"), ("POST", "/index.html", "GET, HEAD"),
             ("PATCH", "/", "GET, HEAD")]
    for method, path, allow in cases:
        got, closed, _ = exchange(port, f"{method} {path} HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                                        f"Content-Length: 2\r\n\r\n7\n".encode())
        report.check(statuses(got) == [405] and header(got, "Allow") == allow and b'"status":405' in body_of(got) and closed,
                     f"{method} {path}: {statuses(got)} Allow: {header(got, 'Allow')} (want 405, {allow})")
    got, _, _ = exchange(port, f"PATCH /api/nothing HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n\r\n".encode())
    report.check(statuses(got) == [404], f"PATCH on no endpoint: {statuses(got)} (404)")


def encodings(port, report):
    for value, gzipped in [("gzip", True), ("GZIP;q=0.5", True), ("x-gzip", True), ("deflate, gzip", True), ("*", True),
                           ("gzip;q=0", False), ("gzip; q=0", False), ("gzip;q=0.000", False), ("x-gzip-nope", False),
                           ("br", False), ("identity", False), ("*;q=0", False), ("gzip;q=0, *", False), ("gzip;q=2", False)]:
        got, _, _ = exchange(port, get(port, "/api/health", f"Accept-Encoding: {value}\r\nConnection: close\r\n"))
        encoding = header(got, "Content-Encoding")
        ok = encoding == "gzip" if gzipped else encoding is None
        if ok and gzipped:
            ok = b'"ok":true' in gzip.decompress(body_of(got))
        report.check(statuses(got) == [200] and ok, f"Accept-Encoding: {value} -> Content-Encoding {encoding} (want {'gzip' if gzipped else 'none'})")


def diagnostics_cap(port, report):
    """--max-diagnostics 2: a tape with 3 warnings (a blank at each line's end) is answered with 2 and the count of
    the third."""
    import json
    tape = b"+100+0 \n" * 3
    got, _, _ = exchange(port, (f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n"
                                f"Content-Length: {len(tape)}\r\nConnection: close\r\n\r\n").encode() + tape)
    try:
        f = json.loads(body_of(got))["files"][0]
        kept, omitted = len(f["diagnostics"]), f.get("diagnostics_omitted")
    except (ValueError, KeyError, IndexError):
        kept, omitted = None, None
    report.check(statuses(got) == [200] and kept == 2 and omitted == 1,
                 f"--max-diagnostics 2 on 3 warnings: {kept} kept, diagnostics_omitted {omitted}")


def slow_body(port, report):
    """A body at 4 KB/s (above --min-transfer-rate 1KB) declaring 1 MB: cut off with 408 after --body-timeout."""
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall(b"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n"
                  b"Content-Length: 1000000\r\n\r\n")
        s.setblocking(False)
        t0, got, end = time.monotonic(), b"", None
        while time.monotonic() - t0 < BODY_TIMEOUT_S + 4 and end is None:
            try:
                s.send(b"+100+0\n" * 58)
            except OSError:
                pass
            try:
                chunk = s.recv(4096)
                got += chunk
                if not chunk:
                    end = time.monotonic() - t0
            except BlockingIOError:
                pass
            except OSError:
                end = time.monotonic() - t0
            time.sleep(0.1)
    report.check(statuses(got) == [408] and b"--body-timeout" in body_of(got) and end is not None and BODY_TIMEOUT_S - 0.5 < end < BODY_TIMEOUT_S + 2,
                 f"a body at 4 KB/s: {statuses(got)} {body_of(got)[:80]!r}, closed after {end} s (--body-timeout {BODY_TIMEOUT_S})")


def large_slot(port, report):
    """--max-large-requests 1: while a slow sender holds the one slot, another 2 MB check waits for it and is
    answered once the slow one is cut off, within --body-timeout (not after the slow body's 1 MB at 4 KB/s)."""
    stop = threading.Event()

    def hog():
        with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
            s.sendall(b"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n"
                      b"Content-Length: 3000000\r\n\r\n")
            while not stop.is_set():
                try:
                    s.sendall(b"+100+0\n" * 58)
                except OSError:
                    return
                time.sleep(0.1)

    t = threading.Thread(target=hog)
    t.start()
    time.sleep(0.5)
    body = b"+100+0\n" * 300000
    request = (f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n"
               f"Content-Length: {len(body)}\r\nConnection: close\r\n\r\n").encode() + body
    got, _, seconds = exchange(port, request, wait_s=BODY_TIMEOUT_S + 6)
    stop.set()
    t.join()
    report.check(statuses(got) == [200] and seconds < BODY_TIMEOUT_S + 3,
                 f"a 2 MB check behind a slow sender holding the only large slot: {statuses(got)} after {seconds:.1f} s")


def busy_check_slot(essi, report):
    """--max-checks 1 --body-timeout 1: a conversion whose 19 MB answer is not read keeps the only check slot (the
    answer is in memory until it is written), so a check sent meanwhile gets 503 with Retry-After after 1 s."""
    proc, port, _ = start_server(essi, "--max-checks", "1", "--body-timeout", "1", "--max-body", "20MB")
    try:
        tape = b"+100+0\n" * (19 * 1024 * 1024 // 7)
        hog = socket.create_connection(("127.0.0.1", port), timeout=10)
        hog.sendall((f"POST /api/convert?to=essi HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n"
                     f"Content-Length: {len(tape)}\r\n\r\n").encode() + tape)
        time.sleep(2)  # converted and being written: the answer fills the socket buffers and waits
        tape = b"+100+0\n"
        got, closed, seconds = exchange(port, (f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: "
                                               f"application/octet-stream\r\nContent-Length: {len(tape)}\r\n\r\n").encode() + tape)
        report.check(statuses(got) == [503] and header(got, "Retry-After") == "5" and b"--max-checks 1" in body_of(got) and closed,
                     f"a check while the only check slot holds an unread answer: {statuses(got)} {body_of(got)[:100]!r} after {seconds:.1f} s")
        hog.close()
        time.sleep(0.5)
        got, _, _ = exchange(port, (f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\n"
                                    f"Content-Length: {len(tape)}\r\nConnection: close\r\n\r\n").encode() + tape)
        report.check(statuses(got) == [200], f"... and once that client is gone: {statuses(got)}")
    finally:
        stop_server(proc)


def main(essi):
    signal.alarm(90)
    report = Report()
    proc, port, _ = start_server(essi, "--request-timeout", str(REQUEST_TIMEOUT_S), "--body-timeout", str(BODY_TIMEOUT_S),
                                 "--min-transfer-rate", "1KB", "--max-large-requests", "1", "--max-body", "4MB",
                                 "--max-diagnostics", "2")
    try:
        connection_endings(port, report)
        early_answer(port, report)
        header_limits(port, report)
        framing(port, report)
        methods(port, report)
        encodings(port, report)
        diagnostics_cap(port, report)
        slow_body(port, report)
        large_slot(port, report)
    finally:
        stop_server(proc)
    busy_check_slot(essi, report)
    return report.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
