// Browser tests of the viewer: headless Debian Chromium driven by playwright-core, run by node:test.
//
//   node --test tests/e2e/          (ctest: the `e2e` test of the native preset)
//
// Needs the viewer built by the wasm preset (build/wasm/web) and, for the statistics, the CLI from the native
// preset (build/native/bin/essi). Override with ESSI_WEB_ROOT, ESSI_BIN, ESSI_CHROMIUM. Screenshots are kept
// in build/e2e/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  webRoot, essiBin, genBin, examplesDir, shots, CUT_RGB, freePort, startHarness, stopHarness,
  newPage as openPage, generatedTape, dropFromUrl, cliReport as cliReportOf, genDir,
} from './support.mjs';

let server, baseUrl, browser;

function examples() {
  return fs.readdirSync(examplesDir).filter((f) => f.endsWith('.esi') || f.endsWith('.eia')).sort();
}

// The CLI's verdict for one tape: {stats, diagnostics}. Falls back to the example's .expected.json golden
// when the CLI is not built.
function cliReport(file) {
  const full = path.join(examplesDir, file);
  if (fs.existsSync(essiBin)) {
    let out;
    try {
      // The viewer reads with --profile auto by default (the dialect the tape's evidence shows).
      out = execFileSync(essiBin, ['check', '--format', 'json', '--profile', 'auto', full], { encoding: 'utf8' });
    } catch (e) {
      out = e.stdout;  // exit 1 when the tape has errors
    }
    const report = JSON.parse(out);
    return { source: 'essi check', ...report.files[0] };
  }
  const golden = path.join(examplesDir, file.replace(/\.(esi|eia)$/, '.expected.json'));
  return { source: path.basename(golden), ...JSON.parse(fs.readFileSync(golden, 'utf8')) };
}

function close(a, b) {
  return Math.abs(a - b) <= 1e-6 + 1e-9 * Math.abs(b);
}

function assertStatsEqual(page, cli, name) {
  for (const [key, want] of Object.entries(cli)) {
    const got = page[key];
    if (want === null || typeof want !== 'object') {
      if (typeof want === 'number') assert.ok(close(got, want), `${name}: ${key} page ${got} != ${want}`);
      else assert.equal(got, want, `${name}: ${key}`);
    } else {
      assert.ok(got && typeof got === 'object', `${name}: ${key} missing on the page`);
      for (const [k, v] of Object.entries(want)) assert.ok(close(got[k], v), `${name}: ${key}.${k} page ${got[k]} != ${v}`);
    }
  }
}

function newPage() {
  return openPage(browser, baseUrl);
}

// Drops a file on the canvas the way a person does (dragenter, dragover, drop with a DataTransfer).
async function dropFile(page, name, bytes) {
  await dropOnly(page, name, bytes);
  await page.waitForFunction((n) => { const s = essikit.state(); return s.name === n && s.status === 'ready'; }, name,
                             { timeout: 60000 });
  return page.evaluate(() => essikit.state());
}

// A profile file (.json) dropped: no tape loads; the toolbar's message says what became of it.
async function dropProfile(page, name, bytes) {
  await dropOnly(page, name, bytes);
  await page.waitForFunction((n) => essikit.state().message.includes(n), name, { timeout: 30000 });
  return page.evaluate(() => essikit.state());
}

async function dropOnly(page, name, bytes) {
  await page.evaluate(async ([n, b64]) => {
    const bin = atob(b64);
    const data = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) data[i] = bin.charCodeAt(i);
    const dt = new DataTransfer();
    dt.items.add(new File([data], n, { type: 'text/plain' }));
    const canvas = document.getElementById('canvas');
    for (const type of ['dragenter', 'dragover', 'drop'])
      canvas.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, Buffer.from(bytes).toString('base64')]);
}

// Pixels of a PNG screenshot, decoded by the browser: returns a function (x, y) -> [r, g, b].
async function pixels(page, png) {
  const data = await page.evaluate(async (b64) => {
    const blob = await (await fetch('data:image/png;base64,' + b64)).blob();
    const bmp = await createImageBitmap(blob);
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const g = c.getContext('2d');
    g.drawImage(bmp, 0, 0);
    // The RGBA bytes as base64 (a JSON array of millions of numbers takes seconds to pass).
    const px = g.getImageData(0, 0, bmp.width, bmp.height).data;
    let bin = '';
    for (let i = 0; i < px.length; i += 0x8000) bin += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
    return { w: bmp.width, h: bmp.height, px: btoa(bin) };
  }, png.toString('base64'));
  const px = Buffer.from(data.px, 'base64');
  return (x, y) => {
    const i = (Math.round(y) * data.w + Math.round(x)) * 4;
    return [px[i], px[i + 1], px[i + 2]];
  };
}

function near(rgb, want, tol = 45) {
  return Math.hypot(rgb[0] - want[0], rgb[1] - want[1], rgb[2] - want[2]) <= tol;
}

before(async () => {
  ({ server, baseUrl, browser } = await startHarness());
});

after(() => stopHarness({ server, browser }));

test('every example tape dropped on the page has the statistics and diagnostics of essi check', async () => {
  const page = await newPage();
  for (const file of examples()) {
    const state = await dropFile(page, file, fs.readFileSync(path.join(examplesDir, file)));
    const cli = cliReport(file);
    assertStatsEqual(state.stats, cli.stats, `${file} (vs ${cli.source})`);
    assert.deepEqual(state.diagnostics.map((d) => [d.severity, d.code, d.line, d.column]),
                     cli.diagnostics.map((d) => [d.severity, d.code, d.line, d.column]), `${file}: diagnostics`);
    await page.screenshot({ path: path.join(shots, file.replace(/\.(esi|eia)$/, '.png')) });
  }
  await page.close();
});

test('the viewer reads with the dialect the tape shows, says why, and switches in one click', async () => {
  const page = await newPage();
  let state = await dropFile(page, 'woyda_end_slash.esi', fs.readFileSync(path.join(examplesDir, 'woyda_end_slash.esi')));
  assert.equal(state.profile, 'auto');
  assert.equal(state.input, 'essi');
  assert.equal(state.dialect, 'woyda');
  assert.deepEqual(state.dialect_evidence, cliReport('woyda_end_slash.esi').dialect_evidence);
  assert.ok(state.dialect_evidence.some((e) => e.includes('`/` ends the program at line 29')), state.dialect_evidence.join('; '));
  assert.equal(state.ok, true);
  // The ISO reading: '/' is no ESSI character there, and the note says the tape looks like woyda.
  state = await page.evaluate(() => essikit.setProfile('iso6582'));
  assert.equal(state.profile, 'iso6582');
  assert.equal(state.dialect, 'iso6582');
  assert.equal(state.ok, false);
  const note = state.diagnostics.find((d) => d.code === 'N403');
  assert.ok(note && note.severity === 'note' && note.message.includes('--profile woyda'), JSON.stringify(state.diagnostics));
  state = await page.evaluate(() => essikit.setProfile('auto'));
  assert.equal(state.dialect, 'woyda');
  assert.equal(state.ok, true);
  // An EIA tape loads like an ESSI one.
  state = await dropFile(page, 'din66025_plate.eia', fs.readFileSync(path.join(examplesDir, 'din66025_plate.eia')));
  assert.equal(state.input, 'eia');
  assert.equal(state.dialect, 'din66025');
  assert.ok(Math.abs(state.stats.cut_length_mm - 694.247780) < 1e-5, state.stats.cut_length_mm);
  await page.screenshot({ path: path.join(shots, 'dialect-din66025.png') });
  // Three torches: each of the 4 cuts is drawn 3 times, the 2 rapids once.
  state = await dropFile(page, 'woyda_multi_torch.esi', fs.readFileSync(path.join(examplesDir, 'woyda_multi_torch.esi')));
  assert.equal(state.dialect, 'woyda');
  assert.equal(state.stats.pierces, 3);
  assert.equal(state.segments, 4 * 3 + 2);
  await page.screenshot({ path: path.join(shots, 'multi-torch.png') });
  // The Export menu's files are essi convert's and essi render's, byte for byte.
  const tape = path.join(examplesDir, 'woyda_multi_torch.esi');
  for (const [format, args] of [['gcode', ['convert', '--to', 'gcode', '--absolute']], ['eia', ['convert', '--to', 'eia']],
                                ['essi', ['convert', '--to', 'essi']], ['dxf', ['render', '--format', 'dxf']]]) {
    const page_text = await page.evaluate((f) => essikit.exportText(f), format);
    const cli = execFileSync(essiBin, [...args, '--profile', 'auto', tape, '-o', '-'], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] });
    assert.equal(page_text, cli, `export ${format}`);
  }
  await page.close();
});

test('a bad tape shows its diagnostics with their lines', async () => {
  const page = await newPage();
  // (a bad tape that needs its own profile, e.g. a placement whose table it leaves, is bad only with that profile)
  const ownProfile = (f) => fs.existsSync(path.join(examplesDir, f.replace(/\.(esi|eia)$/, '.profile.json')));
  const bad = examples().filter((f) => f.startsWith('bad_') && !ownProfile(f));
  assert.ok(bad.length > 0);
  for (const file of bad) {
    const state = await dropFile(page, file, fs.readFileSync(path.join(examplesDir, file)));
    assert.ok(state.diagnostics.length > 0, `${file}: no diagnostics`);
    assert.equal(state.ok, false, `${file}: should have errors`);
    const first = state.diagnostics.find((d) => d.line > 0);
    assert.ok(first, `${file}: diagnostics without lines`);
    // Selecting the diagnostic's line selects that line (what clicking it in the list does).
    await page.evaluate((l) => essikit.selectLine(l), first.line);
    const after = await page.evaluate(() => essikit.state());
    assert.equal(after.selection.line, first.line);
    await page.screenshot({ path: path.join(shots, `diagnostics-${file.replace(/\.(esi|eia)$/, '')}.png`) });
  }
  // Not a tape at all: a clear message, never a blank page (a picture, an empty file: see 'a file that is not a tape').
  const state = await dropFile(page, 'notes.txt', Buffer.from('Hello, this is a letter, not a tape.\nRegards\n'));
  assert.ok(state.banner.length > 0, 'a text file that is not a tape gets a message');
  await page.screenshot({ path: path.join(shots, 'not-a-tape.png') });
  await page.close();
});

test('the Open button path (<input type=file>) loads a tape', async () => {
  const page = await newPage();
  await page.setInputFiles('#file', path.join(examplesDir, 'plate_holes.esi'));
  await page.waitForFunction(() => essikit.state().name === 'plate_holes.esi' && essikit.state().status === 'ready');
  await page.close();
});

test('a share link restores the tape, the view and the selection', async () => {
  const page = await newPage();
  const text = fs.readFileSync(path.join(examplesDir, 'plate_holes.esi'), 'utf8');
  await page.evaluate((t) => essikit.load('plate_holes.esi', t), text);
  await page.evaluate(() => { essikit.setView(210, 95, 4.5); essikit.selectLine(24); });
  await page.waitForTimeout(50);
  const before = await page.evaluate(() => essikit.state());
  const url = await page.evaluate(() => essikit.shareLink());
  assert.match(url, /#c=.*&t=/);
  const other = await browser.newPage({ viewport: { width: 1600, height: 900 } });
  await other.goto(url);
  await other.waitForFunction(() => window.essikit && essikit.started &&
                                    essikit.state().status === 'ready', null, { timeout: 30000 });
  const restored = await other.evaluate(() => essikit.state());
  assert.equal(restored.name, 'plate_holes.esi');
  assert.deepEqual(restored.stats, before.stats);
  assert.equal(restored.selection.line, 24);
  assert.ok(Math.abs(restored.view.x_mm - 210) < 1e-3 && Math.abs(restored.view.y_mm - 95) < 1e-3);
  assert.ok(Math.abs(restored.view.zoom - 4.5) < 1e-6);
  await other.screenshot({ path: path.join(shots, 'share-restored.png') });
  await other.close();
  await page.close();
});

// Opens `url` in a fresh page and waits for its tape, or for the problem it has.
async function openLink(url) {
  const other = await browser.newPage({ viewport: { width: 1600, height: 900 } });
  await other.goto(url);
  await other.waitForFunction(() => window.essikit && essikit.started &&
                                    (essikit.state().status === 'ready' || essikit.state().link_problem), null, { timeout: 30000 });
  return other;
}

test('a share link carries the profile and the format: the receiver sees the sender\'s verdict', async () => {
  const page = await newPage();
  // woyda_end_slash read as iso6582 on purpose: its / is E101 there (auto would pick woyda)
  await loadExample(page, 'woyda_end_slash.esi');
  const sent = await page.evaluate(() => essikit.setProfile('iso6582'));
  assert.equal(sent.profile, 'iso6582');
  assert.ok(sent.diagnostics.length > 0);
  const url = await page.evaluate(() => essikit.shareLink());
  assert.match(url, /&p=iso6582&i=essi&n=woyda_end_slash\.esi&b=\d+&t=/);
  const other = await openLink(url);
  const got = await other.evaluate(() => essikit.state());
  assert.equal(got.profile, 'iso6582');
  assert.equal(got.input, 'essi');
  assert.deepEqual(got.diagnostics, sent.diagnostics);
  assert.deepEqual(got.stats, sent.stats);
  await other.close();
  // A user profile travels in the link as its JSON: the placement on the machine is the sender's.
  await dropProfile(page, 'skewed_plate.profile.json', fs.readFileSync(path.join(examplesDir, 'skewed_plate.profile.json')));
  const { state } = await loadExample(page, 'skewed_plate.esi');
  assert.equal(state.profile, 'skewed-plate');
  const url2 = await page.evaluate(() => essikit.shareLink());
  assert.match(url2, /&p=skewed-plate&pj=[A-Za-z0-9_-]+&i=essi&/);
  const other2 = await openLink(url2);
  const got2 = await other2.evaluate(() => essikit.state());
  assert.equal(got2.profile, 'skewed-plate');
  assert.deepEqual(got2.stats, state.stats);
  assert.ok(got2.stats.machine_cut_bbox_mm, JSON.stringify(got2.stats));
  await other2.close();
  await page.close();
});

test('a share link cut off or damaged says so; a new tape takes the link out of the address', async () => {
  const page = await newPage();
  await loadExample(page, 'plate_holes.esi');
  const url = await page.evaluate(() => essikit.shareLink());
  // cut in the tape's data (as a mail program may do): the length before it tells
  const cut = await openLink(url.slice(0, url.length - 30));
  const problem = (await cut.evaluate(() => essikit.state())).link_problem;
  assert.match(problem, /cut off or damaged/);
  assert.equal((await cut.evaluate(() => essikit.state())).status, 'empty');
  await cut.screenshot({ path: path.join(shots, 'share-link-cut.png') });
  await cut.close();
  // damaged data: not deflate
  const damaged = await openLink(url.replace(/&t=.*$/, '&t=AAAAAAAA'));
  assert.match((await damaged.evaluate(() => essikit.state())).link_problem, /cut off or damaged/);
  await damaged.close();
  // The address holds the shared tape's link; another tape loaded takes it out, and sharing that one puts its
  // own in: a reload shows the tape the address names.
  assert.ok(await page.evaluate(() => location.hash.includes('&t=')));
  await loadExample(page, 'arcs_both_senses.esi');
  assert.equal(await page.evaluate(() => location.hash), '');
  const url2 = await page.evaluate(() => essikit.shareLink());
  assert.equal(await page.evaluate(() => location.href), url2);
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started && essikit.state().status === 'ready', null, { timeout: 30000 });
  assert.equal((await page.evaluate(() => essikit.state())).name, 'arcs_both_senses.esi');
  await page.close();
});

test('clicking a segment selects its source line, and a line selects its segment', async () => {
  const page = await newPage();
  const text = fs.readFileSync(path.join(examplesDir, 'plate_holes.esi'), 'utf8');
  const state = await page.evaluate((t) => essikit.load('plate_holes.esi', t), text);
  const motions = await page.evaluate((n) => Array.from({ length: n }, (_, i) => essikit.motion(i)), state.motions);
  // Long cut lines: their middle is far from every other motion.
  const targets = motions.filter((m) => m.kind === 'cut' && m.curve === 'line' && m.length_mm > 150);
  assert.ok(targets.length >= 2);
  for (const m of targets) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
    await page.mouse.click(p.x, p.y);
    // The click is handled in the next frames (slow under SwiftShader on a busy machine): wait for it.
    await page.waitForFunction((i) => { const s = essikit.state(); return s.selection && s.selection.motion === i; },
                               m.index, { timeout: 10000 }).catch(() => {});
    const s = await page.evaluate(() => essikit.state());
    assert.ok(s.selection, `clicking (${p.x}, ${p.y}) selected nothing`);
    assert.equal(s.selection.line, m.line, `clicked motion ${m.index}`);
    assert.equal(s.selection.motion, m.index);
  }
  await page.screenshot({ path: path.join(shots, 'selection.png') });
  // The other way: a source line selects its motion.
  const arc = motions.find((m) => m.curve === 'arc');
  await page.evaluate((l) => essikit.selectLine(l), arc.line);
  const s = await page.evaluate(() => essikit.state());
  assert.equal(s.selection.motion, arc.index);
  // Clicking empty space clears the selection.
  const empty = await page.evaluate(() => essikit.project(-400, -400));
  await page.mouse.click(Math.max(empty.x, 330), Math.min(empty.y, 880));
  await page.close();
});

test('the screenshot shows the cut colour where the cut path is', async () => {
  const page = await newPage();
  const text = fs.readFileSync(path.join(examplesDir, 'plate_holes.esi'), 'utf8');
  const state = await page.evaluate((t) => essikit.load('plate_holes.esi', t), text);
  assert.deepEqual(state.kind_colors[2], CUT_RGB);
  const motions = await page.evaluate((n) => Array.from({ length: n }, (_, i) => essikit.motion(i)), state.motions);
  await page.mouse.move(5, 890);  // keep the cursor away from the path
  await page.waitForTimeout(100);
  const png = await page.screenshot({ path: path.join(shots, 'cut-colour.png') });
  const at = await pixels(page, png);
  let checked = 0;
  for (const m of motions.filter((x) => x.kind === 'cut' && x.curve === 'line' && x.length_mm > 50)) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
    const hits = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) hits.push(at(p.x + dx, p.y + dy));
    assert.ok(hits.some((c) => near(c, CUT_RGB)), `no cut colour at (${p.x}, ${p.y}): ${JSON.stringify(hits)}`);
    ++checked;
  }
  assert.ok(checked >= 3);
  // And not where nothing is cut: the middle of the plate, between the holes (x 160, y 60).
  const inside = await page.evaluate(() => essikit.project(160, 60));
  assert.ok(!near(at(inside.x, inside.y), CUT_RGB), 'cut colour where nothing is cut');
  await page.close();
});

test('essi serve serves the viewer and the examples', async (t) => {
  let help = '';
  try {
    help = execFileSync(essiBin, ['serve', '--help'], { encoding: 'utf8' });
  } catch { /* not built or no serve command */ }
  if (!help.includes('serve')) return t.skip('essi serve is not available');
  const port = await freePort();
  // Its share store in a folder of its own (by default it is ./essi-data, in whatever folder the tests run from).
  const data = fs.mkdtempSync(path.join(os.tmpdir(), 'essi-serve-'));
  const proc = spawn(essiBin, ['serve', '--host', '127.0.0.1', '--port', String(port), '--data', data],
                     { stdio: ['ignore', 'pipe', 'pipe'] });
  try {
    const address = await new Promise((resolve, reject) => {
      let out = '';
      const timer = setTimeout(() => reject(new Error('essi serve printed no address: ' + out)), 10000);
      proc.stdout.on('data', (d) => {
        out += d;
        const m = out.match(/http:\/\/[^\s]+/);
        if (m) { clearTimeout(timer); resolve(m[0]); }
      });
      proc.on('exit', (code) => reject(new Error('essi serve exited with ' + code)));
    });
    const index = await fetch(address);
    assert.equal(index.status, 200);
    assert.match(await index.text(), /essi_viewer\.js/);
    const wasm = await fetch(new URL('essi_viewer.wasm', address));
    assert.equal(wasm.headers.get('content-type'), 'application/wasm');
    // The CJK font, fetched by the page only when a text needs it (docs/viewer.md#fonts).
    const cjk = await fetch(new URL('essi_cjk.ttc', address));
    assert.equal(cjk.status, 200);
    assert.equal(cjk.headers.get('content-type'), 'font/collection');
    assert.ok((await cjk.arrayBuffer()).byteLength > 1e6);
    const list = await (await fetch(new URL('examples/index.json', address))).json();
    assert.ok(list.includes('plate_holes.esi'));
    const page = await browser.newPage({ viewport: { width: 1600, height: 900 } });
    // The program comes gzip-encoded (its twin made by the build: 40 % of the bytes on the wire).
    const wasmResponse = new Promise((resolve) => page.on('response', (r) => {
      if (r.url().endsWith('/essi_viewer.wasm')) resolve(r);
    }));
    await page.goto(address);
    await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
    await page.evaluate(() => essikit.ready);
    const served = await wasmResponse;
    assert.equal(served.headers()['content-encoding'], 'gzip');
    assert.ok(Number(served.headers()['content-length']) < 0.5 * fs.statSync(path.join(webRoot, 'essi_viewer.wasm')).size,
              `the wasm sent in ${served.headers()['content-length']} bytes`);
    // The start screen offers the server's examples; one click (the button's path) opens one.
    await page.waitForFunction(() => essikit.state().examples.length > 0, null, { timeout: 10000 });
    assert.deepEqual((await page.evaluate(() => essikit.state())).examples, list);
    await page.screenshot({ path: path.join(shots, 'start-screen-examples.png') });
    await page.evaluate(() => window.essikitOpenExample('plate_holes.esi'));
    await page.waitForFunction(() => essikit.state().status === 'ready' && essikit.state().name === 'plate_holes.esi', null, { timeout: 30000 });
    // ... and remembers its name (names only) for the next visit's start screen
    await page.reload();
    await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
    assert.equal((await page.evaluate(() => essikit.state())).recent[0], 'plate_holes.esi');
    await page.close();
  } finally {
    proc.kill();
    fs.rmSync(data, { recursive: true, force: true });
  }
});

