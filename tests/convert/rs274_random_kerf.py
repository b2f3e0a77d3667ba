#!/usr/bin/env python3
"""Differential test of the kerf-compensated path against LinuxCNC on random contours (docs/semantics.md §8).

A fixed seed makes COUNT (default 1000) closed contours of lines and arcs, each cut with kerf compensation (29 or
30, a width of 1 to 4 mm) from a lead-in (a line, or in half of them an arc) and left by a rapid after 38. Every corner turns by an angle drawn
over 0–180° to either side, a fifth of them between 170° and 180°. The contours are one ESSI tape in units of
0.0001 mm (a profile with `unit_mm` 0.0001), so `essi convert --to gcode --absolute` writes the same coordinates
(4 decimals); every arc ends exactly on its circle (its end is its start's radius vector turned by the angle of a
Pythagorean triple, and quarter turns), so LinuxCNC offsets the same circles as essikit.

`essi trace --kerf --decimals 6` of the tape against LinuxCNC's standalone interpreter `rs274` (Debian
linuxcnc-uspace) running the G-code with `G41 D<n>` / `G42 D<n>` for each `G41.1` / `G42.1 D<width>` and a tool
table of those widths (in inches, as rs274 reads it), contour by contour:
- every compensated end point and length within 1e-3 mm of rs274's, in order (an arc's length by its sense);
- where rs274 refuses a contour with a gouge error, essikit reports E307 in that contour, at the motion rs274 was
  converting (at G40: the motion after 38), and the motions before agree; where rs274 does not, essikit reports no
  E307 there.
rs274 stops at its first error: it runs again from the contour after the refused one (about 380 runs, 20 s).

Usage: rs274_random_kerf.py ESSI_BINARY [COUNT [SEED]]. Fails (exit 1) when rs274 is missing.
"""
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

from rs274_differential import arc_length

TOLERANCE_MM = 1e-3
UNIT_MM = 1e-4
UNITS_PER_MM = 10000
CANON = re.compile(r"\b(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|COMMENT)\(([^)]*)\)")
TRACE = re.compile(r"^(\d+) (rapid|travel|cut|mark) (line|arc)(?: head=\d)? \(([-\d.]+),([-\d.]+)\)->\(([-\d.]+),([-\d.]+)\).* len=([-\d.]+)")
E307 = re.compile(r"^# E307 line (\d+)")
INI = "[TRAJ]\nSPINDLES = 3\n[RS274NGC]\nPARAMETER_FILE = {var}\n"
PROFILE = '{"base": "iso6582", "name": "random-kerf", "unit_mm": 0.0001, "arc_tolerance": 2}\n'


def triples(limit):
    """Primitive Pythagorean triples (a, b, c) with c up to `limit`, both ways round."""
    out = []
    for m in range(2, 20):
        for n in range(1, m):
            if (m - n) % 2 == 1 and math.gcd(m, n) == 1 and m * m + n * n <= limit:
                a, b, c = m * m - n * n, 2 * m * n, m * m + n * n
                out += [(a, b, c), (b, a, c)]
    return out


TRIPLES = triples(150)


def rot(v, cos_a, sin_a):
    return (v[0] * cos_a - v[1] * sin_a, v[0] * sin_a + v[1] * cos_a)


def unit_dir(angle):
    return (math.cos(angle), math.sin(angle))


def word(v):
    return f"{'+' if v >= 0 else '-'}{abs(v)}"


