// The npm package essikit (npm/, docs/javascript.md, docs/viewer-element.md), as a user gets it: packed by
// scripts/pack_npm from the wasm build, installed offline from the .tgz into an empty folder. Its API and
// `npx essikit` give what the native `essi` gives, byte for byte, for every example; <essi-viewer> on a plain static
// page (python3 -m http.server) loads a tape in Chromium and fires essi-load and essi-select.
// Environment (ctest npm_package sets it): ESSI_BIN (the native essi), ESSI_WASM_BUILD (build/wasm), ESSI_CHROMIUM.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '..', '..');
const examples = path.join(root, 'examples');
const essiBin = process.env.ESSI_BIN || path.join(root, 'build', 'native', 'bin', 'essi');
const wasmBuild = process.env.ESSI_WASM_BUILD || path.join(root, 'build', 'wasm');
const chromiumPath = process.env.ESSI_CHROMIUM || '/usr/bin/chromium';
// The same environment for essi and essikit: English, UTF-8.
const env = { ...process.env, LANG: 'C.UTF-8' };
delete env.LC_ALL;
delete env.LC_MESSAGES;

// The test's own npm packages (tests/npm/package.json, installed by scripts/setup test).
const testRequire = createRequire(path.join(here, 'package.json'));
function testPackage(name) {
  try {
    return testRequire(name);
  } catch {
    throw new Error(`npm_package needs ${name} in tests/npm/node_modules (scripts/setup test)`);
  }
}

const tapes = fs.readdirSync(examples).filter((f) => /\.(esi|eia)$/.test(f)).sort();

// What a test needs and cannot find is a failure that says so (never a skip).
function need(ok, what) {
  if (!ok) throw new Error(`npm_package needs ${what}`);
}
const onPath = (cmd) => spawnSync('sh', ['-c', `command -v ${cmd}`]).status === 0;

// A program's exit code and output (stdout as bytes).
function runProgram(cmd, args, options = {}) {
  const r = spawnSync(cmd, args, { env, maxBuffer: 1 << 30, ...options });
  if (r.error) throw r.error;
  return { code: r.status, stdout: r.stdout, stderr: r.stderr.toString() };
}
const essi = (...args) => runProgram(essiBin, args);

// The same, without blocking: the examples run two at a time.
function runAsync(cmd, args, options = {}) {
  return new Promise((resolve, reject) => {
    const child = spawn(cmd, args, { env, ...options });
    const out = [];
    const err = [];
    child.stdout.on('data', (d) => out.push(d));
    child.stderr.on('data', (d) => err.push(d));
    child.on('error', reject);
    child.on('close', (code) => resolve({ code, stdout: Buffer.concat(out), stderr: Buffer.concat(err).toString() }));
  });
}

// The tape's --profile: its own file when examples/NAME.expected.json names one, else auto.
function profileArgs(tape) {
  const expected = path.join(examples, tape.replace(/\.(esi|eia)$/, '.expected.json'));
  const file = fs.existsSync(expected) ? JSON.parse(fs.readFileSync(expected, 'utf8')).profile_file : undefined;
  return file ? path.join(examples, file) : 'auto';
}

let work;     // temporary folder: dist/, app/ (the installed package), cache/
let app;
let api;      // the installed package's module
let version;  // CMake's project(VERSION), as essi --version says it

before(() => {
  need(fs.existsSync(essiBin), `the native essi (${essiBin}; ESSI_BIN)`);
  need(onPath('npm') && onPath('npx'), 'npm and npx (apt-get install npm)');
  need(fs.existsSync(path.join(wasmBuild, 'npm', 'essikit', 'package.json')),
    `the package folder ${wasmBuild}/npm/essikit (cmake --build --preset wasm --target essi_npm)`);
  version = essi('--version').stdout.toString().split(' ')[1];
  work = fs.mkdtempSync(path.join(os.tmpdir(), 'essikit-npm-'));
  app = path.join(work, 'app');
  fs.mkdirSync(app);
});

after(() => { if (work) fs.rmSync(work, { recursive: true, force: true }); });

