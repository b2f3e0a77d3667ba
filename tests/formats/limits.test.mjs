// Input size limits of the CLI (`--max-size`, default 1 GB): files, standard input and special files are read
// up to the same cap, and a file beyond it is refused before it is mapped (a 5 GB sparse file was mapped whole
// before E117; standard input and /dev/zero were read without end).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { essi, essiBin, examplesDir, tempDir } from './support.mjs';

// Runs essi under a shell with the address space limited to `kb` (ulimit -v): mapping a big file would fail.
function essiLimited(kb, args) {
  const quoted = args.map((a) => `'${a.replace(/'/g, "'\\''")}'`).join(' ');
  const r = spawnSync('bash', ['-c', `ulimit -v ${kb}; exec "$ESSI" ${quoted}`], {
    encoding: 'utf8', env: { ...process.env, ESSI: essiBin }, timeout: 60000,
  });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

test('a 5 GB file is refused by its size, not mapped', () => {
  const dir = tempDir('limits');
  const big = path.join(dir, 'sparse.esi');
  fs.closeSync(fs.openSync(big, 'w'));
  fs.truncateSync(big, 5 * 1024 ** 3);
  for (const sub of [['check'], ['stats'], ['trace'], ['render', '-o', '-']]) {
    const r = essiLimited(1024 * 1024, [...sub, big]);  // 1 GB of address space
    assert.equal(r.status, 2, `${sub[0]}: ${r.stderr}`);
    assert.match(r.stderr, /the file has 5368709120 bytes, more than --max-size 1GB \(1073741824 bytes\)/, sub[0]);
  }
  fs.rmSync(dir, { recursive: true });
});

test('standard input and /dev/zero stop at --max-size', () => {
  const r = essi(['check', '--max-size', '2KB', '-'], { input: Buffer.alloc(3000, 0x30) });
  assert.equal(r.status, 2, r.stderr);
  assert.match(r.stderr, /cannot read -: the input is larger than --max-size 2KB \(2048 bytes\)/);
  const z = essiLimited(512 * 1024, ['check', '--max-size', '1MB', '/dev/zero']);
  assert.equal(z.status, 2, z.stderr);
  assert.match(z.stderr, /cannot read \/dev\/zero: the input is larger than --max-size 1MB/);
});

test('a tape of exactly --max-size bytes is read', () => {
  const file = path.join(examplesDir, 'crlf.esi');
  const size = String(fs.statSync(file).size);
  assert.equal(essi(['check', '--max-size', size, file]).status, 0);
  assert.equal(essi(['check', '--max-size', String(Number(size) - 1), file]).status, 2);
  const piped = essi(['stats', '--max-size', size, '-'], { input: fs.readFileSync(file) });
  assert.equal(piped.status, 0, piped.stderr);
});
