// Smoke test of the desktop viewer (build/native/bin/essi_viewer): starts it under xvfb-run (an X server in
// memory, OpenGL ES through Mesa's llvmpipe) with a tape, lets it draw a few frames once the tape is loaded and
// checks what it made: it exits 0, its state has the statistics `essi check` gives for the tape, and its last
// frame shows the cut colour where the tape's cuts are.
//
//   node viewer_smoke.mjs VIEWER ESSI TAPE OUT_DIR
//
// Exit code 77 (ctest's SKIP_RETURN_CODE) only when xvfb-run is not installed (scripts/setup installs it).
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

const kSkip = 77;
const kWidth = 1600, kHeight = 900;          // the window the viewer opens (MainLoopGlfw.cpp)
const kFrames = 5;                            // frames drawn after the load, before the viewer exits
const kColorTolerance = 6;                    // per 8-bit channel (llvmpipe rounds like any GPU)
const kMinCutPixels = 500;                    // a plate of cut contours at the fitted view covers far more
const kStatTolerance = 1e-6;

const [viewer, essi, tape, outDir] = process.argv.slice(2);
if (!viewer || !essi || !tape || !outDir) {
  console.error('usage: node viewer_smoke.mjs VIEWER ESSI TAPE OUT_DIR');
  process.exit(2);
}

const which = spawnSync('sh', ['-c', 'command -v xvfb-run'], { encoding: 'utf8' });
if (which.status !== 0) {
  console.log('SKIP: xvfb-run is not installed (scripts/setup installs the Debian package xvfb)');
  process.exit(kSkip);
}

fs.mkdirSync(outDir, { recursive: true });
const shot = path.join(outDir, 'desktop-viewer.ppm');
const stateFile = path.join(outDir, 'desktop-viewer.json');
for (const f of [shot, stateFile]) fs.rmSync(f, { force: true });

const run = spawnSync('xvfb-run', ['-a', '-s', `-screen 0 ${kWidth}x${kHeight}x24`,
                                   viewer, '--frames', String(kFrames), '--screenshot', shot, '--state', stateFile, tape],
                      { encoding: 'utf8', env: { ...process.env, LIBGL_ALWAYS_SOFTWARE: '1' }, timeout: 120000 });
if (run.stdout) process.stdout.write(run.stdout);
if (run.stderr) process.stderr.write(run.stderr);
assert.equal(run.error, undefined, `could not run xvfb-run: ${run.error}`);
assert.equal(run.status, 0, `essi_viewer exited with ${run.status} (signal ${run.signal})`);

// The state: the tape, loaded and drawn, with the CLI's statistics.
const state = JSON.parse(fs.readFileSync(stateFile, 'utf8'));
assert.equal(state.status, 'ready');
assert.equal(state.name, tape);
assert.ok(state.segments > 0, `no segments drawn: ${state.segments}`);
let out;
try {
  out = execFileSync(essi, ['check', '--format', 'json', tape], { encoding: 'utf8' });
} catch (e) {
  out = e.stdout;  // exit 1: the tape has errors, still a report
}
const cli = JSON.parse(out).files[0];
const close = (a, b) => Math.abs(a - b) <= kStatTolerance + 1e-9 * Math.abs(b);
for (const [key, want] of Object.entries(cli.stats)) {
  const got = state.stats[key];
  if (want === null || typeof want !== 'object') {
    if (typeof want === 'number') assert.ok(close(got, want), `${key}: viewer ${got}, essi check ${want}`);
    else assert.equal(got, want, key);
  } else {
    for (const [k, v] of Object.entries(want)) assert.ok(close(got[k], v), `${key}.${k}: viewer ${got[k]}, essi check ${v}`);
  }
}
assert.equal(state.diagnostics.length, cli.diagnostics.length, 'diagnostics');
assert.ok(state.render.frames >= kFrames, `frames drawn: ${state.render.frames}`);

// The screenshot: a binary PPM of the whole window. Count the cut colour inside the drawing area, and check that
// they sit inside the screen box of the tape's cuts (the view's origin_px maps machine mm to pixels).
const ppm = fs.readFileSync(shot);
const header = ppm.subarray(0, 32).toString('latin1').match(/^P6\s+(\d+)\s+(\d+)\s+255\s/);
assert.ok(header, 'not a binary PPM');
const [w, h] = [Number(header[1]), Number(header[2])];
assert.equal(w, kWidth);
assert.equal(h, kHeight);
const pixels = ppm.subarray(header[0].length);
assert.equal(pixels.length, w * h * 3);
const cut = state.kind_colors[2];
const [ax, ay, aw, ah] = state.view.area;
const { zoom, x_mm: cx, y_mm: cy, origin_px: [ox, oy] } = state.view;  // px = ox + (x - cx) * zoom, py = oy - (y - cy) * zoom
const box = state.stats.cut_bbox_mm;
const slack = 3;  // pixels: line width and rounding
const bx0 = ox + (box.min_x - cx) * zoom - slack, bx1 = ox + (box.max_x - cx) * zoom + slack;
const by0 = oy - (box.max_y - cy) * zoom - slack, by1 = oy - (box.min_y - cy) * zoom + slack;
let inArea = 0, outside = 0;
for (let y = Math.ceil(ay); y < Math.floor(ay + ah); ++y) {
  for (let x = Math.ceil(ax); x < Math.floor(ax + aw); ++x) {
    const i = (y * w + x) * 3;
    if (Math.abs(pixels[i] - cut[0]) <= kColorTolerance && Math.abs(pixels[i + 1] - cut[1]) <= kColorTolerance &&
        Math.abs(pixels[i + 2] - cut[2]) <= kColorTolerance) {
      ++inArea;
      if (x < bx0 || x > bx1 || y < by0 || y > by1) ++outside;
    }
  }
}
console.log(`essi_viewer drew ${path.basename(tape)}: ${state.segments} segments, ${inArea} cut-coloured pixels ` +
            `(${outside} outside the cuts' box), zoom ${zoom.toFixed(3)} px/mm`);
assert.ok(inArea >= kMinCutPixels, `only ${inArea} pixels of the cut colour ${cut} in the drawing area`);
assert.equal(outside, 0, 'cut-coloured pixels outside the box of the cuts');
