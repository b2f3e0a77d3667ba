// Browser tests of the viewer (issue 3): headless Debian Chromium driven by playwright-core, run by node:test.
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
import http from 'node:http';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '..', '..');
const webRoot = process.env.ESSI_WEB_ROOT || path.join(root, 'build', 'wasm', 'web');
const essiBin = process.env.ESSI_BIN || path.join(root, 'build', 'native', 'bin', 'essi');
const chromiumPath = process.env.ESSI_CHROMIUM || '/usr/bin/chromium';
const examplesDir = path.join(root, 'examples');
const shots = path.join(root, 'build', 'e2e');
const CUT_RGB = [255, 140, 26];  // kKindColors[cut] in web/render/Renderer.hpp

const chromiumArgs = [
  '--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--disable-gpu-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run',
];

let server, baseUrl, browser;

function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once('error', reject);
    s.listen(0, '127.0.0.1', () => { const p = s.address().port; s.close(() => resolve(p)); });
  });
}

// A static server for the built page and the examples (no caching, correct wasm type).
function startStaticServer(port) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
                  '.esi': 'text/plain', '.json': 'application/json' };
  const srv = http.createServer((req, res) => {
    const urlPath = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    const [base, rel] = urlPath.startsWith('/examples/') ? [examplesDir, urlPath.slice('/examples/'.length)]
                                                        : [webRoot, urlPath.slice(1) || 'index.html'];
    const file = path.resolve(base, rel);
    if (!file.startsWith(base)) { res.writeHead(403); return res.end(); }
    fs.readFile(file, (err, data) => {
      if (err) { res.writeHead(404); return res.end(); }
      res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream',
                           'cache-control': 'no-cache' });
      res.end(data);
    });
  });
  return new Promise((resolve) => srv.listen(port, '127.0.0.1', () => resolve(srv)));
}

function examples() {
  return fs.readdirSync(examplesDir).filter((f) => f.endsWith('.esi')).sort();
}

// The CLI's verdict for one tape: {stats, diagnostics}. Falls back to the example's .expected.json golden
// when the CLI is not built.
function cliReport(file) {
  const full = path.join(examplesDir, file);
  if (fs.existsSync(essiBin)) {
    let out;
    try {
      out = execFileSync(essiBin, ['check', '--format', 'json', full], { encoding: 'utf8' });
    } catch (e) {
      out = e.stdout;  // exit 1 when the tape has errors
    }
    const report = JSON.parse(out);
    return { source: 'essi check', ...report.files[0] };
  }
  const golden = path.join(examplesDir, file.replace(/\.esi$/, '.expected.json'));
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

async function newPage() {
  const page = await browser.newPage({ viewport: { width: 1600, height: 900 } });
  page.on('pageerror', (e) => console.log(`pageerror: ${e.message}`));
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  await page.evaluate(() => essikit.ready);
  return page;
}

// Drops a file on the canvas the way a person does (dragenter, dragover, drop with a DataTransfer).
async function dropFile(page, name, bytes) {
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
  await page.waitForFunction((n) => { const s = essikit.state(); return s.name === n && s.status === 'ready'; }, name,
                             { timeout: 60000 });
  return page.evaluate(() => essikit.state());
}

// Pixels of a PNG screenshot, decoded by the browser: returns a function (x, y) -> [r, g, b].
async function pixels(page, png) {
  const data = await page.evaluate(async (b64) => {
    const blob = await (await fetch('data:image/png;base64,' + b64)).blob();
    const bmp = await createImageBitmap(blob);
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const g = c.getContext('2d');
    g.drawImage(bmp, 0, 0);
    return { w: bmp.width, h: bmp.height, px: Array.from(g.getImageData(0, 0, bmp.width, bmp.height).data) };
  }, png.toString('base64'));
  return (x, y) => {
    const i = (Math.round(y) * data.w + Math.round(x)) * 4;
    return [data.px[i], data.px[i + 1], data.px[i + 2]];
  };
}

function near(rgb, want, tol = 45) {
  return Math.hypot(rgb[0] - want[0], rgb[1] - want[1], rgb[2] - want[2]) <= tol;
}

before(async () => {
  assert.ok(fs.existsSync(path.join(webRoot, 'essi_viewer.wasm')),
            `the viewer is not built in ${webRoot} (cmake --build --preset wasm --target essi_viewer)`);
  assert.ok(fs.existsSync(chromiumPath), `no Chromium at ${chromiumPath} (apt-get install chromium)`);
  fs.mkdirSync(shots, { recursive: true });
  server = await startStaticServer(await freePort());
  baseUrl = `http://127.0.0.1:${server.address().port}/`;
  browser = await chromium.launch({ executablePath: chromiumPath, args: chromiumArgs });
});

after(async () => {
  if (browser) await browser.close();
  if (server) server.close();
});

test('every example tape dropped on the page has the statistics and diagnostics of essi check', async () => {
  const page = await newPage();
  for (const file of examples()) {
    const state = await dropFile(page, file, fs.readFileSync(path.join(examplesDir, file)));
    const cli = cliReport(file);
    assertStatsEqual(state.stats, cli.stats, `${file} (vs ${cli.source})`);
    assert.deepEqual(state.diagnostics.map((d) => [d.severity, d.code, d.line, d.column]),
                     cli.diagnostics.map((d) => [d.severity, d.code, d.line, d.column]), `${file}: diagnostics`);
    await page.screenshot({ path: path.join(shots, file.replace(/\.esi$/, '.png')) });
  }
  await page.close();
});

test('a bad tape shows its diagnostics with their lines', async () => {
  const page = await newPage();
  const bad = examples().filter((f) => f.startsWith('bad_'));
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
    await page.screenshot({ path: path.join(shots, `diagnostics-${file.replace(/\.esi$/, '')}.png`) });
  }
  // Not a tape at all: a clear message, never a blank page.
  const png = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13, 0x49, 0x48, 0x44, 0x52, 0, 1, 2, 3]);
  let state = await dropFile(page, 'picture.png', png);
  assert.match(state.banner, /binary/);
  state = await dropFile(page, 'empty.esi', Buffer.alloc(0));
  assert.match(state.banner, /empty/);
  assert.ok(state.diagnostics.some((d) => d.code === 'E113'));
  state = await dropFile(page, 'notes.txt', Buffer.from('Hello, this is a letter, not a tape.\nRegards\n'));
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
  const proc = spawn(essiBin, ['serve', '--host', '127.0.0.1', '--port', String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
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
    const list = await (await fetch(new URL('examples/index.json', address))).json();
    assert.ok(list.includes('plate_holes.esi'));
    const page = await browser.newPage();
    await page.goto(address);
    await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
    await page.evaluate(() => essikit.ready);
    await page.close();
  } finally {
    proc.kill();
  }
});
