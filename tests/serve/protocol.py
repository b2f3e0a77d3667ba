#!/usr/bin/env python3
"""`essi serve` against malformed HTTP on raw loopback sockets (docs/security.md): the body's framing must be
unambiguous; every method an endpoint does not take gets 405 with Allow; Accept-Encoding is read with its q-values.
Loopback only; stops by itself (90 s alarm). Usage: protocol.py PATH/TO/essi"""
import gzip
import signal
import socket
import sys
import time

from serve_common import Report, start_server, stop_server



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


def main(essi):
    signal.alarm(90)
    report = Report()
    proc, port, _ = start_server(essi, "--max-body", "4MB")
    try:
        framing(port, report)
        methods(port, report)
        encodings(port, report)
    finally:
        stop_server(proc)
    return report.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
