// Shared helpers of the format tests: where essi is, running it, temp folders.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const sourceDir = process.env.ESSI_SOURCE_DIR || path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const essiBin = process.env.ESSI_BIN || path.join(sourceDir, 'build/native/bin/essi');
export const examplesDir = path.join(sourceDir, 'examples');
export const chromiumPath = process.env.ESSI_CHROMIUM || '/usr/bin/chromium';

// Runs essi; returns {status, stdout, stderr}.
export function essi(args, { input, cwd } = {}) {
  const r = spawnSync(essiBin, args, { input, cwd: cwd || sourceDir, encoding: 'utf8', maxBuffer: 256 << 20 });
  if (r.error) throw r.error;
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

export function tempDir(name) {
  return fs.mkdtempSync(path.join(os.tmpdir(), `essi-formats-${name}-`));
}

export function write(file, text) {
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, text);
}

export const goodTape = '39+3000\n+0+1000\n7\n+1000+0\n+0+1000+0+500-\n8\n+5+5\n63\n';
export const badTape = '+100+0\n7\n+1x\n+100+0+0+500+\n8\n63\n';
