// essikit's JavaScript API (docs/javascript.md). Every function runs the `essi` CLI's own main() (native/main.cpp,
// compiled by Emscripten into lib/essikit_api.js) in memory: a fresh instance per call, the input written into its
// file system (MEMFS), the arguments the CLI would get, stdout and stderr captured byte by byte. So check(), stats(),
// trace(), convert() and diff() give exactly what `essi ... --format json` prints; no rule is written here.
import createEssikit from './lib/essikit_api.js';

const isNode = typeof process === 'object' && !!(process.versions && process.versions.node);

// The problem of a call the CLI refused (its exit code 2, or 1 for a conversion it will not write): `diagnostics`
// are the lines it printed on stderr (`FILE:LINE:COLUMN: error E402: ...`, `essi: cannot read ...`).
export class EssikitError extends Error {
  constructor(message, exitCode, stderr) {
    super(message);
    this.name = 'EssikitError';
    this.exitCode = exitCode;
    this.stderr = stderr;
    this.diagnostics = stderr.split('\n').filter((line) => line !== '');
  }
}

// The compiled WebAssembly module, once per process or page; each call instantiates it anew.
let compiled = null;
function wasmModule() {
  if (!compiled) {
    compiled = compileWasm(new URL('./lib/essikit_api.wasm', import.meta.url));
    compiled.catch(() => { compiled = null; });  // (a failed fetch is tried again next time)
  }
  return compiled;
}

async function compileWasm(url) {
  if (isNode) {
    const { readFile } = await import('node:fs/promises');
    return WebAssembly.compile(await readFile(url));
  }
  const response = await fetch(url);
  if (!response.ok) throw new Error(`essikit: cannot fetch ${url}: HTTP ${response.status}`);
  return WebAssembly.compile(await response.arrayBuffer());
}

// Bytes of a tape or a profile: a string (UTF-8), a Uint8Array (a node Buffer too), an ArrayBuffer or a view.
function toBytes(data, what) {
  if (typeof data === 'string') return new TextEncoder().encode(data);
  if (data instanceof Uint8Array) return data;
  if (data instanceof ArrayBuffer) return new Uint8Array(data);
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  throw new TypeError(`essikit: ${what} must be a string, a Uint8Array or an ArrayBuffer`);
}

// A growing byte buffer for stdout.
class ByteSink {
  constructor() { this.bytes = new Uint8Array(1 << 16); this.length = 0; }
  push(byte) {
    if (this.length === this.bytes.length) {
      const bigger = new Uint8Array(this.bytes.length * 2);
      bigger.set(this.bytes);
      this.bytes = bigger;
    }
    this.bytes[this.length++] = byte;
  }
  result() { return this.bytes.slice(0, this.length); }
}

// Runs the CLI once: `args` as after `essi` on a command line, `files` ({path: data}) written first (folders made),
// `stdin` the bytes of '-'. Resolves with {code, stdout (Uint8Array), stderr (string)}; a tape with errors is no
// rejection (code 1), only a failure of the runtime itself is.
export async function run(args, { files = {}, stdin } = {}) {
  const module = await wasmModule();
  const input = stdin === undefined ? new Uint8Array(0) : toBytes(stdin, 'stdin');
  let read = 0;
  const stdout = new ByteSink();
  const stderr = new ByteSink();
  let failed;
  const failure = new Promise((_, reject) => { failed = reject; });
  failure.catch(() => {});  // (an abort in main() throws from callMain below; the race is over by then)
  const instance = await Promise.race([failure, createEssikit({
    instantiateWasm(imports, receive) {
      WebAssembly.instantiate(module, imports).then((inst) => receive(inst, module), failed);
      return {};
    },
    // The environment of a plain POSIX shell: no locale of the browser or of node's process; --lang says it.
    preRun: [(m) => { m.ENV.LANG = 'C.UTF-8'; }],
    stdin: () => (read < input.length ? input[read++] : null),
    stdout: (byte) => { if (byte !== null) stdout.push(byte); },
    stderr: (byte) => { if (byte !== null) stderr.push(byte); },
    print: () => {},
    printErr: () => {},
    onAbort: (what) => failed(new Error(`essikit: the WebAssembly program stopped: ${what}`)),
  })]);
  for (const [path, data] of Object.entries(files)) {
    const slash = path.lastIndexOf('/');
    if (slash > 0) instance.FS.mkdirTree(path.slice(0, slash));
    instance.FS.writeFile(path, toBytes(data, path));
  }
  const code = instance.callMain(args.map(String));
  return { code, stdout: stdout.result(), stderr: new TextDecoder().decode(stderr.result()) };
}

