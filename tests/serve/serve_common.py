"""Shared by the Python tests of `essi serve` (tests/serve/*.py): a stand-in viewer in a temporary folder, starting
the server on a free loopback port, a timed HTTP GET. Loopback only; every wait is bounded."""
import os
import re
import signal
import socket
import subprocess
import tempfile
import time


def start_server(essi, *flags):
    """Starts `essi serve` (stand-in viewer, temporary data) and returns (process, port, tmpdir)."""
    tmp = tempfile.mkdtemp(prefix="essi-serve-")
    web = os.path.join(tmp, "web")
    os.makedirs(web)
    with open(os.path.join(web, "index.html"), "w") as f:
        f.write("<!doctype html><title>stand-in viewer</title>\n")
    with open(os.path.join(web, "essi_viewer.wasm"), "w") as f:
        f.write("not really wasm\n")
    proc = subprocess.Popen([essi, "serve", "--host", "127.0.0.1", "--port", "0", "--web-root", web,
                             "--data", os.path.join(tmp, "data"), *flags],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    line = proc.stdout.readline()
    m = re.search(r"http://127\.0\.0\.1:(\d+)", line)
    if not m:
        proc.kill()
        raise SystemExit("FAIL - server did not start: " + line)
    return proc, int(m.group(1)), tmp


def stop_server(proc):
    proc.send_signal(signal.SIGTERM)
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def timed_get(port, path="/api/health", timeout=5.0, source="127.0.0.1"):
    """GET on a new connection; returns (status line or error text, seconds)."""
    t0 = time.monotonic()
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=timeout, source_address=(source, 0)) as s:
            s.sendall(f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n".encode())
            data = b""
            while b"\r\n" not in data:
                chunk = s.recv(4096)
                if not chunk:
                    break
                data += chunk
        return data.split(b"\r\n", 1)[0].decode(errors="replace"), time.monotonic() - t0
    except OSError as e:
        return f"error: {e}", time.monotonic() - t0


class Report:
    def __init__(self):
        self.failures = 0

    def check(self, ok, name):
        print(("ok   - " if ok else "FAIL - ") + name, flush=True)
        self.failures += 0 if ok else 1

    def finish(self):
        print(f"# {self.failures} failure(s)")
        return 1 if self.failures else 0
