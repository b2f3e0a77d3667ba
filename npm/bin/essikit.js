#!/usr/bin/env node
// essikit: the `essi` command (native/main.cpp, everything but `serve`) compiled for node with node's file system
// (NODERAWFS): the same subcommands, options, output formats and exit codes (docs/cli.md, docs/javascript.md).
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const createEssikitCli = require('../lib/essikit_cli.cjs');

createEssikitCli({
  // The program, the API's too (npm/CMakeLists.txt). Given, so that the module does not fetch it: node 18+ has a
  // fetch that cannot read files.
  wasmBinary: readFileSync(new URL('../lib/essikit_api.wasm', import.meta.url)),
  arguments: process.argv.slice(2),
  // The process's environment (LC_ALL, LC_MESSAGES, LANG: the language and the terminal's charset, as natively).
  preRun: [(m) => { Object.assign(m.ENV, process.env); }],
});
// main's return ends the process with its exit code (EXIT_RUNTIME).
