// The package in Node.js: the WebAssembly module read from beside this file and
// instantiated synchronously, once, on import.
import { readFileSync } from 'node:fs';
import { initSync } from './x3dcheck_wasm.js';

initSync({ module: readFileSync(new URL('./x3dcheck_wasm_bg.wasm', import.meta.url)) });

export { check, rules, version } from './x3dcheck_wasm.js';
