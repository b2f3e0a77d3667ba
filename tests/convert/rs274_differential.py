#!/usr/bin/env python3
"""Differential test against LinuxCNC (docs/conversions.md): `essi convert --to gcode` of every example and real
tape, run by LinuxCNC's standalone interpreter `rs274` (Debian linuxcnc-uspace); its canonical STRAIGHT_TRAVERSE /
STRAIGHT_FEED / ARC_FEED end points must equal essikit's motion stream (`essi trace --decimals 6`) within 1e-4 mm.

Kerf: rs274 offsets the path under G41.1/G42.1, essikit's stream is the programmed path: the kerf words are taken
out of the G-code for this run. Parabolas: the G-code has them as arcs (W502): rs274's end points of those arcs are
skipped up to the parabola's end, which must match.

With --kerf, the compensated path instead (docs/semantics.md §8): the tapes that use kerf compensation, their
G-code with `G41 D<n>` / `G42 D<n>` for each `G41.1/G42.1 D<width>` and a tool table whose tool n has that width
as its diameter (the standalone rs274 reads a tool table's diameters in inches: width / 25.4), against
`essi trace --kerf`: every end point within 1e-3 mm and every length within 1e-3 mm, in order. Where rs274 refuses
a program (a gouge), the motions before its refusal are compared, and essikit must report E307 there too. An arc
whose end misses its circle (ESSI allows it up to the profile's arc_tolerance) is written to G-code with its
centre moved onto the chord's bisector (docs/conversions.md): rs274 then offsets a slightly other circle, so a tape
with such arcs is compared within 1e-3 mm plus its largest miss (the run prints it).

Usage: rs274_differential.py [--kerf] ESSI_BINARY EXAMPLES_DIR [CORPUS_DIR [ESSI_GEN_NEST]]. With essi_gen_nest, a
generated 300 KB nesting tape (thousands of arcs whose ends lie within a unit of their circle) is compared too.
Fails (exit 1) when rs274 is missing.
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

TOLERANCE_MM = 1e-4
KERF_TOLERANCE_MM = 1e-3
CANON = re.compile(r"\b(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)")
TRACE = re.compile(r"^\d+ (rapid|travel|cut|mark) (line|arc|parabola)( head=\d)? \(([-\d.]+),([-\d.]+)\)->\(([-\d.]+),([-\d.]+)\).* len=([-\d.]+)")


def essikit_motions(essi, path, kerf=False):
    """(curve, end x, end y, length) of each motion of `essi trace` (--kerf: the compensated path), and the trace.
    Head 2's motions of a 3-axis tape are not among them: G-code has no head addresses and the conversion leaves
    them out (W501, docs/conversions.md)."""
    args = [essi, "trace", "--profile", "auto", "--decimals", "6"] + (["--kerf"] if kerf else []) + [path]
    out = subprocess.run(args, capture_output=True, text=True)
    motions = []
    for line in out.stdout.splitlines():
        m = TRACE.match(line)
        if m and m.group(3) != " head=2":
            motions.append((m.group(2), float(m.group(6)), float(m.group(7)), float(m.group(8))))
    return motions, out.stdout


# A machine as QtPlasmaC configures it: spindle 0 the torch, 1 the scribe (the writer's M3 $1), 2 the spotting tool.
INI = "[TRAJ]\nSPINDLES = 3\n[RS274NGC]\nPARAMETER_FILE = {var}\n"


def rs274_points(rs274, gcode_path, workdir, tool_table=None):
    """rs274's end points (x, y, length from the point before) and its error lines (a refusal's message)."""
    ini = os.path.join(workdir, "machine.ini")
    var = os.path.join(workdir, "rs274.var")
    with open(ini, "w") as f:
        f.write(INI.format(var=var))
    open(var, "a").close()
    args = [rs274, "-i", ini] + (["-t", tool_table] if tool_table else []) + ["-g", gcode_path]
    out = subprocess.run(args, capture_output=True, text=True, cwd=workdir, timeout=300)
    points = []
    at = (0.0, 0.0)
    for line in out.stdout.splitlines():
        m = CANON.search(line)
        if m:
            a = [float(v) for v in m.group(2).split(",")]
            length = math.hypot(a[0] - at[0], a[1] - at[1])
            if m.group(1) == "ARC_FEED":
                length = arc_length(at, (a[0], a[1]), (a[2], a[3]), int(a[4]))
            points.append((a[0], a[1], length))
            at = (a[0], a[1])
    errors = [l for l in (out.stdout + out.stderr).splitlines()
              if "error" in l.lower() or "invalid" in l.lower() or "unknown" in l.lower() or "goug" in l.lower()
              or "cannot" in l.lower() or "too" in l.lower()]
    return points, errors


def arc_length(start, end, centre, rotation):
    """The length of rs274's ARC_FEED: rotation +n ccw, -n cw (|n| - 1 more full turns), radius the mean of both ends'."""
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    sweep = a1 - a0
    if rotation > 0:
        while sweep <= 1e-12:
            sweep += 2 * math.pi
        sweep += 2 * math.pi * (rotation - 1)
    else:
        while sweep >= -1e-12:
            sweep -= 2 * math.pi
        sweep -= 2 * math.pi * (-rotation - 1)
    r = (math.hypot(start[0] - centre[0], start[1] - centre[1]) + math.hypot(end[0] - centre[0], end[1] - centre[1])) / 2
    return abs(sweep) * r


ARC = re.compile(r"\(([-\d.]+),([-\d.]+)\)->\(([-\d.]+),([-\d.]+)\) c=\(([-\d.]+),([-\d.]+)\)")


def largest_arc_miss(essi, path):
    """The largest difference of an arc's end radius and start radius in the programmed stream (mm)."""
    _, trace = essikit_motions(essi, path)
    miss = 0.0
    for line in trace.splitlines():
        m = ARC.search(line) if " arc " in line else None
        if m:
            sx, sy, ex, ey, cx, cy = map(float, m.groups())
            miss = max(miss, abs(math.hypot(ex - cx, ey - cy) - math.hypot(sx - cx, sy - cy)))
    return miss


