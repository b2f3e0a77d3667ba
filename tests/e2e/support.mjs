// Shared by the browser tests (viewer.test.mjs) and the browser benchmark (bench.mjs): paths, a static server
// for the built page, the examples and generated tapes, Chromium with SwiftShader, and page helpers.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const root = path.resolve(here, '..', '..');
export const webRoot = process.env.ESSI_WEB_ROOT || path.join(root, 'build', 'wasm', 'web');
export const essiBin = process.env.ESSI_BIN || path.join(root, 'build', 'native', 'bin', 'essi');
export const genBin = process.env.ESSI_GEN_NEST || path.join(path.dirname(essiBin), 'essi_gen_nest');
export const chromiumPath = process.env.ESSI_CHROMIUM || '/usr/bin/chromium';
export const examplesDir = path.join(root, 'examples');
export const shots = path.join(root, 'build', 'e2e');
export const genDir = path.join(shots, 'tapes');  // generated tapes, served at /gen/
export const CUT_RGB = [255, 140, 26];  // kKindColors[cut] in web/render/Renderer.hpp

export const chromiumArgs = [
  '--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--disable-gpu-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run',
  '--enable-precise-memory-info',
];

export function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once('error', reject);
    s.listen(0, '127.0.0.1', () => { const p = s.address().port; s.close(() => resolve(p)); });
  });
}

// A static server: the built page at /, examples/ at /examples/, generated tapes at /gen/. `isolated`: every answer
// with COOP/COEP, as essi serve's (the page is cross-origin isolated: its reading worker has threads).
export function startStaticServer(port, { isolated = false } = {}) {
  const isolation = isolated ? { 'cross-origin-opener-policy': 'same-origin', 'cross-origin-embedder-policy': 'require-corp' } : {};
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
                  '.esi': 'text/plain', '.json': 'application/json' };
  const srv = http.createServer((req, res) => {
    const urlPath = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    let base = webRoot, rel = urlPath.slice(1) || 'index.html';
    if (urlPath.startsWith('/examples/')) [base, rel] = [examplesDir, urlPath.slice('/examples/'.length)];
    else if (urlPath.startsWith('/gen/')) [base, rel] = [genDir, urlPath.slice('/gen/'.length)];
    const file = path.resolve(base, rel);
    if (!file.startsWith(base)) { res.writeHead(403); return res.end(); }
    fs.stat(file, (err, st) => {
      if (err || !st.isFile()) { res.writeHead(404); return res.end(); }
      res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream',
                           'content-length': st.size, 'cache-control': 'no-cache', ...isolation });
      fs.createReadStream(file).pipe(res);
    });
  });
  return new Promise((resolve) => srv.listen(port, '127.0.0.1', () => resolve(srv)));
}

// The browser tests' start: the built viewer and Chromium checked, the static server and Chromium started;
// stopHarness ends them.
export async function startHarness() {
  assert.ok(fs.existsSync(path.join(webRoot, 'essi_viewer.wasm')),
            `the viewer is not built in ${webRoot} (cmake --build --preset wasm --target essi_viewer)`);
  assert.ok(fs.existsSync(chromiumPath), `no Chromium at ${chromiumPath} (apt-get install chromium)`);
  fs.mkdirSync(shots, { recursive: true });
  const server = await startStaticServer(await freePort());
  return { server, baseUrl: `http://127.0.0.1:${server.address().port}/`, browser: await launch() };
}

export async function stopHarness({ server, browser }) {
  if (browser) await browser.close();
  if (server) server.close();
}

export function launch() {
  return chromium.launch({ executablePath: chromiumPath, args: chromiumArgs });
}

// `init`: a script run before the page's own (Playwright's addInitScript), if any.
export async function newPage(browser, baseUrl, viewport = { width: 1600, height: 900 }, init = null) {
  const page = await browser.newPage({ viewport });
  page.on('pageerror', (e) => console.log(`pageerror: ${e.message}`));
  if (init) await page.addInitScript(init);
  await page.goto(baseUrl);
  await page.waitForFunction(() => window.essikit && essikit.started, null, { timeout: 30000 });
  await page.evaluate(() => essikit.ready);
  return page;
}

// A generated nesting tape of about `mb` MB (tests/bench/nest_generator.hpp through essi_gen_nest), cached in
// build/e2e/tapes/. Returns the file name (served at /gen/NAME).
export function generatedTape(mb) {
  fs.mkdirSync(genDir, { recursive: true });
  const name = `nest_${String(mb).replace('.', '_')}mb.esi`;
  const file = path.join(genDir, name);
  if (!fs.existsSync(file)) execFileSync(genBin, [String(mb), file], { stdio: 'ignore' });
  return name;
}

// Drops a tape that the page fetches from `url` (a real DataTransfer with a File: the drop path of a person),
// without waiting for the load to end.
export async function dropFromUrl(page, url, name) {
  await page.evaluate(async ([u, n]) => {
    const data = new Uint8Array(await (await fetch(u)).arrayBuffer());
    const dt = new DataTransfer();
    dt.items.add(new File([data], n, { type: 'text/plain' }));
    const canvas = document.getElementById('canvas');
    window.__dropT0 = performance.now();
    for (const type of ['dragenter', 'dragover', 'drop'])
      canvas.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [url, name]);
}

// The CLI's JSON report for one file (exit 1 means "has errors", still a report).
export function cliReport(file) {
  let out;
  try {
    out = execFileSync(essiBin, ['check', '--format', 'json', file], { encoding: 'utf8', maxBuffer: 1 << 28 });
  } catch (e) {
    out = e.stdout;
  }
  return JSON.parse(out).files[0];
}
