// `essi render`: the SVG parsed as XML (xml2js) and checked element by element against the check report, and
// one SVG drawn by headless Chromium (playwright-core, /usr/bin/chromium) whose pixels must show the cut colour.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { parseStringPromise } from 'xml2js';
import { chromium } from 'playwright-core';
import { essi, chromiumPath, tempDir, write } from './support.mjs';

const CUT = '#d62728', TRAVEL = '#7f7f7f', PIERCE = '#ff7f0e', ERROR = '#e000e0';

async function render(tape, extra = []) {
  const out = path.join(tempDir('svg'), path.basename(tape, '.esi') + '.svg');
  const r = essi(['render', tape, '-o', out, ...extra]);
  const json = JSON.parse(essi(['check', '--format', 'json', tape]).stdout).files[0];
  assert.equal(r.status, json.ok ? 0 : 1, r.stderr);
  const text = fs.readFileSync(out, 'utf8');
  return { text, svg: (await parseStringPromise(text)).svg, json, out };
}

// A page with window.imagePixels(src): the image's RGBA pixels as a canvas draws them, and its size.
async function pixelPage(browser) {
  const page = await browser.newPage();
  await page.evaluate(() => {
    window.imagePixels = async (src) => {
      const img = new Image();
      img.src = src;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.naturalWidth;
      c.height = img.naturalHeight;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      return { px: g.getImageData(0, 0, c.width, c.height).data, w: c.width, h: c.height };
    };
  });
  return page;
}

const all = (node, name) => {  // every element `name` below node
  const found = [];
  (function walk(n) {
    if (!n || typeof n !== 'object') return;
    for (const [k, v] of Object.entries(n)) {
      if (k === '$' || k === '_') continue;
      for (const child of [].concat(v)) {
        if (k === name) found.push(child);
        walk(child);
      }
    }
  })(node);
  return found;
};

test('SVG of a good tape: layers in their colours, pierces, y up, legend numbers', async () => {
  const { svg, json } = await render('examples/absolute_offset.esi');
  const paths = all(svg, 'path').filter((p) => p.$.id);
  const cut = paths.find((p) => p.$.id === 'cut');
  assert.equal(cut.$.stroke, CUT);
  assert.match(cut.$.d, /^M[-\d.]+ [-\d.]+(L[-\d.]+ [-\d.]+)+/);
  assert.equal(paths.find((p) => p.$.id === 'travel')?.$.stroke, TRAVEL);
  const pierces = all(svg, 'circle').filter((c) => c.$.class === 'pierce');
  assert.equal(pierces.length, json.stats.pierces);
  // viewBox: the extent with a margin, y flipped (machine y up = SVG y down negated).
  const [vx, vy, vw, vh] = svg.$.viewBox.split(' ').map(Number);
  const b = json.stats.cut_bbox_mm;
  assert.ok(vx < b.min_x && vx + vw > b.max_x, 'x range');
  assert.ok(vy < -b.max_y && vy + vh > -b.min_y, 'y range (flipped)');
  // Every cut point is inside the cut bbox (with y negated).
  for (const [, x, y] of cut.$.d.matchAll(/[ML]([-\d.]+) ([-\d.]+)/g)) {
    assert.ok(+x >= b.min_x - 1e-3 && +x <= b.max_x + 1e-3 && -y >= b.min_y - 1e-3 && -y <= b.max_y + 1e-3, `${x},${y}`);
  }
  // Legend: the file name and the numbers of the check report.
  const texts = all(svg, 'text');
  assert.equal(texts.find((t) => t.$?.id === 'legend-file')._, 'absolute_offset.esi');
  const numbers = texts.find((t) => t.$?.id === 'legend-numbers');
  assert.equal(Number(numbers.$['data-cut-length-mm']), Number(json.stats.cut_length_mm.toFixed(3)));
  assert.equal(Number(numbers.$['data-pierces']), json.stats.pierces);
  assert.equal(Number(numbers.$['data-time-s']), Number(json.stats.estimated_time_s.toFixed(1)));
  assert.match(numbers._, new RegExp(`^cut ${json.stats.cut_length_mm.toFixed(3)} mm, ${json.stats.pierces} pierces, time \\d+:\\d\\d:\\d\\d, 0 errors, 0 warnings$`));
  const keys = all(svg, 'g').filter((g) => g.$?.class === 'key').map((g) => g.$['data-kind']);
  assert.deepEqual(keys, ['cut', 'mark', 'travel', 'rapid', 'pierce', 'error', 'warning', 'note']);
});

test('SVG of a bad tape: each error marked where its block ends (its motion\'s end point)', async () => {
  const { svg, json } = await render('examples/bad_arc_off_circle.esi');
  const marks = all(svg, 'g').filter((g) => /diagnostic error/.test(g.$?.class || ''));
  const errors = json.diagnostics.filter((d) => d.severity === 'error');
  assert.equal(marks.length, errors.length);
  assert.equal(marks[0].$['data-code'], 'E301');
  assert.equal(Number(marks[0].$['data-line']), errors[0].line);
  assert.equal(marks[0].$.stroke, ERROR);
  // The arc of line 12 runs from (150, 50) to its end point off the circle, (200, 100) mm in this tape.
  assert.deepEqual([Number(marks[0].$['data-x']), Number(marks[0].$['data-y'])], [200, 100]);
  const circle = marks[0].circle[0].$;
  assert.deepEqual([Number(circle.cx), Number(circle.cy)], [200, -100]);
  // A constant size in the SVG's pixels: the radius in user units times the pixels a unit.
  const [, , vw] = svg.$.viewBox.split(' ').map(Number);
  assert.ok(Math.abs(Number(circle.r) * Number(svg.$.width) / vw - Number(marks[0].$['data-r-px'])) < 0.01);
  assert.match(marks[0].title[0], /bad_arc_off_circle\.esi:12:1: error E301/);
  const numbers = all(svg, 'text').find((t) => t.$?.id === 'legend-numbers');
  assert.equal(numbers.$['data-errors'], '1');
});