def kerf_gcode(text, workdir):
    """G41.1/G42.1 D<width> as G41/G42 D<tool> with a tool table of those widths (in inches, as rs274 reads it)."""
    widths = []

    def tool(m):
        w = m.group(2)
        if w not in widths:
            widths.append(w)
        return f"{m.group(1)} D{widths.index(w) + 1}"
    text = re.sub(r"^(G4[12])\.1 D([-\d.]+)", tool, text, flags=re.M)
    table = os.path.join(workdir, "tool.tbl")
    with open(table, "w") as f:
        for i, w in enumerate(widths):
            f.write(f"T{i + 1} P{i + 1} D{float(w) / 25.4:.12f} ;kerf {w} mm\n")
    return text, table


def compare(name, motions, points, tolerance=TOLERANCE_MM, lengths=False, partial=False):
    """The motion stream's end points in rs274's points, in order (parabolas: their arcs' points skipped); with
    `lengths`, each motion's length too; `partial`: rs274 stopped early, the motions it made must agree."""
    k = 0
    for i, (curve, x, y, length) in enumerate(motions):
        if curve == "parabola":
            while k < len(points) and not (abs(points[k][0] - x) <= tolerance and abs(points[k][1] - y) <= tolerance):
                k += 1
        if k >= len(points):
            if partial:
                return None
            return f"{name}: rs274 ends after {len(points)} motions; essikit has {len(motions)} (motion {i + 1} missing)"
        px, py, plen = points[k]
        if abs(px - x) > tolerance or abs(py - y) > tolerance:
            return f"{name}: motion {i + 1} ({curve}) ends at ({x:.6f}, {y:.6f}) in essikit, ({px:.4f}, {py:.4f}) in rs274"
        if lengths and curve != "parabola" and abs(plen - length) > tolerance:
            return f"{name}: motion {i + 1} ({curve}) is {length:.6f} mm long in essikit, {plen:.4f} mm in rs274"
        k += 1
    if k != len(points):
        return f"{name}: rs274 has {len(points) - k} more motions than essikit's {len(motions)}"
    return None


