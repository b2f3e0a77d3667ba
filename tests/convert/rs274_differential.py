#!/usr/bin/env python3
"""Differential test against LinuxCNC (docs/conversions.md): `essi convert --to gcode` of every example and real
tape, run by LinuxCNC's standalone interpreter `rs274` (Debian linuxcnc-uspace); its canonical STRAIGHT_TRAVERSE /
STRAIGHT_FEED / ARC_FEED end points must equal essikit's motion stream (`essi trace --decimals 6`) within 1e-4 mm.

Kerf: rs274 offsets the path under G41.1/G42.1, essikit's stream is the programmed path: the kerf words are taken
out of the G-code for this run (the offset path is compared by the kerf tests). Parabolas: the G-code has them as
arcs (W502): rs274's end points of those arcs are skipped up to the parabola's end, which must match.

Usage: rs274_differential.py ESSI_BINARY EXAMPLES_DIR [CORPUS_DIR [ESSI_GEN_NEST]]. With essi_gen_nest, a generated
300 KB nesting tape (thousands of arcs whose ends lie within a unit of their circle) is compared too. Fails (exit
1) when rs274 is missing.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

TOLERANCE_MM = 1e-4
CANON = re.compile(r"\b(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)")
TRACE = re.compile(r"^\d+ (rapid|travel|cut|mark) (line|arc|parabola)(?: head=\d)? \(([-\d.]+),([-\d.]+)\)->\(([-\d.]+),([-\d.]+)\)")


def essikit_motions(essi, path):
    out = subprocess.run([essi, "trace", "--profile", "auto", "--decimals", "6", path], capture_output=True, text=True)
    motions = []
    for line in out.stdout.splitlines():
        m = TRACE.match(line)
        if m:
            motions.append((m.group(2), float(m.group(5)), float(m.group(6))))
    return motions


# A machine as QtPlasmaC configures it: spindle 0 the torch, 1 the scribe (the writer's M3 $1), 2 the spotting tool.
INI = "[TRAJ]\nSPINDLES = 3\n[RS274NGC]\nPARAMETER_FILE = {var}\n"


def rs274_points(rs274, gcode_path, workdir):
    ini = os.path.join(workdir, "machine.ini")
    var = os.path.join(workdir, "rs274.var")
    with open(ini, "w") as f:
        f.write(INI.format(var=var))
    open(var, "a").close()
    out = subprocess.run([rs274, "-i", ini, "-g", gcode_path], capture_output=True, text=True, cwd=workdir, timeout=300)
    points = []
    for line in out.stdout.splitlines():
        m = CANON.search(line)
        if m:
            a = [float(v) for v in m.group(2).split(",")]
            points.append((a[0], a[1]))
    errors = [l for l in (out.stdout + out.stderr).splitlines()
              if "error" in l.lower() or "invalid" in l.lower() or "unknown" in l.lower()]
    return points, errors


def compare(name, motions, points):
    """The motion stream's end points in rs274's points, in order (parabolas: their arcs' points skipped)."""
    k = 0
    for i, (curve, x, y) in enumerate(motions):
        if curve == "parabola":
            while k < len(points) and not (abs(points[k][0] - x) <= TOLERANCE_MM and abs(points[k][1] - y) <= TOLERANCE_MM):
                k += 1
        if k >= len(points):
            return f"{name}: rs274 ends after {len(points)} motions; essikit has {len(motions)} (motion {i + 1} missing)"
        px, py = points[k]
        if abs(px - x) > TOLERANCE_MM or abs(py - y) > TOLERANCE_MM:
            return f"{name}: motion {i + 1} ({curve}) ends at ({x:.6f}, {y:.6f}) in essikit, ({px:.4f}, {py:.4f}) in rs274"
        k += 1
    if k != len(points):
        return f"{name}: rs274 has {len(points) - k} more motions than essikit's {len(motions)}"
    return None


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    essi, examples = sys.argv[1], sys.argv[2]
    corpus = sys.argv[3] if len(sys.argv) > 3 else ""
    gen_nest = sys.argv[4] if len(sys.argv) > 4 else ""
    rs274 = shutil.which("rs274")
    if not rs274:
        print("FAIL rs274 not found: scripts/setup installs linuxcnc-uspace (apt-get install --no-install-recommends linuxcnc-uspace)")
        return 1
    tapes = [os.path.join(examples, f) for f in sorted(os.listdir(examples))
             if f.endswith((".esi", ".eia")) and not f.startswith("bad_")]
    if corpus and os.path.isdir(corpus):
        for root, _, files in os.walk(corpus):
            tapes += [os.path.join(root, f) for f in sorted(files) if not f.startswith(".") and not f.endswith(".md")]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        if gen_nest:
            nest = os.path.join(tmp, "generated_nest.esi")
            subprocess.run([gen_nest, "0.3", nest], check=True)
            tapes.append(nest)
        for tape in tapes:
            name = os.path.relpath(tape)
            gcode = os.path.join(tmp, "t.ngc")
            conv = subprocess.run([essi, "convert", "--to", "gcode", "--absolute", "--profile", "auto", tape, "-o", gcode],
                                  capture_output=True, text=True)
            if conv.returncode not in (0, 1):
                print(f"FAIL {name}: essi convert failed: {conv.stderr.strip()[:300]}")
                failures += 1
                continue
            with open(gcode) as f:
                text = f.read()
            text = re.sub(r"^G4[12]\.1 D[-\d.]+\n", "", text, flags=re.M)  # (the programmed path: no kerf)
            with open(gcode, "w") as f:
                f.write(text)
            motions = essikit_motions(essi, tape)
            points, errors = rs274_points(rs274, gcode, tmp)
            problem = "; ".join(errors[:3]) if errors else compare(name, motions, points)
            if problem:
                print(f"FAIL {problem}")
                failures += 1
            else:
                print(f"ok   {name}: {len(motions)} motions, {len(points)} rs274 points")
    print(f"{len(tapes) - failures} of {len(tapes)} tapes agree with rs274 within {TOLERANCE_MM} mm")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
