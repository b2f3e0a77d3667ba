// Browser tests of the viewer's keyboard and screen-reader access (docs/viewer.md, "Keyboard and screen readers"):
// axe-core finds no WCAG 2.1 A/AA violation on the page's DOM, on the start screen and with a tape; the text beside
// the canvas (its live region) names the tape and its verdict in the UI's language, as the accessibility tree shows
// it; the page's title is "<file> — <verdict> — essikit viewer"; Tab reaches the canvas with a visible focus ring
// and goes on through the panels' controls; the arrows and Enter choose in the problems list; keys pressed within
// one frame are all applied.
//
//   node --test tests/e2e/          (ctest: the `e2e` test of the native preset)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import {
  examplesDir, shots, startHarness, stopHarness, newPage as openPage,
} from './support.mjs';

function resolveAxe() {
  try {
    return createRequire(import.meta.url).resolve('axe-core/axe.min.js');
  } catch (e) {
    return null;
  }
}
const axePath = resolveAxe();
const kWcagTags = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'];

let server, baseUrl, browser;

before(async () => {
  assert.ok(axePath, 'axe-core is not installed in tests/e2e/node_modules (scripts/setup, or npm install there)');
  ({ server, baseUrl, browser } = await startHarness());
});

after(() => stopHarness({ server, browser }));

function newPage() {
  return openPage(browser, baseUrl);
}

async function loadExample(page, file) {
  const text = fs.readFileSync(path.join(examplesDir, file), 'utf8');
  const state = await page.evaluate(([n, t]) => essikit.load(n, t), [file, text]);
  await page.mouse.move(700, 450);
  return state;
}

// Waits until fn(arg) holds in the page, then asserts it.
async function until(page, fn, arg, what) {
  await page.waitForFunction(fn, arg, { timeout: 15000 }).catch(() => {});
  assert.ok(await page.evaluate(fn, arg), what);
}

function frames(page, n) {
  return page.evaluate((k) => new Promise((r) => {
    const next = () => (k-- > 0 ? requestAnimationFrame(next) : r());
    next();
  }), n);
}
const twoFrames = (page) => frames(page, 2);
// After a Tab: down in one frame, up in the next, a window entered in the one after (its first control found
// while it is drawn) and the focus there in the state of the next.
const afterTab = (page) => frames(page, 4);

// The verdict as the toolbar says it in English.
function verdictOf(state) {
  const count = (s) => state.diagnostics.filter((d) => d.severity === s).length;
  const [e, w] = [count('error'), count('warning')];
  const plural = (n, one) => `${n} ${one}${n === 1 ? '' : 's'}`;
  if (e === 0 && w === 0) return 'ok';
  if (e === 0) return `ok, ${plural(w, 'warning')}`;
  return `${plural(e, 'error')}, ${plural(w, 'warning')}`;
}

async function axeViolations(page) {
  if (!(await page.evaluate(() => typeof window.axe !== 'undefined'))) await page.addScriptTag({ path: axePath });
  const result = await page.evaluate((tags) => axe.run(document, { runOnly: { type: 'tag', values: tags } }), kWcagTags);
  return result.violations.map((v) => `${v.id}: ${v.help} (${v.nodes.map((n) => n.target.join(' ')).join('; ')})`);
}

// The keys' events of a key tapped, dispatched as the browser does (GLFW reads keyCode).
const kKeyCodes = { Home: 36, End: 35, ArrowRight: 39, ArrowLeft: 37, ArrowDown: 40, ArrowUp: 38, Enter: 13, Tab: 9 };

test('axe-core: no WCAG 2.1 A/AA violations on the start screen and with a tape loaded', async () => {
  const page = await newPage();
  assert.deepEqual(await axeViolations(page), [], 'start screen');
  await loadExample(page, 'bad_eia_order.eia');
  await until(page, () => document.querySelectorAll('#mirror-list li').length === 5, null, 'the problems list');
  assert.deepEqual(await axeViolations(page), [], 'a tape loaded');
  await page.close();
});

