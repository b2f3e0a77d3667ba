// File names that are not text: invalid UTF-8, control characters (an escape sequence), a backslash. Every
// format must stay well formed and name the file (before: `--format json` aborted with rc 134 for the whole
// folder, JUnit and SVG were malformed XML, the text format printed the raw bytes, SARIF turned '\' into '/').
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { parse as parseJunit } from 'junit2json';
import { parseStringPromise } from 'xml2js';
import { essiBin, tempDir, goodTape, badTape } from './support.mjs';

// The folder with one tape of each awkward name (written through Buffers: node would not make these bytes).
function hostileFolder() {
  const dir = tempDir('names');
  const names = [
    Buffer.concat([Buffer.from('bad'), Buffer.from([0xff, 0xfe]), Buffer.from('.esi')]),
    Buffer.concat([Buffer.from('ctl'), Buffer.from([0x01, 0x1b]), Buffer.from('[31mred.esi')]),
    Buffer.from('back\\slash.esi'),
  ];
  names.forEach((name, k) => fs.writeFileSync(Buffer.concat([Buffer.from(dir + '/'), name]), k === 1 ? badTape : goodTape));
  return dir;
}

function run(args) {
  const r = spawnSync(essiBin, args, { encoding: 'buffer', maxBuffer: 64 << 20 });
  if (r.error) throw r.error;
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

function assertNoControlBytes(buf, what) {
  for (const b of buf) assert.ok(b >= 0x20 || b === 0x0a || b === 0x09 || b === 0x0d, `${what}: control byte 0x${b.toString(16)}`);
  assert.ok(!buf.includes(0x7f), `${what}: DEL`);
}

test('JSON: every file reported, names as valid UTF-8 with \\xNN for the bytes that are not', () => {
  const dir = hostileFolder();
  const r = run(['check', '--format', 'json', dir]);
  assert.equal(r.status, 1, r.stderr.toString());  // the bad tape has an error: not an abort (134)
  const report = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(r.stdout));
  const names = report.files.map((f) => path.basename(f.path)).sort();
  assert.deepEqual(names, ['back\\slash.esi', 'bad\\xFF\\xFE.esi', 'ctl\\x01\\x1B[31mred.esi']);
  fs.rmSync(dir, { recursive: true });
});

test('JUnit, SARIF, text and GitHub output stay well formed', async () => {
  const dir = hostileFolder();
  const junit = run(['check', '--format', 'junit', dir]);
  assertNoControlBytes(junit.stdout, 'junit');
  const suites = await parseJunit(junit.stdout.toString('utf8'));
  assert.equal(suites.tests, 3);
  const xml = await parseStringPromise(junit.stdout.toString('utf8'));  // a strict XML parser
  assert.ok(xml.testsuites);

  const sarif = JSON.parse(run(['check', '--format', 'sarif', dir]).stdout.toString('utf8'));
  const uris = sarif.runs[0].results.map((res) => res.locations[0].physicalLocation.artifactLocation.uri);
  assert.ok(uris.some((u) => u.includes('ctl%01%1B%5B31mred.esi')), uris.join(' '));
  const all = JSON.stringify(sarif);
  assert.ok(!all.includes('back/slash'), 'a backslash stays a backslash');

  const text = run(['check', dir]);
  assertNoControlBytes(text.stdout, 'text stdout');
  assertNoControlBytes(text.stderr, 'text stderr');
  assert.match(text.stdout.toString('utf8'), /ctl\\x01\\x1B\[31mred\.esi/);

  const github = run(['check', '--format', 'github', dir]);
  assertNoControlBytes(github.stdout, 'github');
  fs.rmSync(dir, { recursive: true });
});

test('SVG of a tape with such a name is well formed XML', async () => {
  const dir = hostileFolder();
  // node cannot pass these bytes as an argument: the shell's glob does.
  const r = spawnSync('bash', ['-c', '"$ESSI" render -o - bad*.esi'], {
    cwd: dir, encoding: 'buffer', env: { ...process.env, ESSI: essiBin },
  });
  assert.equal(r.status, 0, r.stderr.toString());
  assertNoControlBytes(r.stdout, 'svg');
  const svg = await parseStringPromise(new TextDecoder('utf-8', { fatal: true }).decode(r.stdout));
  assert.ok(svg.svg);
  fs.rmSync(dir, { recursive: true });
});
