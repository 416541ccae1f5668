// The package in browsers and bundlers: the WebAssembly module fetched from beside this
// file (bundlers rewrite that URL) and instantiated once, on import.
import init from './x3dcheck_wasm.js';

await init({ module_or_path: new URL('./x3dcheck_wasm_bg.wasm', import.meta.url) });

export { check, rules, version } from './x3dcheck_wasm.js';