test('the live region names the file and the verdict, in English and German; the page title too', async () => {
  const page = await newPage();
  let snap = await page.locator('body').ariaSnapshot();
  assert.match(snap, /status: "?essikit viewer: ESSI cutting tapes/, snap);
  assert.equal(await page.title(), 'essikit viewer');

  const state = await loadExample(page, 'bad_eia_order.eia');
  const verdict = verdictOf(state);
  assert.equal(verdict, '5 errors, 0 warnings');
  await until(page, (t) => document.title === t, `bad_eia_order.eia — ${verdict} — essikit viewer`,
              'the title does not name the tape and its verdict');
  snap = await page.locator('body').ariaSnapshot();
  assert.ok(snap.includes(`status: "bad_eia_order.eia: ${verdict}."`) || snap.includes(`status: bad_eia_order.eia: ${verdict}.`), snap);
  assert.match(snap, /heading "Diagnostics" \[level=2\]/, snap);
  // The list a screen reader walks: the problems in the Diagnostics list's words, with their messages.
  const items = await page.locator('#mirror-list li').allTextContents();
  assert.equal(items.length, state.diagnostics.length);
  state.diagnostics.forEach((d, i) => assert.equal(items[i], `${d.code} line ${d.line}:${d.column}: ${d.message}`));
  assert.equal(await page.locator('#canvas').getAttribute('role'), 'application');
  assert.match(await page.locator('#canvas').getAttribute('aria-label'), /^The tape's drawing and the viewer's panels/);

  // A selected line: its problem joins the live region.
  await page.evaluate((n) => essikit.selectLine(n), state.diagnostics[1].line);
  await until(page, (s) => document.getElementById('mirror-status').textContent.includes(s),
              `Selected: ${state.diagnostics[1].code} line ${state.diagnostics[1].line}:`, 'the selection is not said');

  // German: the same texts in the UI's language.
  await page.evaluate(() => essikit.setLanguage('de'));
  await until(page, () => document.title === 'bad_eia_order.eia — 5 Fehler, 0 Warnungen — essikit-Viewer', null,
              'the German title');
  snap = await page.locator('body').ariaSnapshot();
  assert.ok(snap.includes('bad_eia_order.eia: 5 Fehler, 0 Warnungen. Ausgewählt:'), snap);
  assert.match(snap, /heading "Meldungen" \[level=2\]/, snap);
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'de');
  await page.evaluate(() => essikit.setLanguage('zh'));
  await until(page, () => document.title.startsWith('bad_eia_order.eia — 5 个错误，0 个警告'), null, 'the Chinese title');
  await page.close();
});

test('Tab reaches the canvas with a visible focus ring, then the panels; arrows and Enter choose a problem', async () => {
  const page = await newPage();
  const state = await loadExample(page, 'bad_eia_order.eia');
  // From the page, Tab focuses the canvas, with its focus ring.
  await page.keyboard.press('Tab');
  assert.equal(await page.evaluate(() => document.activeElement && document.activeElement.id), 'canvas');
  const ring = await page.evaluate(() => {
    const c = document.getElementById('canvas');
    const s = getComputedStyle(c);
    return { visible: c.matches(':focus-visible'), style: s.outlineStyle, width: parseFloat(s.outlineWidth) };
  });
  assert.deepEqual(ring, { visible: true, style: 'solid', width: 3 });
  await page.screenshot({ path: path.join(shots, 'a11y-focus-canvas.png') });
  // Tab goes on inside the viewer: the toolbar's first control, with ImGui's highlight.
  await page.keyboard.press('Tab');
  await until(page, () => essikit.state().keyboard.mode === 'panels' && essikit.state().keyboard.window === '##toolbar',
              null, 'Tab did not reach the toolbar');
  // On through the controls to the Diagnostics list (one stop: Enter goes into it).
  let k = 0;
  for (; k < 120; ++k) {
    const kb = (await page.evaluate(() => essikit.state())).keyboard;
    if (kb.list.includes('diaglist')) break;
    await page.keyboard.press('Tab');
    await afterTab(page);
  }
  assert.ok(k < 120, 'Tab never reached the Diagnostics list');
  await page.screenshot({ path: path.join(shots, 'a11y-focus-list.png') });
  await page.keyboard.press('Enter');
  await until(page, () => essikit.state().keyboard.window.includes('diaglist'), null, 'Enter did not go into the list');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('Enter');
  await until(page, (l) => (essikit.state().selection || {}).line === l, state.diagnostics[2].line,
              'Down, Down, Enter did not select the third problem');
  await page.screenshot({ path: path.join(shots, 'a11y-list-chosen.png') });
  // The playback's keys wait while the focus is on a control; Esc backs out of the list.
  await page.keyboard.press('Escape');
  await until(page, () => !essikit.state().keyboard.window.includes('diaglist'), null, 'Esc did not leave the list');
  assert.equal((await page.evaluate(() => essikit.state())).selection?.line, state.diagnostics[2].line);
  // Past the last window's last control: the drawing, with a ring around it; the shortcuts act on it again (Esc
  // clears the selection).
  for (k = 0; k < 400 && (await page.evaluate(() => essikit.state().keyboard.mode)) !== 'drawing'; ++k) {
    await page.keyboard.press('Tab');
    await afterTab(page);  // (a Tab is down in one frame and up in the next: none queued past the drawing)
  }
  assert.equal((await page.evaluate(() => essikit.state())).keyboard.mode, 'drawing');
  await page.screenshot({ path: path.join(shots, 'a11y-focus-drawing.png') });
  await page.keyboard.press('Escape');
  await until(page, () => essikit.state().selection === null, null, 'Esc on the drawing did not clear the selection');
  // No keyboard trap (WCAG 2.1.2): Tab from the last stop leaves the canvas; Tab from the page comes back in.
  assert.equal(await page.evaluate(() => document.activeElement.id), 'canvas');
  await page.keyboard.press('Tab');
  await until(page, () => document.activeElement !== document.getElementById('canvas'), null,
              'Tab from the drawing did not leave the canvas');
  await page.keyboard.press('Tab');
  await until(page, () => document.activeElement === document.getElementById('canvas'), null,
              'Tab from the page did not come back to the canvas');
  // A mouse press ends the keyboard's focus.
  await page.mouse.click(700, 450);
  await until(page, () => essikit.state().keyboard.mode === 'mouse', null, 'a click did not end the keyboard focus');
  await page.close();
});

