// The viewer served by `essi serve` shares a tape too big for a link through /api/share (web/share_store.js) and
// opens the /#share=ID link again. Needs the wasm build's viewer (build/wasm/web); skipped without it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import crypto from 'node:crypto';
import { chromium } from 'playwright-core';
import { chromiumPath, chromiumArgs as args, haveViewer, startServer, tempDir } from './support.mjs';

// A valid tape of about `bytes` bytes: many small square parts.
function bigTape(bytes) {
  const part = '+2000+0\n7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n';
  let s = '%\n39+3000\n';
  while (s.length < bytes) s += part;
  return s + '63\n';
}

test('share button: a big tape goes to /api/share and the /#share=ID link opens it', { skip: !haveViewer && 'viewer not built (build/wasm/web)', timeout: 240000 }, async () => {
  const data = tempDir('share');
  const { proc, url } = await startServer(data);
  const browser = await chromium.launch({ executablePath: chromiumPath, args });
  try {
    const page = await browser.newPage();
    await page.goto(url + '/');
    await page.waitForFunction(() => window.essikit && window.essikit.started, null, { timeout: 120000 });
    const server = await page.evaluate(() => window.essikit.shareStore.ready);
    assert.equal(server.ok, true);
    const tape = bigTape(1.5e6);
    const state = await page.evaluate((t) => window.essikit.load('big.esi', t), tape);
    assert.equal(state.status, 'ready');
    assert.equal(state.bytes, tape.length);
    const link = await page.evaluate(() => window.essikit.shareLink());
    const id = crypto.createHash('sha256').update(tape).digest('hex');
    assert.match(link, new RegExp(`^${url}/#share=${id}&c=[^&]+&l=\\d+&p=auto&i=essi&n=big\\.esi$`));
    // The server has the tape byte for byte.
    const stored = await (await fetch(`${url}/api/share/${id}`)).text();
    assert.equal(stored, tape);
    // A small tape still gets an ordinary link (the tape in the URL).
    await page.evaluate(() => window.essikit.load('small.esi', '+100+0\n63\n'));
    const small = await page.evaluate(() => window.essikit.shareLink());
    assert.match(small, /#c=.*&t=/);
    // The link opens the tape in a fresh page (the same tab: a background tab's frames are throttled).
    await page.goto('about:blank');
    const page2 = page;
    await page2.goto(link);
    await page2.waitForFunction(() => window.essikit && window.essikit.started, null, { timeout: 120000 });
    await page2.waitForFunction(() => { const s = window.essikit.state(); return s.status === 'ready' && s.name === 'big.esi'; }, null, { timeout: 120000 });
    const s2 = await page2.evaluate(() => window.essikit.state());
    assert.equal(s2.bytes, tape.length);
  } finally {
    await browser.close();
    proc.kill();
  }
});