// ---- the viewer's features, one test each -------------------------------------------------------------------

async function loadExample(page, file) {
  const text = fs.readFileSync(path.join(examplesDir, file), 'utf8');
  const state = await page.evaluate(([n, t]) => essikit.load(n, t), [file, text]);
  const motions = await page.evaluate((n) => Array.from({ length: n }, (_, i) => essikit.motion(i)), state.motions);
  await page.mouse.move(700, 450);  // over the drawing, so that keys go to the canvas
  return { state, motions };
}

// ImGui 1.86 reads the key state once a frame (no input queue): hold a key down across two frames.
async function tap(page, key) {
  await page.keyboard.down(key);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
  await page.keyboard.up(key);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
}

// Keys are handled in the next frames: wait until the state says so.
async function until(page, fn, arg, what) {
  await page.waitForFunction(fn, arg, { timeout: 15000 }).catch(() => {});
  assert.ok(await page.evaluate(fn, arg), what);
}

test('pasting a tape\'s text loads it', async () => {
  const page = await newPage();
  const file = 'arcs_both_senses.esi';
  const text = fs.readFileSync(path.join(examplesDir, file), 'utf8');
  await page.evaluate((t) => {
    const dt = new DataTransfer();
    dt.setData('text/plain', t);
    document.dispatchEvent(new ClipboardEvent('paste', { clipboardData: dt, bubbles: true, cancelable: true }));
  }, text);
  await until(page, () => essikit.state().name === 'pasted.esi' && essikit.state().status === 'ready', null, 'paste loaded nothing');
  const state = await page.evaluate(() => essikit.state());
  assert.equal(state.stats.motions, cliReportOf(path.join(examplesDir, file)).stats.motions);
  await page.close();
});

test('the Open... button opens the file picker and loads the chosen tape', async () => {
  const page = await newPage();
  // Headless Chromium shows no file chooser for a mouse click while a WebGL canvas draws every frame (a
  // plain page shows it; keys work), so the click is checked where the page does its part: the picker
  // (<input type=file>) is opened inside the click itself, with the user activation browsers require.
  await page.evaluate(() => {
    const input = document.getElementById('file');
    window.__opened = [];
    input.click = () => window.__opened.push(`${window.event ? window.event.type : 'frame'} ${navigator.userActivation.isActive}`);
  });
  // The ImGui toolbar's first button (window padding 8 px, 13 px font).
  await page.mouse.click(28, 18);
  assert.deepEqual(await page.evaluate(() => window.__opened), ['click true'], 'the Open button did not open the picker in the click');
  // A click elsewhere on the toolbar opens nothing.
  await page.mouse.click(1500, 18);
  await page.waitForTimeout(300);
  assert.equal((await page.evaluate(() => window.__opened)).length, 1, 'a click beside the Open button opened the picker');
  // The chosen file arrives through the input's change event.
  await page.setInputFiles('#file', path.join(examplesDir, 'marking.esi'));
  await until(page, () => essikit.state().name === 'marking.esi' && essikit.state().status === 'ready', null, 'not loaded');
  await page.close();

  // Ctrl+O opens it too, in the key press (and the browser's own "open file" is prevented).
  const page2 = await newPage();
  await page2.evaluate(() => {
    window.__opened = [];
    document.getElementById('file').click = () => window.__opened.push(`${window.event ? window.event.type : 'frame'} ${navigator.userActivation.isActive}`);
    window.addEventListener('keydown', (e) => { window.__prevented = e.defaultPrevented; });  // after the page's (capture) listener
  });
  await page2.keyboard.press('Control+o');
  assert.deepEqual(await page2.evaluate(() => window.__opened), ['keydown true'], 'Ctrl+O did not open the picker in the key press');
  assert.equal(await page2.evaluate(() => window.__prevented), true, 'Ctrl+O was left to the browser');
  await page2.close();
});

test('help window (H) and layer toggles (keys 1-4, setLayer)', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'plate_holes.esi');
  await page.keyboard.press('h');
  await until(page, () => essikit.state().help === true, null, 'H did not open the help');
  await page.waitForTimeout(100);
  await page.screenshot({ path: path.join(shots, 'help.png') });
  await tap(page, 'Escape');
  await until(page, () => essikit.state().help === false, null, 'Esc did not close the help');

  const cuts = motions.filter((m) => m.kind === 'cut' && m.curve === 'line' && m.length_mm > 50);
  const cutVisible = async (name) => {
    await page.waitForTimeout(100);
    return cutHits(page, cuts, name);
  };
  assert.equal(await cutVisible('layers-all.png'), cuts.length);
  await page.keyboard.press('1');
  await until(page, () => essikit.state().layers.cut === false, null, 'key 1 did not hide the cut layer');
  assert.equal(await cutVisible('layers-no-cut.png'), 0, 'cut colour drawn with the cut layer off');
  await page.keyboard.press('1');
  await until(page, () => essikit.state().layers.cut === true, null, 'key 1 did not show the cut layer');
  await page.keyboard.press('4');
  await until(page, () => essikit.state().layers.pierces === false, null, 'key 4: pierces');
  await page.evaluate(() => essikit.setLayer(2, false));
  assert.equal((await page.evaluate(() => essikit.state())).layers.cut, false);
  await page.close();
});

test('playback: the scrubber draws the path up to a motion and shows the tool state there', async () => {
  const page = await newPage();
  const { state, motions } = await loadExample(page, 'plate_holes.esi');
  await tap(page, 'Home');
  for (let i = 0; i < 6; ++i) await tap(page, 'ArrowRight');
  // (a key held over a slow frame may repeat: the position is at least 6)
  await until(page, () => essikit.state().playback.active && essikit.state().playback.position >= 6, null,
              'Home + 6 x Right did not move the scrubber to motion 6');
  const pb = (await page.evaluate(() => essikit.state())).playback;
  const at6 = pb.position;
  const m = motions[at6];
  assert.equal(pb.motion, at6);
  assert.equal(pb.line, m.line);
  assert.equal(pb.kind, m.kind);
  assert.equal(pb.drawn_motions, at6);
  assert.ok(Math.hypot(pb.tool_mm[0] - m.start[0], pb.tool_mm[1] - m.start[1]) < 1e-9, 'tool not at the start of the motion');
  assert.match(m.text, new RegExp('tools ' + pb.tools.replace(/[+]/g, '\\+')));
  // A later cut is not drawn yet.
  await page.mouse.move(5, 890);
  await page.waitForTimeout(150);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'playback.png') }));
  const later = motions.filter((x) => x.index > at6 && x.kind === 'cut' && x.curve === 'line' && x.length_mm > 50);
  assert.ok(later.length > 0);
  for (const x of later) {
    const p = await page.evaluate(([a, b]) => essikit.project(a, b), x.mid);
    assert.ok(!near(at(p.x, p.y), CUT_RGB), `motion ${x.index} is drawn before its time (scrubber at ${at6})`);
  }
  await page.mouse.move(700, 450);
  await tap(page, 'End');
  await until(page, () => !essikit.state().playback.active, null, 'End did not leave the playback');
  assert.equal(state.motions, motions.length);
  await page.close();
});

test('playback in machine time: the tool moves at the programmed feed times the factor; the source follows', async () => {
  const page = await newPage();
  const { state, motions } = await loadExample(page, 'arcs_both_senses.esi');
  let pb = (await page.evaluate(() => essikit.state())).playback;
  // the whole program's machine time is the statistics' estimate (no kerf, no dwell in this tape)
  assert.ok(Math.abs(pb.total_s - state.stats.estimated_time_s) < 1e-3, `${pb.total_s} vs ${state.stats.estimated_time_s}`);
  assert.equal(pb.elapsed_s, pb.total_s);  // (not playing: everything shown)
  // 50 x: the program's 196 s take about 4 s; after about a second, roughly a quarter is done
  await tap(page, 'Home');
  await page.evaluate(() => essikit.setPlayback(50, true));
  const t0 = Date.now();
  await page.waitForTimeout(1000);
  const playing = await page.evaluate(() => essikit.state());
  pb = playing.playback;
  const wall = (Date.now() - t0) / 1000;
  assert.equal(pb.factor, 50);
  assert.ok(pb.playing && pb.elapsed_s > 0 && pb.elapsed_s <= 50 * (wall + 0.5), JSON.stringify(pb));
  assert.ok(Math.abs(pb.elapsed_s + pb.remaining_s - pb.total_s) < 1e-6);
  // the source view and the inspector follow the playback: the selected line is the tool's
  assert.equal(playing.selection.line, pb.line);
  await page.evaluate(() => essikit.setPlayback(1000, true));
  await until(page, () => !essikit.state().playback.playing, null, 'the playback did not reach the end at 1000 x');
  pb = (await page.evaluate(() => essikit.state())).playback;
  assert.equal(pb.position, motions.length);
  assert.ok(Math.abs(pb.elapsed_s - pb.total_s) < 1e-9 && pb.remaining_s === 0);
  await page.screenshot({ path: path.join(shots, 'playback-machine-time.png') });
  await page.close();
});

test('copy and export: a problem, a line, the inspector and the report as essi check gives them', async () => {
  const page = await newPage();
  const file = 'bad_kerf_gouge.esi';
  const { state } = await loadExample(page, file);
  assert.ok(state.diagnostics.length > 0);
  const cli = (args) => {
    try {
      return execFileSync(essiBin, ['check', '--profile', 'auto', ...args, file], { encoding: 'utf8', cwd: examplesDir });
    } catch (e) {
      return e.stdout;  // exit 1: the tape has an error
    }
  };
  // the report as text: essi check's lines (its summary's timing aside)
  await page.evaluate(() => essikit.copy('report'));
  const copied = (await page.evaluate(() => essikit.state())).copied;
  const text = cli([]);
  assert.equal(copied.trimEnd(), text.trimEnd().replace(/; [0-9.]+ s$/, ''));
  // one problem: its line of the report
  await page.evaluate(() => essikit.copy('diagnostic', 0));
  assert.equal((await page.evaluate(() => essikit.state())).copied, text.split('\n')[0] + '\n');
  // a source line, and the inspector's text of the selected line
  const line = state.diagnostics[0].line;
  await page.evaluate((n) => essikit.copy('line', n), line);
  const source = fs.readFileSync(path.join(examplesDir, file), 'utf8').split(/\r?\n/);
  assert.equal((await page.evaluate(() => essikit.state())).copied, source[line - 1] + '\n');
  await page.evaluate((n) => { essikit.selectLine(n); essikit.copy('inspector'); }, line);
  const insp = await page.evaluate(() => essikit.state());
  assert.equal(insp.copied, `${file}:${line}: ${source[line - 1]}\n` + insp.inspector.map((l) => l + '\n').join('') +
               text.split('\n')[0] + '\n');
  // the report as JSON is essi check's; the problems as CSV one row each
  const json = JSON.parse(await page.evaluate(() => essikit.exportText('report-json')));
  const cliJson = JSON.parse(cli(['--format', 'json']));
  assert.deepEqual(json.files, cliJson.files);
  assert.equal(json.profile, cliJson.profile);
  const csv = (await page.evaluate(() => essikit.exportText('report-csv'))).split('\r\n');
  assert.equal(csv[0], 'file,severity,code,line,column,message');
  assert.equal(csv.length, 2 + state.diagnostics.length);  // (the header, a row each, the last line end)
  // (the first problem is the cut plan's note on its lone contour, the gouge's error further down)
  assert.match(csv[1], new RegExp(`^${file.replace('.', '\\.')},note,N603,${line},1,`));
  assert.ok(csv.some((row) => /^bad_kerf_gouge\.esi,error,E307,14,1,/.test(row)), csv.join('\n'));
  await page.close();
});

test('the Job panel: the job sheet\'s time and cost as essi report has them; its print view and HTML are essi report\'s', async () => {
  const page = await newPage();
  const file = 'bad_kerf_gouge.esi';
  await loadExample(page, file);
  const report = (args) => {
    try {
      return execFileSync(essiBin, ['report', '--profile', 'auto', '--format', 'html', '-o', '-', ...args, file],
                          { encoding: 'utf8', cwd: examplesDir });
    } catch (e) {
      return e.stdout;  // exit 1: the tape has an error
    }
  };
  const cli = report([]);
  // The panel's sections are the sheet's "time" section (and parts and plates, when the tape has them), field for
  // field as the HTML lists them.
  const job = (await page.evaluate(() => essikit.state())).job;
  assert.ok(Array.isArray(job) && job.length >= 1, JSON.stringify(job));
  const time = job.find((s) => s.id === 'time');
  assert.ok(time && time.fields.length >= 1, JSON.stringify(job));
  const section = cli.match(/<section id="time">([\s\S]*?)<\/section>/);
  assert.ok(section, 'essi report has a time section');
  const cliFields = [...section[1].matchAll(/<tr><th>(.*?)<\/th><td>(.*?)<\/td><\/tr>/g)].map((m) => [m[1], m[2]]);
  assert.deepEqual(time.fields, cliFields);
  // The HTML export is essi report's page, but for the date it was made (the SHA-256 of the tape's bytes the same:
  // OpenSSL's natively, the digest written out in WebAssembly).
  const undated = (html) => html.replace(/\d{4}-\d\d-\d\d \d\d:\d\d UTC/g, 'DATE');
  const html = await page.evaluate(() => essikit.exportText('job-html'));
  assert.equal(undated(html), undated(cli));
  assert.match(html, /[0-9a-f]{64}/);
  // In German: the panel's words change with the UI's language, as the sheet's do with --lang.
  await page.evaluate(() => essikit.setLanguage('de'));
  const de = (await page.evaluate(() => essikit.state())).job.find((s) => s.id === 'time');
  const cliDe = report(['--lang', 'de']).match(/<section id="time">\s*<h2>(.*?)<\/h2>/);
  assert.equal(de.title, cliDe[1]);
  await page.evaluate(() => essikit.setLanguage('en'));
  // The print view: the sheet in a new tab, styled (its one style sheet applies), the same page.
  const popup = page.waitForEvent('popup');
  await page.evaluate(() => essikit.printJobSheet());
  const tab = await popup;
  await tab.waitForLoadState();
  assert.match(tab.url(), /^blob:/);
  assert.equal(await tab.evaluate(() => document.querySelector('h1').textContent), 'Job sheet');
  assert.equal(await tab.evaluate(() => getComputedStyle(document.querySelector('h1')).fontSize), '21.3333px');  // 16pt
  assert.equal(undated(await tab.content()).includes('bad_kerf_gouge.esi'), true);
  await tab.close();
  await page.close();
});

test('colour by feed and by cut order: the cuts in the ramp\'s colours, a legend says which is which', async () => {
  const page = await newPage();
  // feed_dwell.esi cuts one rectangle (20, 20)-(120, 70): its right edge at 150 mm/min, the other three at 300.
  await loadExample(page, 'feed_dwell.esi');
  await page.mouse.move(5, 890);  // (the cursor away from the path)
  const colourBy = async (mode) => {
    assert.equal(await page.evaluate((m) => essikit.setColourBy(m), mode), true);
    await until(page, (m) => essikit.state().colour_by.drawn === m && essikit.state().status === 'ready', mode,
                `colour by ${mode} drawn`);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
    return (await page.evaluate(() => essikit.state())).colour_by;
  };
  const colourAt = async (x, y) => {
    const at = await pixels(page, await page.screenshot());
    const p = await page.evaluate(([px, py]) => essikit.project(px, py), [x, y]);
    const hits = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) hits.push(at(p.x + dx, p.y + dy));
    return hits;
  };
  const feed = await colourBy('feed');
  // Two feeds: the slowest the ramp's first colour (blue), the fastest its last (red).
  assert.deepEqual(feed.legend.map((e) => e.text), ['150 mm/min', '300 mm/min']);
  const [slow, fast] = feed.legend.map((e) => e.colors[0]);
  assert.ok(slow[2] > 200 && slow[0] < 100, `the slow feed is blue: ${slow}`);
  assert.ok(fast[0] > 140 && fast[2] < 30, `the fast feed is red: ${fast}`);
  assert.ok((await colourAt(120, 45)).some((c) => near(c, slow)), 'the right edge (150 mm/min) in the slow colour');
  assert.ok((await colourAt(70, 20)).some((c) => near(c, fast)), 'the bottom edge (300 mm/min) in the fast colour');
  assert.ok(!(await colourAt(70, 20)).some((c) => near(c, CUT_RGB)), 'no cut colour left on the bottom edge');
  // By cut order: one cut, the first.
  const order = await colourBy('order');
  assert.deepEqual(order.legend.map((e) => e.text), ['first cut']);
  assert.ok((await colourAt(120, 45)).some((c) => near(c, order.legend[0].colors[0])));
  // Rejected names change nothing; by kind the cut colour is back, with no legend.
  assert.equal(await page.evaluate(() => essikit.setColourBy('speed!')), false);
  const kind = await colourBy('kind');
  assert.deepEqual(kind.legend, []);
  assert.ok((await colourAt(70, 20)).some((c) => near(c, CUT_RGB)), 'the cut colour again');
  await page.close();
});

test('parts: the Job panel, the parts layer and colour by part group as essi parts has them; colour by speed', async () => {
  const page = await newPage();
  // kerf_parts.esi makes two parts of different shapes on one plate, with a remnant at its far end in x.
  const file = 'kerf_parts.esi';
  await loadExample(page, file);
  await page.mouse.move(5, 890);  // (the cursor away from the path)
  const cli = JSON.parse(execFileSync(essiBin, ['parts', '--format', 'json', file], { encoding: 'utf8', cwd: examplesDir }));
  assert.equal(cli.groups.length, 2);
  // The Job panel has no parts until something asks for them (the core reads the tape again for them).
  assert.ok(!(await page.evaluate(() => essikit.state())).job.some((s) => s.id === 'parts'));
  // The parts layer: off at first; on, the remnant is filled with its colour (purple: more blue than green).
  const frames = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
  const r = cli.plates[0].remnant_mm;
  const fillAt = async () => {
    const at = await pixels(page, await page.screenshot());
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), [(r.x0 + r.x1) / 2, (r.y0 + r.y1) / 2]);
    return at(p.x, p.y);
  };
  assert.equal((await page.evaluate(() => essikit.state())).layers.parts, false);
  const before = await fillAt();
  await page.evaluate(() => essikit.setLayer(9, true));
  await frames();
  assert.equal((await page.evaluate(() => essikit.state())).layers.parts, true);
  const after = await fillAt();
  assert.ok(after[2] > after[1] + 8 && !(before[2] > before[1] + 8), `the remnant filled: ${before} -> ${after}`);
  // Now the Job panel's parts table: a row a group, as the job sheet has it.
  const job = (await page.evaluate(() => essikit.state())).job;
  const parts = job.find((s) => s.id === 'parts');
  assert.ok(parts && parts.table && parts.table.rows.length === cli.groups.length, JSON.stringify(job));
  // Colour by part group: a colour a group, the legend names them with their counts.
  const colourBy = async (mode) => {
    assert.equal(await page.evaluate((m) => essikit.setColourBy(m), mode), true);
    await until(page, (m) => essikit.state().colour_by.drawn === m && essikit.state().status === 'ready', mode,
                `colour by ${mode} drawn`);
    return (await page.evaluate(() => essikit.state())).colour_by;
  };
  const group = await colourBy('group');
  assert.deepEqual(group.legend.map((e) => e.text), cli.groups.map((g) => `group ${g.group} (${g.count}\u00d7)`));
  assert.notDeepEqual(group.legend[0].colors[0], group.legend[1].colors[0]);
  // Colour by speed with a profile that accelerates: the planner's top speeds, never above the fastest feed.
  const feeds = (await colourBy('feed')).legend.map((e) => parseFloat(e.text));
  await page.evaluate(() => essikit.load('accel.json', '{"accel_mm_s2": 0.5, "junction_deviation_mm": 0.01}'));
  await until(page, () => essikit.state().status === 'ready', null, 'read again with accel.json');
  const speed = await colourBy('speed');
  const speeds = speed.legend.map((e) => parseFloat(e.text));
  assert.ok(speeds.length >= 1 && speed.legend.every((e) => / mm\/min$/.test(e.text)), JSON.stringify(speed.legend));
  assert.ok(Math.max(...speeds) <= Math.max(...feeds) + 0.5, `${speeds} above ${feeds}`);
  assert.ok(Math.min(...speeds) < Math.min(...feeds), `a = 0.5 mm/s² keeps the short lines below the feed: ${speeds} / ${feeds}`);
  await page.close();
});