test('keys pressed within one frame are all applied', async () => {
  const page = await newPage();
  await loadExample(page, 'plate_holes.esi');
  // Home and three Rights, down and up, in one task: one frame sees them all.
  await page.evaluate((codes) => {
    const send = (type, key) => {
      const e = new KeyboardEvent(type, { key, bubbles: true, cancelable: true });
      Object.defineProperty(e, 'keyCode', { get: () => codes[key] });
      window.dispatchEvent(e);
    };
    for (const key of ['Home', 'ArrowRight', 'ArrowRight', 'ArrowRight']) {
      send('keydown', key);
      send('keyup', key);
    }
  }, kKeyCodes);
  await until(page, () => essikit.state().playback.active && essikit.state().playback.position === 3, null,
              'Home and three Rights in one frame did not move the scrubber to motion 3');
  await page.waitForTimeout(200);
  assert.equal((await page.evaluate(() => essikit.state())).playback.position, 3, 'a key was applied twice');
  await page.close();
});

// Tabs until `done(state.keyboard)` holds (at most `max` Tabs), a Tab at a time.
async function tabUntil(page, done, max = 150) {
  for (let k = 0; k < max; ++k) {
    if (await page.evaluate(done)) return;
    await page.keyboard.press('Tab');
    await afterTab(page);
  }
  assert.ok(await page.evaluate(done), `${max} Tabs did not get there`);
}

test('the source lines and the toolbar\'s lists: Enter, arrows, Enter', async () => {
  const page = await newPage();
  await loadExample(page, 'bad_eia_order.eia');
  await page.keyboard.press('Tab');  // (the canvas)
  // The source lines: Enter goes into the list on line 1, Down twice, Enter selects line 3.
  await tabUntil(page, () => essikit.state().keyboard.list.includes('/source_'));
  await page.keyboard.press('Enter');
  await until(page, () => essikit.state().keyboard.window.includes('/source_'), null, 'Enter did not go into the source');
  for (const key of ['ArrowDown', 'ArrowDown', 'Enter']) await page.keyboard.press(key);
  await until(page, () => (essikit.state().selection || {}).line === 3, null, 'Down, Down, Enter did not select line 3');
  // The language list, the toolbar's last control: Enter opens it, Down, Enter chooses Deutsch.
  await page.keyboard.press('Escape');
  // The keyboard's way ends with a click, in the viewer's next frame; a Tab after that starts again at the toolbar.
  // (A Tab in the click's own frame would move the focus before the click ends it: no person presses that fast.)
  await page.mouse.click(700, 450);
  await until(page, () => essikit.state().keyboard.mode === 'mouse', null, 'a click did not end the keyboard focus');
  await page.keyboard.press('Tab');
  await until(page, () => essikit.state().keyboard.window === '##toolbar', null, 'Tab did not reach the toolbar');
  for (let i = 0; i < 12; ++i) {
    await page.keyboard.press('Tab');
    await afterTab(page);
  }
  await page.keyboard.press('Enter');
  await until(page, () => essikit.state().keyboard.window.startsWith('##Combo'), null, 'Enter did not open the list');
  await frames(page, 3);  // (the list's first choice is focused once it is drawn)
  await page.keyboard.press('ArrowDown');
  await frames(page, 3);
  await page.keyboard.press('Enter');
  await until(page, () => essikit.state().lang === 'de', null, 'Enter, Down, Enter on the language list did not choose German');
  await page.close();
});
