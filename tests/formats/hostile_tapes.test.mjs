// Tapes and folders an attacker or an unlucky user hands to the CLI (docs/hostile-input.md): every byte where a
// message quotes the tape keeps every format well formed; findings are bounded per code; a tape with errors is not
// converted; an unreadable folder is reported; render refuses what it cannot do.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { parse as parseJunit } from 'junit2json';
import { essi, essiBin, examplesDir, tempDir } from './support.mjs';

function run(args) {
  const r = spawnSync(essiBin, args, { encoding: 'buffer', maxBuffer: 256 << 20 });
  if (r.error) throw r.error;
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

const utf8 = (buf) => new TextDecoder('utf-8', { fatal: true }).decode(buf);

function assertNoControlBytes(buf, what) {
  for (const b of buf) assert.ok(b >= 0x20 || b === 0x0a || b === 0x09 || b === 0x0d, `${what}: control byte 0x${b.toString(16)}`);
  assert.ok(!buf.includes(0x7f), `${what}: DEL`);
}

// One EIA tape per byte 0-255, the byte where W124, E122 and E119 quote the line.
function everyByteFolder() {
  const dir = tempDir('bytes');
  for (let b = 0; b < 256; ++b) {
    const x = Buffer.from([b]);
    const tape = Buffer.concat([Buffer.from('%\nG90\nM03\nG-1'), x, Buffer.from('\nX12345678901234'), x,
                                Buffer.from('\nX1'), x, Buffer.from('Y2\nM05\nM30\n')]);
    fs.writeFileSync(path.join(dir, `b${String(b).padStart(3, '0')}.eia`), tape);
  }
  return dir;
}

test('every byte 0-255 in a quoted place: JSON, SARIF and JUnit stay valid, text and github carry no control byte', async () => {
  const dir = everyByteFolder();
  const args = ['--input', 'eia', '--profile', 'din66025', '--ext', 'eia', dir];
  const json = run(['check', '--format', 'json', ...args]);
  assert.equal(json.status, 1, json.stderr.toString());  // tapes with errors, no abort (134)
  const report = JSON.parse(utf8(json.stdout));
  assert.equal(report.files.length, 256);
  const w124 = report.files[32].diagnostics.find((d) => d.code === 'W124');  // byte ' ' (32): the word ends there
  assert.equal(w124.message, 'G-1 is not a G code; it is ignored');
  for (const f of report.files) for (const d of f.diagnostics) assertNoControlBytes(Buffer.from(d.message), f.path);
  const sarif = run(['check', '--format', 'sarif', ...args]);
  const log = JSON.parse(utf8(sarif.stdout));
  assert.ok(log.runs[0].results.length >= 256, String(log.runs[0].results.length));
  const junit = run(['check', '--format', 'junit', ...args]);
  const parsed = await parseJunit(utf8(junit.stdout));
  assert.equal(parsed.tests, 256);
  for (const format of ['text', 'github']) {
    const r = run(['check', '--format', format, ...args]);
    utf8(r.stdout);
    assertNoControlBytes(r.stdout, format);
  }
  fs.rmSync(dir, { recursive: true });
});

test('--max-per-code N lists N of a code and one line that counts the rest', () => {
  const dir = tempDir('per-code');
  const file = path.join(dir, 'blanks.esi');
  fs.writeFileSync(file, '+10+0 \n'.repeat(50) + '64\n');
  const r = essi(['check', '--max-per-code', '3', '--format', 'json', file]);
  assert.equal(r.status, 0, r.stderr);
  const d = JSON.parse(r.stdout).files[0].diagnostics;
  assert.deepEqual(d.map((x) => [x.code, x.line]), [['W109', 1], ['W109', 2], ['W109', 3], ['W109', 4]]);
  assert.equal(d[3].message, '47 more W109 diagnostics not listed (at most 3 of a code: --max-per-code)');
  const all = essi(['check', '--max-per-code', '0', '--format', 'json', file]);
  assert.equal(JSON.parse(all.stdout).files[0].diagnostics.length, 50);
  assert.equal(essi(['check', '--max-per-code', '-1', file]).status, 2);
  fs.rmSync(dir, { recursive: true });
});

test('convert writes nothing for a tape that check rejects, unless --force', () => {
  const dir = tempDir('convert');
  for (const name of ['bad_kerf_gouge.esi', 'plan_kerf.esi', 'plan_collision.esi', 'plan_cross.esi']) {
    const out = path.join(dir, name + '.ngc');
    const r = essi(['convert', '--to', 'gcode', path.join(examplesDir, name), '-o', out]);
    assert.equal(r.status, 1, name);
    assert.equal(r.stdout, '', name);
    assert.ok(!fs.existsSync(out), name);
    assert.match(r.stderr, /error E(307|602|605|606)/, name);
    assert.match(r.stderr, /has errors; nothing was written \(--force writes what the machine would run of it\)/, name);
    const forced = essi(['convert', '--to', 'gcode', '--force', path.join(examplesDir, name), '-o', out]);
    assert.equal(forced.status, 1, name);
    assert.match(fs.readFileSync(out, 'utf8'), /^G17 G21/, name);
  }
  fs.rmSync(dir, { recursive: true });
});

test('a folder that cannot be listed is an error naming it, and the rest is checked', (t) => {
  if (spawnSync('setpriv', ['--help']).status !== 0) return t.skip('setpriv (util-linux) missing');
  const dir = tempDir('walk');
  fs.chmodSync(dir, 0o755);
  fs.writeFileSync(path.join(dir, 'a.esi'), '+10+0\n64\n');
  fs.mkdirSync(path.join(dir, 'locked'));
  fs.writeFileSync(path.join(dir, 'locked', 'b.esi'), '+10+0\n64\n');
  fs.chmodSync(path.join(dir, 'locked'), 0o000);
  // As an unprivileged user (root reads any folder): nobody can list `locked`.
  const r = spawnSync('setpriv', ['--reuid=65534', '--regid=65534', '--clear-groups', essiBin, 'check', dir], { encoding: 'utf8' });
  fs.chmodSync(path.join(dir, 'locked'), 0o755);
  assert.equal(r.status, 2, r.stderr);
  assert.match(r.stderr, new RegExp(`essi: cannot read ${dir}/locked: Permission denied`));
  assert.match(r.stdout, /1 file checked/);
  fs.rmSync(dir, { recursive: true });
});

test('render: DXF is no picture; the messages follow --lang', () => {
  const dir = tempDir('render');
  const tape = path.join(examplesDir, 'crlf.esi');
  for (const args of [['--format', 'dxf', '--png', '-o', path.join(dir, 'x.png')], ['--format', 'dxf', '-o', path.join(dir, 'y.png')]]) {
    const r = essi(['render', tape, ...args]);
    assert.equal(r.status, 2, r.stderr);
    assert.match(r.stderr, /--format dxf writes a drawing, not a picture: it cannot go to a PNG/);
  }
  assert.deepEqual(fs.readdirSync(dir), []);
  const de = essi(['render', '--lang', 'de', tape, '-o', path.join(dir, 'z.svg')]);
  assert.equal(de.status, 0, de.stderr);
  assert.match(de.stderr, /essi render: .*z\.svg geschrieben/);
  fs.rmSync(dir, { recursive: true });
});

test('stats names a tape with errors in the chosen language; the text report names the profile --profile auto chose', () => {
  const bad = path.join(examplesDir, 'bad_kerf_gouge.esi');
  const de = essi(['stats', '--lang', 'de', bad]);
  assert.match(de.stderr, /bad_kerf_gouge\.esi hat 1 Fehler \(siehe essi check /);
  const auto = essi(['check', '--profile', 'auto', path.join(examplesDir, 'woyda_end_slash.esi')]);
  assert.match(auto.stdout, /woyda_end_slash\.esi: read with profile woyda \(--profile auto: the dialect its codes show\)/);
});

test('a GB 18030 terminal gets its text reports in GB 18030; JSON stays UTF-8', () => {
  const bad = path.join(examplesDir, 'bad_kerf_gouge.esi');
  const env = { ...process.env, LC_ALL: '', LC_CTYPE: '', LANG: 'zh_CN.GB18030' };
  const text = spawnSync(essiBin, ['check', bad], { env, encoding: 'buffer' });
  assert.equal(text.status, 1);
  assert.throws(() => utf8(text.stdout));  // not UTF-8 ...
  const decoded = new TextDecoder('gb18030', { fatal: true }).decode(text.stdout);  // ... but GB 18030
  assert.match(decoded, /错误 E307/);
  assert.match(decoded, /已检查 1 个文件/);  // (the text format's summary is on stdout)
  const json = spawnSync(essiBin, ['check', '--format', 'json', bad], { env, encoding: 'buffer' });
  assert.match(utf8(json.stdout), /"message": "[^"]*割炬/);
  const utf = spawnSync(essiBin, ['check', bad], { env: { ...env, LANG: 'zh_CN.UTF-8' }, encoding: 'buffer' });
  assert.match(utf8(utf.stdout), /错误 E307/);
});