class Contour:
    """One contour in integer units: its tape blocks and the turn angles of its corners (degrees, signed)."""

    def __init__(self, rng, start):
        self.rng = rng
        self.blocks = []
        self.turns = []
        self.start = start
        self.at = start
        self.heading = rng.uniform(-math.pi, math.pi)  # the direction of travel at `at`
        self.end_heading = None  # the last piece's direction at its end
        self.side = rng.choice((29, 30))
        self.offset_mm = rng.uniform(0.5, 2.0)
        self.width_units = int(round(2 * self.offset_mm * UNITS_PER_MM))
        self.offset_mm = self.width_units / 2 / UNITS_PER_MM

    def turn_angle(self):
        rng = self.rng
        a = rng.uniform(170, 180) if rng.random() < 0.2 else rng.uniform(0, 180)
        return a if rng.random() < 0.5 else -a

    def line(self, length_mm):
        d = unit_dir(self.heading)
        dx, dy = int(round(d[0] * length_mm * UNITS_PER_MM)), int(round(d[1] * length_mm * UNITS_PER_MM))
        self.blocks.append(word(dx) + word(dy))
        self.at = (self.at[0] + dx, self.at[1] + dy)
        self.corner(math.atan2(dy, dx))
        self.heading = self.end_heading = math.atan2(dy, dx)

    def corner(self, start_heading):
        """Notes the turn from the last piece's end direction into a piece that starts in `start_heading`."""
        if self.end_heading is not None:
            t = math.degrees(start_heading - self.end_heading)
            self.turns.append((t + 180) % 360 - 180)

    def arc(self, radius_mm, ccw):
        """An arc starting in the current heading: its centre to the left (ccw) or right, its sweep a triple's angle
        plus quarter turns; its end exactly on its circle."""
        rng = self.rng
        a, b, c = rng.choice(TRIPLES)
        quarters = rng.randrange(0, 3)
        sense = 1 if ccw else -1
        # from the centre to the start: opposite the normal towards the centre, a multiple of c
        n = (-sense * math.sin(self.heading), sense * math.cos(self.heading))
        r_units = radius_mm * UNITS_PER_MM
        p, q = int(round(-n[0] * r_units / c)), int(round(-n[1] * r_units / c))
        v = (p * c, q * c)
        centre = (self.at[0] - v[0], self.at[1] - v[1])
        # turned by the triple's angle (towards the sense) and the quarter turns: integers, the same length
        w = (v[0] * a - sense * v[1] * b, sense * v[0] * b + v[1] * a)
        w = (w[0] // c, w[1] // c)
        for _ in range(quarters):
            w = (-sense * w[1], sense * w[0])
        end = (centre[0] + w[0], centre[1] + w[1])
        self.blocks.append(word(end[0] - self.at[0]) + word(end[1] - self.at[1]) + word(centre[0] - self.at[0]) +
                           word(centre[1] - self.at[1]) + ("+" if ccw else "-"))
        self.at = end
        # the directions of travel at the start and the end: perpendicular to the radius
        self.corner(math.atan2(sense * v[0], -sense * v[1]))
        self.heading = math.atan2(sense * w[0], -sense * w[1])
        self.end_heading = self.heading

    def arc_lead_in(self, heading):
        """Makes the lead-in an arc that ends at the start travelling in `heading` (when one fits: its chord longer
        than the offset, and its compensated centre on the same side of its compensated end as its own centre;
        rs274 trims an entry arc whose centre moved beyond its end at a point off the next piece's offset)."""
        rng = self.rng
        for _ in range(20):
            a, b, c = rng.choice(TRIPLES)
            sense = rng.choice((1, -1))
            radius = rng.uniform(5, 20) * UNITS_PER_MM
            # from the centre to the end, a multiple of c; the start is the end turned back by the triple's angle
            d = heading - sense * math.pi / 2
            v_end = (int(round(math.cos(d) * radius / c)) * c, int(round(math.sin(d) * radius / c)) * c)
            centre = (self.start[0] - v_end[0], self.start[1] - v_end[1])
            v_start = ((v_end[0] * a + sense * v_end[1] * b) // c, (-sense * v_end[0] * b + v_end[1] * a) // c)
            start = (centre[0] + v_start[0], centre[1] + v_start[1])
            r = self.offset_mm * UNITS_PER_MM
            if math.hypot(self.start[0] - start[0], self.start[1] - start[1]) < r + 0.5 * UNITS_PER_MM:
                continue
            # the compensated end and the entry's centre (docs/semantics.md §8, entry)
            inside = (self.side == 29) == (sense > 0)
            big_r = math.hypot(*v_end)
            k = (big_r - r if inside else big_r + r) / big_r
            end = (centre[0] + k * v_end[0], centre[1] + k * v_end[1])
            u = ((end[0] - centre[0]) / (k * big_r), (end[1] - centre[1]) / (k * big_r))
            ct = (centre[0] - start[0], centre[1] - start[1])
            den = 2 * (u[0] * ct[0] + u[1] * ct[1] + k * big_r)
            if den == 0:
                continue
            s = ((k * big_r) ** 2 - ct[0] ** 2 - ct[1] ** 2) / den
            moved = (centre[0] + s * u[0], centre[1] + s * u[1])
            if (moved[0] - end[0]) * (centre[0] - end[0]) + (moved[1] - end[1]) * (centre[1] - end[1]) <= 0:
                continue
            self.lead_start = start
            self.lead_in = (word(self.start[0] - start[0]) + word(self.start[1] - start[1]) + word(centre[0] - start[0]) +
                            word(centre[1] - start[1]) + ("+" if sense > 0 else "-"))
            self.end_heading = math.atan2(sense * v_end[0], -sense * v_end[1])
            return

    def build(self):
        rng = self.rng
        pieces = rng.randrange(3, 8)
        # lead-in: 10 to 30 mm, turning into the first piece by a random angle
        first_heading = self.heading
        lead_heading = first_heading - math.radians(self.turn_angle())
        lead = rng.uniform(10, 30) * UNITS_PER_MM
        lead_start = (self.start[0] - int(round(math.cos(lead_heading) * lead)),
                      self.start[1] - int(round(math.sin(lead_heading) * lead)))
        self.lead_start = lead_start
        self.lead_in = word(self.start[0] - lead_start[0]) + word(self.start[1] - lead_start[1])
        self.end_heading = math.atan2(self.start[1] - lead_start[1], self.start[0] - lead_start[0])
        if rng.random() < 0.5:
            self.arc_lead_in(lead_heading)
        self.heading = first_heading
        for i in range(pieces):
            if i > 0:
                self.heading += math.radians(self.turn_angle())
            if rng.random() < 0.5:
                self.line(rng.uniform(5, 50))
            else:
                ccw = rng.random() < 0.5
                inside = (self.side == 29) == ccw
                low = self.offset_mm + 1 if inside else 1
                self.arc(rng.uniform(low, low + 30), ccw)
        # closing line back to the start (if not there already)
        dx, dy = self.start[0] - self.at[0], self.start[1] - self.at[1]
        if dx or dy:
            self.blocks.append(word(dx) + word(dy))
            self.corner(math.atan2(dy, dx))
            self.at = self.start


def tape(contours):
    """The ESSI tape of the contours and the line where each contour's blocks start (1-based)."""
    lines = ["3", "RANDOM CONTOURS WITH KERF COMPENSATION (rs274_random_kerf.py)", "4", "39+1000"]
    at = (0, 0)
    first_lines = []
    for c in contours:
        lines += ["5", word(c.lead_start[0] - at[0]) + word(c.lead_start[1] - at[1]), "6"]
        first_lines.append(len(lines) + 1)
        lines += [f"{c.side}+{c.width_units}", "7", c.lead_in] + c.blocks + ["8", "38"]
        at = c.start
    lines += ["5", word(-at[0]) + word(-at[1]), "6", "64"]
    return "\n".join(lines) + "\n", first_lines


def rs274_run(rs274, gcode, workdir, table):
    """rs274's motions by contour (COMMENT("contour k") starts contour k): {k: [(x, y)]}, and its refusal: the
    contour, the failing G-code line's text, or None."""
    ini = os.path.join(workdir, "machine.ini")
    var = os.path.join(workdir, "rs274.var")
    with open(ini, "w") as f:
        f.write(INI.format(var=var))
    open(var, "a").close()
    path = os.path.join(workdir, "t.ngc")
    with open(path, "w") as f:
        f.write(gcode)
    out = subprocess.run([rs274, "-i", ini, "-t", table, "-g", path], capture_output=True, text=True, cwd=workdir,
                         timeout=300)
    motions = {}
    k = None
    at = (0.0, 0.0)
    for line in out.stdout.splitlines():
        m = CANON.search(line)
        if not m:
            continue
        if m.group(1) == "COMMENT":
            c = re.match(r'"contour (\d+)"', m.group(2))
            if c:
                k = int(c.group(1))
                motions[k] = []
            continue
        a = [float(v) for v in m.group(2).split(",")]
        length = math.hypot(a[0] - at[0], a[1] - at[1])
        if m.group(1) == "ARC_FEED":
            length = arc_length(at, (a[0], a[1]), (a[2], a[3]), int(a[4]))
        at = (a[0], a[1])
        if k is not None:
            motions[k].append((a[0], a[1], length))
    text = out.stdout + out.stderr
    refusal = None
    if out.returncode != 0 or "goug" in text.lower() or "error" in text.lower():
        tail = text.splitlines()
        failing = ""
        for i, line in enumerate(tail):
            if line.strip() == "executing" and i + 2 < len(tail):
                failing = tail[i + 2].strip()
        message = next((l for l in tail if "goug" in l.lower() or "cannot" in l.lower() or "error" in l.lower()
                        or "invalid" in l.lower() or "too" in l.lower()), "?")
        refusal = (k, message.strip(), failing)
    return motions, refusal


def main():
    argv = sys.argv[1:]
    if not argv:
        print(__doc__)
        return 2
    essi = argv[0]
    count = int(argv[1]) if len(argv) > 1 else 1000
    seed = int(argv[2]) if len(argv) > 2 else 6582
    rs274 = shutil.which("rs274")
    if not rs274:
        print("FAIL rs274 not found: scripts/setup installs linuxcnc-uspace (apt-get install --no-install-recommends linuxcnc-uspace)")
        return 1
    rng = random.Random(seed)
    contours = []
    for i in range(count):
        c = Contour(rng, ((i % 25) * 100 * UNITS_PER_MM, (i // 25) * 100 * UNITS_PER_MM))
        c.build()
        contours.append(c)
    text, first_lines = tape(contours)
    with tempfile.TemporaryDirectory() as tmp:
        tape_path = os.path.join(tmp, "random_kerf.esi")
        profile = os.path.join(tmp, "random_kerf.profile.json")
        with open(tape_path, "w") as f:
            f.write(text)
        with open(profile, "w") as f:
            f.write(PROFILE)
        gcode_path = os.path.join(tmp, "random_kerf.ngc")
        conv = subprocess.run([essi, "convert", "--to", "gcode", "--force", "--absolute", "--profile", profile, tape_path,
                               "-o", gcode_path], capture_output=True, text=True)
        if conv.returncode not in (0, 1):  # (1: the contours rs274 refuses are E307, written with --force)
            print(f"FAIL essi convert: {conv.stderr.strip()[:500]}")
            return 1
        trace = subprocess.run([essi, "trace", "--profile", profile, "--kerf", "--decimals", "6", tape_path],
                               capture_output=True, text=True).stdout
        plain = subprocess.run([essi, "trace", "--profile", profile, "--decimals", "6", tape_path],
                               capture_output=True, text=True).stdout

        def contour_of(line):
            k = -1
            for i, first in enumerate(first_lines):
                if line >= first:
                    k = i
            return k
        # essikit's compensated motions and first E307 by contour
        ours = {k: [] for k in range(count)}
        gouge_line = {}
        for line in trace.splitlines():
            m = TRACE.match(line)
            if m:
                k = contour_of(int(m.group(1)))
                if k >= 0:
                    ours[k].append((float(m.group(6)), float(m.group(7)), float(m.group(8))))
                continue
            m = E307.match(line)
            if m:
                k = contour_of(int(m.group(1)))
                gouge_line.setdefault(k, int(m.group(1)))
        # the programmed motions' ends (4 decimals, as the G-code has them) -> tape line, by contour
        programmed = {}
        for line in plain.splitlines():
            m = TRACE.match(line)
            if m:
                programmed[(contour_of(int(m.group(1))), f"{float(m.group(6)):.4f}", f"{float(m.group(7)):.4f}")] = \
                    int(m.group(1))

        # the G-code by contour: a comment before each G41.1 / G42.1, which become G41 / G42 D<tool>
        lines = open(gcode_path).read().splitlines()
        header, chunks, chunk = [], [], None
        for line in lines:
            if re.match(r"^G4[12]\.1 D", line):
                chunk = []
                chunks.append(chunk)
            (header if chunk is None else chunk).append(line)
        if len(chunks) != count:
            print(f"FAIL the G-code has {len(chunks)} compensated contours, the tape {count}")
            return 1
        widths = []
        for chunk in chunks:
            side, width = re.match(r"^(G4[12])\.1 D([-\d.]+)", chunk[0]).groups()
            if width not in widths:
                widths.append(width)
            chunk[0] = f"{side} D{widths.index(width) + 1}"
        table = os.path.join(tmp, "tool.tbl")
        with open(table, "w") as f:
            for i, w in enumerate(widths):
                f.write(f"T{i + 1} P{i + 1} D{float(w) / 25.4:.12f} ;kerf {w} mm\n")
        setup = [l for l in header if l.startswith("G17")]

        failures = []
        refused = agreed = runs = 0  # (refused: contours rs274 refuses with a gouge)
        k = 0
        while k < count:
            c = contours[k]
            body = setup + [f"G0 X{c.lead_start[0] / UNITS_PER_MM:.4f} Y{c.lead_start[1] / UNITS_PER_MM:.4f}", "F1000"]
            for j in range(k, count):
                body += [f"(contour {j})"] + chunks[j]
            body.append("M2")
            theirs, refusal = rs274_run(rs274, "\n".join(body) + "\n", tmp, table)
            runs += 1
            last = refusal[0] if refusal else count - 1
            if last is None:
                failures.append(f"rs274 refused before contour {k}: {refusal[1]}")
                break
            for j in range(k, last + 1):
                name = f"contour {j} (tape line {first_lines[j]})"
                mine, their = ours[j], theirs.get(j, [])
                is_refused = refusal is not None and j == last
                problem = None
                n = len(their)
                if not is_refused and len(mine) != n:
                    problem = f"{len(mine)} motions in essikit, {n} in rs274"
                for i in range(min(n, len(mine))):
                    (x, y, length), (px, py, plength) = mine[i], their[i]
                    if abs(x - px) > TOLERANCE_MM or abs(y - py) > TOLERANCE_MM:
                        problem = f"motion {i + 1} ends at ({x:.6f}, {y:.6f}) in essikit, ({px:.4f}, {py:.4f}) in rs274"
                        break
                    if abs(length - plength) > TOLERANCE_MM:
                        problem = f"motion {i + 1} is {length:.6f} mm long in essikit, {plength:.4f} mm in rs274"
                        break
                if is_refused and len(mine) < n and not problem:
                    problem = f"rs274 made {n} motions before refusing, essikit has {len(mine)}"
                if is_refused and "goug" not in refusal[1].lower():
                    problem = f"rs274 refuses it for another reason than a gouge: {refusal[1]} (at `{refusal[2]}`)"
                elif is_refused:
                    refused += 1
                if not problem and is_refused:
                    failing = refusal[2]
                    where = None
                    if failing.startswith("G40"):
                        where = "exit"
                    else:
                        m = re.search(r"X(-?[\d.]+) Y(-?[\d.]+)", failing)
                        if m:
                            where = programmed.get((j, f"{float(m.group(1)):.4f}", f"{float(m.group(2)):.4f}"))
                    if j not in gouge_line:
                        problem = f"rs274 refuses it ({refusal[1]}, at `{failing}`) but essikit reports no E307"
                    elif where == "exit":
                        # the motion after 38 (the rapid to the next lead-in, or home)
                        if gouge_line[j] != first_lines[j] + 6 + len(contours[j].blocks):
                            problem = f"rs274 refuses it at G40, essikit's first E307 is at tape line {gouge_line[j]}"
                    elif where is not None and gouge_line[j] != where:
                        problem = f"rs274 refuses it at `{failing}` (tape line {where}), essikit's first E307 is at tape line {gouge_line[j]}"
                elif not problem and j in gouge_line:
                    problem = f"essikit reports E307 at tape line {gouge_line[j]}, rs274 takes it"
                if problem:
                    failures.append(f"{name}: {problem}")
                else:
                    agreed += 1
            k = last + 1
    turns = [abs(t) for c in contours for t in c.turns]
    band = sum(1 for t in turns if t >= 170)
    for f in failures[:40]:
        print(f"FAIL {f}")
    if len(failures) > 40:
        print(f"FAIL ... {len(failures) - 40} more")
    print(f"{agreed} of {count} random contours (seed {seed}; {len(turns)} corners, {band} of them turning 170-180 degrees) "
          f"agree with rs274 within {TOLERANCE_MM} mm, E307 included; rs274 refused {refused} of them with a gouge "
          f"({runs} rs274 runs)")
    if band < 100:
        print(f"FAIL only {band} corners turn between 170 and 180 degrees (want at least 100)")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