// The statistics' time: the machine time with the profile's accelerations, else the estimate at the feeds.
function statisticsTime(stats) {
  return stats.machine_time_s ?? stats.estimated_time_s;
}

test('playback lasts the statistics\' time, with accelerations too, and follows every new tape (over 1 MB too)', async () => {
  const page = await newPage();
  const { state } = await loadExample(page, 'kerf_parts.esi');  // (kerf compensation: the torch's path is longer)
  let pb = state.playback;
  assert.ok(Math.abs(pb.total_s - state.stats.estimated_time_s) < 1e-6, `${pb.total_s} vs ${state.stats.estimated_time_s}`);
  // Read again with accelerations: the machine time, longer than the estimate; played to the end, all of it.
  await page.evaluate(() => essikit.load('accel.json', '{"accel_mm_s2": 50, "junction_deviation_mm": 0.05}'));
  await until(page, () => essikit.state().status === 'ready' && essikit.state().stats.machine_time_s > 0, null,
              'read again with accel.json');
  let s = await page.evaluate(() => essikit.state());
  pb = s.playback;
  assert.ok(s.stats.machine_time_s > s.stats.estimated_time_s + 1, JSON.stringify(s.stats));
  assert.ok(Math.abs(pb.total_s - s.stats.machine_time_s) < 1e-6, `${pb.total_s} vs ${s.stats.machine_time_s}`);
  await tap(page, 'Home');
  await page.evaluate(() => essikit.setPlayback(1000, true));
  await until(page, () => !essikit.state().playback.playing, null, 'the playback did not reach the end at 1000 x');
  pb = (await page.evaluate(() => essikit.state())).playback;
  assert.ok(Math.abs(pb.elapsed_s - s.stats.machine_time_s) < 1e-6 && pb.remaining_s === 0, JSON.stringify(pb));
  const first = pb.total_s;
  // A tape over 1 MB (read in slices): its own time, read with the same profile, as soon as it is there.
  const big = generatedTape(1.2);
  await dropFromUrl(page, '/gen/' + big, big);
  await page.waitForFunction((n) => { const t = essikit.state(); return t.name === n && t.status === 'ready'; }, big,
                             { timeout: 120000 });
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.load.at_once, false);
  pb = s.playback;
  assert.ok(s.stats.machine_time_s > 0 && Math.abs(pb.total_s - statisticsTime(s.stats)) < 1e-6,
            `${big}: playback ${pb.total_s} s, statistics ${statisticsTime(s.stats)} s`);
  assert.notEqual(pb.total_s, first);
  assert.equal(pb.elapsed_s, pb.total_s);
  // Played: the clock runs in the new tape's time.
  await tap(page, 'Home');
  await page.evaluate(() => essikit.setPlayback(1000, true));
  await until(page, () => essikit.state().playback.elapsed_s > 0, null, 'the big tape\'s playback did not start');
  pb = (await page.evaluate(() => essikit.state())).playback;
  assert.ok(pb.elapsed_s < pb.total_s && Math.abs(pb.elapsed_s + pb.remaining_s - pb.total_s) < 1e-6, JSON.stringify(pb));
  await page.evaluate(() => essikit.setPlayback(10, false));
  await page.close();
});

test('a file that is not a tape is said and the open tape stays; a UTF-16 tape is read as text', async () => {
  const page = await newPage();
  const file = 'bad_character.esi';  // (a verdict with an error: E101 on line 13)
  const text = fs.readFileSync(path.join(examplesDir, file), 'utf8');
  const first = await dropFile(page, file, Buffer.from(text));
  assert.equal(first.ok, false);
  const kept = (s) => ({ name: s.name, ok: s.ok, diagnostics: s.diagnostics, stats: s.stats, motions: s.motions,
                         view: [s.view.x_mm, s.view.y_mm, s.view.zoom] });
  const before = kept(first);
  const notTapes = [
    ['picture.png', Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13, 0x49, 0x48, 0x44, 0x52]),
     'picture.png is not a tape: it is a PNG picture. bad_character.esi stays open.'],
    ['empty.esi', Buffer.alloc(0), 'empty.esi is not a tape: the file is empty. bad_character.esi stays open.'],
    ['tapes.zip', Buffer.from([0x50, 0x4b, 0x03, 0x04, 0x14, 0, 0, 0]), 'tapes.zip is not a tape: it is a ZIP archive.'],
  ];
  for (const [name, bytes, said] of notTapes) {
    await dropOnly(page, name, bytes);
    await page.waitForFunction((n) => essikit.state().message.includes(n), name, { timeout: 30000 });
    const s = await page.evaluate(() => essikit.state());
    assert.ok(s.message.startsWith(said), `${name}: ${s.message}`);
    assert.deepEqual(kept(s), before, `${name} changed the open tape`);
    assert.equal(s.status, 'ready');
  }
  // The same tape saved as UTF-16 LE with a byte order mark: read as text, the UTF-8 tape's verdict and lines.
  const utf16 = Buffer.concat([Buffer.from([0xff, 0xfe]), Buffer.from(text, 'utf16le')]);
  const s = await dropFile(page, 'bad_character_utf16.esi', utf16);
  assert.equal(s.banner, '');
  assert.equal(s.ok, first.ok);
  assert.deepEqual(s.diagnostics, first.diagnostics);
  assert.deepEqual(s.stats, first.stats);
  assert.equal(s.bytes, Buffer.byteLength(text));
  await page.close();
});

test('touch: a tap selects, one finger pans, two fingers zoom about their middle', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1600, height: 900 }, hasTouch: true });
  const page = await ctx.newPage();
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  const { motions } = await loadExample(page, 'plate_holes.esi');
  const cdp = await ctx.newCDPSession(page);
  const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
  const frames = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
  // a tap on a long cut line selects it (no hover before it)
  const m = motions.find((x) => x.kind === 'cut' && x.curve === 'line' && x.length_mm > 150);
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
  await page.touchscreen.tap(p.x, p.y);
  await until(page, (i) => { const s = essikit.state(); return s.selection && s.selection.motion === i; }, m.index, 'the tap did not select the line');
  // one finger drags the drawing along
  let v0 = (await page.evaluate(() => essikit.state())).view;
  const a = await page.evaluate(([x, y]) => essikit.project(x, y), [v0.x_mm, v0.y_mm]);
  await touch('touchStart', [[600, 500]]);
  for (let k = 1; k <= 5; ++k) { await touch('touchMove', [[600 + 20 * k, 500 + 10 * k]]); await frames(); }
  await touch('touchEnd', []);
  await frames();
  const b = await page.evaluate(([x, y]) => essikit.project(x, y), [v0.x_mm, v0.y_mm]);
  assert.ok(Math.abs(b.x - a.x - 100) < 25 && Math.abs(b.y - a.y - 50) < 25, `the drawing moved by (${b.x - a.x}, ${b.y - a.y}), not (100, 50)`);
  // two fingers spread to twice their distance: twice the zoom, the point between them stays under them
  v0 = (await page.evaluate(() => essikit.state())).view;
  await touch('touchStart', [[650, 450], [750, 450]]);
  for (let k = 1; k <= 4; ++k) { await touch('touchMove', [[650 - 12.5 * k, 450], [750 + 12.5 * k, 450]]); await frames(); }
  await touch('touchEnd', []);
  await frames();
  const v1 = (await page.evaluate(() => essikit.state())).view;
  assert.ok(Math.abs(v1.zoom / v0.zoom - 2) < 1e-6, `zoom ${v0.zoom} -> ${v1.zoom}`);
  // (no selection change, no pan from the pinch's fingers)
  assert.equal((await page.evaluate(() => essikit.state())).selection.motion, m.index);
  await ctx.close();
});

test('any screen: at 1024x600 the drawing keeps half the width; panels hide, resize and are remembered', async () => {
  const page = await openPage(browser, baseUrl, { width: 1024, height: 600 });
  await loadExample(page, 'plate_holes.esi');
  let s = await page.evaluate(() => essikit.state());
  const [x, , w] = s.view.area;
  assert.ok(w >= 512, `the drawing is ${w} of 1024 pixels wide`);
  await page.screenshot({ path: path.join(shots, 'layout-1024x600.png') });
  // [ hides the left panel: the drawing starts at the left edge; ] the right one
  await page.mouse.move(x + w / 2, 300);
  await tap(page, 'BracketLeft');
  await until(page, () => !essikit.state().layout.left_shown && essikit.state().view.area[0] === 0, null, '[ did not hide the left panel');
  await tap(page, 'BracketRight');
  await until(page, () => essikit.state().view.area[2] === 1024, null, '] did not hide the right panel');
  await page.screenshot({ path: path.join(shots, 'layout-hidden.png') });
  // the right panel back (the left one hidden: room for it to grow), dragged 30 px wider at its inner edge
  await page.evaluate(() => essikit.setPanels(false, true));
  await nextFrames(page, 3);
  s = await page.evaluate(() => essikit.state());
  const edge = s.view.area[0] + s.view.area[2];  // (the right panel's left edge)
  await page.mouse.move(edge + 1, 300);
  await nextFrames(page, 2);  // (the border is hovered before it is pressed)
  await page.mouse.down();
  await nextFrames(page, 2);
  // (a frame between the moves, and frames on the last before the release: the resize follows the position a
  // frame sees while the button is down)
  for (let k = 1; k <= 3; ++k) { await page.mouse.move(edge + 1 - 10 * k, 300); await nextFrames(page, 2); }
  await nextFrames(page, 3);
  await page.mouse.up();
  await nextFrames(page, 3);
  const after = await page.evaluate(() => essikit.state());
  const moved = edge - (after.view.area[0] + after.view.area[2]);
  assert.ok(Math.abs(moved - 30) <= 4, `the right panel's edge moved by ${moved} px, not 30`);
  assert.ok(Math.abs(after.layout.right - (1024 - after.view.area[0] - after.view.area[2])) < 1, JSON.stringify(after.layout));
  // kept across sessions
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  await nextFrames(page, 3);
  const kept = (await page.evaluate(() => essikit.state())).layout;
  assert.deepEqual(kept, after.layout);
  await page.evaluate(() => essikit.setPanels(true, true, 310, 470));  // (the defaults, for the tests after)
  await page.close();
});

test('compare two revisions: B over A in its own colour, the differences listed and shown', async () => {
  const page = await newPage();
  const a = '7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+2000+0\n6\n7\n+500+0\n+0+500\n-500+0\n+0-500\n8\n64\n';
  // B: a comment before (every line renumbered), the small square 5 mm to the right
  const b = '3\nREV B\n4\n7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+2050+0\n6\n7\n+500+0\n+0+500\n-500+0\n+0-500\n8\n64\n';
  await page.evaluate((t) => essikit.load('rev_a.esi', t), a);
  const s = await page.evaluate((t) => essikit.compare('rev_b.esi', t), b);
  assert.equal(s.name, 'rev_a.esi');  // (A stays loaded)
  assert.equal(s.compare.name, 'rev_b.esi');
  assert.equal(s.compare.summary, '1 same, 1 moved, 0 changed, 0 removed, 0 added');
  assert.deepEqual(s.compare.differences, [{ change: 'moved', a_lines: [11, 14], b_lines: [14, 17], offset_mm: [5, 0] }]);
  // the difference shown: A's contour selected and in view; B's moved square drawn in B's colour
  await page.evaluate(() => essikit.showDifference(0));
  await nextFrames(page, 3);
  const st = await page.evaluate(() => essikit.state());
  assert.equal(st.selection.line, 11);
  await page.mouse.move(5, 890);
  await nextFrames(page, 3);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'compare.png') }));
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), [255, 25]);  // B's square's right edge
  const hits = [];
  for (let dx = -2; dx <= 2; ++dx) hits.push(at(p.x + dx, p.y));
  assert.ok(hits.some((c) => c[2] > 200 && c[1] > 150 && c[0] < 150), `no B colour at B's edge: ${JSON.stringify(hits)}`);
  // the mode ends; a new tape loaded ends it too
  await page.evaluate(() => essikit.endCompare());
  assert.equal((await page.evaluate(() => essikit.state())).compare, null);
  await page.close();
});

test('a window the size of the screen (F11, kiosk) is drawn at its size: no stretched canvas', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 660 }, screen: { width: 1280, height: 720 } });
  const page = await ctx.newPage();
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  await loadExample(page, 'plate_holes.esi');
  await page.setViewportSize({ width: 1280, height: 720 });  // (F11: the window becomes the screen)
  await nextFrames(page, 5);
  const size = await page.evaluate(() => { const c = document.getElementById('canvas'); return [c.width, c.height, screen.width, innerWidth]; });
  assert.deepEqual(size.slice(0, 2), [1280, 720], `canvas ${size}`);
  const s = await page.evaluate(() => essikit.state());
  assert.equal(s.view.area[0] + s.view.area[2] + s.layout.right, 1280);
  await page.screenshot({ path: path.join(shots, 'kiosk-1280x720.png') });
  await ctx.close();
});

test('hi-DPI: the canvas at the device pixel ratio, clicks where they land, the cuts sharp', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1200, height: 700 }, deviceScaleFactor: 2 });
  const page = await ctx.newPage();
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  const { motions } = await loadExample(page, 'plate_holes.esi');
  await nextFrames(page, 3);
  const size = await page.evaluate(() => { const c = document.getElementById('canvas'); return [c.width, c.height, innerWidth, devicePixelRatio]; });
  assert.deepEqual(size, [2400, 1400, 1200, 2]);
  // a click on a cut line (CSS pixels) selects it
  const m = motions.find((x) => x.kind === 'cut' && x.curve === 'line' && x.length_mm > 150);
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
  await page.mouse.click(p.x, p.y);
  await until(page, (i) => { const s = essikit.state(); return s.selection && s.selection.motion === i; }, m.index, 'the click did not select the line');
  // the screenshot (device pixels) has the cut's colour at twice the CSS position, on a line a few pixels wide
  await page.evaluate(() => essikit.selectLine(0));
  await page.mouse.move(5, 690);
  await nextFrames(page, 3);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'hidpi.png') }));
  const hits = [];
  for (let d = -2; d <= 2; ++d) hits.push(at(2 * p.x + d, 2 * p.y), at(2 * p.x, 2 * p.y + d));
  assert.ok(hits.some((c) => c[0] > c[2] + 80 && c[0] > c[1] + 30), `no cut colour at (${2 * p.x}, ${2 * p.y}): ${JSON.stringify(hits)}`);
  await ctx.close();
});

// The share of pixels (sampled every 2 px) that differ between two screenshots of the same size: a panel drawn in
// another language.
async function changedShare(page, pngA, pngB, [x0, y0, w, h]) {
  const a = await pixels(page, pngA), b = await pixels(page, pngB);
  let changed = 0, all = 0;
  for (let y = y0; y < y0 + h; y += 2)
    for (let x = x0; x < x0 + w; x += 2) {
      ++all;
      const p = a(x, y), q = b(x, y);
      if (Math.abs(p[0] - q[0]) + Math.abs(p[1] - q[1]) + Math.abs(p[2] - q[2]) > 30) ++changed;
    }
  return changed / all;
}

test('languages: the panels in German and Chinese from the catalogue, the switch kept across a reload', async () => {
  const page = await newPage();
  await loadExample(page, 'plate_holes.esi');
  await page.evaluate(() => essikit.selectLine(15));  // a cut line: the inspector's words
  await nextFrames(page, 3);
  const panels = [0, 40, 300, 800];  // the left panel (the tape's reading, statistics, layers ...)
  let s = await page.evaluate(() => essikit.state());
  assert.equal(s.lang, 'en');
  assert.match(s.inspector.join('\n'), /^cut line from \(/m);
  const en = await page.screenshot({ path: path.join(shots, 'lang-en.png') });
  // German: the toolbar, the panels, the inspector; the language's own word for it in the switch
  await page.evaluate(() => essikit.setLanguage('de'));
  await nextFrames(page, 3);
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.lang, 'de');
  assert.match(s.inspector.join('\n'), /^Schneiden: Strecke von \(/m);
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'de');
  await page.waitForTimeout(100);
  const de = await page.screenshot({ path: path.join(shots, 'lang-de.png') });
  const deShare = await changedShare(page, en, de, panels);
  assert.ok(deShare > 0.01, `the left panel in German looks like the English one (${deShare} of it changed)`);
  // Chinese (the CJK font's glyphs come in when they are needed)
  await page.evaluate(() => essikit.setLanguage('zh'));
  await nextFrames(page, 3);
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.lang, 'zh');
  assert.match(s.inspector.join('\n'), /^切割直线，从 \(/m);
  // the CJK font (fetched once), every character of the Chinese panels in the atlas, drawn
  const fonts = await page.evaluate(() => essikit.requireGlyphs(''));
  assert.equal(fonts.cjk, 'loaded', JSON.stringify(fonts));
  assert.equal(fonts.missing, 0, JSON.stringify(fonts));
  assert.ok(fonts.cjk_glyphs > 300, `only ${fonts.cjk_glyphs} Chinese glyphs for the panels`);
  assert.ok(await page.evaluate((t) => essikit.hasGlyphs(t), s.inspector.join('') + s.message), 'the inspector\'s glyphs are missing');
  await nextFrames(page, 3);
  const zh = await page.screenshot({ path: path.join(shots, 'lang-zh.png') });
  for (const [name, other] of [['English', en], ['German', de]]) {
    const share = await changedShare(page, other, zh, panels);
    assert.ok(share > 0.01, `the left panel in Chinese looks like the ${name} one (${share} of it changed)`);
  }
  // A language essikit has no texts for changes nothing; the choice is kept across sessions
  await page.evaluate(() => essikit.setLanguage('fr'));
  assert.equal((await page.evaluate(() => essikit.state())).lang, 'zh');
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  assert.equal((await page.evaluate(() => essikit.state())).lang, 'zh');
  assert.equal(await page.evaluate(() => localStorage.getItem('essikit.lang')), 'zh');
  await page.evaluate(() => essikit.setLanguage('en'));
  await page.close();
});

test('a browser in German starts the viewer in German (navigator.languages); a share link\'s problem in its words', async () => {
  for (const [locale, want] of [['de-DE', 'de'], ['zh-CN', 'zh'], ['fr-FR', 'en']]) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, locale });
    const page = await context.newPage();
    page.on('pageerror', (e) => console.log(`pageerror: ${e.message}`));
    // a link whose tape data is damaged: the problem window, in the page's language
    await page.goto(baseUrl + '#c=0,0,1&n=damaged.esi&b=100&t=AAAAAAAA');
    await page.waitForFunction(() => window.essikit && essikit.started && essikit.state().link_problem, null, { timeout: 30000 });
    const s = await page.evaluate(() => essikit.state());
    assert.equal(s.lang, want, `${locale}: ${s.lang}`);
    assert.equal(await page.evaluate(() => document.documentElement.lang), want);
    const problem = { de: /abgeschnitten oder beschädigt/, zh: /被截断或已损坏/, en: /cut off or damaged/ }[want];
    assert.match(s.link_problem, problem);
    if (want === 'de') {
      await page.screenshot({ path: path.join(shots, 'lang-de-start.png') });
      // the problem follows the language when it is switched
      await page.evaluate(() => essikit.setLanguage('en'));
      assert.match((await page.evaluate(() => essikit.state())).link_problem, /cut off or damaged/);
    }
    await context.close();
  }
});

