#!/usr/bin/env python3
"""essi report as a user runs it (ctest report_cli): the job sheet of example tapes as PDF and HTML.

The PDF is read back with poppler (pdfinfo: pages, A4; pdftotext: the tape's name, its SHA-256, the cut length, a
diagnostic's code, German and Chinese labels, the Chinese extracted as characters; pdffonts: every font embedded).
The HTML is parsed as XML (well-formed) and by html.parser, and holds the same numbers. A tool that is missing
fails the test and says so (scripts/setup test installs poppler-utils).

    report_cli.py ESSI EXAMPLES_DIR [WASM_BUILD]

With WASM_BUILD (build/wasm) holding the npm package's CLI (targets essikit_cli, essikit_api), that build is run
too: it has no PDF, says so (exit 2), and writes the same HTML as essi.
"""
import hashlib
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ESSI, EXAMPLES = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
WASM_BUILD = os.path.abspath(sys.argv[3]) if len(sys.argv) > 3 else None
EPOCH = "1764201600"  # 2025-11-27 00:00 UTC: a fixed date on the sheet (SOURCE_DATE_EPOCH)
failures = 0


def check(ok, what):
    global failures
    print(("ok   - " if ok else "FAIL - ") + what)
    if not ok:
        failures += 1
    return ok


def run(args, **kw):
    env = dict(os.environ, SOURCE_DATE_EPOCH=EPOCH, LANG="C.UTF-8")
    return subprocess.run([ESSI] + args, capture_output=True, env=env, **kw)


def tool(name):
    path = shutil.which(name)
    if not path:
        print(f"FAIL - {name} not found: install poppler-utils (scripts/setup test does)")
        sys.exit(1)
    return path


def pdf_text(pdf):
    return subprocess.run([tool("pdftotext"), "-enc", "UTF-8", pdf, "-"], capture_output=True, check=True).stdout.decode()


def pdf_pages(pdf):
    """[(width, height) in points] of every page, and pdfinfo's page count."""
    info = subprocess.run([tool("pdfinfo"), "-f", "1", "-l", "1000", pdf], capture_output=True, check=True).stdout.decode()
    pages = int(re.search(r"^Pages:\s+(\d+)", info, re.M).group(1))
    sizes = [(float(w), float(h)) for w, h in re.findall(r"^Page\s+\d+ size:\s+([\d.]+) x ([\d.]+) pts", info, re.M)]
    return pages, sizes, info


def pdf_fonts(pdf):
    """[(name, emb)] from pdffonts' table."""
    out = subprocess.run([tool("pdffonts"), pdf], capture_output=True, check=True).stdout.decode().splitlines()
    rows = []
    for line in out[2:]:
        cols = line.split()
        # name type [encoding words] emb sub uni object ID: emb is the 5th column from the end
        rows.append((cols[0], cols[-5]))
    return rows


def stats_and_diagnostics(tape):
    r = run(["check", "--format", "json", tape])
    f = json.loads(r.stdout)["files"][0]
    return f["stats"], f["diagnostics"]


def is_a4(size):
    return abs(size[0] - 595.276) < 0.5 and abs(size[1] - 841.89) < 0.5


def parse_html(path):
    text = open(path, encoding="utf-8").read()
    ET.fromstring(text.replace("<!DOCTYPE html>", "", 1))  # well-formed (raises otherwise)

    class Collect(html.parser.HTMLParser):
        def __init__(self):
            super().__init__()
            self.text, self.stack, self.ids = [], [], []

        def handle_starttag(self, tag, attrs):
            if tag not in ("meta",):
                self.stack.append(tag)
            self.ids += [v for k, v in attrs if k == "id"]

        def handle_startendtag(self, tag, attrs):
            pass

        def handle_endtag(self, tag):
            assert self.stack and self.stack[-1] == tag, f"</{tag}> closes <{self.stack[-1] if self.stack else None}>"
            self.stack.pop()

        def handle_data(self, data):
            self.text.append(data)

    c = Collect()
    c.feed(text)
    c.close()
    assert not c.stack, f"unclosed {c.stack}"
    return text, " ".join(c.text), c.ids


# The npm package's CLI (npm/bin/essikit.js does the same): the program with node's file system and environment.
NODE_RUNNER = ("const cli = require(process.argv[1]); cli({wasmBinary: require('fs').readFileSync(process.argv[2]), "
               "arguments: process.argv.slice(3), preRun: [(m) => { Object.assign(m.ENV, process.env); }]});")


