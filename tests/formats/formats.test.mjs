// `essi check` output formats read by their real consumers:
//   SARIF 2.1.0  validated with ajv against the official schema (sarif-2.1.0-rtm.5.json, shipped in the npm
//                package @microsoft/jest-sarif; draft-04, so ajv-draft-04 + ajv-formats)
//   JUnit XML    parsed by junit2json (the converter CI dashboards use)
//   JSON         validated against docs/report-schema.json (JSON Schema 2020-12, ajv)
//   github       workflow command syntax
// and batch mode on directories (extensions, sniffing, stdin, --jobs, --fail-on, --max-diagnostics, --quiet).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { spawnSync } from 'node:child_process';
import Ajv04 from 'ajv-draft-04';
import Ajv2020 from 'ajv/dist/2020.js';
import addFormats from 'ajv-formats';
import { parse as parseJunit } from 'junit2json';
import { essi, examplesDir, sourceDir, tempDir, write, goodTape, badTape } from './support.mjs';

const require = createRequire(import.meta.url);
const sarifSchemaPath = require.resolve('@microsoft/jest-sarif/lib/schemas/sarif-2.1.0-rtm.5.json');

const exampleTapes = fs.readdirSync(examplesDir).filter((f) => f.endsWith('.esi')).sort();

function sarifValidator() {
  const ajv = new Ajv04({ allErrors: true, strict: false, unicodeRegExp: false });
  addFormats(ajv);
  return ajv.compile(JSON.parse(fs.readFileSync(sarifSchemaPath, 'utf8')));
}

test('SARIF of the examples validates against the official SARIF 2.1.0 schema', () => {
  const r = essi(['check', '--format', 'sarif', '--docs-url', 'https://example.org/essikit/docs', 'examples/']);
  assert.equal(r.status, 1, r.stderr);  // some examples have errors
  const log = JSON.parse(r.stdout);
  const validate = sarifValidator();
  assert.ok(validate(log), JSON.stringify(validate.errors, null, 1));
  assert.equal(log.version, '2.1.0');
  const run = log.runs[0];
  const rules = run.tool.driver.rules;
  // One rule per diagnostic code, each with help text and a link into docs/diagnostics.md.
  const ids = rules.map((x) => x.id);
  assert.equal(new Set(ids).size, ids.length);
  assert.ok(ids.includes('E101') && ids.includes('E301') && ids.includes('W109'));
  for (const rule of rules) {
    assert.match(rule.id, /^[EWN][1-6]\d\d$/);
    assert.ok(rule.shortDescription.text.length > 10, rule.id);
    assert.ok(rule.help.text.length > 10, rule.id);
    assert.equal(rule.helpUri, `https://example.org/essikit/docs/diagnostics.md#${rule.id.toLowerCase()}`);
    assert.equal(rule.defaultConfiguration.level, { E: 'error', W: 'warning', N: 'note' }[rule.id[0]]);
  }
  // The anchors exist in docs/diagnostics.md.
  const doc = fs.readFileSync(path.join(sourceDir, 'docs/diagnostics.md'), 'utf8');
  for (const id of ids) assert.ok(doc.includes(`<a id="${id.toLowerCase()}"></a>`), `docs/diagnostics.md has no anchor for ${id}`);
  // Results: the same diagnostics as the JSON report, pointing at their rule and position.
  const json = JSON.parse(essi(['check', '--format', 'json', 'examples/']).stdout);
  const expected = json.files.flatMap((f) => f.diagnostics.map((d) => `${f.path}|${d.code}|${d.line}|${d.column}|${d.severity}`));
  const got = run.results.map((res) => {
    const loc = res.locations[0].physicalLocation;
    return `${loc.artifactLocation.uri}|${res.ruleId}|${loc.region?.startLine ?? 0}|${loc.region?.startColumn ?? 0}|${res.level}`;
  });
  assert.deepEqual(got, expected);
  for (const res of run.results) assert.equal(rules[res.ruleIndex].id, res.ruleId);
  assert.ok(run.results.some((res) => res.ruleId === 'E301'));
  assert.equal(run.invocations[0].executionSuccessful, true);
});