test('at 1024x600 every toolbar item is reachable in every language: what does not fit is in the » menu', async () => {
  const page = await openPage(browser, baseUrl, { width: 1024, height: 600 });
  await loadExample(page, 'plate_holes.esi');
  for (const lang of ['en', 'de', 'zh']) {
    await page.evaluate((l) => essikit.setLanguage(l), lang);
    await page.mouse.move(600, 400);
    // (Chinese fetches the CJK font: the widths of the items, and so the » button's place, change when it is in)
    await until(page, () => { const f = essikit.state().fonts; return f.cjk !== 'loading' && !f.pending; }, null,
                `${lang}: the fonts did not settle`);
    await nextFrames(page, 3);
    let tb = (await page.evaluate(() => essikit.state())).toolbar;
    const ids = tb.items.map((i) => i.id);
    for (const id of ['open', 'paste', 'share', 'export', 'fit', 'measure', 'help', 'panels', 'compare', 'profile',
                      'orientation', 'coordinates', 'language', 'verdict'])
      assert.ok(ids.includes(id), `${lang}: no toolbar item ${id}`);
    // the bar: items side by side inside the window's width and the toolbar's height
    const bar = tb.items.filter((i) => !i.in_menu);
    assert.ok(bar.some((i) => i.id === 'open'), `${lang}: Open is not in the bar`);
    let right = 0;
    for (const i of bar) {
      const r = i.rect;
      assert.ok(r.w > 0 && r.x >= right && r.x + r.w <= 1024 && r.y >= 0 && r.y + r.h <= 38, `${lang}: ${i.id} at ${JSON.stringify(r)}`);
      right = r.x + r.w;
    }
    const menu = tb.items.filter((i) => i.in_menu);
    if (menu.length === 0) continue;
    // the rest in the overflow menu: its button in the bar, the items drawn in it when it is open
    assert.ok(tb.more && tb.more.x >= right && tb.more.x + tb.more.w <= 1024, `${lang}: the » button at ${JSON.stringify(tb.more)}`);
    await page.mouse.click(tb.more.x + tb.more.w / 2, tb.more.y + tb.more.h / 2);
    await nextFrames(page, 3);
    tb = (await page.evaluate(() => essikit.state())).toolbar;
    assert.ok(tb.menu_open, `${lang}: the » menu did not open`);
    for (const i of tb.items.filter((x) => x.in_menu)) {
      const r = i.rect;
      assert.ok(r.w > 0 && r.x >= 0 && r.x + r.w <= 1024 && r.y >= 0 && r.y + r.h <= 600, `${lang}: ${i.id} in the menu at ${JSON.stringify(r)}`);
    }
    await page.screenshot({ path: path.join(shots, `toolbar-1024x600-${lang}.png`) });
    if (lang === 'de') await page.screenshot({ path: path.join(shots, 'layout-1024x600-de.png') });
    await tap(page, 'Escape');
    await page.mouse.click(600, 400);  // (closes the menu)
    await nextFrames(page, 3);
  }
  // Narrower: the buttons go into the menu too, and work there (Help opens the help window)
  await page.evaluate(() => essikit.setLanguage('de'));
  await page.setViewportSize({ width: 560, height: 600 });
  await nextFrames(page, 4);
  let tb = (await page.evaluate(() => essikit.state())).toolbar;
  assert.ok(tb.items.find((i) => i.id === 'help').in_menu, JSON.stringify(tb.items.map((i) => [i.id, i.in_menu])));
  await page.mouse.click(tb.more.x + tb.more.w / 2, tb.more.y + tb.more.h / 2);
  await nextFrames(page, 3);
  tb = (await page.evaluate(() => essikit.state())).toolbar;
  const help = tb.items.find((i) => i.id === 'help').rect;
  assert.ok(help.w > 0, 'Help is not drawn in the open menu');
  await page.mouse.click(help.x + help.w / 2, help.y + help.h / 2);
  await until(page, () => essikit.state().help === true, null, 'Help in the » menu did not open the help');
  await until(page, () => !essikit.state().toolbar.menu_open, null, 'the » menu stayed open after Help');
  await page.evaluate(() => essikit.setLanguage('en'));
  await page.close();
});

test('a light theme beside the dark one: the drawing, the panels and the grid light, the cuts still the cut colour; kept', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'plate_holes.esi');
  await page.evaluate(() => essikit.setTheme('light'));
  await page.mouse.move(5, 890);
  await nextFrames(page, 3);
  assert.equal((await page.evaluate(() => essikit.state())).theme, 'light');
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'theme-light.png') }));
  const s = await page.evaluate(() => essikit.state());
  const [ax, ay] = s.view.area;
  const bg = at(ax + 3, ay + s.view.area[3] - 40);  // (an empty corner of the drawing)
  assert.ok(bg[0] > 200 && bg[1] > 200 && bg[2] > 200, `the drawing's background is ${bg}`);
  const panel = at(40, 880);
  assert.ok(panel[0] > 180, `the left panel is ${panel}`);
  const cut = motions.find((m) => m.kind === 'cut' && m.curve === 'line' && m.length_mm > 150);
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), cut.mid);
  const hits = [];
  for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) hits.push(at(p.x + dx, p.y + dy));
  assert.ok(hits.some((c) => c[0] > c[2] + 80 && c[0] > c[1] + 30), `no cut colour on the light drawing: ${JSON.stringify(hits)}`);
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  assert.equal((await page.evaluate(() => essikit.state())).theme, 'light');
  await page.evaluate(() => essikit.setTheme('dark'));
  await page.close();
});

test('export the view as PNG (the drawing area as drawn) and as SVG (that part of the tape)', async () => {
  const page = await newPage();
  await loadExample(page, 'plate_holes.esi');
  await page.evaluate(() => essikit.setView(160, 120, 3));
  await nextFrames(page, 3);
  const s = await page.evaluate(() => essikit.state());
  const url = await page.evaluate(() => essikit.exportPng());
  const png = Buffer.from(url.replace(/^data:image\/png;base64,/, ''), 'base64');
  fs.writeFileSync(path.join(shots, 'view-export.png'), png);
  assert.equal(png.readUInt32BE(16), Math.round(s.view.area[2]));  // (IHDR: width, height)
  assert.equal(png.readUInt32BE(20), Math.round(s.view.area[3]));
  const at = await pixels(page, png);
  // the plate's bottom edge (y = 20 mm) where the view puts it, in the picture's own pixels
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), [160, 20]);
  const hits = [];
  for (let d = -2; d <= 2; ++d) hits.push(at(p.x - s.view.area[0], p.y - s.view.area[1] + d));
  assert.ok(hits.some((c) => c[0] > c[2] + 80 && c[0] > c[1] + 30), `no cut colour in the PNG: ${JSON.stringify(hits)}`);
  // the SVG: the part of the tape in view (its box), the tape's own drawing (essi render's)
  const svg = await page.evaluate(() => essikit.exportText('view-svg'));
  const m = svg.match(/data-view="([-\d.]+) ([-\d.]+) ([-\d.]+) ([-\d.]+)"/);
  assert.ok(m, svg.slice(0, 300));
  const [x0, y0, x1, y1] = m.slice(1).map(Number);
  const halfW = s.view.area[2] / 2 / 3, halfH = s.view.area[3] / 2 / 3;
  assert.ok(Math.abs(x0 - (160 - halfW)) < 0.5 && Math.abs(x1 - (160 + halfW)) < 0.5, `${x0} ${x1}`);
  assert.ok(Math.abs(y0 - (120 - halfH)) < 0.5 && Math.abs(y1 - (120 + halfH)) < 0.5, `${y0} ${y1}`);
  assert.match(svg, /id="cut"/);
  await page.close();
});

test('compare, a difference shown: A and B both in view, B\'s circle round at any zoom', async () => {
  const page = await newPage();
  // A: a square; B: the square moved 150 mm to the right, and a circle of radius 50 about (350, 0) added
  const a = '7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n64\n';
  const b = '5\n+1500+0\n6\n7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+1500+0\n6\n7\n+0+0+500+0+\n8\n64\n';
  await page.evaluate((t) => essikit.load('rev_a.esi', t), a);
  const s = await page.evaluate((t) => essikit.compare('rev_b.esi', t), b);
  assert.deepEqual(s.compare.differences.map((d) => d.change).sort(), ['added', 'moved'], JSON.stringify(s.compare));
  const moved = s.compare.differences.findIndex((d) => d.change === 'moved');
  await page.evaluate((k) => essikit.showDifference(k), moved);
  await nextFrames(page, 3);
  // the view holds A's square (0..100) and B's (150..250) whole
  const area = (await page.evaluate(() => essikit.state())).view.area;
  for (const [x, y] of [[0, 0], [100, 100], [150, 0], [250, 100]]) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), [x, y]);
    assert.ok(p.x >= area[0] && p.x <= area[0] + area[2] && p.y >= area[1] && p.y <= area[1] + area[3],
              `(${x}, ${y}) out of view at ${JSON.stringify(p)} in ${JSON.stringify(area)}`);
  }
  // 400 px a mm on the circle (its start at 180 degrees, kept as 71 chords within 0.05 mm: a chord's middle lies
  // 0.049 mm = 20 px inside the circle): B's colour on the circle itself all along
  const mid = Math.PI + Math.PI / 71;
  await page.evaluate(([x, y]) => essikit.setView(x, y, 400), [350 + 50 * Math.cos(mid), 50 * Math.sin(mid)]);
  await page.mouse.move(5, 890);
  await nextFrames(page, 3);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'compare-circle-close.png') }));
  const off = [];
  for (let d = 0; d <= 0.0151; d += 0.0015) {  // (from the chord's middle down: the Compare window is above)
    const t = mid + d;
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), [350 + 50 * Math.cos(t), 50 * Math.sin(t)]);
    const hits = [];
    for (let dx = -2; dx <= 2; ++dx) hits.push(at(Math.round(p.x) + dx, Math.round(p.y)));
    if (!hits.some((c) => c[2] > 200 && c[1] > 150 && c[0] < 150)) off.push([t.toFixed(4), JSON.stringify(hits)]);
  }
  assert.deepEqual(off, [], 'B\'s circle drawn off the circle (facets)');
  await page.evaluate(() => essikit.endCompare());
  await page.close();
});

test('a toolbar button\'s tooltip opens under the bar: Compare\'s new label never covers the profile list', async () => {
  const page = await newPage();
  await page.evaluate(() => essikit.setLanguage('de'));
  await page.evaluate(() => essikit.load('a.esi', '7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n64\n'));
  await nextFrames(page, 3);
  let tb = (await page.evaluate(() => essikit.state())).toolbar;
  const compare = tb.items.find((i) => i.id === 'compare').rect;
  await page.mouse.click(compare.x + compare.w / 2, compare.y + compare.h / 2);  // (the label becomes longer)
  await nextFrames(page, 4);
  tb = (await page.evaluate(() => essikit.state())).toolbar;
  const profile = tb.items.find((i) => i.id === 'profile').rect;
  const shot = async (name) => pixels(page, await page.screenshot({ path: path.join(shots, name) }));
  const hovered = await shot('toolbar-tooltip.png');  // the mouse still on Compare: its tooltip shown
  await page.mouse.move(800, 600);
  await nextFrames(page, 4);
  const away = await shot('toolbar-no-tooltip.png');
  const covered = [];
  for (let y = Math.ceil(profile.y); y < profile.y + profile.h; y += 2)
    for (let x = Math.ceil(profile.x); x < profile.x + profile.w; x += 3) {
      const a = hovered(x, y), b = away(x, y);
      if (a.some((v, k) => Math.abs(v - b[k]) > 8)) covered.push([x, y]);
    }
  assert.deepEqual(covered.slice(0, 5), [], `the profile list is covered at ${covered.length} points while Compare is hovered`);
  await page.evaluate(() => { essikit.endCompare(); essikit.setLanguage('en'); });
  await page.close();
});

test('View as PNG with the Export menu open: the picture holds the drawing, not the menu', async () => {
  const page = await newPage();
  await page.evaluate(() => essikit.setPanels(false, true, 310, 470));  // (the menu opens over the drawing)
  await loadExample(page, 'plate_holes.esi');
  await page.evaluate(() => essikit.setView(160, 120, 3));
  await nextFrames(page, 3);
  const s = await page.evaluate(() => essikit.state());
  const decode = async (url) => pixels(page, Buffer.from(url.replace(/^data:image\/png;base64,/, ''), 'base64'));
  const closed = await decode(await page.evaluate(() => essikit.exportPng()));
  // the Export menu opened by its button; the screen shows it over the drawing
  const button = s.toolbar.items.find((i) => i.id === 'export' && !i.in_menu);
  assert.ok(button, JSON.stringify(s.toolbar.items.map((i) => i.id)));
  await page.mouse.click(button.rect.x + button.rect.w / 2, button.rect.y + button.rect.h / 2);
  await nextFrames(page, 3);
  const screen = await pixels(page, await page.screenshot({ path: path.join(shots, 'export-menu-open.png') }));
  const [ax, ay] = s.view.area;
  const box = [];  // where the menu opens: under its button, inside the drawing area (the picture's own pixels)
  for (let y = 10; y < 110; y += 10)
    for (let x = 10; x < 150; x += 10) box.push([button.rect.x + x - ax, button.rect.y + button.rect.h + y - ay]);
  const inside = box.filter(([x, y]) => x >= 0 && y >= 0 && x < s.view.area[2] && y < s.view.area[3]);
  assert.ok(inside.length > 50, `the menu's place is not over the drawing: ${JSON.stringify(s.view.area)}`);
  const same = (a, b) => a.every((v, k) => Math.abs(v - b[k]) <= 2);
  const covered = inside.filter(([x, y]) => !same(screen(x + ax, y + ay), closed(x, y))).length;
  assert.ok(covered > inside.length / 4, `the open menu is not drawn over the drawing (${covered} of ${inside.length})`);
  const open = await decode(await page.evaluate(() => essikit.exportPng()));
  const differing = inside.filter(([x, y]) => !same(open(x, y), closed(x, y)));
  assert.equal(differing.length, 0, `the PNG holds the open menu at ${JSON.stringify(differing.slice(0, 5))}`);
  await tap(page, 'Escape');
  await page.evaluate(() => essikit.setPanels(true, true, 310, 470));  // (the defaults, for the tests after)
  await page.close();
});

test('measure: distance and dx/dy between two points, snapping to end points and arc centres', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'plate_holes.esi');
  await page.keyboard.press('m');
  await until(page, () => essikit.state().measure.active, null, 'M did not start measuring');
  const longCuts = motions.filter((m) => m.kind === 'cut' && m.curve === 'line' && m.length_mm > 150);
  const a = longCuts[0].end, b = longCuts[1].end;
  const click = async (pt, dx, dy) => {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), pt);
    await page.mouse.click(p.x + dx, p.y + dy);
  };
  await click(a, 4, -3);  // a few pixels off: snaps
  await until(page, () => essikit.state().measure.points === 1, null, 'first click not taken');
  await click(b, -3, 4);
  await until(page, () => essikit.state().measure.points === 2, null, 'second click not taken');
  let ms = (await page.evaluate(() => essikit.state())).measure;
  assert.deepEqual(ms.a_mm, a, 'A did not snap to the end point');
  assert.deepEqual(ms.b_mm, b, 'B did not snap to the end point');
  assert.ok(Math.abs(ms.distance_mm - Math.hypot(b[0] - a[0], b[1] - a[1])) < 1e-9);
  assert.ok(Math.abs(ms.dx_mm - (b[0] - a[0])) < 1e-9 && Math.abs(ms.dy_mm - (b[1] - a[1])) < 1e-9);
  await page.screenshot({ path: path.join(shots, 'measure.png') });
  // An arc centre (a hole's centre: nothing else is near it).
  const hole = motions.find((m) => m.curve === 'arc' && m.centre);
  await click(hole.centre, 3, 3);
  await until(page, () => essikit.state().measure.points === 1, null, 'third click not taken');
  ms = (await page.evaluate(() => essikit.state())).measure;
  assert.deepEqual(ms.a_mm, hole.centre, 'did not snap to the arc centre');
  await page.close();
});

test('measure: the Measure window never covers the mouse or the points A and B', async () => {
  const page = await newPage();
  await loadExample(page, 'plate_holes.esi');
  await page.keyboard.press('m');
  await until(page, () => essikit.state().measure.active, null, 'M did not start measuring');
  const area = (await page.evaluate(() => essikit.state())).view.area;
  const inside = (r, x, y) => x >= r.x - 4 && x <= r.x + r.w + 4 && y >= r.y - 4 && y <= r.y + r.h + 4;
  const windowAt = async () => {
    await nextFrames(page, 3);
    const w = (await page.evaluate(() => essikit.state())).measure.window;
    assert.ok(w && w.w > 50 && w.h > 20, JSON.stringify(w));
    assert.ok(w.x >= area[0] && w.y >= area[1] && w.x + w.w <= area[0] + area[2] + 1 && w.y + w.h <= area[1] + area[3] + 1,
              `the window ${JSON.stringify(w)} is not inside the drawing area ${JSON.stringify(area)}`);
    return w;
  };
  // the mouse far from the top left: the window there; the mouse where it was: it goes elsewhere
  await page.mouse.move(area[0] + area[2] - 40, area[1] + area[3] - 40);
  const first = await windowAt();
  assert.ok(Math.abs(first.x - area[0] - 10) < 2 && Math.abs(first.y - area[1] - 10) < 2, JSON.stringify(first));
  const under = [first.x + 30, first.y + 15];
  await page.mouse.move(...under);
  const moved = await windowAt();
  assert.ok(!inside(moved, ...under), `the window ${JSON.stringify(moved)} covers the mouse at ${under}`);
  // A picked in the top right corner, the mouse in the bottom left: the window neither on A nor under the mouse
  const a = [area[0] + area[2] - 30, area[1] + 30], mouse = [area[0] + 30, area[1] + area[3] - 30];
  await page.mouse.click(...a);
  await until(page, () => essikit.state().measure.points === 1, null, 'the click was not taken');
  await page.mouse.move(...mouse);
  const third = await windowAt();
  const pa = await page.evaluate(([x, y]) => essikit.project(x, y), (await page.evaluate(() => essikit.state())).measure.a_mm);
  assert.ok(!inside(third, pa.x, pa.y) && !inside(third, ...mouse), `the window ${JSON.stringify(third)} covers A ${JSON.stringify(pa)} or the mouse ${mouse}`);
  await page.keyboard.press('Escape');
  await page.close();
});

test('the block inspector says in words what a block does', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'plate_holes.esi');
  const words = async (line) => {
    await page.evaluate((l) => essikit.selectLine(l), line);
    return (await page.evaluate(() => essikit.state())).inspector.join('\n');
  };
  assert.match(await words(9), /^function 39: .*400 mm\/min/m);
  assert.match(await words(13), /^function 29: .*kerf compensation left/im);
  assert.match(await words(14), /^function 7: .*oxygen/im);
  const arc = motions.find((m) => m.curve === 'arc');
  const t = await words(arc.line);
  assert.match(t, /motion block, 5 words: DX [+-]\d+, DY [+-]\d+, XC [+-]\d+, YC [+-]\d+, TC [+-] \((counter-)?clockwise\)/);
  assert.match(t, /cut (full circle|arc) (CCW|CW) r=\d+\.\d{3} mm, centre \(/);
  await page.screenshot({ path: path.join(shots, 'inspector.png') });
  // Every function block of every example is explained (never "not a machine function").
  for (const file of ['feed_dwell.esi', 'bevel_plasma.esi', 'marking.esi', 'three_axis.esi']) {
    const st = await loadExample(page, file);
    for (let line = 1; line <= st.state.lines; ++line) {
      const w = await words(line);
      for (const sentence of w.split('\n').filter((x) => x.startsWith('function ')))
        assert.match(sentence, /^function \d+: [^:]+.*: \S/, `${file}:${line}: ${sentence}`);
    }
  }
  await page.close();
});

test('kerf compensation: the torch path and the cut\'s width are drawn, toggled, and the inspector shows both positions', async () => {
  const page = await newPage();
  const { state } = await loadExample(page, 'kerf_parts.esi');
  assert.ok(state.kerf.segments > 40, `kerf segments: ${state.kerf.segments}`);
  assert.deepEqual(state.kerf.widths_mm, [3]);
  assert.equal(state.layers.kerf, true);
  assert.equal(state.layers.kerf_band, true);
  // Zoom onto part A's left side (programmed x 200, the torch 1.5 mm to its left at x 198.5).
  await page.evaluate(() => essikit.setView(199, 250, 40));
  await page.mouse.move(5, 890);
  await page.waitForTimeout(150);
  const KERF_RGB = [77, 242, 115];  // kPathColorTable[kKerfPathKind]
  let lastHits = '';
  const torchAt = async () => {
    const at = await pixels(page, await page.screenshot());
    const p = await page.evaluate(() => essikit.project(198.5, 250));
    const hits = [];
    for (let dx = -3; dx <= 3; ++dx) hits.push(at(p.x + dx, p.y));  // (a thin line: a few pixels across it)
    lastHits = JSON.stringify({ p, hits });
    // the line is a pixel or two wide, blended where it crosses a pixel: green well above red and blue
    return hits.some((c) => near(c, KERF_RGB) || (c[1] > c[0] + 60 && c[1] > c[2] + 60));
  };
  await page.screenshot({ path: path.join(shots, 'kerf-layers.png') });
  assert.ok(await torchAt(), `no kerf path colour where the torch runs: ${lastHits}`);
  await page.evaluate(() => essikit.setLayer(6, false));
  await page.waitForTimeout(150);
  assert.equal((await page.evaluate(() => essikit.state())).layers.kerf, false);
  assert.ok(!(await torchAt()), 'the kerf path is still drawn when its layer is off');
  await page.evaluate(() => essikit.setLayer(6, true));
  // The inspector: the programmed motion and the torch's.
  await page.evaluate(() => essikit.selectLine(15));
  const words = (await page.evaluate(() => essikit.state())).inspector.join('\n');
  assert.match(words, /^cut line from \(200\.000, 210\.000\) to \(200\.000, 290\.000\)/m);
  assert.match(words, /^torch \(kerf\): cut line from \(198\.500, 210\.000\) to \(198\.500, 290\.000\)/m);
  // the kerf said as what it is: the torch's offset and the cut's width
  assert.match(words, /kerf: torch 1\.500 mm to the left \(a cut 3\.000 mm wide\)/);
  // A tape without compensation has no kerf segments.
  const plain = await loadExample(page, 'arcs_both_senses.esi');
  assert.equal(plain.state.kerf.segments, 0);
  await page.close();
});

