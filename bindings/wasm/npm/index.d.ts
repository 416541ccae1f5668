// The types of the x3dcheck package (generated from the Rust crate, bindings/wasm).
export type {
  CheckOptions, Diagnostic, FileReport, Fix, Level, RelatedPlace, Report, Rule, Severity, Summary,
} from './x3dcheck_wasm.js';
export { check, rules, version } from './x3dcheck_wasm.js';