test('essi render --png writes a PNG (rsvg-convert)', { skip: !fs.existsSync('/usr/bin/rsvg-convert') && 'rsvg-convert not installed' }, () => {
  const out = path.join(tempDir('png'), 'a.png');
  const r = essi(['render', 'examples/absolute_offset.esi', '--png', '-o', out]);
  assert.equal(r.status, 0, r.stderr);
  const head = fs.readFileSync(out).subarray(0, 8);
  assert.deepEqual([...head], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
});

test('Chromium draws the SVG: pixels of the cut colour and the pierce colour appear', async () => {
  const { text } = await render('examples/absolute_offset.esi', ['--width', '800']);
  const browser = await chromium.launch({ executablePath: chromiumPath, args: ['--no-sandbox'] });
  try {
    const page = await pixelPage(browser);
    const src = 'data:image/svg+xml;base64,' + Buffer.from(text).toString('base64');
    const counts = await page.evaluate(async ({ src, colors }) => {
      const { px, w, h } = await window.imagePixels(src);
      const out = { size: [w, h], white: 0 };
      const rgb = colors.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
      colors.forEach((h) => { out[h] = 0; });
      for (let i = 0; i < px.length; i += 4) {
        if (px[i] > 250 && px[i + 1] > 250 && px[i + 2] > 250) out.white++;
        rgb.forEach((col, k) => {
          if (Math.abs(px[i] - col[0]) < 24 && Math.abs(px[i + 1] - col[1]) < 24 && Math.abs(px[i + 2] - col[2]) < 24) out[colors[k]]++;
        });
      }
      return out;
    }, { src, colors: [CUT, PIERCE] });
    assert.equal(counts.size[0], 800);
    assert.ok(counts[CUT] > 500, `cut-coloured pixels: ${counts[CUT]}`);
    assert.ok(counts[PIERCE] > 10, `pierce-coloured pixels: ${counts[PIERCE]}`);
    assert.ok(counts.white > counts.size[0] * counts.size[1] * 0.5, 'a white background');
  } finally {
    await browser.close();
  }
});

// A square of 1 km and one of 100 km, drawn to PNG by rsvg-convert: the cut is there (its strokes were given in mm
// a pixel too thin to show, or none; at 100 km the legend's font made rsvg-convert fail and a 0-byte PNG was left).
test('PNG of tapes of 1 km and 100 km: the cut shows, the legend is drawn', { skip: !fs.existsSync('/usr/bin/rsvg-convert') && 'rsvg-convert not installed' }, async () => {
  const dir = tempDir('png-extent');
  const browser = await chromium.launch({ executablePath: chromiumPath, args: ['--no-sandbox'] });
  try {
    const profile = path.join(dir, 'mm.profile.json');
    write(profile, '{"name": "mm units", "unit_mm": 1}');  // (100 km in 0.1 mm would be a word of 10 digits)
    for (const km of [1, 100]) {
      const u = km * 1000000;  // mm
      const tape = path.join(dir, `square_${km}km.esi`);
      write(tape, `7\n+${u}+0\n+0+${u}\n-${u}+0\n+0-${u}\n8\n64\n`);
      const out = path.join(dir, `square_${km}km.png`);
      const r = essi(['render', tape, '--profile', profile, '--width', '600', '-o', out]);
      assert.equal(r.status, 0, r.stderr);
      assert.doesNotMatch(r.stderr, /WARNING|failed/, r.stderr);
      const b64 = fs.readFileSync(out).toString('base64');
      const page = await pixelPage(browser);
      const counts = await page.evaluate(async ({ b64, cut }) => {
        const { px, w } = await window.imagePixels('data:image/png;base64,' + b64);
        const rgb = [1, 3, 5].map((i) => parseInt(cut.slice(i, i + 2), 16));
        let red = 0, dark = 0;
        for (let i = 0; i < px.length; i += 4) {
          if (Math.abs(px[i] - rgb[0]) < 40 && Math.abs(px[i + 1] - rgb[1]) < 40 && Math.abs(px[i + 2] - rgb[2]) < 40) red++;
          if (px[i] < 80 && px[i + 1] < 80 && px[i + 2] < 80) dark++;  // the legend's text
        }
        return { red, dark, w };
      }, { b64, cut: CUT });
      await page.close();
      assert.equal(counts.w, 600);
      assert.ok(counts.red > 4 * 500, `${km} km: cut-coloured pixels ${counts.red}`);  // (4 sides of ~545 px)
      assert.ok(counts.dark > 200, `${km} km: legend pixels ${counts.dark}`);
    }
  } finally {
    await browser.close();
  }
});