test('the machine\'s view orientation: x up and y left (Woyda), drawn so, and kept across sessions', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'plate_holes.esi');
  await page.evaluate(() => essikit.setOrientation(1));
  let state = await page.evaluate(() => essikit.state());
  assert.equal(state.view.turns, 1);
  // +x points up the screen: a point 10 mm further along x is 10 mm x zoom pixels higher, at the same column.
  const a = await page.evaluate(() => essikit.project(100, 100));
  const b = await page.evaluate(() => essikit.project(110, 100));
  assert.ok(Math.abs(a.x - b.x) < 1e-6 && Math.abs((a.y - b.y) - 10 * state.view.zoom) < 1e-6, JSON.stringify([a, b]));
  // The cut colour where the turned cut lines are (the drawing follows the turn).
  await page.evaluate(() => essikit.setView(160, 110, 2.5));
  await page.mouse.move(5, 890);
  await page.waitForTimeout(150);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'orientation-woyda.png') }));
  let checked = 0;
  for (const m of motions.filter((x) => x.kind === 'cut' && x.curve === 'line' && x.length_mm > 50)) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
    if (p.x < 300 || p.x > 1100 || p.y < 40 || p.y > 880) continue;  // (on the drawing area only)
    const hits = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) hits.push(at(p.x + dx, p.y + dy));
    assert.ok(hits.some((c) => near(c, CUT_RGB)), `no cut colour at (${p.x}, ${p.y}) turned: ${JSON.stringify(hits)}`);
    ++checked;
  }
  assert.ok(checked >= 2, `only ${checked} cut lines on screen`);
  // Kept across sessions: the page loaded again starts turned.
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  await page.evaluate(() => essikit.ready);
  state = await page.evaluate(() => essikit.state());
  assert.equal(state.view.turns, 1);
  assert.equal(await page.evaluate(() => window.localStorage.getItem('essikit.orientation')), '1');
  await page.evaluate(() => essikit.setOrientation(0));
  assert.equal((await page.evaluate(() => essikit.state())).view.turns, 0);
  await page.close();
});

test('a profile file dropped on the page checks the tape with it (placement on the machine)', async () => {
  const page = await newPage();
  let state = await dropProfile(page, 'bad.json', Buffer.from('{"plate_rotation_deg": 999}'));
  assert.match(state.message, /bad\.json is not a profile: "plate_rotation_deg" must be a number between -360 and 360/);
  state = await dropProfile(page, 'skewed_plate.profile.json', fs.readFileSync(path.join(examplesDir, 'skewed_plate.profile.json')));
  assert.equal(state.profile, 'skewed-plate');
  state = await dropFile(page, 'skewed_plate.esi', fs.readFileSync(path.join(examplesDir, 'skewed_plate.esi')));
  assert.equal(state.profile, 'skewed-plate');
  const cli = JSON.parse(execFileSync(essiBin, ['check', '--format', 'json', '--profile',
    path.join(examplesDir, 'skewed_plate.profile.json'), path.join(examplesDir, 'skewed_plate.esi')]).toString()).files[0];
  for (const k of ['min_x', 'min_y', 'max_x', 'max_y'])
    assert.ok(Math.abs(state.stats.machine_cut_bbox_mm[k] - cli.stats.machine_cut_bbox_mm[k]) < 1e-6, k);
  assert.ok(Math.abs(state.stats.machine_cut_bbox_mm.min_x - 1497.161155) < 1e-5);
  // The table (0..3000 x 0..1500 on the machine) under the program: R(-3.5 deg) (machine - G55 (1500, 250)).
  const a = -3.5 * Math.PI / 180;
  const program = ([x, y]) => [Math.cos(a) * (x - 1500) - Math.sin(a) * (y - 250), Math.sin(a) * (x - 1500) + Math.cos(a) * (y - 250)];
  const want = [[0, 0], [3000, 0], [3000, 1500], [0, 1500]].map(program);
  assert.equal(state.table_mm.length, 4);
  state.table_mm.forEach((c, k) => assert.ok(Math.hypot(c[0] - want[k][0], c[1] - want[k][1]) < 1e-9, `corner ${k}: ${c} != ${want[k]}`));
  assert.equal(state.layers.table, true);
  await page.evaluate(() => essikit.setView(0, 0, 0.25));
  await page.waitForTimeout(150);
  await page.screenshot({ path: path.join(shots, 'dropped-profile.png') });
  await page.close();
});

test('machine coordinates: the program turned and placed as it lies on the table, measured in machine mm, kept', async () => {
  const page = await newPage();
  await dropProfile(page, 'skewed_plate.profile.json', fs.readFileSync(path.join(examplesDir, 'skewed_plate.profile.json')));
  const { motions } = await loadExample(page, 'skewed_plate.esi');
  await page.evaluate(() => essikit.setCoordinates('machine'));
  let state = await page.evaluate(() => essikit.state());
  assert.equal(state.view.coordinates, 'machine');
  // machine = G55 (1500, 250) + R(3.5 deg) program (docs/semantics.md section 12)
  const a = 3.5 * Math.PI / 180;
  const machine = ([x, y]) => [1500 + Math.cos(a) * x - Math.sin(a) * y, 250 + Math.sin(a) * x + Math.cos(a) * y];
  assert.ok(Math.abs(state.view.rotation[0] - Math.cos(a)) < 1e-12 && Math.abs(state.view.rotation[1] - Math.sin(a)) < 1e-12,
            JSON.stringify(state.view.rotation));
  const centre = machine([state.view.x_mm, state.view.y_mm]);
  assert.ok(Math.hypot(state.view.shown_mm[0] - centre[0], state.view.shown_mm[1] - centre[1]) < 1e-9);
  // The plate's edges, skewed in the program, run along the screen's axes: the table's are square on the screen.
  const cuts = motions.filter((m) => m.kind === 'cut' && m.curve === 'line');
  assert.equal(cuts.length, 4);
  for (const m of cuts) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.start);
    const q = await page.evaluate(([x, y]) => essikit.project(x, y), m.end);
    const [dx, dy] = [m.end[0] - m.start[0], m.end[1] - m.start[1]];
    // program x runs 3.5 degrees up the screen; program y 3.5 degrees left of up
    const along = Math.abs(dx) > Math.abs(dy) ? Math.abs(q.y - p.y) / Math.abs(q.x - p.x) : Math.abs(q.x - p.x) / Math.abs(q.y - p.y);
    assert.ok(Math.abs(along - Math.tan(a)) < 1e-9, `line ${m.line}: ${along}`);
  }
  const corners = await Promise.all(state.table_mm.map((c) => page.evaluate(([x, y]) => essikit.project(x, y), c)));
  assert.ok(Math.abs(corners[0].y - corners[1].y) < 1e-6 && Math.abs(corners[1].x - corners[2].x) < 1e-6,
            `the table is not square on the screen: ${JSON.stringify(corners)}`);
  // The cut colour where the placed lines are.
  await page.evaluate(() => essikit.setView(160, 110, 2.5));
  await page.mouse.move(5, 890);
  await page.waitForTimeout(150);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'machine-coordinates.png') }));
  for (const m of cuts) {
    const mid = [(m.start[0] + m.end[0]) / 2, (m.start[1] + m.end[1]) / 2];
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), mid);
    const hits = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) hits.push(at(p.x + dx, p.y + dy));
    // a slanted line a pixel wide is blended where it crosses a pixel: orange, red well above green and blue
    const cutish = (c) => near(c, CUT_RGB) || (c[0] > c[2] + 80 && c[0] > c[1] + 30);
    assert.ok(hits.some(cutish), `no cut colour at (${p.x}, ${p.y}): ${JSON.stringify(hits)}`);
  }
  // The measure in machine millimetres: the first cut's ends.
  await page.keyboard.press('m');
  await until(page, () => essikit.state().measure.active, null, 'M did not start measuring');
  for (const [k, pt] of [[1, cuts[0].start], [2, cuts[0].end]]) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), pt);
    await page.mouse.click(p.x + 2, p.y - 2);
    await until(page, (n) => essikit.state().measure.points === n, k, `measure click ${k} not taken`);
  }
  const ms = (await page.evaluate(() => essikit.state())).measure;
  assert.equal(ms.coordinates, 'machine');
  const [ma, mb] = [machine(cuts[0].start), machine(cuts[0].end)];
  assert.ok(Math.hypot(ms.a_mm[0] - ma[0], ms.a_mm[1] - ma[1]) < 1e-9, `A ${ms.a_mm} != ${ma}`);
  assert.ok(Math.abs(ms.dx_mm - (mb[0] - ma[0])) < 1e-9 && Math.abs(ms.dy_mm - (mb[1] - ma[1])) < 1e-9);
  assert.ok(Math.abs(ms.distance_mm - cuts[0].length_mm) < 1e-9);
  // The playback says where the tool is in machine millimetres.
  await tap(page, 'Escape');
  await tap(page, 'Home');
  await until(page, () => essikit.state().playback.active, null, 'Home did not start the playback');
  const pb = (await page.evaluate(() => essikit.state())).playback;
  const tool = machine(pb.tool_mm);
  assert.ok(Math.hypot(pb.tool_shown_mm[0] - tool[0], pb.tool_shown_mm[1] - tool[1]) < 1e-9, JSON.stringify(pb));
  await tap(page, 'End');
  // Kept across sessions; back to program coordinates: no turn.
  assert.equal(await page.evaluate(() => window.localStorage.getItem('essikit.coordinates')), '1');
  await page.evaluate(() => essikit.setCoordinates('program'));
  state = await page.evaluate(() => essikit.state());
  assert.equal(state.view.coordinates, 'program');
  assert.deepEqual(state.view.rotation, [1, 0]);
  await page.close();
});

test('a share link for a tape too large for a URL says so', async () => {
  const page = await newPage();
  const name = generatedTape(12);  // (about 3 MB deflated: more than a URL takes)
  await page.evaluate(async (n) => {
    const bytes = new Uint8Array(await (await fetch('/gen/' + n)).arrayBuffer());
    await essikit.load(n, bytes);
  }, name);
  const err = await page.evaluate(() => essikit.shareLink().then(() => 'ok', (e) => e.message));
  assert.match(err, /too large for a link .* and no essi serve share store answers/);
  assert.match((await page.evaluate(() => essikit.state())).share_url, /too large/);
  await page.close();
});

test('a share link of a megabyte or two is made and opens (no 4 MB cap, the link passed on the heap)', async () => {
  const page = await newPage();
  const name = generatedTape(5);
  await page.evaluate(async (n) => {
    const bytes = new Uint8Array(await (await fetch('/gen/' + n)).arrayBuffer());
    await essikit.load(n, bytes);
  }, name);
  const before = await page.evaluate(() => essikit.state());
  const url = await page.evaluate(() => essikit.shareLink());
  assert.ok(url.length > 500000 && url.length < 2000000, `${url.length} characters`);
  const other = await openLink(url);
  const got = await other.evaluate(() => essikit.state());
  assert.equal(got.bytes, before.bytes);
  assert.deepEqual(got.stats, before.stats);
  await other.close();
  await page.close();
});

// Most real tapes are small. One under 1 MB is read, checked, its drawing made and uploaded when it is handed
// over, and the first frame after that draws all of it (no progress bar, no slices, no image filled over frames):
// state().load counts it in the viewer's frames. A bigger one is loaded in slices with the progress bar. (No timing
// here: `make bench` measures it.)
test('a tape under 1 MB is drawn complete in the first frame after the drop; a 2 MB tape shows the progress bar', async () => {
  const page = await newPage();
  await page.mouse.move(5, 890);  // (no hover over the drawing)
  for (const [url, name] of [['/examples/plate_holes.esi', 'plate_holes.esi'], ['/gen/' + generatedTape(0.14), generatedTape(0.14)]]) {
    await dropFromUrl(page, url, name);
    await page.waitForFunction((n) => { const s = essikit.state(); return s.name === n && s.load.complete_frame > 0; }, name, { timeout: 60000 });
    const png = await page.screenshot({ path: path.join(shots, `at-once-${name.replace(/\.esi$/, '')}.png`) });
    const s = await page.evaluate(() => essikit.state());
    const { load } = s;
    console.log(`${name}: ${s.motions} motions, ${s.segments} segments; load ${JSON.stringify(load)}`);
    assert.equal(s.status, 'ready');
    assert.ok(load.at_once, `${name} was not loaded at once`);
    // Handed over between two frames, complete before the next one began; that one drew all of it.
    assert.equal(load.drawable_frame, load.handed_frame, `${name}: a frame began between the hand-over and the drawing's completion`);
    assert.equal(load.frames_to_show, 1, `${name}: shown ${load.frames_to_show} frames after it was handed over`);
    assert.equal(load.shown_frame, load.handed_frame + 1);
    assert.equal(load.complete_frame, load.shown_frame, `${name}: the first frame that showed it did not draw every segment`);
    assert.equal(load.steps, 1, `${name}: loaded in ${load.steps} slices`);
    assert.equal(load.progress_frames, 0, `${name}: ${load.progress_frames} frames showed the progress bar`);
    // On the screen right after: the cut colour where cuts are.
    const at = await pixels(page, png);
    const [ax, ay, aw, ah] = s.view.area;
    let cut = 0;
    for (let y = ay + 4; y < ay + ah - 4; y += 3) for (let x = ax + 4; x < ax + aw - 4; x += 3) if (near(at(x, y), CUT_RGB)) ++cut;
    assert.ok(cut >= 20, `${name}: ${cut} sampled pixels in the cut colour`);
    if (name === 'plate_holes.esi') {
      const motions = await page.evaluate((n) => Array.from({ length: n }, (_, i) => essikit.motion(i)), s.motions);
      let checked = 0;
      for (const m of motions.filter((x) => x.kind === 'cut' && x.curve === 'line' && x.length_mm > 50)) {
        const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
        const around = [];
        for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) around.push(at(p.x + dx, p.y + dy));
        assert.ok(around.some((c) => near(c, CUT_RGB)), `no cut colour at (${p.x}, ${p.y}): ${JSON.stringify(around)}`);
        ++checked;
      }
      assert.ok(checked >= 3);
    }
  }

  // 2.1 MB (about 150 000 motions): in slices, the progress bar over several frames.
  const big = generatedTape(2.1);
  // (every animation frame from before the drop until the tape is ready: a watch started after the drop can
  // miss a load that a fast machine finishes first)
  await page.evaluate((n) => {
    window.__seen = [];
    const tick = () => {
      const s = essikit.state();
      window.__seen.push([s.status, s.progress]);
      if (!(s.name === n && s.status === 'ready' && s.load.complete_frame > 0)) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }, big);
  await dropFromUrl(page, '/gen/' + big, big);
  await page.waitForFunction((n) => { const s = essikit.state(); return s.name === n && s.status === 'ready' && s.load.complete_frame > 0; }, big,
                             { timeout: 120000 });
  const { load } = await page.evaluate(() => essikit.state());
  const loading = (await page.evaluate(() => window.__seen)).filter(([st, p]) => st === 'loading' && typeof p === 'number');
  console.log(`${big}: load ${JSON.stringify(load)}, ${loading.length} animation frames saw it loading`);
  assert.equal(load.at_once, false);
  assert.ok(load.progress_frames >= 2, `the 2.1 MB tape showed the progress bar in ${load.progress_frames} frames`);
  assert.ok(loading.length >= 1 && loading[0][1] < 1, 'no animation frame saw the 2.1 MB tape loading');
  assert.ok(load.steps >= 2, `the 2.1 MB tape was loaded in ${load.steps} slices`);
  assert.ok(load.frames_to_show >= 2, `the 2.1 MB tape was shown ${load.frames_to_show} frames after it was handed over`);
  await page.close();
});

// Before the first tape the page runs the load path on built-in tapes (web/app/WarmUp.hpp), so that the browser's
// compilers are done with it before a person drops one; none of it shows. A tape dropped meanwhile stops it.
test('the page warms up on built-in tapes before the first drop and shows none of them; a drop stops it', async () => {
  const page = await newPage();
  await page.mouse.move(5, 890);
  await page.waitForFunction(() => essikit.state().warm_up.state === 'done', null, { timeout: 60000 });
  const s = await page.evaluate(() => essikit.state());
  console.log(`warm-up: ${JSON.stringify(s.warm_up)}`);
  assert.ok(s.warm_up.tapes >= 11, `${s.warm_up.tapes} tapes`);  // every built-in one at least once
  assert.ok(s.warm_up.bytes >= 200000, `${s.warm_up.bytes} bytes`);
  // A page that is not cross-origin isolated leaves its reading worker to the first big tape (its first load stays
  // as it was); serve_csp.test.mjs has the isolated page that starts it now.
  assert.deepEqual(await page.evaluate(() => [self.crossOriginIsolated, typeof Worker,
                                              Module.essikitReading ? Module.essikitReading.worker : 'no set-up']),
                   [false, 'function', null]);
  assert.equal(s.status, 'empty');
  assert.equal(s.name, '');
  // Nothing of the warm-up's tapes on the screen (a frame drawn after it: the grid off and on again).
  await page.keyboard.press('g');
  await page.keyboard.press('g');
  await page.waitForFunction((f) => essikit.state().frame > f + 2, s.frame);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'warm-up-done.png') }));
  const [ax, ay, aw, ah] = s.view.area;
  let cut = 0;
  for (let y = ay + 4; y < ay + ah - 4; y += 3) for (let x = ax + 4; x < ax + aw - 4; x += 3) if (near(at(x, y), CUT_RGB)) ++cut;
  assert.equal(cut, 0, `${cut} sampled pixels in the cut colour on the empty page`);
  await page.close();

  // Dropped at once in a new page: the tape is the one shown, checked as essi check does, and the warm-up stops.
  const early = await newPage();
  const file = 'kerf_parts.esi';
  const state = await dropFile(early, file, fs.readFileSync(path.join(examplesDir, file)));
  await early.waitForFunction(() => essikit.state().warm_up.state === 'stopped', null, { timeout: 10000 });
  const cli = cliReport(file);
  assertStatsEqual(state.stats, cli.stats, file);
  assert.deepEqual(state.diagnostics.map((d) => [d.code, d.line]), cli.diagnostics.map((d) => [d.code, d.line]));
  const w = await early.evaluate(() => essikit.state().warm_up);
  assert.ok(w.bytes < 200000, `the warm-up went on after the drop: ${JSON.stringify(w)}`);
  await early.close();
});

