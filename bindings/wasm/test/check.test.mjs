// The npm package as a user gets it: run by .ci/wasm.sh in a fresh project where it is
// installed from `npm pack`, with no Rust toolchain on PATH. X3DCHECK_REPO names the
// checkout whose corpus/rules scenes are read (default: this file's repository).
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

import { check, rules, version } from 'x3dcheck';

const repo = process.env.X3DCHECK_REPO ?? path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const scene = (name) => readFileSync(path.join(repo, 'corpus/rules', name));
const codes = (report) => report.files.flatMap((f) => f.diagnostics.map((d) => d.code));

const valid =
  "<X3D profile='Interchange' version='4.0'><Scene><Shape><Box size='1 2 3'/></Shape></Scene></X3D>";

test('a valid scene gives no errors', () => {
  const report = check(valid);
  assert.equal(report.tool, 'x3dcheck');
  assert.equal(report.version, version());
  assert.equal(report.files.length, 1);
  assert.equal(report.files[0].path, '<stdin>');
  assert.equal(report.summary.errors, 0);
});

test('a known-bad scene gives its code, with its place', () => {
  const report = check(scene('INDEX_OUT_OF_RANGE/fail.x3d'), { path: 'fail.x3d' });
  const found = report.files[0].diagnostics.filter((d) => d.code === 'INDEX_OUT_OF_RANGE');
  assert.ok(found.length > 0, JSON.stringify(codes(report)));
  assert.equal(found[0].severity, 'error');
  assert.equal(report.files[0].path, 'fail.x3d');
  assert.ok(found[0].line > 1);
});

test('gzip-compressed bytes are read', () => {
  const report = check(gzipSync(scene('INDEX_OUT_OF_RANGE/fail.x3d')));
  assert.equal(report.files[0].compressed, true);
  assert.ok(codes(report).includes('INDEX_OUT_OF_RANGE'));
});

test('ClassicVRML and JSON scenes are read', () => {
  const vrml = check('#X3D V4.0 utf8\nPROFILE Interchange\nShape { geometry Box { size -1 1 1 } }\n');
  assert.equal(vrml.files[0].encoding, 'classicvrml');
  assert.ok(vrml.summary.errors > 0, JSON.stringify(codes(vrml)));
  const json = check(scene('INDEX_OUT_OF_RANGE/fail_json.json'));
  assert.equal(json.files[0].encoding, 'json');
  assert.ok(codes(json).includes('INDEX_OUT_OF_RANGE'));
});

test('options select, ignore and level as on the command line', () => {
  const bad = scene('INDEX_OUT_OF_RANGE/fail.x3d');
  assert.deepEqual([...new Set(codes(check(bad, { select: ['INDEX_OUT_OF_RANGE'] })))], ['INDEX_OUT_OF_RANGE']);
  assert.ok(!codes(check(bad, { ignore: ['index_'], level: 'deep' })).includes('INDEX_OUT_OF_RANGE'));
  assert.throws(() => check(bad, { select: ['NO_SUCH_CODE'] }), /NO_SUCH_CODE/);
  assert.throws(() => check(bad, { level: 'thorough' }), /unknown level/);
});

test('SARIF', () => {
  const log = check(scene('INDEX_OUT_OF_RANGE/fail.x3d'), { format: 'sarif' });
  assert.equal(log.version, '2.1.0');
  assert.ok(log.runs[0].results.some((r) => r.ruleId === 'INDEX_OUT_OF_RANGE'));
});

test('rules() is the catalogue', () => {
  const all = rules();
  assert.ok(all.length > 100);
  const rule = all.find((r) => r.code === 'INDEX_OUT_OF_RANGE');
  assert.equal(rule.severity, 'error');
  assert.ok(rule.doc.includes('## What it does'));
});

test('a shader is VALIDATION_INCOMPLETE: this build has no GLSL compiler', () => {
  const report = check(scene('SHADER_COMPILE_ERROR/pass.x3d'));
  const notes = report.files[0].diagnostics.filter((d) => d.code === 'VALIDATION_INCOMPLETE');
  assert.ok(notes.some((d) => d.message.includes('no GLSL compiler')), JSON.stringify(notes));
  assert.ok(!codes(report).includes('SHADER_COMPILE_ERROR'));
});

// WebAssembly has no file system: the files url fields name are not read, and the deep level
// says so for each relative url instead of calling it unresolved.
test('url fields are not followed: VALIDATION_INCOMPLETE, never URL_UNRESOLVED', () => {
  const parent =
    "<X3D profile='Immersive' version='4.0'><Scene><Inline url='\"parts/child.x3d\"'/></Scene></X3D>";
  const report = check(parent, { path: 'scenes/main.x3d', level: 'deep' });
  assert.deepEqual(report.files.map((f) => f.path), ['scenes/main.x3d']);
  const found = codes(report);
  assert.ok(found.includes('VALIDATION_INCOMPLETE'), JSON.stringify(found));
  assert.ok(!found.includes('URL_UNRESOLVED'), JSON.stringify(found));
  assert.throws(() => check(parent, { resolve: () => null }), /reads no other file/);
});

test('bad input throws', () => {
  assert.throws(() => check(42), /string or a Uint8Array/);
  assert.throws(() => check(valid, { format: 'xml' }), /unknown format/);
});
