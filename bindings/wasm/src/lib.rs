//! The x3dcheck checker in WebAssembly: [`x3dcheck::api`] (what the command line, the
//! Python and the Node.js packages call) behind `check`, `rules` and `version` for
//! JavaScript, built by `build.sh` into the npm package and the web page's module.
//!
//! Nothing here touches a file system or spawns a thread: the caller hands in the scene;
//! the files its url fields name (Inlines, textures, external prototypes) are not read, and
//! each relative url is reported as VALIDATION_INCOMPLETE at the deep level. This build has
//! no GLSL compiler (glslang is C++): shaders are reported as VALIDATION_INCOMPLETE too.

use std::path::PathBuf;

use js_sys::{Array, Reflect, Uint8Array, JSON};
use wasm_bindgen::prelude::*;
use x3dcheck::api;

#[wasm_bindgen(typescript_custom_section)]
const TYPES: &'static str = r#"
export type Severity = 'error' | 'warning' | 'info' | 'hint';
export type Level = 'fast' | 'standard' | 'deep';

export interface CheckOptions {
  /** The name the scene is reported under (`<stdin>` when absent). */
  path?: string;
  /** fast, standard or deep (default: standard). */
  level?: Level;
  /** Codes, prefixes of codes (`BACK_MATERIAL_`) or `ALL`, in any case. */
  select?: string[];
  ignore?: string[];
  /** `json` (default): the report of `x3dcheck --format json`; `sarif`: the SARIF 2.1.0
   * log of `--format sarif`. */
  format?: 'json' | 'sarif';
}

export interface RelatedPlace {
  line: number;
  column: number;
  message: string;
}

export interface Fix {
  title: string;
  applicability: 'safe' | 'unsafe';
  edits: { line: number; column: number; endLine: number; endColumn: number; content: string }[];
}

export interface Diagnostic {
  code: string;
  severity: Severity;
  message: string;
  /** 1-based; columns count Unicode characters. */
  line: number;
  column: number;
  endLine: number;
  endColumn: number;
  /** The structural path: `/X3D/Scene/Shape[0]/Appearance`. */
  path: string;
  /** The ISO/IEC 19775-1 clause. */
  clause: string;
  index?: number;
  indices?: number[];
  value?: string;
  help?: string;
  related?: RelatedPlace[];
  count?: number;
  fix?: Fix;
}

export interface FileReport {
  path: string;
  encoding: 'xml' | 'json' | 'classicvrml' | 'vrml97' | null;
  compressed?: boolean;
  x3dVersion: string | null;
  profile: string | null;
  diagnostics: Diagnostic[];
  truncated: boolean;
  suppressed?: number;
  stats: Record<string, unknown>;
}

export interface Summary {
  files: number;
  errors: number;
  warnings: number;
  infos: number;
  hints: number;
  suppressed?: number;
}

/** The report of `x3dcheck --format json`. */
export interface Report {
  tool: 'x3dcheck';
  version: string;
  /** The input, then the files its Inlines load (deep level). */
  files: FileReport[];
  summary: Summary;
}

export interface Rule {
  code: string;
  severity: Severity;
  level: Level;
  versions: string;
  clause: string;
  summary: string;
  /** Markdown. */
  doc: string;
}
"#;

/// Checks a scene (a string, or the bytes of a file: any encoding, gzip-compressed or not)
/// into the command line's JSON report (or SARIF log). Throws when nothing could be
/// checked: an unknown code, level or format.
#[wasm_bindgen(unchecked_return_type = "Report")]
pub fn check(
    #[wasm_bindgen(unchecked_param_type = "string | Uint8Array")] input: JsValue,
    #[wasm_bindgen(unchecked_param_type = "CheckOptions")] options: Option<js_sys::Object>,
) -> Result<JsValue, JsError> {
    let source = match input.as_string() {
        Some(text) => text.into_bytes(),
        None => input
            .dyn_into::<Uint8Array>()
            .map_err(|_| JsError::new("check: the scene must be a string or a Uint8Array"))?
            .to_vec(),
    };
    let options = options.map(JsValue::from).unwrap_or(JsValue::UNDEFINED);
    let format = string_option(&options, "format")?;
    // An option this build cannot honour is refused, not ignored.
    if get(&options, "resolve")?.is_some() {
        return Err(JsError::new(
            "check: options.resolve: this build reads no other file (Inlines, textures, external prototypes)",
        ));
    }
    let api_options = api::Options {
        path: string_option(&options, "path")?.map(PathBuf::from),
        level: string_option(&options, "level")?
            .as_deref()
            .map(api::level)
            .transpose()
            .map_err(to_js)?,
        select: strings_option(&options, "select")?,
        ignore: strings_option(&options, "ignore")?,
        config: None,
    };
    let text = match format.as_deref() {
        None | Some("json") => api::check(&source, &api_options).map_err(to_js)?.to_json(),
        Some("sarif") => api::check_sarif(&source, &api_options).map_err(to_js)?,
        Some(other) => {
            return Err(JsError::new(&format!(
                "unknown format `{other}` (json or sarif)"
            )))
        }
    };
    JSON::parse(&text).map_err(|_| JsError::new("the report is not JSON"))
}

/// Every rule, in catalogue order, as `x3dcheck rules --format json` lists them.
#[wasm_bindgen(unchecked_return_type = "Rule[]")]
pub fn rules() -> Result<JsValue, JsError> {
    let text = serde_json::to_string(&api::rules()).map_err(|e| JsError::new(&e.to_string()))?;
    JSON::parse(&text).map_err(|_| JsError::new("the rules are not JSON"))
}

/// The version of x3dcheck, as the report's `version` gives it.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

fn to_js(error: api::Error) -> JsError {
    JsError::new(&error.to_string())
}

fn get(options: &JsValue, name: &str) -> Result<Option<JsValue>, JsError> {
    if options.is_undefined() || options.is_null() {
        return Ok(None);
    }
    let value = Reflect::get(options, &JsValue::from_str(name))
        .map_err(|_| JsError::new(&format!("options.{name} cannot be read")))?;
    Ok((!value.is_undefined() && !value.is_null()).then_some(value))
}

fn string_option(options: &JsValue, name: &str) -> Result<Option<String>, JsError> {
    get(options, name)?
        .map(|v| {
            v.as_string()
                .ok_or_else(|| JsError::new(&format!("options.{name} must be a string")))
        })
        .transpose()
}

fn strings_option(options: &JsValue, name: &str) -> Result<Vec<String>, JsError> {
    let Some(value) = get(options, name)? else {
        return Ok(Vec::new());
    };
    let wrong = || JsError::new(&format!("options.{name} must be an array of strings"));
    let array = value.dyn_into::<Array>().map_err(|_| wrong())?;
    array
        .iter()
        .map(|v| v.as_string().ok_or_else(wrong))
        .collect()
}
