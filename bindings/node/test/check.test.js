// The npm package against the command line: same findings, same JSON bytes.
'use strict';

const test = require('node:test');
const assert = require('node:assert/strict');
const { execFileSync } = require('node:child_process');
const fs = require('node:fs');
const path = require('node:path');

const x3dcheck = require('..');

const repo = path.resolve(__dirname, '../../..');
const fail = path.join(repo, 'corpus/rules/INDEX_OUT_OF_RANGE/fail.x3d');
const scene =
  "<X3D profile='Interchange' version='4.0'><Scene><Shape>" +
  "<IndexedFaceSet coordIndex='0 1 5 -1'><Coordinate point='0 0 0 1 0 0 0 1 0'/>" +
  '</IndexedFaceSet></Shape></Scene></X3D>';

test('a string is checked into diagnostics', () => {
  const report = x3dcheck.check(scene);
  assert.equal(report.diagnostics.length, 1);
  const [d] = report.diagnostics;
  assert.deepEqual([d.code, d.severity, d.line, d.column], ['INDEX_OUT_OF_RANGE', 'error', 1, 88]);
  assert.equal(d.file, '<stdin>');
  assert.ok(d.path.startsWith('/X3D/Scene/Shape'));
  assert.equal(report.summary.errors, 1);
});

// The x3dcheck binary of the workspace's release build (cargo test --release builds it,
// before this step in .ci/run); without it this one comparison is skipped, saying so.
const cli = path.join(repo, 'target/release/x3dcheck');
const noCli = !fs.existsSync(cli) && 'no target/release/x3dcheck: run cargo test --workspace --release first';

test('the JSON is the command line JSON', { skip: noCli }, () => {
  let expected;
  try {
    execFileSync(cli, [fail, '--format', 'json'], { encoding: 'utf8' });
    assert.fail('the command line found nothing');
  } catch (error) {
    assert.equal(error.status, 1);
    expected = error.stdout;
  }
  const report = x3dcheck.check(fs.readFileSync(fail), { path: fail });
  assert.equal(report.toJsonText(), expected);
  assert.equal(x3dcheck.checkFile(fail).toJsonText(), expected);
});

test('the async variant gives the same report, off the event loop', async () => {
  const points = Array.from({ length: 100000 }, (_, i) => `${i} ${i} ${i}`).join(' ');
  const big = scene.replace('0 0 0 1 0 0 0 1 0', points);
  let ticks = 0;
  const timer = setInterval(() => ticks++, 1);
  const report = await x3dcheck.checkAsync(big, { level: 'deep' });
  clearInterval(timer);
  assert.equal(report.toJsonText(), x3dcheck.check(big, { level: 'deep' }).toJsonText());
  assert.ok(ticks > 0, 'the event loop ran while checking');
});

test('select, ignore, level and errors', async () => {
  assert.equal(x3dcheck.check(scene, { ignore: ['index_'] }).diagnostics.length, 0);
  assert.equal(x3dcheck.check(scene, { level: 'fast' }).diagnostics.length, 0);
  assert.throws(() => x3dcheck.check(scene, { select: ['NO_SUCH_CODE'] }), /NO_SUCH_CODE/);
  await assert.rejects(x3dcheck.checkAsync(scene, { level: 'thorough' }), /unknown level/);
  assert.throws(() => x3dcheck.checkFile(path.join(repo, 'no-such-file.x3d')));
});

test('rules are listed', () => {
  const rules = x3dcheck.rules();
  assert.ok(rules.some((r) => r.code === 'INDEX_OUT_OF_RANGE' && r.doc));
});

test("the README's example runs", (t) => {
  const readme = fs.readFileSync(path.join(repo, 'README.md'), 'utf8');
  const libraries = readme.slice(readme.indexOf('## Libraries'));
  const example = libraries.split('```js\n')[1].split('```')[0];
  const dir = fs.mkdtempSync(path.join(require('node:os').tmpdir(), 'x3dcheck-'));
  fs.copyFileSync(fail, path.join(dir, 'scene.x3d'));
  const cwd = process.cwd();
  process.chdir(dir);
  const lines = [];
  t.mock.method(console, 'log', (line) => lines.push(line));
  try {
    const load = (name) => (name === 'x3dcheck-native' ? x3dcheck : require(name));
    new Function('require', example)(load);
  } finally {
    process.chdir(cwd);
    fs.rmSync(dir, { recursive: true });
  }
  assert.ok(lines.some((l) => l.startsWith('scene.x3d:5:48: error[INDEX_OUT_OF_RANGE]')), lines.join('\n'));
});