test('a 50 MB tape loads with a moving progress bar while the page keeps drawing', async () => {
  const name = generatedTape(50);
  const page = await newPage();
  // The path layers are hidden: drawing 7 M segments takes SwiftShader tens of seconds a frame
  // (docs/performance.md); this test is about loading.
  await page.evaluate(() => { for (const k of [0, 1, 2, 3]) essikit.setLayer(k, false); });
  await page.evaluate(() => {
    window.__frames = [];
    const tick = (t) => { window.__frames.push(t); if (!window.__stop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  await dropFromUrl(page, '/gen/' + name, name);
  const samples = [];
  const t0 = Date.now();
  for (;;) {
    const asked = Date.now();
    const s = await page.evaluate(() => { const st = essikit.state(); return { status: st.status, progress: st.progress, name: st.name, drawn: st.drawn, lod: !!(st.lod && st.lod.available), frames: window.__frames.length }; });
    samples.push({ ...s, answer_ms: Date.now() - asked, t: Date.now() - t0 });
    if (s.name === name && s.status === 'ready') break;
    assert.ok(Date.now() - t0 < 600000, 'the 50 MB tape did not load in 10 minutes');
    await new Promise((r) => setTimeout(r, 200));
  }
  const loading = samples.filter((s) => s.status === 'loading' && typeof s.progress === 'number');
  const progress = loading.map((s) => s.progress);
  const rising = progress.filter((p, i) => i > 0 && p > progress[i - 1]).length;
  const frameTimes = await page.evaluate(() => { window.__stop = true; return window.__frames; });
  const gaps = frameTimes.slice(1).map((t, i) => t - frameTimes[i]);
  const maxGap = Math.max(...gaps);
  const maxAnswer = Math.max(...samples.map((s) => s.answer_ms));
  const state = await page.evaluate(() => essikit.state());
  console.log(`50 MB: ${samples.at(-1).t} ms to load, ${loading.length} samples while loading, progress rose ${rising} times, ` +
              `${frameTimes.length} frames, longest frame gap ${maxGap.toFixed(0)} ms, slowest answer ${maxAnswer} ms, ` +
              `memory_bytes ${state.memory_bytes}, drawn from the level of detail at ${loading.find((s) => s.drawn && s.name === name)?.t} ms`);
  assert.ok(rising >= 5, `the progress bar did not move: ${JSON.stringify(progress)}`);
  // The level of detail is made before the exact segments: the tape is on the screen from it while its 7 M
  // segments are made and uploaded (seconds: many 200 ms samples).
  const overview = loading.filter((s) => s.name === name && s.drawn && s.lod);
  assert.ok(overview.length >= 1, 'the tape was not drawn from its level of detail while its segments were made');
  assert.ok(frameTimes.length >= 20, 'requestAnimationFrame stopped while loading');
  assert.ok(maxGap < 5000, `the page froze for ${maxGap} ms`);
  // (no screenshot: drawing 7 M segments takes SwiftShader seconds a frame, see docs/performance.md)
  const cli = cliReportOf(path.join(genDir, name));
  assertStatsEqual(state.stats, cli.stats, name);
  assert.equal(state.diagnostics.length, cli.diagnostics.length);
  await page.close();
});

// Drawing a zoomed-in view of a big tape takes SwiftShader seconds (about a million segments a second): the image
// is filled over several frames (Renderer::kSegmentsPerFrame) and the page goes on drawing meanwhile.
test('a zoomed-in view of a big tape fills over several frames while the page keeps drawing', async () => {
  const name = generatedTape(14);  // about 1 M motions, 3.4 M segments
  const page = await newPage();
  await dropFromUrl(page, '/gen/' + name, name);
  await page.waitForFunction((n) => { const s = essikit.state(); return s.name === n && s.status === 'ready' && !s.busy; },
                             name, { timeout: 300000, polling: 200 });
  const before = await page.evaluate(() => essikit.state());
  const v = before.view;
  // Every animation frame from the zoom (8x, at the centre) until the image is complete and no work is left.
  const seen = await page.evaluate(async ([x, y, zoom]) => {
    const out = [];
    const t0 = performance.now();
    essikit.setView(x, y, zoom);
    let last = t0;
    for (;;) {
      await new Promise((r) => requestAnimationFrame(r));
      const t = performance.now();
      const s = essikit.state();
      out.push({ gap: Math.round(t - last), pending: s.render.pending_segments, busy: s.busy, lod: s.lod.drawn });
      last = t;
      if ((out.length > 3 && s.render.pending_segments === 0 && !s.busy) || t - t0 > 240000) break;
    }
    return out;
  }, [v.x_mm, v.y_mm, v.zoom * 8]);
  const after = await page.evaluate(() => essikit.state());
  const filling = seen.filter((f) => f.pending > 0);
  const maxGap = Math.max(...seen.map((f) => f.gap));
  console.log(`zoom 8x on ${after.segments} segments: ${seen.length} frames until complete, ${filling.length} of them ` +
              `with segments still to draw (at most ${Math.max(...seen.map((f) => f.pending))}), longest frame gap ${maxGap} ms, ` +
              `${after.render.filling_frames - before.render.filling_frames} filling frames`);
  assert.equal(seen.at(-1).pending, 0, 'the zoomed-in image was not completed in 4 minutes');
  // The raster stands in only while the segments are made again at the zoom's tolerance (busy).
  assert.ok(seen.every((f) => !f.lod || f.busy), 'the zoomed-in view was drawn from the level of detail');
  assert.ok(!seen.at(-1).lod, 'the completed view is the level of detail');
  assert.ok(filling.length >= 2, `the image was drawn in one frame (${JSON.stringify(seen.slice(0, 5))})`);
  assert.ok(after.render.filling_frames - before.render.filling_frames >= 2, 'no frame went on filling the image');
  assert.ok(maxGap < 4000, `the page froze for ${maxGap} ms`);
  // The completed image shows the cuts: the cut colour in the drawing area.
  await page.mouse.move(5, 890);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'zoomed-big-tape.png') }));
  const [ax, ay, aw, ah] = after.view.area;
  let cut = 0;
  for (let y = ay + 4; y < ay + ah - 4; y += 4) for (let x = ax + 4; x < ax + aw - 4; x += 4) if (near(at(x, y), CUT_RGB)) ++cut;
  assert.ok(cut > 200, `only ${cut} cut-coloured samples in the zoomed-in drawing`);
  await page.close();
});

// The memory budget (docs/performance.md): the page's memory for a tape stays below 2 x its bytes + what the core's Tape of it holds
// (tape_memory_bytes: 12 bytes a block, 4 a word). Checked on the viewer's own count and on the WASM heap: the
// peak of malloc's footprint (what HEAPU8 must hold; it never shrinks) and HEAPU8's growth. Returns the state.
async function assertMemoryBudget(mb) {
  const name = generatedTape(mb);
  const bytes = fs.statSync(path.join(genDir, name)).size;
  const page = await newPage();
  const heap = () => page.evaluate(() => ({ length: Module.HEAPU8.length, ...JSON.parse(Module.UTF8ToString(Module._essi_heap())) }));
  const empty = await heap();
  await dropFromUrl(page, '/gen/' + name, name);
  // (also the work after "ready": a big tape's finer level of detail)
  await page.waitForFunction((n) => { const s = essikit.state(); return s.name === n && s.status === 'ready' && !s.busy; }, name,
                             { timeout: 300000, polling: 200 });
  const loaded = await heap();
  const state = await page.evaluate(() => essikit.state());
  const budget = 2 * bytes + state.tape_memory_bytes;
  const perBlock = state.tape_memory_bytes / state.blocks_read;
  console.log(`memory of ${name} (${bytes} bytes, ${state.motions} motions, ${state.blocks_read} blocks): viewer ` +
              `${state.memory_bytes} (${(state.memory_bytes / state.motions).toFixed(1)} B/motion), heap peak ` +
              `${loaded.peak - empty.footprint} over the empty page, HEAPU8 ${empty.length} -> ${loaded.length}; ` +
              `budget ${budget} (${perBlock.toFixed(1)} B/block), level of detail ${JSON.stringify(state.lod)}`);
  assert.ok(perBlock > 12 && perBlock < 24, `the core's bytes per block: ${perBlock}`);
  assert.ok(state.memory_bytes < budget, `viewer memory ${state.memory_bytes} over the budget ${budget}: ${JSON.stringify(state.memory_parts)}`);
  assert.ok(loaded.peak - empty.footprint < budget, `WASM heap peak ${loaded.peak - empty.footprint} over the budget ${budget}`);
  assert.ok(loaded.length - empty.length < budget, `WASM heap grew by ${loaded.length - empty.length}, over the budget ${budget}`);
  await page.close();
  return state;
}

// A 1.35 MB tape (96 000 motions: below the level of detail's threshold; the loader's fixed few hundred KB, and
// where the allocator leaves holes, which varies with the timing of the slices, weigh less than on a smaller tape).
test('the memory of a loaded tape stays below 2 x its bytes + the core\'s bytes per block', async () => {
  const state = await assertMemoryBudget(1.35);
  assert.ok(state.motions < 100000 && !state.lod.available, `${state.motions} motions, level of detail ${state.lod.available}`);
});

// A 2.1 MB tape (about 150 000 motions: just above the level of detail's threshold, where its raster weighs most
// against the budget; it is sized by the tape's motions, LodRaster::cells_for).
test('the memory of a tape with a level of detail (150 000 motions) stays within the same budget', async () => {
  const state = await assertMemoryBudget(2.1);
  assert.ok(state.motions > 140000 && state.motions < 160000, `${state.motions} motions`);
  assert.ok(state.lod.available, 'no level of detail');
  // The finer level of detail was made (after the one the fitted view needs) and counted in the peak.
  assert.ok(state.lod.cell_mm < 3000 / 1024, `level of detail of ${state.lod.cell_mm} mm cells`);
});

// ---- drawing performance: the cached image, panning, level of detail ---------------------------------------

// How many of the motions show the cut colour at (or next to) the page pixel of their middle.
async function cutHits(page, list, shot) {
  await page.mouse.move(5, 890);  // keep the cursor away from the drawing
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, shot) }));
  let hits = 0;
  for (const m of list) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
    const around = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) around.push(at(p.x + dx, p.y + dy));
    if (around.some((c) => near(c, CUT_RGB))) ++hits;
  }
  return hits;
}

// The motions whose middle is inside the drawing area (not under a panel).
async function inArea(page, list) {
  const [ax, ay, aw, ah] = (await page.evaluate(() => essikit.state())).view.area;
  const out = [];
  for (const m of list) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
    if (p.x > ax + 5 && p.x < ax + aw - 5 && p.y > ay + 5 && p.y < ay + ah - 5) out.push(m);
  }
  return out;
}

async function nextFrames(page, n = 2) {
  for (let i = 0; i < n; ++i) await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
}

// Drags the drawing with the left button from the area's centre by (dx, dy) pixels.
async function drag(page, dx, dy) {
  const [ax, ay, aw, ah] = (await page.evaluate(() => essikit.state())).view.area;
  const x = ax + aw / 2, y = ay + ah / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await nextFrames(page, 1);
  for (let i = 1; i <= 4; ++i) {
    await page.mouse.move(x + (dx * i) / 4, y + (dy * i) / 4);
    await nextFrames(page, 1);
  }
  await page.mouse.up();
  await nextFrames(page, 2);
}

test('panning moves the cached drawing with the mouse; a zoom or a far pan draws it again', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'plate_holes.esi');
  const cuts = motions.filter((m) => m.kind === 'cut' && m.curve === 'line' && m.length_mm > 50);
  assert.equal(await cutHits(page, cuts, 'pan-before.png'), cuts.length);
  const before = await page.evaluate(() => essikit.state());
  const p0 = await page.evaluate(([x, y]) => essikit.project(x, y), cuts[0].mid);

  // A pan within the image's margin: the drawing follows the mouse and is not drawn again.
  await drag(page, 80, -50);
  const panned = await page.evaluate(() => essikit.state());
  const p1 = await page.evaluate(([x, y]) => essikit.project(x, y), cuts[0].mid);
  assert.ok(Math.hypot(p1.x - p0.x, p1.y - p0.y) > 40, `the view did not move: ${JSON.stringify([p0, p1])}`);
  assert.equal(panned.render.full_redraws, before.render.full_redraws, 'a small pan drew the whole scene again');
  assert.ok(panned.render.cached_frames > before.render.cached_frames, 'no frame reused the image');
  // The cut colour is where the cuts are now: the image moved by the pan.
  const shown = await inArea(page, cuts);
  assert.ok(shown.length >= 2, 'no cut left in view after the pan');
  assert.equal(await cutHits(page, shown, 'pan-after.png'), shown.length, 'the moved image does not match the view');

  // A zoom draws the image again, at the new scale.
  const [ax, ay, aw, ah] = panned.view.area;
  await page.mouse.move(ax + aw / 2, ay + ah / 2);
  await page.keyboard.press('=');  // zoom in 1.25x at the centre
  await until(page, (z) => essikit.state().view.zoom > z * 1.2, panned.view.zoom, 'the key = did not zoom');
  await nextFrames(page, 2);
  const zoomed = await page.evaluate(() => essikit.state());
  assert.ok(zoomed.render.full_redraws > panned.render.full_redraws, 'the zoom did not draw the image again');
  const inView = await inArea(page, cuts);
  assert.ok(inView.length >= 2, 'no cut left in view after the zoom');
  assert.equal(await cutHits(page, inView, 'pan-zoomed.png'), inView.length, 'the cuts are not where the zoom put them');

  // A pan farther than the margin draws the image again (nothing is left blank).
  await page.keyboard.press('f');
  await until(page, (z) => Math.abs(essikit.state().view.zoom - z) < 1e-9, before.view.zoom, 'F did not fit');
  await nextFrames(page, 2);
  const fitted = await page.evaluate(() => essikit.state());
  await drag(page, -Math.round(aw * 0.8), 0);
  const far = await page.evaluate(() => essikit.state());
  assert.ok(far.render.full_redraws > fitted.render.full_redraws, 'a far pan did not draw the image again');
  const visible = await inArea(page, cuts);
  assert.ok(visible.length >= 1, 'no cut left in view after the far pan');
  assert.equal(await cutHits(page, visible, 'pan-far.png'), visible.length, 'the far pan left cuts undrawn');

  // One wheel notch (120 pixels of the browser) zooms by about 1.2x at the cursor: up in, down out.
  await page.mouse.move(ax + aw / 2, ay + ah / 2);
  await nextFrames(page, 2);  // (ImGui knows the cursor is over the drawing, not a panel)
  const z0 = (await page.evaluate(() => essikit.state())).view.zoom;
  await page.mouse.wheel(0, 120);
  await until(page, (z) => essikit.state().view.zoom < z / 1.05, z0, 'the wheel did not zoom out');
  const z1 = (await page.evaluate(() => essikit.state())).view.zoom;
  assert.ok(z1 > z0 / 2, `one wheel notch zoomed out ${z0 / z1} times`);
  await page.mouse.wheel(0, -120);
  await until(page, (z) => essikit.state().view.zoom > z * 1.05, z1, 'the wheel did not zoom in');
  await page.close();
});

// A tape of N x N small round parts (64 cut lines each) on a pitch of `pitch` mm: over 100 000 motions, so
// that the viewer makes its level of detail, with empty space between the parts.
function partGrid(n = 40, pitch = 20, radius = 2, sides = 64) {
  const u = 10;  // units a mm (0.1 mm units)
  const out = ['%', '39+2000'];
  const num = (v) => (v >= 0 ? '+' : '-') + Math.abs(v);
  let x = 0, y = 0;  // position in units
  const parts = [];
  for (let j = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i) {
      const cx = Math.round((i + 0.5) * pitch * u), cy = Math.round((j + 0.5) * pitch * u);
      const pts = [];
      for (let k = 0; k <= sides; ++k) {
        const a = (2 * Math.PI * (k % sides)) / sides;
        pts.push([cx + Math.round(radius * u * Math.cos(a)), cy + Math.round(radius * u * Math.sin(a))]);
      }
      out.push('5', num(pts[0][0] - x) + num(pts[0][1] - y), '6', '7');
      for (let k = 1; k < pts.length; ++k) out.push(num(pts[k][0] - pts[k - 1][0]) + num(pts[k][1] - pts[k - 1][1]));
      out.push('8');
      [x, y] = pts[0];
      parts.push({ centre: [cx / u, cy / u], onCut: [pts[0][0] / u, pts[0][1] / u] });
    }
  }
  // One arc (a full circle around the last part's first point): zooming in rebuilds the segments at a finer
  // chord tolerance.
  out.push('7', '+0+0-10+0+', '8');
  out.push('5', num(-x) + num(-y), '6', '63');
  return { text: out.join('\n') + '\n', parts, pitch };
}

// How many of the machine points (mm) have the cut colour at or next to their page pixel.
async function cutAt(page, points, shot) {
  await page.mouse.move(5, 890);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, shot) }));
  let hits = 0;
  for (const pt of points) {
    const p = await page.evaluate(([x, y]) => essikit.project(x, y), pt);
    const around = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) around.push(at(p.x + dx, p.y + dy));
    if (around.some((c) => near(c, CUT_RGB))) ++hits;
  }
  return hits;
}

test('a big tape zoomed out is drawn from the level-of-detail raster: cuts where the cuts are, nothing between', async () => {
  const page = await newPage();
  const grid = partGrid();
  const st = await page.evaluate((t) => essikit.load('parts_grid.esi', t), grid.text);
  assert.ok(st.motions > 100000, `only ${st.motions} motions`);
  await nextFrames(page, 2);
  const lod = (await page.evaluate(() => essikit.state())).lod;
  assert.ok(lod.available, 'no level of detail for a tape of over 100 000 motions');
  assert.ok(lod.drawn, 'the fitted view of a big tape did not use the level of detail');
  await page.evaluate(() => essikit.setLayer(4, false));  // pierces (drawn over the cuts in the raster)
  const sample = grid.parts.filter((_, k) => k % 97 === 0);
  const onCut = sample.map((p) => p.onCut);
  const between = sample.map((p) => [p.centre[0] + grid.pitch / 2, p.centre[1] + grid.pitch / 2]);
  assert.equal(await cutAt(page, onCut, 'lod-cuts.png'), onCut.length, 'the level of detail lost cuts');
  assert.equal(await cutAt(page, between, 'lod-cuts.png'), 0, 'cut colour between the parts');
  // The layers apply to it: without the cut layer, no cut colour.
  await page.evaluate(() => essikit.setLayer(2, false));
  assert.equal(await cutAt(page, onCut, 'lod-no-cut.png'), 0, 'cut colour with the cut layer hidden');
  await page.evaluate(() => essikit.setLayer(2, true));
  // Zoomed in, the segments themselves are drawn again, in the cut colour (rebuilt at a finer tolerance).
  const fitted = (await page.evaluate(() => essikit.state())).view;
  const tolerance = (await page.evaluate(() => essikit.state())).chord_tolerance_mm;
  const part = grid.parts[Math.floor(grid.parts.length / 2)];
  await page.evaluate(([x, y]) => essikit.setView(x, y, 20), part.centre);
  await until(page, () => !essikit.state().lod.drawn, null, 'zoomed in, the level of detail is still drawn');
  await until(page, (t) => essikit.state().chord_tolerance_mm < t / 2, tolerance, 'zooming in did not rebuild the segments');
  assert.equal(await cutAt(page, [part.onCut], 'lod-zoomed-in.png'), 1, 'zoomed in, the part is not drawn');
  // Back out: the same level of detail as before the rebuild.
  await page.evaluate(([x, y, z]) => essikit.setView(x, y, z), [fitted.x_mm, fitted.y_mm, fitted.zoom]);
  await until(page, () => essikit.state().lod.drawn, null, 'zoomed out again, no level of detail');
  assert.equal(await cutAt(page, onCut, 'lod-again.png'), onCut.length, 'after a rebuild the level of detail lost cuts');
  assert.equal(await cutAt(page, between, 'lod-again.png'), 0, 'after a rebuild, cut colour between the parts');
  await page.close();
});

// ---- fonts (docs/viewer.md#fonts) ---------------------------------------------------------------------------

// Glyph edges along the rows of a screenshot region: of the steps from background (< 15 % of the text's contrast)
// to full ink (> 85 %), the share that passes at most one pixel in between. A font rasterised at the screen's
// pixels has nearly all its edges that sharp; a font made for half the pixels and magnified has a ramp of two or
// more (measured: 0.93 against 0.29 for DejaVu Sans at 1x magnified, 0.76 for the old bitmap font magnified).
function sharpEdgeShare(at, w, h) {
  const lum = (x, y) => { const c = at(x, y); return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; };
  const counts = new Map();
  const L = [];
  for (let y = 0; y < h; ++y) for (let x = 0; x < w; ++x) {
    const l = Math.round(lum(x, y));
    L.push(l);
    counts.set(l, (counts.get(l) || 0) + 1);
  }
  const bg = [...counts.entries()].sort((a, b) => b[1] - a[1])[0][0];
  const dist = L.map((l) => Math.abs(l - bg));
  const top = [...dist].sort((a, b) => a - b)[Math.floor(dist.length * 0.995)];
  const d = (x, y) => dist[y * w + x] / top;
  let sharp = 0, edges = 0;
  for (let y = 0; y < h; ++y) {
    for (let x = 0; x < w;) {
      if (d(x, y) >= 0.15) { ++x; continue; }
      let k = x + 1;
      while (k < w && d(k, y) >= 0.15 && d(k, y) <= 0.85) ++k;
      if (k < w && k > x + 0 && d(k, y) > 0.85) {
        ++edges;
        if (k - x - 1 <= 1) ++sharp;
      }
      x = k;
    }
  }
  return { share: edges ? sharp / edges : 0, edges };
}