test('SARIF with an unreadable file and cut diagnostics still validates', () => {
  const d = tempDir('sarif');
  write(path.join(d, 'bad one.esi'), badTape.repeat(3));
  const r = essi(['check', '--format', 'sarif', '--max-diagnostics', '1', path.join(d, 'bad one.esi'), path.join(d, 'missing.esi')]);
  assert.equal(r.status, 2);
  const log = JSON.parse(r.stdout);
  const validate = sarifValidator();
  assert.ok(validate(log), JSON.stringify(validate.errors, null, 1));
  const inv = log.runs[0].invocations[0];
  assert.equal(inv.executionSuccessful, false);
  assert.ok(inv.toolExecutionNotifications.some((n) => /cannot read/.test(n.message.text)));
  assert.ok(inv.toolExecutionNotifications.some((n) => /more diagnostics? not shown/.test(n.message.text)));
  assert.equal(log.runs[0].results.length, 1);
  assert.match(log.runs[0].results[0].locations[0].physicalLocation.artifactLocation.uri, /bad%20one\.esi$/);
});

test('JUnit XML is read by junit2json: one test case per file, failures carry the diagnostics', async () => {
  const r = essi(['check', '--format', 'junit', 'examples/', 'examples/missing.esi']);
  assert.equal(r.status, 2);  // the unreadable file
  const report = await parseJunit(r.stdout);
  const json = JSON.parse(essi(['check', '--format', 'json', 'examples/']).stdout);
  assert.equal(report.tests, exampleTapes.length + 1);
  const suite = report.testsuite[0];
  assert.equal(suite.testcase.length, exampleTapes.length + 1);
  assert.equal(suite.failures, json.files.filter((f) => !f.ok).length);
  assert.equal(suite.errors, 1);
  assert.deepEqual(suite.testcase.map((c) => c.name), [...exampleTapes.map((t) => `examples/${t}`), 'examples/missing.esi']);
  for (const file of json.files) {
    const tc = suite.testcase.find((c) => c.name === file.path);
    assert.equal(tc.classname, 'essi.check');
    if (file.ok) {
      assert.equal(tc.failure, undefined, file.path);
    } else {
      assert.equal(tc.failure.length, 1);
      for (const d of file.diagnostics) assert.ok(tc.failure[0].inner.includes(`${d.code}: ${d.message}`), `${file.path} ${d.code}`);
      assert.match(tc.failure[0].message, /\d+ errors?/);
    }
  }
  const missing = suite.testcase.at(-1);
  assert.match(missing.error[0].message, /cannot read/);
  assert.equal(suite.properties.find((p) => p.name === 'profile').value, 'iso6582');
});

test('JUnit: --fail-on warning turns warnings into failures', async () => {
  const d = tempDir('junitw');
  write(path.join(d, 'w.esi'), '+100+0\n37\n63\n');  // W201 only
  const strict = essi(['check', '--format', 'junit', '--fail-on', 'warning', d]);
  assert.equal(strict.status, 1);
  assert.equal((await parseJunit(strict.stdout)).failures, 1);
  const normal = essi(['check', '--format', 'junit', d]);
  assert.equal(normal.status, 0);
  assert.equal((await parseJunit(normal.stdout)).failures, 0);
});