describe('the package', () => {
  test('packs into essikit-<version>.tgz and installs offline into an empty folder', async () => {
    const tgz = execFileSync(path.join(root, 'scripts', 'pack_npm'), [wasmBuild, path.join(work, 'dist')],
      { encoding: 'utf8' }).trim();
    assert.equal(path.basename(tgz), `essikit-${version}.tgz`);
    // An empty cache and --offline: nothing can come from a registry.
    execFileSync('npm', ['install', '--offline', '--no-audit', '--no-fund', '--cache', path.join(work, 'cache'), tgz],
      { cwd: app, env, stdio: 'pipe' });
    const pkg = JSON.parse(fs.readFileSync(path.join(app, 'node_modules', 'essikit', 'package.json'), 'utf8'));
    assert.equal(pkg.version, version);
    assert.equal(pkg.type, 'module');
    assert.deepEqual(pkg.bin, { essikit: 'bin/essikit.js' });
    assert.ok(fs.existsSync(path.join(app, 'node_modules', '.bin', 'essikit')));
    for (const f of ['index.d.ts', 'viewer/essi-viewer.d.ts', 'lib/essikit_api.wasm', 'viewer/page/essi_viewer.wasm',
                    'viewer/page/essi_reader.js', 'viewer/page/essi_reader.wasm', 'viewer/page/essi_reader_mt.js',
                    'viewer/page/essi_reader_mt.wasm', 'viewer/page/essi_reader_mt.worker.js'])
      assert.ok(fs.existsSync(path.join(app, 'node_modules', 'essikit', f)), f);
    // The package's name resolves from the folder it is installed in (its "exports").
    const probe = "import('essikit').then(async (e) => console.log((await e.profiles()).join(',')))";
    const out = execFileSync('node', ['--input-type=module', '-e', probe], { cwd: app, encoding: 'utf8' });
    assert.equal(out.trim(), essi('profile', 'list').stdout.toString().trim().split('\n').join(','));
    api = await import(pathToFileURL(path.join(app, 'node_modules', 'essikit', 'index.js')));
    assert.equal(await api.version(), version);
  });

  test('its TypeScript declarations type-check a program that uses every name', () => {
    need(api, 'the installed package (the test before)');
    const tsc = path.join(path.dirname(testRequire.resolve('typescript/package.json')), 'bin', 'tsc');
    fs.writeFileSync(path.join(app, 'uses.mts'), kTypeScriptUse);
    const r = runProgram('node', [tsc, '--noEmit', '--strict', '--module', 'nodenext', '--moduleResolution', 'nodenext',
      '--target', 'es2022', '--lib', 'es2022,dom', 'uses.mts'], { cwd: app });
    assert.equal(r.code, 0, r.stdout.toString());
    // and a wrong use is caught (the declarations are read, not ignored)
    fs.writeFileSync(path.join(app, 'wrong.mts'), "import { check } from 'essikit';\nconst n: number = await check('x');\n");
    const wrong = runProgram('node', [tsc, '--noEmit', '--module', 'nodenext', '--moduleResolution', 'nodenext',
      '--target', 'es2022', 'wrong.mts'], { cwd: app });
    assert.notEqual(wrong.code, 0);
    assert.match(wrong.stdout.toString(), /Type 'Report' is not assignable to type 'number'/);
  });
});

// Every name of the API and the element, as a TypeScript program uses them.
const kTypeScriptUse = `
import { check, stats, trace, convert, diff, profiles, version, run, EssikitError, type Report } from 'essikit';
import { EssiViewer } from 'essikit/viewer';

export async function uses(): Promise<void> {
  const report: Report = await check('+1+1\\n', { profile: 'auto', input: 'essi', lang: 'de', name: 'x.esi', maxDiagnostics: 3 });
  const ok: boolean = report.files[0].ok;
  const perFile = (await stats(new Uint8Array(3), { input: 'eia', profile: { name: 'shop' } })).files;
  const records: string = await trace(new ArrayBuffer(2), { kerf: true, machine: false, decimals: 4 });
  const gcode: string = await convert('x', { to: 'gcode', toProfile: 'woyda', absolute: true, force: true });
  const changes = await diff('a', 'b', { names: ['a.esi', 'b.esi'], profile: 'woyda' });
  const names: string[] = await profiles();
  const v: string = await version();
  const r = await run(['check', '-'], { stdin: 'x', files: { 'a.esi': 'y' } });
  const code: number = r.code;
  const out: Uint8Array = r.stdout;
  try { await check('x'); } catch (e) { if (e instanceof EssikitError) console.log(e.exitCode, e.stderr, e.diagnostics.join()); }
  const viewer = document.querySelector('essi-viewer')!;
  viewer.addEventListener('essi-load', (e) => console.log(e.detail.name, e.detail.ok, e.detail.summary.errors));
  viewer.addEventListener('essi-select', (e) => console.log(e.detail.line, e.detail.motion));
  const shown: Report = await viewer.load(new Uint8Array(1), 'y.esi');
  const last: Report | null = viewer.report;
  const element: EssiViewer = viewer;
  const state = element.viewer?.state();
  element.viewer?.selectLine(3);
  console.log(ok, perFile, records, gcode, changes, names, v, code, out, shown, last, state);
}
`;