test('fonts: at a device pixel ratio of 2 the panels\' text is rasterised at 2x (sharp); a new ratio makes the atlas again', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1200, height: 700 }, deviceScaleFactor: 2, locale: 'en-US' });
  const page = await ctx.newPage();
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  await loadExample(page, 'plate_holes.esi');
  await until(page, () => essikit.state().fonts.pixel_size === 26, null, 'the font was not made at 26 px');
  const f = (await page.evaluate(() => essikit.state())).fonts;
  assert.equal(f.font, 'DejaVu Sans');
  assert.equal(f.css_size, 13);
  assert.equal(f.ratio, 2);
  await page.mouse.move(700, 690);
  await nextFrames(page, 3);
  // The left panel (its statistics, layers, playback), in device pixels.
  const clip = { x: 0, y: 40, width: 300, height: 640 };
  const at = await pixels(page, await page.screenshot({ clip, path: path.join(shots, 'fonts-hidpi-panel.png') }));
  const edges = sharpEdgeShare(at, clip.width * 2, clip.height * 2);
  assert.ok(edges.edges > 2000, `only ${edges.edges} glyph edges in the panel`);
  assert.ok(edges.share > 0.85, `glyph edges not sharp: ${(edges.share * 100).toFixed(1)} % within a pixel`);
  // The window moves to a screen of ratio 1 (or the browser zooms): the atlas is made again at 13 px, and back.
  const cdp = await ctx.newCDPSession(page);
  await cdp.send('Emulation.setDeviceMetricsOverride', { width: 1200, height: 700, deviceScaleFactor: 1, mobile: false });
  await until(page, () => { const g = essikit.state().fonts; return g.pixel_size === 13 && g.ratio === 1; }, null,
              'a ratio of 1 did not make the atlas at 13 px');
  await cdp.send('Emulation.setDeviceMetricsOverride', { width: 1200, height: 700, deviceScaleFactor: 1.5, mobile: false });
  await until(page, () => { const g = essikit.state().fonts; return g.pixel_size === 20 && g.ratio === 1.5; }, null,
              'a ratio of 1.5 did not make the atlas at 20 px');
  await ctx.close();
});

test('fonts: the first load in English is under 2.5 MB and does not fetch the CJK font; German letters are there', async () => {
  const ctx = await browser.newContext({ viewport: { width: 1600, height: 900 }, locale: 'en-US' });
  const page = await ctx.newPage();
  const requests = [];
  page.on('requestfinished', (r) => requests.push(r));
  page.on('requestfailed', (r) => requests.push(r));
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  await page.evaluate(() => essikit.ready);
  await nextFrames(page, 10);
  await page.waitForTimeout(1000);  // (anything fetched late would show here)
  let total = 0;
  const list = [];
  for (const r of requests) {
    const s = await r.sizes();
    total += s.responseBodySize + s.responseHeadersSize;
    list.push(`${new URL(r.url()).pathname} ${s.responseBodySize}`);
  }
  assert.ok(list.some((l) => l.startsWith('/essi_viewer.wasm')), `no wasm among ${list}`);
  assert.ok(total < 2.5e6, `the first load transferred ${total} bytes: ${list.join(', ')}`);
  assert.ok(!requests.some((r) => r.url().includes('essi_cjk')), `the CJK font was fetched: ${list.join(', ')}`);
  const s = await page.evaluate(() => essikit.state());
  assert.equal(s.fonts.cjk, 'none');
  assert.equal(s.fonts.cjk_loads, 0);
  assert.equal(s.fonts.pixel_size, 13);
  // German (and the language switch's 中文, embedded) need nothing more.
  assert.ok(await page.evaluate(() => essikit.hasGlyphs('äöüß ÄÖÜ „Größe“ – 5 mm² ± 0,1 °')), 'German letters missing');
  assert.ok(await page.evaluate(() => essikit.hasGlyphs('中文')), '中文 (the language switch) missing');
  assert.ok(!(await page.evaluate(() => essikit.hasGlyphs('切割程序块'))), 'Chinese glyphs there before they were asked for');
  await ctx.close();
});

// A fresh page in English that counts its requests of the CJK font.
async function englishPageCountingCjkFetches() {
  const ctx = await browser.newContext({ viewport: { width: 1600, height: 900 }, locale: 'en-US' });
  const page = await ctx.newPage();
  let fetches = 0;
  page.on('request', (r) => { if (r.url().includes('essi_cjk.ttc')) ++fetches; });
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  return { ctx, page, cjkFetches: () => fetches };
}

test('fonts: Chinese text fetches the CJK font once, only its glyphs go into the atlas, and they are drawn', async () => {
  const { ctx, page, cjkFetches } = await englishPageCountingCjkFetches();
  const text = fs.readFileSync(path.join(examplesDir, 'plate_holes.esi'), 'utf8');
  await page.evaluate((t) => essikit.load('abcde.esi', t), text);
  await page.mouse.move(700, 450);
  const before = (await page.evaluate(() => essikit.state())).fonts;
  assert.equal(before.cjk, 'none');
  const f = await page.evaluate(() => essikit.requireGlyphs('切割程序块'));
  assert.equal(f.cjk, 'loaded');
  assert.equal(f.cjk_glyphs, 5, `cjk glyphs ${JSON.stringify(f)}`);
  assert.equal(f.missing, 0);
  assert.equal(f.glyphs, before.glyphs + 5);
  assert.ok(await page.evaluate(() => essikit.hasGlyphs('切割程序块')));
  assert.equal(cjkFetches(), 1);
  // The same characters again: nothing to do; new ones: the atlas grows, the font is not fetched again.
  const same = await page.evaluate(() => essikit.requireGlyphs('程序块切割'));
  assert.equal(same.builds, f.builds);
  const more = await page.evaluate(() => essikit.requireGlyphs('已打开'));
  assert.equal(more.cjk_glyphs, 8);
  assert.equal(more.builds, f.builds + 1);
  assert.equal(cjkFetches(), 1, 'the CJK font was fetched again');
  // Drawn: the tape's name in the toolbar, 切割程序块.esi beside abcde.esi: where they differ, five glyphs of ink.
  const band = { x: 0, y: 0, width: 1600, height: 38 };
  await nextFrames(page, 3);
  const latin = await pixels(page, await page.screenshot({ clip: band, path: path.join(shots, 'fonts-latin-name.png') }));
  await page.evaluate((t) => essikit.load('切割程序块.esi', t), text);
  await page.mouse.move(700, 460);
  await nextFrames(page, 3);
  const cjk = await pixels(page, await page.screenshot({ clip: band, path: path.join(shots, 'fonts-cjk-name.png') }));
  let x0 = -1;
  for (let x = 0; x < band.width && x0 < 0; ++x)
    for (let y = 4; y < band.height - 4; ++y) if (!near(latin(x, y), cjk(x, y), 12)) { x0 = x; break; }
  assert.ok(x0 >= 0, 'the two names draw the same pixels');
  const bg = cjk(x0 - 2, 3);
  const glyph = f.pixel_size;  // (a CJK glyph is one em wide)
  for (let k = 0; k < 5; ++k) {
    let ink = 0;
    for (let x = x0 + k * glyph; x < x0 + (k + 1) * glyph; ++x)
      for (let y = 4; y < band.height - 4; ++y) if (!near(cjk(x, y), bg, 90)) ++ink;
    assert.ok(ink >= 12, `glyph ${k + 1} of 切割程序块 at x ${x0 + k * glyph}: ${ink} pixels of ink`);
  }
  // ... five different glyphs (a missing glyph is drawn as U+FFFD: five times the same pixels)
  for (let k = 0; k + 1 < 5; ++k) {
    let differ = 0;
    for (let x = 0; x < glyph; ++x)
      for (let y = 4; y < band.height - 4; ++y)
        if (!near(cjk(x0 + k * glyph + x, y), cjk(x0 + (k + 1) * glyph + x, y), 90)) ++differ;
    assert.ok(differ >= 12, `glyphs ${k + 1} and ${k + 2} of 切割程序块 look alike (${differ} pixels differ)`);
  }
  await ctx.close();
});

test('comments written in GB 18030 or UTF-8 are shown as written (detected per tape, overridable, the CJK font loaded)', async () => {
  const { ctx, page, cjkFetches } = await englishPageCountingCjkFetches();
  await page.evaluate(() => essikit.setCommentEncoding('auto'));
  // "零件 A1 切割" (part A1, cut) in a 3 ... 4 section, as a Chinese CAM system writes it: GBK bytes.
  const comment = '零件 A1 切割';
  const gbk = Buffer.from([0xC1, 0xE3, 0xBC, 0xFE, 0x20, 0x41, 0x31, 0x20, 0xC7, 0xD0, 0xB8, 0xEE]);
  const tape = Buffer.concat([Buffer.from('3\n'), gbk, Buffer.from('\n4\n7\n+1000+0\n+0+1000\n8\n64\n')]);
  let s = await dropFile(page, 'gbk_comment.esi', tape);
  assert.deepEqual(s.comment_encoding, { detected: 'gb18030', chosen: 'auto', used: 'gb18030' });
  assert.deepEqual(s.diagnostics, []);
  await page.evaluate(() => essikit.selectLine(2));
  await page.mouse.move(700, 450);
  await nextFrames(page, 2);
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.line_text, comment);
  // The characters of the comment came from the CJK font, fetched once.
  // (the font arrives between frames; its glyphs go into the atlas at the next update: nothing pending then)
  await page.waitForFunction(() => { const f = essikit.state().fonts; return f.cjk === 'loaded' && !f.pending; }, null,
                             { timeout: 30000 });
  assert.ok(await page.evaluate((t) => essikit.hasGlyphs(t), comment));
  assert.equal(cjkFetches(), 1);
  await page.screenshot({ path: path.join(shots, 'comment-gb18030.png') });
  // Read as UTF-8 instead (the user's choice, kept): the bytes that are no UTF-8 are shown as \xNN.
  await page.evaluate(() => essikit.setCommentEncoding('utf-8'));
  await nextFrames(page, 2);
  s = await page.evaluate(() => essikit.state());
  assert.deepEqual(s.comment_encoding, { detected: 'gb18030', chosen: 'utf-8', used: 'utf-8' });
  assert.ok(s.line_text.startsWith('\\xC1\\xE3'), s.line_text);
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 60000 });
  assert.equal((await page.evaluate(() => essikit.state())).comment_encoding.chosen, 'utf-8');
  await page.evaluate(() => essikit.setCommentEncoding('auto'));
  // The same comment written in UTF-8: detected as UTF-8, shown the same.
  s = await dropFile(page, 'utf8_comment.esi', Buffer.from(`3\n${comment}\n4\n7\n+1000+0\n8\n64\n`));
  assert.equal(s.comment_encoding.used, 'utf-8');
  await page.evaluate(() => essikit.selectLine(2));
  await nextFrames(page, 2);
  assert.equal((await page.evaluate(() => essikit.state())).line_text, comment);
  await ctx.close();
});

// --- The diagnostics on the drawing (docs/viewer.md "Problems on the drawing") ---

// A tape of `plates` plates of `per` 10 x 10 mm parts (compensated, clockwise, a 3 mm lead-in), written as a nesting
// program writes them (incremental, 0.1 mm), with two mistakes: a part over another on plate 3, and on plate 7 a
// part cut before its hole.
function platesTape(plates, per) {
  const lines = ['3', 'plates of small parts', '4', '39+1000'];
  let x = 0, y = 0;
  const w = (v) => (v < 0 ? '-' : '+') + Math.abs(v);
  const to = (mx, my) => {
    const X = Math.round(mx * 10), Y = Math.round(my * 10);
    lines.push(w(X - x) + w(Y - y));
    x = X; y = Y;
  };
  const rapid = (mx, my) => { lines.push('5'); to(mx, my); lines.push('6'); };
  const part = (x0, y0) => {
    rapid(x0 - 3, y0 + 5); lines.push('29', '7');
    to(x0, y0 + 5); to(x0, y0 + 10); to(x0 + 10, y0 + 10); to(x0 + 10, y0); to(x0, y0); to(x0, y0 + 5);
    lines.push('8', '38');
  };
  const hole = (cx, cy) => {
    rapid(cx, cy); lines.push('29', '7'); to(cx + 2, cy);
    lines.push(w(0) + w(0) + w(-20) + w(0) + '+');  // a full circle about (cx, cy), counter-clockwise
    lines.push('8', '38');
  };
  for (let p = 1; p <= plates; ++p) {
    for (let k = 0; k < per; ++k) {
      const px = 20 + 20 * (k % 60), py = 20 + 20 * Math.floor(k / 60);
      if (p === 7 && k === 5) { part(px, py); hole(px + 5, py + 5); continue; }
      part(px, py);
      if (p === 3 && k === 10) part(px + 5, py);  // over part 10
    }
    rapid(0, 0);
    lines.push(p === plates ? '64' : '0');
  }
  return lines.join('\r\n') + '\r\n';
}

test('a big tape is drawn before its cut plan is checked; the plan\'s findings then join the list, as essi check has them', async () => {
  const page = await newPage();
  const tape = platesTape(25, 600);
  assert.ok(tape.length > 1e6, `the tape has ${tape.length} bytes: it must be loaded in slices`);
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'essi-plan-')), 'plates.esi');
  fs.writeFileSync(file, tape);
  const state = await dropFile(page, 'plates.esi', Buffer.from(tape));
  const cli = cliReportOf(file);
  assert.deepEqual(state.diagnostics.map((d) => [d.severity, d.code, d.line, d.column, d.message]),
                   cli.diagnostics.map((d) => [d.severity, d.code, d.line, d.column, d.message]));
  const codes = state.diagnostics.map((d) => d.code);
  assert.ok(codes.includes('E605') && codes.includes('W604'), codes.join(' '));
  // Its drawing was complete before its plan's findings joined the list (loaded in slices, not at once).
  assert.equal(state.load.at_once, false);
  assert.ok(state.load.drawable_frame > 0 && state.load.planned_frame >= state.load.drawable_frame, JSON.stringify(state.load));
  // Each finding has its mark on the drawing once the plan is done.
  assert.equal(state.marks.count, state.diagnostics.filter((d) => d.line > 0).length);
  // A small tape has its plan checked with its reading, at once.
  const small = await dropFile(page, 'plan_collision.esi', fs.readFileSync(path.join(examplesDir, 'plan_collision.esi')));
  assert.equal(small.load.at_once, true);
  assert.equal(small.load.planned_frame, 0);
  assert.ok(small.diagnostics.some((d) => d.code === 'E605'), JSON.stringify(small.diagnostics));
  await page.close();
});


const ERROR_MARK_RGB = [255, 102, 89];  // kMarkerColors[Error] (the problems list's error colour)

// Pixels of the error mark's colour in a box of `half` pixels around (x, y).
function markPixels(at, x, y, half = 14) {
  let n = 0;
  for (let dy = -half; dy <= half; ++dy)
    for (let dx = -half; dx <= half; ++dx) if (near(at(x + dx, y + dy), ERROR_MARK_RGB, 30)) ++n;
  return n;
}

test('every diagnostic has a mark where it is: the same size at two zooms, its message on hover, a click selects its block', async () => {
  const page = await newPage();
  const { state, motions } = await loadExample(page, 'bad_arc_off_circle.esi');
  assert.equal(state.marks.count, state.diagnostics.filter((d) => d.line > 0).length);
  const mark = state.marks.items.find((m) => m.code === 'E301');
  assert.ok(mark, JSON.stringify(state.marks));
  assert.equal(mark.line, 12);
  // At the end point of line 12's motion (the arc that ends off its circle), where essikit.project draws it.
  const arc = motions.find((m) => m.line === 12);
  assert.deepEqual(mark.at_mm, arc.end);
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), arc.end);
  assert.ok(Math.abs(mark.px[0] - p.x) < 0.01 && Math.abs(mark.px[1] - p.y) < 0.01);
  // Drawn in the error colour, the same size at the fitted zoom and 4x closer (centred on the mark).
  await page.mouse.move(5, 890);
  await nextFrames(page, 3);
  let at = await pixels(page, await page.screenshot({ path: path.join(shots, 'marks-fit.png') }));
  const fitted = markPixels(at, p.x, p.y);
  assert.ok(fitted > 60, `the mark has ${fitted} pixels of the error colour at (${p.x}, ${p.y})`);
  await page.evaluate(([x, y, z]) => essikit.setView(x, y, z), [arc.end[0], arc.end[1], state.view.zoom * 4]);
  await nextFrames(page, 3);
  const q = await page.evaluate(([x, y]) => essikit.project(x, y), arc.end);
  at = await pixels(page, await page.screenshot({ path: path.join(shots, 'marks-zoom4.png') }));
  const zoomed = markPixels(at, q.x, q.y);
  assert.ok(Math.abs(zoomed - fitted) <= 0.15 * fitted, `the mark has ${fitted} pixels fitted, ${zoomed} zoomed 4x`);
  // Hover: the message in the viewer's language, and the mark is the hovered one.
  await page.mouse.move(q.x + 2, q.y + 1);
  await page.waitForFunction(() => essikit.state().marks.hovered !== null, null, { timeout: 10000 });
  let s = await page.evaluate(() => essikit.state());
  const e301 = state.diagnostics.find((d) => d.code === 'E301');
  assert.equal(s.marks.hovered.code, 'E301');
  assert.equal(s.marks.hovered.message, e301.message);
  assert.ok(s.marks.active.includes(s.marks.hovered.diagnostic));
  await page.screenshot({ path: path.join(shots, 'marks-hover.png') });
  await page.evaluate(() => essikit.setLanguage('de'));
  await nextFrames(page, 2);
  s = await page.evaluate(() => essikit.state());
  assert.notEqual(s.marks.hovered.message, e301.message, 'the hover text follows the language');
  await page.evaluate(() => essikit.setLanguage('en'));
  // A click on the mark selects its block (line 12), not the motion of line 13 that starts there.
  await page.mouse.click(q.x + 2, q.y + 1);
  await page.waitForFunction(() => { const t = essikit.state(); return t.selection && t.selection.line === 12; }, null,
                             { timeout: 10000 });
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.selection.motion, arc.index);
  await page.close();
});

test('problems only: everything no diagnostic concerns drawn faint, the concerned block in full; key P; kept', async () => {
  const page = await newPage();
  const { motions } = await loadExample(page, 'bad_arc_off_circle.esi');
  const arc = motions.find((m) => m.line === 12);
  const other = motions.find((m) => m.kind === 'cut' && m.curve === 'line' && m.line > 13 && m.length_mm > 50);
  const cutAt = async (file, m) => {
    await page.mouse.move(5, 890);
    await nextFrames(page, 3);
    const at = await pixels(page, await page.screenshot({ path: path.join(shots, file) }));
    const c = await page.evaluate(([x, y]) => essikit.project(x, y), m.mid);
    const hits = [];
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) hits.push(at(c.x + dx, c.y + dy));
    return hits.some((h) => near(h, CUT_RGB));
  };
  assert.equal((await page.evaluate(() => essikit.state())).problems_only, false);
  assert.ok(await cutAt('problems-off.png', other), 'the cut is drawn in full');
  await page.evaluate(() => essikit.setProblemsOnly(true));
  assert.equal((await page.evaluate(() => essikit.state())).problems_only, true);
  assert.ok(!(await cutAt('problems-only.png', other)), 'a cut no diagnostic concerns is faint');
  assert.ok(await cutAt('problems-only.png', arc), 'the diagnostic\'s block stays in full');
  await page.reload();
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  assert.equal((await page.evaluate(() => essikit.state())).problems_only, true, 'kept across sessions');
  await loadExample(page, 'bad_arc_off_circle.esi');
  await page.keyboard.press('p');
  await page.waitForFunction(() => !essikit.state().problems_only, null, { timeout: 10000 });
  assert.ok(await cutAt('problems-key-p.png', other), 'P brings the rest back');
  await page.close();
});

test('a collision: its overlapping area filled, its contour and the other part highlighted on hover', async () => {
  const page = await newPage();
  const { state } = await loadExample(page, 'plan_collision.esi');
  const collisions = state.diagnostics.filter((d) => d.code === 'E605');
  assert.equal(collisions.length, 2);
  assert.equal(state.marks.count, 2);
  assert.equal(state.marks.overlaps, 1);
  // Parts 1 (60..260 x 50..150 mm) and 2 (240..440 x 50..150) overlap by 20 x 100 mm: the area between x 240 and
  // 260 is filled in the error colour (translucent over the background); inside one part only it is not (points off
  // the grid's lines).
  await page.mouse.move(5, 890);
  await nextFrames(page, 3);
  const at = await pixels(page, await page.screenshot({ path: path.join(shots, 'collision.png') }));
  const [bx, by] = await page.evaluate(() => { const s = essikit.state(); return [s.view.area[0] + 3, s.view.area[1] + 3]; });
  const background = at(bx, by);
  const inOverlap = await page.evaluate(() => essikit.project(253, 117));
  const inOnePart = await page.evaluate(() => essikit.project(167, 117));
  const fill = at(inOverlap.x, inOverlap.y);
  assert.ok(fill[0] > background[0] + 60 && fill[0] > fill[2] + 40, `the overlap is ${fill}, the background ${background}`);
  assert.ok(near(at(inOnePart.x, inOnePart.y), background, 20), `inside one part: ${at(inOnePart.x, inOnePart.y)}`);
  // Hover the first collision's mark: its message and the other part among its related places.
  const mark = state.marks.items.find((m) => m.line === collisions[0].line);
  await page.mouse.move(mark.px[0] + 1, mark.px[1] + 1);
  await page.waitForFunction(() => essikit.state().marks.hovered !== null, null, { timeout: 10000 });
  const s = await page.evaluate(() => essikit.state());
  assert.equal(s.marks.hovered.message, collisions[0].message);
  assert.ok(s.marks.hovered.related.length >= 1, JSON.stringify(s.marks.hovered));
  assert.equal(s.marks.hovered.overlap_polygons, 2);
  // the diagnostic as the report has it: the same contour, {first_line, last_line}
  assert.deepEqual(s.marks.hovered.contour, collisions[0].contour, 'a collision concerns a contour');
  assert.ok(s.marks.hovered.contour.first_line > 0 && s.marks.hovered.contour.first_line <= s.marks.hovered.contour.last_line);
  await page.screenshot({ path: path.join(shots, 'collision-hover.png') });
  await page.close();
});

