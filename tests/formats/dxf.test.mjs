// `essi render --format dxf`: every example's DXF read by an independent parser (dxf-parser, npm): the entities
// per layer and their lengths must be the statistics of `essi check` (the KERF layer: the compensated pieces of
// `essi trace --kerf`), a clockwise arc is written from its end, a
// full circle as two half arcs, and each diagnostic is on the DIAGNOSTICS layer.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import DxfParser from 'dxf-parser';
import { essi, sourceDir, tempDir } from './support.mjs';

const examplesDir = path.join(sourceDir, 'examples');
const corpusDir = path.join(sourceDir, '..', 'shared', 'corpus', 'essiconv');

function dxfOf(tape) {
  const out = path.join(tempDir('dxf'), path.basename(tape) + '.dxf');
  const r = essi(['render', '--format', 'dxf', '--profile', 'auto', tape, '-o', out]);
  assert.ok(r.status === 0 || r.status === 1, r.stderr);
  return new DxfParser().parseSync(fs.readFileSync(out, 'utf8'));
}

function length(e) {
  if (e.type === 'LINE') return Math.hypot(e.vertices[1].x - e.vertices[0].x, e.vertices[1].y - e.vertices[0].y);
  if (e.type === 'ARC') {
    let sweep = e.endAngle - e.startAngle;  // radians, counter-clockwise
    if (sweep <= 0) sweep += 2 * Math.PI;
    return e.radius * sweep;
  }
  return 0;
}

function tapes() {
  const list = fs.readdirSync(examplesDir).filter((f) => /\.(esi|eia)$/.test(f)).map((f) => path.join(examplesDir, f));
  if (fs.existsSync(corpusDir)) list.push(...fs.readdirSync(corpusDir).map((f) => path.join(corpusDir, f)));
  return list.sort();
}

test('every example and real tape: DXF lengths per layer are the statistics of essi check', () => {
  let checked = 0;
  for (const tape of tapes()) {
    const report = JSON.parse(essi(['check', '--format', 'json', '--profile', 'auto', tape]).stdout).files[0];
    if (!report.ok) continue;  // (a rejected arc's geometry is not defined)
    const dxf = dxfOf(tape);
    assert.deepEqual(Object.keys(dxf.tables.layer.layers).sort(), ['CUT', 'DIAGNOSTICS', 'KERF', 'MARK', 'TRAVEL'], tape);
    const sum = { CUT: 0, MARK: 0, TRAVEL: 0, KERF: 0 };
    for (const e of dxf.entities) if (e.layer in sum) sum[e.layer] += length(e);
    const s = report.stats;
    // parabolas are flattened within 0.01 mm a chord: a little shorter than the curve
    for (const [layer, want] of [['CUT', s.cut_length_mm], ['MARK', s.mark_length_mm], ['TRAVEL', s.travel_length_mm]])
      assert.ok(Math.abs(sum[layer] - want) <= 1e-3 + 1e-4 * want, `${tape}: ${layer} ${sum[layer]} != ${want}`);
    const kerfTrace = essi(['trace', '--kerf', '--decimals', '6', '--profile', 'auto', tape]).stdout.split('\n');
    const copies = (l) => Number((l.match(/ torches=(\d+)/) || [0, 1])[1]);  // (each torch's copy is drawn)
    const kerfWant = kerfTrace.filter((l) => / kerf=/.test(l)).reduce((a, l) => a + copies(l) * Number(l.match(/ len=([\d.]+)/)[1]), 0);
    assert.ok(Math.abs(sum.KERF - kerfWant) <= 1e-3 + 1e-4 * kerfWant, `${tape}: KERF ${sum.KERF} != ${kerfWant}`);
    if (/kerf_parts/.test(tape)) assert.ok(kerfWant > 900, `${tape}: the kerf layer is drawn (${kerfWant} mm)`);
    const diagnostics = dxf.entities.filter((e) => e.layer === 'DIAGNOSTICS' && e.type === 'TEXT');
    assert.equal(diagnostics.length, report.diagnostics.filter((d) => d.line > 0).length, tape);
    ++checked;
  }
  assert.ok(checked >= 40, `only ${checked} tapes compared`);
});

test('a clockwise arc from its end, a full circle as two half arcs, entity counts', () => {
  const dxf = dxfOf(path.join(examplesDir, 'arcs_both_senses.esi'));
  const trace = essi(['trace', path.join(examplesDir, 'arcs_both_senses.esi')]).stdout.split('\n');
  const arcs = trace.filter((l) => / arc /.test(l));
  const full = arcs.filter((l) => /sweep=-?360\.000/.test(l)).length;
  const dxfArcs = dxf.entities.filter((e) => e.type === 'ARC');
  assert.equal(dxfArcs.length, arcs.length + full);
  const lines = trace.filter((l) => / line /.test(l)).length;
  assert.equal(dxf.entities.filter((e) => e.type === 'LINE').length, lines);
  // the first clockwise arc: DXF's start angle is the angle of the motion's end point
  const cw = arcs.find((l) => / cw /.test(l) && !/sweep=-360/.test(l));
  const [, ex, ey, cx, cy] = cw.match(/->\(([-\d.]+),([-\d.]+)\) c=\(([-\d.]+),([-\d.]+)\)/).map(Number);
  const want = Math.atan2(ey - cy, ex - cx);
  assert.ok(dxfArcs.some((e) => Math.abs(((e.startAngle - want) % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI)) < 1e-6 &&
                                Math.abs(e.center.x - cx) < 1e-3 && Math.abs(e.center.y - cy) < 1e-3), 'no ARC starting at the cw arc\'s end');
});

test('a bad tape: its diagnostics on the DIAGNOSTICS layer', () => {
  const dxf = dxfOf(path.join(examplesDir, 'bad_arc_off_circle.esi'));
  const texts = dxf.entities.filter((e) => e.layer === 'DIAGNOSTICS' && e.type === 'TEXT').map((e) => e.text);
  assert.deepEqual(texts, ['E301 line 12']);
  assert.equal(dxf.entities.filter((e) => e.layer === 'DIAGNOSTICS' && e.type === 'POINT').length, 1);
});