const kProfileFile = 'profile.json';

// The options every subcommand shares, as arguments; files the profile needs.
function commonArgs(options, files) {
  const args = [];
  const { profile, input, lang = 'en' } = options;
  if (profile !== undefined && profile !== null) {
    if (typeof profile === 'string') {
      args.push('--profile', profile);
    } else {
      files[kProfileFile] = JSON.stringify(profile);
      args.push('--profile', kProfileFile);
    }
  }
  if (input !== undefined && input !== null) args.push('--input', input);
  args.push('--lang', lang);
  return args;
}

// One tape as the CLI reads it: written under `name` (which the report then shows), or '-' (standard input).
function tapeArg(data, name, files, stdinHolder) {
  const bytes = toBytes(data, 'the tape');
  if (name === undefined || name === '-') {
    stdinHolder.stdin = bytes;
    return '-';
  }
  files[name] = bytes;
  return name;
}

async function runChecked(args, files, stdin, okCodes) {
  const r = await run(args, { files, stdin });
  if (!okCodes.includes(r.code)) {
    const first = r.stderr.split('\n').find((line) => line !== '') || `essi ${args[0]} exited with ${r.code}`;
    throw new EssikitError(first, r.code, r.stderr);
  }
  return r;
}

const text = (bytes) => new TextDecoder().decode(bytes);

// essi check --format json: the report (docs/report-schema.json). A tape with errors resolves (report.summary).
export async function check(data, options = {}) {
  const files = {};
  const holder = {};
  const args = ['check', '--format', 'json', ...commonArgs(options, files)];
  if (options.maxDiagnostics !== undefined) args.push('--max-diagnostics', options.maxDiagnostics);
  if (options.maxPerCode !== undefined) args.push('--max-per-code', options.maxPerCode);
  args.push(tapeArg(data, options.name, files, holder));
  return JSON.parse(text((await runChecked(args, files, holder.stdin, [0, 1])).stdout));
}

// essi stats --format json: {files: [{path, stats}], profile}.
export async function stats(data, options = {}) {
  const files = {};
  const holder = {};
  const args = ['stats', '--format', 'json', ...commonArgs(options, files), tapeArg(data, options.name, files, holder)];
  return JSON.parse(text((await runChecked(args, files, holder.stdin, [0, 1])).stdout));
}

// essi trace: the motion stream, one record a line (a string).
export async function trace(data, options = {}) {
  const files = {};
  const holder = {};
  const args = ['trace', ...commonArgs(options, files)];
  if (options.decimals !== undefined) args.push('--decimals', options.decimals);
  if (options.kerf) args.push('--kerf');
  if (options.machine) args.push('--machine');
  args.push(tapeArg(data, options.name, files, holder));
  return text((await runChecked(args, files, holder.stdin, [0, 1])).stdout);
}

// essi convert --to essi|eia|gcode: the converted tape (a string). A tape with errors rejects unless `force`.
export async function convert(data, options = {}) {
  const files = {};
  const holder = {};
  const args = ['convert', '--to', options.to ?? 'essi', ...commonArgs(options, files)];
  if (options.toProfile !== undefined) {
    if (typeof options.toProfile === 'string') {
      args.push('--to-profile', options.toProfile);
    } else {
      files['to-profile.json'] = JSON.stringify(options.toProfile);
      args.push('--to-profile', 'to-profile.json');
    }
  }
  if (options.absolute) args.push('--absolute');
  if (options.force) args.push('--force');
  args.push(tapeArg(data, options.name, files, holder));
  return text((await runChecked(args, files, holder.stdin, options.force ? [0, 1] : [0])).stdout);
}

// essi diff --format json A B: the two revisions compared contour by contour.
export async function diff(a, b, options = {}) {
  const files = {};
  const [nameA, nameB] = options.names ?? ['A', 'B'];
  if (nameA === nameB) throw new TypeError('essikit: diff needs two different names');
  const args = ['diff', '--format', 'json', ...commonArgs(options, files)];
  files[nameA] = toBytes(a, 'tape A');
  files[nameB] = toBytes(b, 'tape B');
  args.push(nameA, nameB);
  return JSON.parse(text((await runChecked(args, files, undefined, [0, 1])).stdout));
}

// essi profile list: the built-in profiles' names.
export async function profiles() {
  const out = text((await runChecked(['profile', 'list'], {}, undefined, [0])).stdout);
  return out.split('\n').filter((name) => name !== '');
}

// essi --version's version: the package's (CMake's project(VERSION)).
export async function version() {
  const out = text((await runChecked(['--version'], {}, undefined, [0])).stdout);
  return out.trim().split(' ')[1];
}