// Each subcommand of every example: native essi, npx essikit (same arguments, same files) and the API.
describe('the API and npx essikit give what essi gives, for every example', { concurrency: 2 }, () => {
  let validateReport;  // docs/report-schema.json (JSON Schema 2020-12)
  before(() => {
    const Ajv2020 = testPackage('ajv/dist/2020.js');
    const schema = JSON.parse(fs.readFileSync(path.join(root, 'docs', 'report-schema.json'), 'utf8'));
    validateReport = new (Ajv2020.default || Ajv2020)({ allErrors: true, strict: false }).compile(schema);
  });
  const npx = (args) => runProgram('npx', ['--no', 'essikit', ...args], { cwd: app });
  const same = async (args) => {
    const [want, got] = await Promise.all([runAsync(essiBin, args), runAsync('npx', ['--no', 'essikit', ...args], { cwd: app })]);
    assert.equal(got.code, want.code, `exit code of essikit ${args.join(' ')}: ${got.stderr}`);
    assert.ok(got.stdout.equals(want.stdout), `output of essikit ${args.join(' ')} differs from essi's`);
    return want;
  };
  const profileOf = (p) => (p === 'auto' ? 'auto' : JSON.parse(fs.readFileSync(p, 'utf8')));

  for (const tape of tapes) {
    test(tape, async () => {
      need(api, 'the installed package (the test before)');
      const file = path.join(examples, tape);
      const bytes = fs.readFileSync(file);
      const profile = profileArgs(tape);
      const options = { name: file, profile: profileOf(profile) };
      // check and stats: JSON (no timing field: the run's seconds are only on stderr's summary line)
      for (const sub of ['check', 'stats']) {
        const want = await same([sub, '--format', 'json', '--profile', profile, file]);
        const got = await api[sub](bytes, options);
        assert.deepEqual(got, JSON.parse(want.stdout));
        if (sub === 'check') assert.ok(validateReport(got), JSON.stringify(validateReport.errors));
      }
      const trace = await same(['trace', '--profile', profile, file]);
      assert.equal(await api.trace(bytes, options), trace.stdout.toString());
      const eia = await same(['convert', '--to', 'eia', '--profile', profile, file]);
      if (eia.code === 0) {
        assert.equal(await api.convert(bytes, { ...options, to: 'eia' }), eia.stdout.toString());
      } else {
        await assert.rejects(api.convert(bytes, { ...options, to: 'eia' }),
          (e) => e instanceof api.EssikitError && e.exitCode === eia.code && e.diagnostics.length > 0);
      }
      // diff with the next example (the last with the first)
      const other = path.join(examples, tapes[(tapes.indexOf(tape) + 1) % tapes.length]);
      const d = await same(['diff', '--format', 'json', '--profile', 'auto', file, other]);
      assert.deepEqual(await api.diff(bytes, fs.readFileSync(other), { names: [file, other], profile: 'auto' }),
        JSON.parse(d.stdout));
    });
  }

  test('folders, every report format and the exit codes', () => {
    need(api, 'the installed package');
    for (const format of ['json', 'sarif', 'codeclimate', 'github', 'junit', 'text']) {
      const want = essi('check', '--format', format, '--jobs', '1', examples);
      const got = npx(['check', '--format', format, examples]);
      assert.equal(got.code, want.code);
      assert.equal(want.code, 1);  // (examples/ has tapes with errors)
      // junit, text and github carry the run's seconds (the timing fields): compared without them
      const untimed = (b) => b.toString().replace(/time="[0-9.]+"/g, 'time=""').replace(/; [0-9.]+ s\n/g, '; s\n');
      if (['junit', 'text', 'github'].includes(format)) assert.equal(untimed(got.stdout), untimed(want.stdout));
      else assert.ok(got.stdout.equals(want.stdout), `essikit check --format ${format} examples/`);
    }
    const usage = npx(['check', '--format', 'nope', examples]);
    assert.equal(usage.code, 2);
    assert.equal(essi('check', '--format', 'nope', examples).code, 2);
    const missing = npx(['stats', path.join(work, 'no-such.esi')]);
    assert.equal(missing.code, 2);
    assert.match(missing.stderr, /cannot read .*no-such\.esi: No such file or directory/);
    assert.equal(npx(['check', '--fail-on', 'never', examples]).code, 0);
  });

  test('bytes from memory, languages and errors', async () => {
    need(api, 'the installed package');
    const tape = fs.readFileSync(path.join(examples, 'bad_arc_off_circle.esi'));
    const viaStdin = runProgram(essiBin, ['check', '--format', 'json', '--profile', 'woyda', '--lang', 'de', '-'],
      { input: tape });
    assert.notEqual(viaStdin.stdout.length, 0);
    const report = await api.check(tape.toString('latin1'), { profile: 'woyda', lang: 'de' });
    assert.equal(report.files[0].path, '-');
    assert.equal(report.files[0].ok, false);
    assert.deepEqual(report, JSON.parse(viaStdin.stdout));
    assert.deepEqual(await api.check(tape.buffer.slice(tape.byteOffset, tape.byteOffset + tape.length),
      { profile: 'woyda', lang: 'de' }), report);
    await assert.rejects(api.check('+10+0\n64\n', { profile: 'nope' }),
      (e) => e instanceof api.EssikitError && e.exitCode === 2 && /unknown profile 'nope'/.test(e.message));
    await assert.rejects(api.check('+10+0\n64\n', { lang: 'fr' }), /expected en, de or zh/);
    await assert.rejects(api.check('+10+0\n64\n', { profile: { feed_mm_min: 'fast' } }),
      (e) => e.diagnostics.some((line) => /error E402/.test(line)));
    const gouge = fs.readFileSync(path.join(examples, 'bad_kerf_gouge.esi'));
    await assert.rejects(api.convert(gouge, { to: 'gcode' }), (e) => e.diagnostics.some((l) => /E307/.test(l)));
    const forced = runProgram(essiBin, ['convert', '--to', 'gcode', '--force', '-'], { input: gouge });
    assert.equal(await api.convert(gouge, { to: 'gcode', force: true }), forced.stdout.toString());
  });
});