// ---- a phone's screen and many findings -----------------------------------------------------------------------

// A page as a phone shows it: 390 x 844 CSS pixels, touch, a mobile viewport.
async function phonePage() {
  const page = await browser.newPage({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  page.on('pageerror', (e) => console.log(`pageerror: ${e.message}`));
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  await page.evaluate(() => essikit.ready);
  return page;
}

// A finger dragged over the canvas from (x, y) by (dx, dy): touch events only (a pan, no mouse event follows).
async function fingerDrag(page, x, y, dx, dy) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x, y }] });
  for (let k = 1; k <= 4; ++k) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: x + (dx * k) / 4, y: y + (dy * k) / 4 }] });
    await nextFrames(page, 1);
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}

function centreOf(r) { return [r[0] + r[2] / 2, r[1] + r[3] / 2]; }

// One W109 (a blank at a block's end) on each of `lines` lines, and an E101 (a letter) on the last line but one.
function blanksTape(lines) {
  return '+10+0 \n'.repeat(lines) + '+10x\n64\n';
}

test('a phone: the drawing takes the width, the panels are a bottom sheet with tabs, the verdict stays in the bar', async () => {
  const page = await phonePage();
  let s = await page.evaluate(() => essikit.state());
  assert.equal(s.compact, true);
  await page.screenshot({ path: path.join(shots, 'phone-start.png') });
  ({ state: s } = await loadExample(page, 'plan_collision.esi'));
  await nextFrames(page, 3);
  s = await page.evaluate(() => essikit.state());
  // the drawing: the whole width, from the toolbar to the sheet's tabs
  assert.deepEqual(s.view.area, [0, 38, 390, 844 - 38 - 40]);
  assert.deepEqual(s.sheet, { open: false, tab: 'problems' });
  // the verdict in the bar, inside the screen; what does not fit is in the » menu
  const verdict = s.toolbar.items.find((i) => i.id === 'verdict');
  assert.equal(verdict.in_menu, false);
  assert.ok(verdict.rect.w > 0 && verdict.rect.x >= 0 && verdict.rect.x + verdict.rect.w <= 390, JSON.stringify(verdict));
  assert.ok(s.toolbar.more && s.toolbar.more.x >= verdict.rect.x + verdict.rect.w, JSON.stringify(s.toolbar));
  // four tabs side by side along the bottom, inside the screen
  const tabs = ['tab_problems', 'tab_statistics', 'tab_source', 'tab_inspector'].map((id) => s.controls[id]);
  let right = 0;
  for (const r of tabs) {
    assert.ok(r && r[0] >= right && r[0] + r[2] <= 390 && r[1] >= 844 - 40 && r[1] + r[3] <= 844, JSON.stringify(tabs));
    right = r[0] + r[2];
  }
  await page.screenshot({ path: path.join(shots, 'phone-collapsed.png') });
  // a tab opens the sheet on it (the drawing gives it the room), the open tab closes it
  await page.touchscreen.tap(...centreOf(s.controls.tab_statistics));
  await until(page, () => essikit.state().sheet.open && essikit.state().sheet.tab === 'statistics', null, 'the Statistics tab did not open');
  await nextFrames(page, 3);  // (the frame that opened it had laid the drawing out for the closed sheet)
  s = await page.evaluate(() => essikit.state());
  assert.ok(Math.abs(s.view.area[3] - (844 - 38 - 844 * 0.45)) < 1, JSON.stringify(s.view.area));
  await page.screenshot({ path: path.join(shots, 'phone-statistics.png') });
  const tab = s.controls.tab_statistics;
  await page.touchscreen.tap(...centreOf(tab));
  await until(page, () => !essikit.state().sheet.open, null, 'the open tab did not close the sheet');
  await nextFrames(page, 3);  // (the frame that closed it drew its tabs where the open sheet had them)
  s = await page.evaluate(() => essikit.state());
  await page.touchscreen.tap(...centreOf(s.controls.tab_problems));
  await until(page, () => essikit.state().sheet.open && essikit.state().sheet.tab === 'problems', null, 'the Problems tab did not open');
  await page.screenshot({ path: path.join(shots, 'phone-problems.png') });
  // the side panels are not drawn: their layout is kept for a wider window
  await page.setViewportSize({ width: 1024, height: 600 });
  await nextFrames(page, 3);
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.compact, false);
  assert.ok(s.view.area[0] > 0 && s.view.area[2] >= 512, JSON.stringify(s.view.area));
  await page.close();
});

test('next and previous problem (N, Shift+N, the buttons) select each finding in turn and zoom to it', async () => {
  const page = await phonePage();
  const { state } = await loadExample(page, 'plan_collision.esi');
  const lines = state.diagnostics.map((d) => d.line);
  assert.deepEqual(lines, [24, 37]);
  const fitted = state.view;
  assert.equal(state.problems.shown, null);
  await tap(page, 'KeyN');
  await until(page, () => essikit.state().problems.shown === 0, null, 'N did not show the first problem');
  let s = await page.evaluate(() => essikit.state());
  assert.equal(s.selection.line, 24);
  assert.ok(s.view.zoom > fitted.zoom * 1.2, `the view did not zoom to the problem: ${fitted.zoom} -> ${s.view.zoom}`);
  // the problem's contour (lines 24-29) is in view, around the middle of the drawing
  const first = await page.evaluate(() => essikit.motion(essikit.state().selection.motion));
  const p = await page.evaluate(([x, y]) => essikit.project(x, y), first.mid);
  const [ax, ay, aw, ah] = s.view.area;
  assert.ok(p.x > ax && p.x < ax + aw && p.y > ay && p.y < ay + ah, `line 24 at ${JSON.stringify(p)}, the area ${s.view.area}`);
  const view1 = s.view;
  await tap(page, 'KeyN');
  await until(page, () => essikit.state().problems.shown === 1, null, 'N did not show the second problem');
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.selection.line, 37);
  assert.ok(s.view.x_mm !== view1.x_mm || s.view.y_mm !== view1.y_mm, 'the view stayed on the first problem');
  await page.keyboard.down('Shift');
  await tap(page, 'KeyN');
  await page.keyboard.up('Shift');
  await until(page, () => essikit.state().problems.shown === 0, null, 'Shift+N did not go back to the first problem');
  assert.equal((await page.evaluate(() => essikit.state())).selection.line, 24);
  // the buttons over the drawing's corner, by touch: round from the first to the second and back
  s = await page.evaluate(() => essikit.state());
  const next = s.controls.next_problem, previous = s.controls.previous_problem;
  assert.ok(next && previous && next[0] + next[2] <= 390 && next[1] + next[3] <= s.view.area[1] + s.view.area[3], JSON.stringify(s.controls));
  await page.touchscreen.tap(...centreOf(next));
  await until(page, () => essikit.state().problems.shown === 1, null, 'the next problem button did not go on');
  await page.touchscreen.tap(...centreOf(previous));
  await until(page, () => essikit.state().problems.shown === 0, null, 'the previous problem button did not go back');
  await page.close();
});

test('a phone: a tapped mark\'s tooltip stays inside the screen; the next touch takes a tooltip away', async () => {
  const page = await phonePage();
  const { state } = await loadExample(page, 'plan_collision.esi');
  // the second collision's mark near the right edge of the screen
  const mark = state.marks.items.find((m) => m.line === 37);
  const zoom = state.view.zoom;
  const [, ay, aw, ah] = state.view.area;
  await page.evaluate(([x, y, z]) => essikit.setView(x, y, z), [mark.at_mm[0] - (aw / 2 - 14) / zoom, mark.at_mm[1], zoom]);
  await nextFrames(page, 3);
  const px = await page.evaluate(([x, y]) => essikit.project(x, y), mark.at_mm);
  assert.ok(px.x > 360 && px.x < 390 && px.y > ay && px.y < ay + ah, JSON.stringify(px));
  await page.touchscreen.tap(px.x, px.y);
  await until(page, () => essikit.state().tooltip !== null, null, 'no tooltip after a tap on the mark');
  await nextFrames(page, 2);
  let s = await page.evaluate(() => essikit.state());
  assert.equal(s.selection.line, 37);
  const [tx, ty, tw, th] = s.tooltip;
  assert.ok(tx >= 0 && tx + tw <= 390 && ty >= 0 && ty + th <= 844, `the tooltip at ${s.tooltip}`);
  await page.screenshot({ path: path.join(shots, 'phone-mark-tooltip.png') });
  // a finger on the drawing (a pan: no mouse event follows it) takes the tooltip away
  await fingerDrag(page, 150, 300, 40, 30);
  await until(page, () => essikit.state().tooltip === null, null, 'the mark\'s tooltip stayed after the next touch');
  // a tapped button's tooltip too
  s = await page.evaluate(() => essikit.state());
  await page.touchscreen.tap(...centreOf(s.controls.next_problem));
  await until(page, () => essikit.state().tooltip !== null, null, 'no tooltip over the tapped button');
  s = await page.evaluate(() => essikit.state());
  assert.ok(s.tooltip[0] >= 0 && s.tooltip[0] + s.tooltip[2] <= 390, `the tooltip at ${s.tooltip}`);
  await fingerDrag(page, 150, 300, -40, 0);
  await until(page, () => essikit.state().tooltip === null, null, 'the button\'s tooltip stayed after the next touch');
  await page.close();
});

test('many findings of one code are one row that opens to list them; state() pages through the problems', async () => {
  const page = await phonePage();
  const tape = blanksTape(3000);
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'essi-many-')), 'blanks.esi');
  fs.writeFileSync(file, tape);
  const cli = cliReportOf(file);
  assert.equal(cli.diagnostics.length, 1002);  // 1 000 W109 kept, their summary, the E101
  let s = await dropFile(page, 'blanks.esi', Buffer.from(tape));
  // the default page: the first 100, with the list's total
  assert.equal(s.problems.total, 1002);
  assert.equal(s.problems.offset, 0);
  assert.equal(s.problems.limit, 100);
  assert.deepEqual(s.diagnostics, cli.diagnostics.slice(0, 100));
  // a page asked for, and the last one (shorter)
  const page2 = await page.evaluate(() => essikit.state({ problems: { offset: 100, limit: 50 } }));
  assert.equal(page2.problems.offset, 100);
  assert.equal(page2.problems.limit, 50);
  assert.deepEqual(page2.diagnostics, cli.diagnostics.slice(100, 150));
  const last = await page.evaluate(() => essikit.state({ problems: { offset: 990, limit: 100 } }));
  assert.deepEqual(last.diagnostics, cli.diagnostics.slice(990));
  assert.equal(last.diagnostics.length, 12);
  assert.ok(last.diagnostics.some((d) => d.code === 'W109' && /^2000 more W109 diagnostics not listed/.test(d.message)), JSON.stringify(last.diagnostics));
  // the default answer does not grow with the list: a page of it, far smaller than the whole list (its time is
  // printed for the record: a timed assertion would fail on a busy machine, not on a defect)
  const answer = await page.evaluate(() => {
    const t0 = performance.now();
    const bytes = JSON.stringify(essikit.state()).length;
    return { bytes, ms: performance.now() - t0 };
  });
  console.log(`state() with ${s.problems.total} problems: ${answer.ms.toFixed(2)} ms, ${answer.bytes} bytes`);
  const whole = JSON.stringify(cli.diagnostics).length;
  assert.ok(answer.bytes < whole / 2, `state() is ${answer.bytes} bytes; the whole list ${whole}`);
  // the list: one row for the 3 000 W109 (closed), the E101 a row of its own
  await page.touchscreen.tap(...centreOf(s.controls.tab_problems));
  await until(page, () => essikit.state().sheet.open, null, 'the Problems tab did not open');
  await nextFrames(page, 3);
  s = await page.evaluate(() => essikit.state());
  assert.equal(s.problems.groups.length, 1);
  const g = s.problems.groups[0];
  assert.deepEqual([g.code, g.severity, g.findings, g.kept, g.open], ['W109', 'warning', 3000, 1001, false]);
  assert.ok(g.rect[2] > 0 && g.rect[1] > s.view.area[1] + s.view.area[3], JSON.stringify(g));
  await page.screenshot({ path: path.join(shots, 'phone-many-findings.png') });
  await page.touchscreen.tap(g.rect[0] + 20, g.rect[1] + g.rect[3] / 2);
  await until(page, () => essikit.state().problems.groups[0].open, null, 'the group did not open');
  await page.screenshot({ path: path.join(shots, 'phone-many-findings-open.png') });
  await page.close();
});

test('the problems list wraps its texts beside its scroll bar (German, Chinese): none runs on under it', async () => {
  const page = await newPage();
  await page.evaluate((t) => essikit.load('blanks.esi', t), blanksTape(60));
  await nextFrames(page, 3);
  for (const lang of ['de', 'zh']) {
    await page.evaluate((l) => essikit.setLanguage(l), lang);
    await nextFrames(page, 4);  // (the list laid out in that language: the group's row where it is now)
    let s = await page.evaluate(() => essikit.state());
    const g = s.problems.groups[0];
    if (!g.open) {
      await page.mouse.click(g.rect[0] + 20, g.rect[1] + g.rect[3] / 2);
      await until(page, () => essikit.state().problems.groups[0].open, null, 'the group did not open');
    }
    await nextFrames(page, 4);
    s = await page.evaluate(() => essikit.state());
    const [lx, , lw] = s.controls.problems_list, [, , rw] = s.controls.problems_rows;
    await page.screenshot({ path: path.join(shots, `problems-wrapped-${lang}.png`) });
    assert.ok(lw > 100 && rw > 100, JSON.stringify(s.controls));
    assert.ok(lx + rw <= lx + lw + 1, `${lang}: the rows' texts end at ${lx + rw}, the list's visible part at ${lx + lw}`);
  }
  await page.evaluate(() => essikit.setLanguage('en'));
  await page.close();
});

test('a tape with a million findings of one code loads in slices while the page draws; its list is one row', async () => {
  const page = await newPage();
  const tape = '+10+0 \n'.repeat(1000000) + '64\n';  // 7 MB, one W109 a line
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'essi-million-')), 'million.esi');
  fs.writeFileSync(file, tape);
  const cli = cliReportOf(file);
  // (the path layers hidden: this test is about the findings, not SwiftShader drawing a million segments)
  await page.evaluate(() => { for (const k of [0, 1, 2, 3]) essikit.setLayer(k, false); });
  await page.evaluate(() => {
    window.__frames = [];
    const tick = (t) => { window.__frames.push(t); if (!window.__stop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  const s = await dropFile(page, 'million.esi', Buffer.from(tape));
  const frameTimes = await page.evaluate(() => { window.__stop = true; return window.__frames; });
  const gaps = frameTimes.slice(1).map((t, i) => t - frameTimes[i]);
  const maxGap = Math.max(...gaps);
  console.log(`a million W109: ${frameTimes.length} frames while loading, the longest gap ${maxGap.toFixed(0)} ms`);
  assert.equal(s.load.at_once, false);
  // (drawn in slices: frames and steps while it loads; the longest gap is printed, not asserted, as it is the
  // host's speed as much as the viewer's: docs/performance.md measures it)
  assert.ok(frameTimes.length >= 5, `${frameTimes.length} frames while loading`);
  assert.ok(s.load.steps >= 5 && s.load.progress_frames >= 3, JSON.stringify(s.load));
  // 1 000 kept and the cap's summary of the 999 000 more: one row
  assert.equal(s.problems.total, cli.diagnostics.length);
  assert.equal(s.problems.total, 1001);
  assert.deepEqual(s.diagnostics, cli.diagnostics.slice(0, 100));
  await nextFrames(page, 3);
  const groups = (await page.evaluate(() => essikit.state())).problems.groups;
  assert.deepEqual(groups.map((g) => [g.code, g.findings, g.kept]), [['W109', 1000000, 1001]]);
  await page.close();
});

test('at 1024x600 the problems list is on the screen and the Compare window leaves the plate\'s top edge in sight', async () => {
  const page = await openPage(browser, baseUrl, { width: 1024, height: 600 });
  const { state } = await loadExample(page, 'plan_collision.esi');
  await nextFrames(page, 3);
  let s = await page.evaluate(() => essikit.state());
  // the left panel's Diagnostics section, its buttons above the list, inside the window
  const next = s.controls.next_problem;
  assert.ok(next && next[0] + next[2] <= s.view.area[0] && next[1] >= 38 && next[1] + next[3] <= 600 - 40, JSON.stringify(next));
  await page.screenshot({ path: path.join(shots, 'problems-1024x600.png') });
  // compare with itself: the window over the drawing no lower than the fitted view's margin (24 px)
  const text = fs.readFileSync(path.join(examplesDir, 'plan_collision.esi'), 'utf8');
  await page.evaluate((t) => essikit.compare('plan_collision_b.esi', t), text);
  await nextFrames(page, 4);
  s = await page.evaluate(() => essikit.state());
  const w = s.controls.compare_window;
  assert.ok(w, JSON.stringify(s.controls));
  const top = await page.evaluate(([x, y]) => essikit.project(x, y), [0, state.bbox_mm.max_y]);
  assert.ok(w[1] + w[3] <= top.y + 1, `the Compare window (${w}) covers the plate's top edge at y ${top.y}`);
  await page.screenshot({ path: path.join(shots, 'compare-1024x600.png') });
  await page.evaluate(() => essikit.endCompare());
  await page.close();
});

// A page with the reading worker (the default; ?worker=0 turns it off), its Worker replaced before its scripts run
// when `script` (an init script) says so.
function pageWithWorker(script = null, query = '') {
  return openPage(browser, `${baseUrl}${query}`, undefined, script);
}

test('a tape loaded in slices is read and checked in the reading worker: the same verdict, its blocks read again for the inspector; with ?worker=0, without a Worker, or when the worker fails, the page reads it', async () => {
  const tape = platesTape(25, 600);
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'essi-worker-')), 'plates.esi');
  fs.writeFileSync(file, tape);
  const cli = cliReportOf(file);
  const verdict = (s) => s.diagnostics.map((d) => [d.severity, d.code, d.line, d.column, d.message]);
  const want = cli.diagnostics.map((d) => [d.severity, d.code, d.line, d.column, d.message]);
  const lastLine = tape.split('\r\n').length - 1;  // (the last line: 64, the program's end)

  const page = await pageWithWorker();
  assert.equal(await page.evaluate(() => typeof Worker), 'function');
  const state = await dropFile(page, 'plates.esi', Buffer.from(tape));
  assert.equal(state.load.at_once, false);
  assert.equal(state.load.read_in, 'worker', JSON.stringify(state.load));
  assert.equal(state.load.worker_failure, '');
  assert.ok(state.load.progress_frames >= 2, `the page drew ${state.load.progress_frames} frames while the worker read`);
  assert.deepEqual(verdict(state), want);
  assert.equal(state.stats.motions, cli.stats.motions);
  assert.equal(state.stats.cut_length_mm, cli.stats.cut_length_mm);
  // The inspector reads the last line's blocks again from the reader the worker handed over before its chunk.
  await page.evaluate((line) => essikit.selectLine(line), lastLine);
  await page.waitForFunction((line) => essikit.state().selection.line === line, lastLine);
  const inspector = await page.evaluate(() => essikit.state().inspector);
  assert.ok(inspector.length > 0 && inspector.some((l) => l.includes('64')), JSON.stringify(inspector));
  await page.close();

  // With ?worker=0, and without a Worker in the page: the page reads the tape itself (and starts no worker).
  const plain = await pageWithWorker(null, '?worker=0');
  const here = await dropFile(plain, 'plates.esi', Buffer.from(tape));
  assert.deepEqual([here.load.read_in, here.load.worker_failure], ['page', '']);
  assert.deepEqual(verdict(here), want);
  assert.equal(await plain.evaluate(() => typeof Module.essikitReading), 'undefined');
  await plain.close();
  const none = await pageWithWorker('window.Worker = undefined;');
  const alone = await dropFile(none, 'plates.esi', Buffer.from(tape));
  assert.equal(alone.load.read_in, 'page');
  assert.equal(alone.load.worker_failure, '');
  assert.deepEqual(verdict(alone), want);
  await none.close();

  // A worker whose script cannot be loaded: the page reads the tape itself and says why.
  const broken = await pageWithWorker(
    'const W = window.Worker; window.Worker = class extends W { constructor(u, o) { super("no_such_reader.js", o); } };');
  const fallen = await dropFile(broken, 'plates.esi', Buffer.from(tape));
  assert.equal(fallen.load.read_in, 'page');
  assert.match(fallen.load.worker_failure, /^the reading worker failed: /);
  assert.deepEqual(verdict(fallen), want);
  await broken.close();
});