def check_wasm_build(tape, tmp):
    lib = os.path.join(WASM_BUILD or "", "npm", "essikit", "lib")
    cjs, wasm = os.path.join(lib, "essikit_cli.cjs"), os.path.join(lib, "essikit_api.wasm")
    node = shutil.which("node")
    if not (WASM_BUILD and os.path.exists(cjs) and os.path.exists(wasm) and node):
        print(f"skip - the WebAssembly build's CLI: {cjs} or node not there (cmake --build --preset wasm)")
        return
    env = dict(os.environ, SOURCE_DATE_EPOCH=EPOCH, LANG="C.UTF-8")

    def essikit(args):
        return subprocess.run([node, "-e", NODE_RUNNER, cjs, wasm] + args, capture_output=True, env=env)

    r = essikit(["report", tape, "-o", os.path.join(tmp, "wasm.pdf")])
    check(r.returncode == 2 and b"no PDF writer" in r.stderr and not os.path.exists(os.path.join(tmp, "wasm.pdf")),
          f"WebAssembly: no PDF, said, exit 2 ({r.stderr.decode().strip()})")
    native_html = run(["report", tape, "--format", "html", "-o", "-"]).stdout
    r = essikit(["report", tape, "--format", "html", "-o", "-"])
    check(r.returncode == 1 and r.stdout == native_html, "WebAssembly: the same HTML as essi's")


