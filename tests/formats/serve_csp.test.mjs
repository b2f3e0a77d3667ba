// The real viewer (build/wasm/web) served by `essi serve` runs under the server's Content-Security-Policy and
// COOP/COEP headers: no CSP violation, the WebAssembly module starts, the page is cross-origin isolated
// (SharedArrayBuffer available), a big tape is read in the reading worker built with threads (essi_reader_mt.js, its
// thread's worker essi_reader_mt.worker.js) under its scripts' own policy, twice in one worker, with the document
// the page reads itself, and a cross-origin page can neither frame it nor write a share.
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
    // A tape over 1 MB is read in the reading worker, whose script has a policy of its own. The page is
    // cross-origin isolated, so the worker (the one with threads) is started once the page's warm-up is done.
    await page.goto(url + '/');
    await page.waitForFunction(() => window.essikit && window.essikit.started, null, { timeout: 120000 });
    await page.waitForFunction(() => window.essikit.state().warm_up.state === 'done', null, { timeout: 60000 });
    assert.deepEqual(await page.evaluate(() => [Module.essikitReading.worker !== null, Module.essikitReading.job]), [true, 0]);
    const big = '+100+0\n'.repeat(180000) + '63\n';
    const bigState = await page.evaluate((t) => window.essikit.load('big.esi', t), big);
    assert.equal(bigState.status, 'ready');
    assert.equal(bigState.stats.motions, 180000);
    assert.deepEqual([bigState.load.read_in, bigState.load.worker_failure], ['worker', ''], JSON.stringify(bigState.load));
    assert.equal(await page.evaluate(() => Module.essikitReading.script), 'essi_reader_mt.js');
    // A second big tape in the same worker (its reading thread back in the pool), with arcs and findings: the
    // verdict of the page's own reading (?worker=0).
    const arcs = ('+1000+0\n+1000+1000+0+1000-\n-0-1000-1000+0-\n').repeat(50000) + '63\n';
    const second = await page.evaluate((t) => window.essikit.load('arcs.esi', t), arcs);
    assert.deepEqual([second.status, second.load.read_in, second.load.worker_failure], ['ready', 'worker', '']);
    const onPage = await browser.newPage();
    await onPage.goto(url + '/?worker=0');
    await onPage.waitForFunction(() => window.essikit && window.essikit.started, null, { timeout: 120000 });
    const here = await onPage.evaluate((t) => window.essikit.load('arcs.esi', t), arcs);
    assert.equal(here.load.read_in, 'page');
    assert.deepEqual([second.stats, second.diagnostics], [here.stats, here.diagnostics]);
    await onPage.close();
    for (const script of ['essi_reader.js', 'essi_reader_mt.js', 'essi_reader_mt.worker.js']) {
      const worker = await fetch(url + '/' + script);
      assert.equal(worker.status, 200, script);
      assert.match(worker.headers.get('content-security-policy'), /^default-src 'none'; script-src 'self' 'wasm-unsafe-eval'/, script);
      assert.equal(worker.headers.get('cross-origin-embedder-policy'), 'require-corp', script);
    }
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
