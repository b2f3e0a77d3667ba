// Shared helpers of the format tests: where essi is, running it, temp folders.
import { spawn, spawnSync } from 'node:child_process';
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

// The viewer's build and Chromium for the tests that run it under `essi serve`.
export const webRoot = process.env.ESSI_WEB_ROOT || path.join(sourceDir, 'build/wasm/web');
export const haveViewer = fs.existsSync(path.join(webRoot, 'essi_viewer.wasm'));
export const chromiumArgs = ['--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

// Starts `essi serve` on a free loopback port with the viewer and a share store in `dataDir`: {proc, url}.
export function startServer(dataDir) {
  return new Promise((resolve, reject) => {
    const p = spawn(essiBin, ['serve', '--port', '0', '--web-root', webRoot, '--data', dataDir], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    p.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/http:\/\/127\.0\.0\.1:\d+/);
      if (m) resolve({ proc: p, url: m[0] });
    });
    p.on('exit', (code) => reject(new Error('essi serve exited with ' + code)));
  });
}
