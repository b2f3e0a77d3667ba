// The real viewer (build/wasm/web) served by `essi serve` runs under the server's Content-Security-Policy and
// COOP/COEP headers: no CSP violation, the WebAssembly module starts, the page is cross-origin isolated
// (SharedArrayBuffer available), a big tape is read in the reading worker under its script's own policy, and a
// cross-origin page can neither frame it nor write a share.
// Needs the wasm build's viewer; skipped without it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import { chromiumPath, chromiumArgs as args, haveViewer, startServer, tempDir } from './support.mjs';

test('the viewer runs under the CSP and is cross-origin isolated', { skip: !haveViewer && 'viewer not built (build/wasm/web)', timeout: 240000 }, async () => {
  const { proc, url } = await startServer(tempDir('csp'));
  const browser = await chromium.launch({ executablePath: chromiumPath, args });
  try {
    const page = await browser.newPage();
    const violations = [];
    page.on('console', (m) => { if (/Content.Security.Policy|Refused to/i.test(m.text())) violations.push(m.text()); });
    await page.addInitScript(() => {
      document.addEventListener('securitypolicyviolation', (e) => console.error('Refused to: CSP ' + e.violatedDirective + ' ' + e.blockedURI));
    });
    const res = await page.goto(url + '/');
    assert.match(res.headers()['content-security-policy'], /'wasm-unsafe-eval'/);
    await page.waitForFunction(() => window.essikit && window.essikit.started, null, { timeout: 120000 });
    const state = await page.evaluate(() => window.essikit.load('t.esi', '+100+0\n63\n'));
    assert.equal(state.status, 'ready');
    assert.deepEqual(await page.evaluate(() => [window.crossOriginIsolated, typeof SharedArrayBuffer]), [true, 'function']);
    assert.equal((await page.evaluate(() => window.essikit.shareStore.ready)).ok, true);
    // With ?worker=1, a tape over 1 MB is read in the reading worker, whose script has a policy of its own.
    await page.goto(url + '/?worker=1');
    await page.waitForFunction(() => window.essikit && window.essikit.started, null, { timeout: 120000 });
    const big = '+100+0\n'.repeat(180000) + '63\n';
    const bigState = await page.evaluate((t) => window.essikit.load('big.esi', t), big);
    assert.equal(bigState.status, 'ready');
    assert.equal(bigState.stats.motions, 180000);
    assert.deepEqual([bigState.load.read_in, bigState.load.worker_failure], ['worker', ''], JSON.stringify(bigState.load));
    const worker = await fetch(url + '/essi_reader.js');
    assert.match(worker.headers.get('content-security-policy'), /^default-src 'none'; script-src 'self' 'wasm-unsafe-eval'/);
    assert.deepEqual(violations, []);
    // Another origin (http://localhost:PORT is another origin than http://127.0.0.1:PORT to the browser, though
    // the same server): its page cannot write a share.
    const other = await browser.newPage();
    await other.goto(url.replace('127.0.0.1', 'localhost') + '/api/health');
    const status = await other.evaluate(async (target) => {
      try {
        const r = await fetch(target + '/api/share', { method: 'POST', mode: 'no-cors', body: 'x', headers: { 'Content-Type': 'text/plain' } });
        return r.type;
      } catch (e) { return 'blocked'; }
    }, url);
    assert.ok(status === 'opaque' || status === 'blocked');
    const stored = await (await fetch(`${url}/api/share/${'2d711642b726b04401627ca9fbac32f5c8530fb1903cc4db02258717921a4881'}`)).status;
    assert.equal(stored, 404);  // sha256("x"): not stored
  } finally {
    await browser.close();
    proc.kill();
  }
});
