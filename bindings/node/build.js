// What `npm install` runs: builds the native addon (crate x3dcheck-node, release) with
// cargo and copies it to x3dcheck.node, which index.js loads.
'use strict';

const { execFileSync } = require('node:child_process');
const fs = require('node:fs');
const path = require('node:path');

const output = execFileSync(
  'cargo',
  ['build', '--release', '-p', 'x3dcheck-node', '--message-format=json-render-diagnostics'],
  { cwd: __dirname, stdio: ['ignore', 'pipe', 'inherit'], maxBuffer: 1 << 30, encoding: 'utf8' },
);
// cargo names the library by platform (.so, .dylib, .dll): its own message says which.
const library = output
  .split('\n')
  .filter((line) => line.startsWith('{'))
  .map((line) => JSON.parse(line))
  .filter((m) => m.reason === 'compiler-artifact' && m.target.name === 'x3dcheck_node')
  .flatMap((m) => m.filenames)
  .find((file) => /\.(so|dylib|dll)$/.test(file));
if (!library) {
  throw new Error('cargo built no x3dcheck_node library');
}
fs.copyFileSync(library, path.join(__dirname, 'x3dcheck.node'));