def main():
    argv = sys.argv[1:]
    kerf = "--kerf" in argv
    argv = [a for a in argv if a != "--kerf"]
    if len(argv) < 2:
        print(__doc__)
        return 2
    essi, examples = argv[0], argv[1]
    corpus = argv[2] if len(argv) > 2 else ""
    gen_nest = argv[3] if len(argv) > 3 else ""
    rs274 = shutil.which("rs274")
    if not rs274:
        print("FAIL rs274 not found: scripts/setup installs linuxcnc-uspace (apt-get install --no-install-recommends linuxcnc-uspace)")
        return 1
    # (with --kerf also the bad kerf examples: rs274 must refuse them where essikit reports the gouge)
    tapes = [os.path.join(examples, f) for f in sorted(os.listdir(examples))
             if f.endswith((".esi", ".eia")) and (not f.startswith("bad_") or (kerf and f.startswith("bad_kerf")))]
    if corpus and os.path.isdir(corpus):
        for root, _, files in os.walk(corpus):
            tapes += [os.path.join(root, f) for f in sorted(files) if not f.startswith(".") and not f.endswith(".md")]
    failures = compared = 0
    with tempfile.TemporaryDirectory() as tmp:
        if gen_nest:
            nest = os.path.join(tmp, "generated_nest.esi")
            subprocess.run([gen_nest, "0.3", nest], check=True)
            tapes.append(nest)
        for tape in tapes:
            name = os.path.relpath(tape)
            gcode = os.path.join(tmp, "t.ngc")
            conv = subprocess.run([essi, "convert", "--to", "gcode", "--force", "--absolute", "--profile", "auto", tape, "-o", gcode],
                                  capture_output=True, text=True)
            if conv.returncode not in (0, 1):
                print(f"FAIL {name}: essi convert failed: {conv.stderr.strip()[:300]}")
                failures += 1
                continue
            with open(gcode) as f:
                text = f.read()
            motions, trace = essikit_motions(essi, tape, kerf)
            if kerf and " kerf=" not in trace:
                continue  # no compensation: the plain run compares it
            compared += 1
            table = None
            if kerf:
                text, table = kerf_gcode(text, tmp)
            else:
                text = re.sub(r"^G4[12]\.1 D[-\d.]+\n", "", text, flags=re.M)  # (the programmed path: no kerf)
            with open(gcode, "w") as f:
                f.write(text)
            points, errors = rs274_points(rs274, gcode, tmp, table)
            tolerance = KERF_TOLERANCE_MM
            if kerf:
                miss = largest_arc_miss(essi, tape)
                if miss > TOLERANCE_MM:
                    tolerance += miss
                    print(f"     {name}: arcs miss their circle by up to {miss:.4f} mm; compared within {tolerance:.4f} mm")
            if errors and kerf:
                # rs274 refuses the program: what it did must agree, and essikit must name the gouge.
                problem = compare(name, motions, points, tolerance, lengths=True, partial=True)
                if not problem and "E307" not in trace:
                    problem = f"{name}: rs274 refuses it ({errors[0].strip()}) but essikit reports no E307"
                if problem:
                    print(f"FAIL {problem}")
                    failures += 1
                else:
                    print(f"ok   {name}: rs274 refuses it ({errors[0].strip()}); its {len(points)} motions agree and essikit reports E307")
                continue
            if errors:
                problem = "; ".join(errors[:3])
            elif kerf:
                problem = compare(name, motions, points, tolerance, lengths=True)
            else:
                problem = compare(name, motions, points)
            if problem:
                print(f"FAIL {problem}")
                failures += 1
            else:
                print(f"ok   {name}: {len(motions)} motions, {len(points)} rs274 points")
    what = "compensated paths" if kerf else "tapes"
    tolerance = KERF_TOLERANCE_MM if kerf else TOLERANCE_MM
    print(f"{compared - failures} of {compared} {what} agree with rs274 within {tolerance} mm (or as printed)")
    if kerf and compared == 0:
        print("FAIL no tape with kerf compensation was compared")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
