#!/usr/bin/env python3
"""`essi serve`'s memory under 16 large requests at once: 16 x 8 MB tapes POSTed to /api/check together
(--max-body 16MB --threads 16). Bodies over 1 MB wait for one of --max-large-requests slots (2) before they are
read, so the server's peak RSS (VmHWM) stays under BASE + LARGE x PER_LARGE (docs/security.md); without the
cap it holds all 16 bodies. Then 16 checks of small bodies at once (300 KB tapes with a warning on every line: a large
working set for their size) with --max-checks 2: at most 2 run at once, and each answer holds at most
--max-diagnostics diagnostics, so the peak stays under BASE + CHECKS x PER_CHECK. Loopback only; stops by itself
(120 s alarm). Usage: memory_bound.py PATH/TO/essi"""
import http.client
import signal
import sys
import threading

from serve_common import Report, start_server, stop_server

REQUESTS = 16
BODY_MB = 8
LARGE = 2
BASE_MB = 24      # the idle server, its threads and a small request
PER_LARGE_MB = 24  # one large request: the body (8 MB) + the checker's working set
CHECKS = 2
PER_CHECK_MB = 24  # one check of a 300 KB tape with 38 400 warnings, 10 000 of them in its answer (measured 15 MB)


def vm_hwm_mb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    return -1


def post_check(port, body, statuses, i):
    try:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=90)
        conn.request("POST", "/api/check", body=body, headers={"Content-Type": "application/octet-stream"})
        r = conn.getresponse()
        r.read()
        statuses[i] = r.status
        conn.close()
    except OSError as e:
        statuses[i] = str(e)


def checks_at_once(port, body):
    """REQUESTS checks of `body` posted at once; their HTTP statuses (or errors)."""
    statuses = [None] * REQUESTS
    threads = [threading.Thread(target=post_check, args=(port, body, statuses, i)) for i in range(REQUESTS)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(100)
    return statuses


def many_small_checks(essi, report):
    proc, port, _ = start_server(essi, "--threads", str(REQUESTS), "--max-checks", str(CHECKS))
    try:
        body = b"+100+0 \n" * 38400  # 300 KB: a W109 on every line
        statuses = checks_at_once(port, body)
        report.check(statuses == [200] * REQUESTS, f"{REQUESTS} x 300 KB checks answered: {statuses}")
        peak = vm_hwm_mb(proc.pid)
        bound = BASE_MB + CHECKS * PER_CHECK_MB
        report.check(0 < peak < bound, f"peak RSS {peak:.1f} MB < {bound} MB = {BASE_MB} + {CHECKS} x {PER_CHECK_MB} MB "
                                       f"(--max-checks {CHECKS})")
    finally:
        stop_server(proc)


def main(essi):
    signal.alarm(120)
    report = Report()
    proc, port, _ = start_server(essi, "--max-body", "16MB", "--threads", str(REQUESTS),
                                 "--max-large-requests", str(LARGE))
    try:
        body = b"+100+0\n" * (BODY_MB * 1024 * 1024 // 7)
        idle = vm_hwm_mb(proc.pid)
        statuses = checks_at_once(port, body)
        report.check(statuses == [200] * REQUESTS, f"{REQUESTS} x {BODY_MB} MB checks answered: {statuses}")
        peak = vm_hwm_mb(proc.pid)
        bound = BASE_MB + LARGE * PER_LARGE_MB
        report.check(0 < peak < bound, f"peak RSS {peak:.1f} MB (idle {idle:.1f} MB) < {bound} MB "
                                       f"= {BASE_MB} + {LARGE} x {PER_LARGE_MB} MB")
    finally:
        stop_server(proc)
    many_small_checks(essi, report)
    return report.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