// --- <essi-viewer> in Chromium, on a static page served by python3 -m http.server ----------------------------
function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once('error', reject);
    s.listen(0, '127.0.0.1', () => { const p = s.address().port; s.close(() => resolve(p)); });
  });
}

async function waitForServer(port) {
  for (let i = 0; i < 100; ++i) {
    try {
      const r = await fetch(`http://127.0.0.1:${port}/index.html`);
      if (r.ok) return;
    } catch { /* not yet */ }
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error(`python3 -m http.server did not answer on port ${port}`);
}

const kPage = `<!doctype html>
<html><head><meta charset="utf-8"><title>essi-viewer</title>
<script type="module" src="node_modules/essikit/viewer/essi-viewer.js"></script></head>
<body>
<essi-viewer id="viewer" src="plate_holes.esi" theme="light" style="width: 900px; height: 600px"></essi-viewer>
<script>
  window.loads = [];
  window.selections = [];
  const v = document.getElementById('viewer');
  v.addEventListener('essi-load', (e) => window.loads.push(e.detail));
  v.addEventListener('essi-select', (e) => window.selections.push(e.detail));
</script>
</body></html>
`;

describe('<essi-viewer> on a static page', () => {
  let server;
  let browser;
  after(async () => {
    if (browser) await browser.close();
    if (server) server.kill();
  });

  test('loads a tape from src, fires essi-load and essi-select, and load() shows another', async () => {
    need(api, 'the installed package');
    need(fs.existsSync(chromiumPath), `Chromium (${chromiumPath}; ESSI_CHROMIUM)`);
    need(onPath('python3'), 'python3 (the static server)');
    const e2e = path.join(root, 'tests', 'e2e', 'package.json');
    let chromium;
    try {
      ({ chromium } = createRequire(e2e)('playwright-core'));
    } catch {
      need(false, 'playwright-core in tests/e2e/node_modules (scripts/setup test)');
    }
    fs.writeFileSync(path.join(app, 'index.html'), kPage);
    fs.copyFileSync(path.join(examples, 'plate_holes.esi'), path.join(app, 'plate_holes.esi'));
    const port = await freePort();
    server = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1'], { cwd: app, stdio: 'ignore' });
    await waitForServer(port);

    browser = await chromium.launch({
      executablePath: chromiumPath,
      args: ['--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
             '--disable-gpu-sandbox', '--disable-background-networking', '--no-first-run'],
    });
    const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
    const problems = [];
    page.on('pageerror', (e) => problems.push(e.message));
    await page.goto(`http://127.0.0.1:${port}/index.html`);
    await page.waitForFunction(() => window.loads.length > 0, null, { timeout: 120000 });

    // essi-load: the tape's name and its report's summary; report: what check() (and essi check) gives.
    const first = await page.evaluate(() => window.loads[0]);
    const want = JSON.parse(runProgram(essiBin, ['check', '--format', 'json', '--profile', 'auto', 'plate_holes.esi'],
      { cwd: app }).stdout);
    assert.equal(first.name, 'plate_holes.esi');
    assert.equal(first.ok, want.files[0].ok);
    assert.deepEqual(first.summary, want.summary);
    assert.deepEqual(await page.evaluate(() => document.getElementById('viewer').report), want);
    // The viewer in the frame shows that tape, in the theme asked for.
    const state = await page.evaluate(() => document.getElementById('viewer').viewer.state());
    assert.equal(state.status, 'ready');
    assert.equal(state.name, 'plate_holes.esi');
    assert.equal(state.theme, 'light');
    assert.equal(state.stats.pierces, want.files[0].stats.pierces);

    // essi-select: a line selected in the viewer (as a click on it would) reaches the page.
    await page.evaluate(() => document.getElementById('viewer').viewer.selectLine(5));
    await page.waitForFunction(() => window.selections.some((s) => s.line === 5), null, { timeout: 30000 });
    const [selected, selection] = await page.evaluate(() =>
      [window.selections.at(-1), document.getElementById('viewer').viewer.state().selection]);
    assert.deepEqual(selected, { line: selection.line, motion: selection.motion });

    // load(bytes, name): another tape, another essi-load with its report.
    const bad = fs.readFileSync(path.join(examples, 'bad_arc_off_circle.esi'), 'latin1');
    const report = await page.evaluate((text) => document.getElementById('viewer').load(text, 'bad.esi'), bad);
    const badWant = JSON.parse(runProgram(essiBin, ['check', '--format', 'json', '--profile', 'auto', '-'],
      { input: Buffer.from(bad, 'latin1') }).stdout);
    badWant.files[0].path = 'bad.esi';
    assert.deepEqual(report, badWant);
    const loads = await page.evaluate(() => window.loads);
    assert.equal(loads.length, 2);
    assert.deepEqual(loads[1], { name: 'bad.esi', ok: false, profile: 'auto', summary: badWant.summary });

    // The attributes after the start: profile and lang check the tape again (essi-load), theme changes the viewer.
    const nativeBad = (...args) => {
      const r = JSON.parse(runProgram(essiBin, ['check', '--format', 'json', ...args, '-'],
        { input: Buffer.from(bad, 'latin1') }).stdout);
      r.files[0].path = 'bad.esi';
      return r;
    };
    await page.evaluate(() => document.getElementById('viewer').setAttribute('profile', 'woyda'));
    await page.waitForFunction(() => window.loads.length === 3, null, { timeout: 60000 });
    assert.deepEqual(await page.evaluate(() => document.getElementById('viewer').report), nativeBad('--profile', 'woyda'));
    assert.equal(await page.evaluate(() => document.getElementById('viewer').viewer.state().profile), 'woyda');
    await page.evaluate(() => document.getElementById('viewer').setAttribute('lang', 'de'));
    await page.waitForFunction(() => window.loads.length === 4, null, { timeout: 60000 });
    assert.deepEqual(await page.evaluate(() => document.getElementById('viewer').report),
      nativeBad('--profile', 'woyda', '--lang', 'de'));
    await page.evaluate(() => document.getElementById('viewer').setAttribute('theme', 'dark'));
    await page.waitForFunction(() => document.getElementById('viewer').viewer.state().theme === 'dark', null,
      { timeout: 10000 });
    assert.equal(await page.evaluate(() => document.getElementById('viewer').viewer.state().lang), 'de');
    assert.deepEqual(problems, []);
  });
});