def main():
    tool("pdfinfo"), tool("pdftotext"), tool("pdffonts")
    tmp = tempfile.mkdtemp(prefix="essi-report-")
    tape = os.path.join(EXAMPLES, "plan_collision.esi")
    sha = hashlib.sha256(open(tape, "rb").read()).hexdigest()
    stats, diags = stats_and_diagnostics(tape)
    cut = f"{stats['cut_length_mm']:.3f} mm"
    code = diags[0]["code"]

    # English PDF: one A4 page or more, the name, digest, cut length and a code; fonts embedded.
    pdf = os.path.join(tmp, "job.pdf")
    r = run(["report", tape, "-o", pdf, "--lang", "en"])
    check(r.returncode == 1, f"a tape with errors: exit 1 (got {r.returncode}: {r.stderr.decode()})")
    check(f"essi report: wrote {pdf}" in r.stderr.decode(), "says what it wrote")
    pages, sizes, info = pdf_pages(pdf)
    check(pages >= 1 and len(sizes) == pages and all(is_a4(s) for s in sizes), f"{pages} A4 pages: {sizes}")
    check("Creator:         essi report" in info, "creator: essi report")
    check("2025-11-27" in info or "Nov 27" in info, "creation date from SOURCE_DATE_EPOCH")
    text = pdf_text(pdf)
    for want in ["Job sheet", "plan_collision.esi", sha, cut, code, "2025-11-27 00:00 UTC", f"page 1 of {pages}"]:
        check(want in text, f"English PDF shows {want!r}")
    fonts = pdf_fonts(pdf)
    check(fonts and all(emb == "yes" for _, emb in fonts), f"every font embedded: {fonts}")

    # German and Chinese: the labels in the language, the Chinese extracted as characters (the CJK font embedded).
    pdf_de = os.path.join(tmp, "job_de.pdf")
    run(["report", tape, "-o", pdf_de, "--lang", "de"])
    text = pdf_text(pdf_de)
    for want in ["Auftragsblatt", "Schnittlänge", "Offene Meldungen", "Prüfsumme", cut, code, "Seite 1 von"]:
        check(want in text, f"German PDF shows {want!r}")
    pdf_zh = os.path.join(tmp, "job_zh.pdf")
    run(["report", tape, "-o", pdf_zh, "--lang", "zh"])
    text = pdf_text(pdf_zh)
    for want in ["切割作业单", "切割长度", "待处理的诊断", "零点偏移", cut, code, sha]:
        check(want in text, f"Chinese PDF shows {want!r}")
    fonts = pdf_fonts(pdf_zh)
    check(any("WenQuanYi" in name for name, emb in fonts if emb == "yes"), f"the CJK font embedded: {fonts}")
    check(all(emb == "yes" for _, emb in fonts), "every font embedded (zh)")

    # HTML: well-formed, self-contained, the same numbers.
    page = os.path.join(tmp, "job.html")
    r = run(["report", tape, "-o", page, "--lang", "zh"])
    check(r.returncode == 1, "HTML: exit 1 for a tape with errors")
    try:
        raw, text, ids = parse_html(page)
        check(True, "HTML is well-formed (XML) and every tag closes in order")
        for want in ["切割作业单", "plan_collision.esi", sha, cut, code, "2025-11-27 00:00 UTC"]:
            check(want in text, f"HTML shows {want!r}")
        check(ids[:3] == ["job", "drawing", "statistics"] and "diagnostics" in ids, f"sections: {ids}")
        check("<svg class=\"drawing\"" in raw and "@page" in raw and "<script" not in raw, "inline SVG and CSS, no script")
    except Exception as e:  # noqa: BLE001
        check(False, f"HTML parses: {e}")

    # The format: --format, the extension, stdout; an extension that says nothing is a usage error.
    r = run(["report", tape, "--format", "html", "-o", "-"])
    check(r.stdout.startswith(b"<!DOCTYPE html>"), "--format html -o - writes HTML to stdout")
    r = run(["report", tape, "--format", "pdf", "-o", "-"])
    check(r.stdout.startswith(b"%PDF-"), "--format pdf -o - writes PDF to stdout")
    r = run(["report", tape, "-o", os.path.join(tmp, "job.txt")])
    check(r.returncode == 2 and b"--format pdf|html" in r.stderr, f"-o job.txt: exit 2 ({r.stderr.decode().strip()})")
    r = subprocess.run([ESSI, "report", "plan_collision.esi"], capture_output=True, cwd=tmp,
                       env=dict(os.environ, SOURCE_DATE_EPOCH=EPOCH))
    check(r.returncode == 2, "a missing tape: exit 2")
    shutil.copy(tape, tmp)
    r = subprocess.run([ESSI, "report", "plan_collision.esi"], capture_output=True, cwd=tmp)
    check(r.returncode == 1 and os.path.exists(os.path.join(tmp, "plan_collision.esi.pdf")),
          "without -o: NAME.pdf in the current folder")

    # A clean tape exits 0; many diagnostics run onto more pages, each A4, the table's header again on each.
    r = run(["report", os.path.join(EXAMPLES, "marking.esi"), "-o", os.path.join(tmp, "marking.pdf")])
    check(r.returncode == 0, "a tape without errors: exit 0")
    check("none: the tape has no open diagnostics" in pdf_text(os.path.join(tmp, "marking.pdf")), "no diagnostics: said")
    many = os.path.join(tmp, "many.esi")
    with open(many, "w") as f:
        f.write("+1000+0\n" + "+10+x0\n" * 150 + "63\n")
    long_pdf = os.path.join(tmp, "many.pdf")
    run(["report", many, "-o", long_pdf])
    pages, sizes, _ = pdf_pages(long_pdf)
    text = pdf_text(long_pdf)
    check(pages >= 3 and all(is_a4(s) for s in sizes), f"a hundred diagnostics: {pages} A4 pages")
    onto = [subprocess.run([tool("pdftotext"), "-f", str(n), "-l", str(n), long_pdf, "-"], capture_output=True,
                           check=True).stdout.decode() for n in range(2, pages + 1)]
    check(all("severity" in page_text and "E101" in page_text for page_text in onto),
          "the table's header on every page it runs onto")
    check(f"page {pages} of {pages}" in text, f"the last page says page {pages} of {pages}")
    listed = len(stats_and_diagnostics(many)[1])  # (reading stops after 100 errors: E115)
    r = run(["report", many, "-o", os.path.join(tmp, "few.pdf"), "--max-diagnostics", "5"])
    check(f"{listed - 5} more diagnostics not shown (--max-diagnostics 5)" in pdf_text(os.path.join(tmp, "few.pdf")),
          f"--max-diagnostics 5: the other {listed - 5} counted")

    # The PDF writer is the module essi-pdf.so beside essi, loaded only for a PDF: essi itself links no cairo or pango,
    # and a module that cannot be found (ESSI_PDF_MODULE) is an error that names where it was looked for.
    ldd = subprocess.run(["ldd", ESSI], capture_output=True).stdout.decode()
    check("libcairo" not in ldd and "libpango" not in ldd, "essi links neither cairo nor pango")
    check(os.path.exists(os.path.join(os.path.dirname(ESSI), "essi-pdf.so")), "essi-pdf.so beside essi")
    missing = os.path.join(tmp, "no-such-module.so")
    r = subprocess.run([ESSI, "report", os.path.join(EXAMPLES, "marking.esi"), "-o", os.path.join(tmp, "m.pdf")],
                       capture_output=True, env=dict(os.environ, LANG="C.UTF-8", ESSI_PDF_MODULE=missing))
    err = r.stderr.decode()
    check(r.returncode == 2 and "cannot make the PDF" in err and f"{missing}: not found" in err,
          f"ESSI_PDF_MODULE not found: exit 2, said where ({r.returncode}: {err.strip()})")
    r = subprocess.run([ESSI, "report", os.path.join(EXAMPLES, "marking.esi"), "-o", os.path.join(tmp, "m.html")],
                       capture_output=True, env=dict(os.environ, LANG="C.UTF-8", ESSI_PDF_MODULE=missing))
    check(r.returncode == 0, "HTML needs no module")

    check_wasm_build(tape, tmp)
    shutil.rmtree(tmp)
    print(f"{failures} failed" if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