test('JSON report (and --max-diagnostics) validates against docs/report-schema.json', () => {
  const ajv = new Ajv2020({ allErrors: true, strict: false });
  const validate = ajv.compile(JSON.parse(fs.readFileSync(path.join(sourceDir, 'docs/report-schema.json'), 'utf8')));
  const full = JSON.parse(essi(['check', '--format', 'json', 'examples/']).stdout);
  assert.ok(validate(full), JSON.stringify(validate.errors));
  const cut = JSON.parse(essi(['check', '--format', 'json', '--max-diagnostics', '0', 'examples/']).stdout);
  assert.ok(validate(cut), JSON.stringify(validate.errors));
  assert.deepEqual(cut.summary, full.summary);  // counts include the omitted diagnostics
  for (const [i, f] of full.files.entries()) {
    assert.equal(cut.files[i].diagnostics.length, 0);
    assert.equal(cut.files[i].ok, f.ok);
    if (f.diagnostics.length) assert.equal(cut.files[i].diagnostics_omitted, f.diagnostics.length);
  }
});

test('github format: workflow commands with file, line, col and title', () => {
  const r = essi(['check', '--format', 'github', 'examples/bad_arc_off_circle.esi', 'examples/warn_unknown_function.esi']);
  assert.equal(r.status, 1);
  const lines = r.stdout.trim().split('\n');
  assert.match(lines[0], /^::error file=examples\/bad_arc_off_circle\.esi,line=12,col=1,title=E301::the arc's end point is not on its circle/);
  assert.match(lines[1], /^::warning file=examples\/warn_unknown_function\.esi,line=\d+,col=\d+,title=W201::/);
  assert.match(lines.at(-1), /^2 files checked \(profile iso6582\): 1 ok, 1 with errors; 1 error, 1 warning; [\d.]+ s$/);
  for (const l of lines.slice(0, -1)) assert.match(l, /^::(error|warning|notice) file=[^,:]+(,line=\d+(,col=\d+)?)?,title=[EW]\d{3}::[^\r\n]+$/);
});

test('batch: directories recursively, extensions, sniffing, stdin, deterministic order with --jobs', () => {
  const d = tempDir('batch');
  const tapes = {};
  for (let i = 0; i < 40; ++i) {
    const rel = `${i % 4 ? 'plates' : 'parts'}/${String(i % 5)}/t${String(i).padStart(3, '0')}.${['esi', 'nc', 'txt', 'ESS', 'essi'][i % 5]}`;
    tapes[rel] = i % 7 === 3 ? badTape : goodTape;
  }
  tapes['plates/NOEXT_TAPE'] = '3\nPART 99 from the nester\n4\n' + goodTape;  // sniffed in
  tapes['plates/readme'] = 'Tapes for plate 7.\nCut them in order.\n';           // sniffed out
  tapes['plates/data.json'] = '{"x": 1}\n';
  for (const [rel, text] of Object.entries(tapes)) write(path.join(d, rel), text);
  const expectedFiles = Object.keys(tapes).filter((r) => !/readme|json/.test(r)).map((r) => path.join(d, r)).sort();

  const runs = [1, 2, 4].map((j) => essi(['check', '--format', 'json', '--jobs', String(j), d]));
  for (const r of runs) assert.equal(r.status, 1, r.stderr);
  const reports = runs.map((r) => JSON.parse(r.stdout));
  assert.deepEqual(reports[0].files.map((f) => f.path), expectedFiles);
  assert.deepEqual(reports[1], reports[0]);
  assert.deepEqual(reports[2], reports[0]);
  const bad = Object.values(tapes).filter((t) => t === badTape).length;
  assert.equal(reports[0].summary.files, expectedFiles.length);
  assert.equal(reports[0].summary.files - reports[0].summary.files_ok, bad);

  // Text: the same order, one summary line with files, errors, warnings and time.
  const text1 = essi(['check', '--jobs', '1', d]).stdout.replace(/; [\d.]+ s\n$/, '');
  const text2 = essi(['check', '--jobs', '2', d]).stdout.replace(/; [\d.]+ s\n$/, '');
  assert.equal(text2, text1);
  assert.match(essi(['check', d]).stdout.split('\n').at(-2),
    new RegExp(`^${expectedFiles.length} files checked \\(profile iso6582\\): ${expectedFiles.length - bad} ok, ${bad} with errors; \\d+ errors, \\d+ warnings; [\\d.]+ s$`));

  // --ext: only these extensions; --no-sniff: no content sniffing.
  const onlyNc = JSON.parse(essi(['check', '--format', 'json', '--ext', 'nc', '--no-sniff', d]).stdout);
  assert.deepEqual(onlyNc.files.map((f) => f.path), expectedFiles.filter((f) => f.endsWith('.nc')));
  const ncAndSniff = JSON.parse(essi(['check', '--format', 'json', '--ext', '.NC', d]).stdout);
  // With sniffing on, files of other extensions still count when their first KB is ESSI (all of them here).
  assert.deepEqual(ncAndSniff.files.map((f) => f.path), expectedFiles);

  // stdin.
  const stdin = essi(['check', '--format', 'json', '-'], { input: badTape });
  assert.equal(stdin.status, 1);
  assert.equal(JSON.parse(stdin.stdout).files[0].path, '-');
});

test('batch: --fail-on, --quiet, --max-diagnostics and exit codes', () => {
  const d = tempDir('exit');
  write(path.join(d, 'good.esi'), goodTape);
  write(path.join(d, 'warn.esi'), '+100+0\n37\n63\n');
  assert.equal(essi(['check', d]).status, 0);
  assert.equal(essi(['check', '--fail-on', 'warning', d]).status, 1);
  write(path.join(d, 'bad.esi'), badTape.repeat(4));
  assert.equal(essi(['check', d]).status, 1);
  assert.equal(essi(['check', '--fail-on', 'never', d]).status, 0);
  assert.equal(essi(['check', '--fail-on', 'never', d, path.join(d, 'missing.esi')]).status, 2);
  assert.equal(essi(['check', '--fail-on', 'sometimes', d]).status, 2);

  const quiet = essi(['check', '--quiet', d]);
  const qlines = quiet.stdout.trim().split('\n');
  assert.ok(qlines.every((l) => /: (error|warning) [EW]\d{3}: /.test(l) || /files checked/.test(l)), quiet.stdout);
  assert.ok(!/; cut /.test(quiet.stdout));  // no stats lines

  const limited = essi(['check', '--max-diagnostics', '2', path.join(d, 'bad.esi')]);
  const dl = limited.stdout.split('\n').filter((l) => /: (error|warning) /.test(l));
  assert.equal(dl.length, 2);
  const all = essi(['check', path.join(d, 'bad.esi')]).stdout.split('\n').filter((l) => /: (error|warning) /.test(l));
  assert.match(limited.stdout, new RegExp(`note: ${all.length - 2} more diagnostics? not shown \\(--max-diagnostics 2\\)`));
  // JSON/JUnit/SARIF keep stdout a document: the summary goes to stderr (not with --quiet).
  const j = essi(['check', '--format', 'json', d]);
  assert.doesNotThrow(() => JSON.parse(j.stdout));
  assert.match(j.stderr, /files checked/);
  assert.equal(essi(['check', '--format', 'json', '--quiet', d]).stderr, '');
});

// One version (CMake's project(VERSION)) and the commit the binary was built from, in --version, SARIF and JUnit.
test('--version names the version of CMakeLists.txt and the git commit; SARIF and JUnit the same version', async () => {
  const version = fs.readFileSync(path.join(sourceDir, 'CMakeLists.txt'), 'utf8').match(/project\(essikit VERSION ([0-9.]+)/)[1];
  const git = spawnSync('git', ['-C', sourceDir, 'rev-parse', '--short=12', 'HEAD'], { encoding: 'utf8' });
  const commit = git.status === 0 ? git.stdout.trim() : 'unknown';
  const r = essi(['--version']);
  assert.equal(r.status, 0);
  assert.equal(r.stdout.trim(), `essi ${version} (commit ${commit})`);
  const sarif = JSON.parse(essi(['check', '--format', 'sarif', path.join(examplesDir, 'crlf.esi')]).stdout);
  assert.equal(sarif.runs[0].tool.driver.version, version);
  const junit = essi(['check', '--format', 'junit', path.join(examplesDir, 'crlf.esi')]).stdout;
  assert.match(junit, new RegExp(`<property name="essi.version" value="${version.replace(/\./g, '\\.')}"/>`));
});

// GitLab Code Quality: every diagnostic an issue with GitLab's fields; the fingerprint the same in every run and
// language, unique per finding.
test('codeclimate: GitLab Code Quality issues with stable fingerprints', () => {
  const run = (lang) => {
    const r = essi(['check', '--format', 'codeclimate', '--lang', lang, '--profile', 'auto', examplesDir]);
    assert.equal(r.status, 1, r.stderr);  // (the bad_ examples)
    return JSON.parse(r.stdout);
  };
  const en = run('en'), de = run('de'), again = run('en');
  const json = JSON.parse(essi(['check', '--format', 'json', '--profile', 'auto', examplesDir]).stdout);
  assert.equal(en.length, json.files.reduce((n, f) => n + f.diagnostics.length, 0));
  for (const i of en) {
    assert.equal(i.type, 'issue');
    assert.match(i.check_name, /^[EWN]\d{3}$/);
    assert.ok(['info', 'minor', 'major', 'critical', 'blocker'].includes(i.severity));
    assert.equal(i.severity, { E: 'critical', W: 'minor', N: 'info' }[i.check_name[0]]);
    assert.match(i.fingerprint, /^[0-9a-f]{32}$/);
    assert.ok(i.location.path.startsWith(examplesDir));
    assert.ok(Number.isInteger(i.location.lines.begin) && i.location.lines.begin >= 1);
    assert.ok(i.description.length > 0);
  }
  assert.equal(new Set(en.map((i) => i.fingerprint)).size, en.length);
  assert.deepEqual(again.map((i) => i.fingerprint), en.map((i) => i.fingerprint));
  assert.deepEqual(de.map((i) => i.fingerprint), en.map((i) => i.fingerprint));
  assert.notDeepEqual(de.map((i) => i.description), en.map((i) => i.description));
});

// The profile's schema (docs/profile-schema.json) against what essi reads and shows: every built-in profile and a
// profile with every key validate; each profile of tests/data/profile_errors (E402) does not.
test('profile JSON validates against docs/profile-schema.json; the E402 ones do not', () => {
  const ajv = new Ajv2020({ allErrors: true, strict: false });
  const validate = ajv.compile(JSON.parse(fs.readFileSync(path.join(sourceDir, 'docs/profile-schema.json'), 'utf8')));
  const list = essi(['profile', 'list']).stdout.trim().split('\n');
  assert.ok(list.length >= 4);
  for (const name of list) {
    const shown = JSON.parse(essi(['profile', 'show', name]).stdout);
    assert.ok(validate(shown), `${name}: ${JSON.stringify(validate.errors)}`);
  }
  const d = tempDir('profile');
  const full = {
    name: 'shop-a', base: 'woyda', accel_mm_s2: 800, junction_deviation_mm: 0.02,
    material: { name: 'S355', thickness_mm: 15, density_kg_m3: 7850 }, plate_mm: { x: 3000, y: 1500 },
    costs: { currency: 'EUR', machine_per_hour: 90, per_pierce: 0.05, per_m_cut: 0.4, material_per_kg: 1.1 },
    consumables: { electrode_pierces: 800, electrode_arc_s: 7200 },
  };
  assert.ok(validate(full), JSON.stringify(validate.errors));
  write(path.join(d, 'full.json'), JSON.stringify(full));
  const shown = essi(['profile', 'show', path.join(d, 'full.json')]);
  assert.equal(shown.status, 0, shown.stderr);
  assert.ok(validate(JSON.parse(shown.stdout)), JSON.stringify(validate.errors));
  assert.deepEqual(JSON.parse(shown.stdout).costs, full.costs);
  const errorsDir = path.join(sourceDir, 'tests/data/profile_errors');
  for (const f of fs.readdirSync(errorsDir).filter((n) => n.endsWith('.json'))) {
    const text = fs.readFileSync(path.join(errorsDir, f), 'utf8');
    assert.ok(!validate(JSON.parse(text)), `${f} validates, but essi refuses it`);
    const r = essi(['profile', 'show', path.join(errorsDir, f)]);
    assert.equal(r.status, 2, f);
    assert.match(r.stderr, new RegExp(`${f.replace('.', '\\.')}:\\d+:\\d+: error E402: `), f);
  }
});

// The machine time, cost and consumables in the JSON report validate, and the text report names them.
test('machine time, cost and consumables: JSON report validates, text shows them', () => {
  const ajv = new Ajv2020({ allErrors: true, strict: false });
  const validate = ajv.compile(JSON.parse(fs.readFileSync(path.join(sourceDir, 'docs/report-schema.json'), 'utf8')));
  const d = tempDir('machine-time');
  write(path.join(d, 'p.json'), JSON.stringify({
    accel_mm_s2: 500, costs: { currency: 'EUR', machine_per_hour: 60, per_pierce: 0.5 },
    consumables: { electrode_pierces: 1000 },
  }));
  const json = JSON.parse(essi(['check', '--format', 'json', '--profile', path.join(d, 'p.json'), 'examples/']).stdout);
  assert.ok(validate(json), JSON.stringify(validate.errors));
  for (const f of json.files) {
    const s = f.stats;
    assert.ok(s.machine_time_s >= s.estimated_time_s - 1e-6, f.path);
    const b = s.machine_time_breakdown_s;
    const sum = b.cutting + b.marking + b.rapid + b.travel + b.pierce + b.dwell;
    assert.ok(Math.abs(sum - s.machine_time_s) < 1e-5, f.path);
    assert.ok(Math.abs(s.machine_time_s - b.acceleration - s.estimated_time_s) < 1e-5, f.path);
    assert.equal(s.cost.time_basis, 'machine_time_s');
    assert.equal(s.cost.material, null);
    assert.equal(s.consumables.pierces, s.pierces);
  }
  const text = essi(['check', '--profile', path.join(d, 'p.json'), 'tests/data/machine_time/line.esi']);
  assert.match(text.stdout, /; machine time 0:00:0\d \([\d.]+ s accelerating\); cost [\d.]+ EUR; electrodes [\d.]+\n/);
  // The other reports: JUnit's system-out and `essi stats` carry it, `essi diff` compares it.
  const junit = essi(['check', '--format', 'junit', '--profile', path.join(d, 'p.json'), 'tests/data/machine_time/line.esi']);
  assert.match(junit.stdout, /<system-out>[^<]*; machine time 0:00:03 \(0\.2 s accelerating\); cost [\d.]+ EUR; electrodes [\d.]+/);
  const stats = essi(['stats', '--profile', path.join(d, 'p.json'), 'tests/data/machine_time/line.esi']);
  assert.match(stats.stdout, /machine time: +3\.2 s \(0:00:03\)/);
  const diff = essi(['diff', '--format', 'json', '--profile', path.join(d, 'p.json'), 'tests/data/machine_time/line.esi',
    'tests/data/machine_time/square.esi']);
  const change = JSON.parse(diff.stdout).stats_change;
  assert.equal(change.machine_time_s.a, 3.2);  // 1.2 s and a pierce of 2 s
  assert.equal(change.machine_time_s.b, 6.759032);  // square.expected's 4.759032 s and the pierce
  assert.ok('cost_total' in change);
  // Without the keys nothing of it is in the report.
  const plain = JSON.parse(essi(['check', '--format', 'json', 'examples/']).stdout);
  for (const f of plain.files)
    for (const key of ['machine_time_s', 'machine_time_breakdown_s', 'cost', 'consumables']) assert.ok(!(key in f.stats), key);
});
