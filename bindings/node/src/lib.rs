//! The native half of the `x3dcheck` npm package: [`x3dcheck::api`] behind functions that
//! give the JSON report as a string; `index.js` parses it into the `Report` of
//! `index.d.ts`. The async variant checks on libuv's thread pool, off the event loop.

use std::path::PathBuf;

use napi::bindgen_prelude::{AsyncTask, Buffer, Either};
use napi::{Env, Error, Result, Task};
use napi_derive::napi;
use x3dcheck::api;

/// The options of `check` (index.d.ts documents them).
#[napi(object)]
#[derive(Clone, Default)]
pub struct CheckOptions {
    pub path: Option<String>,
    pub level: Option<String>,
    pub select: Option<Vec<String>>,
    pub ignore: Option<Vec<String>>,
    pub config: Option<String>,
}

impl CheckOptions {
    fn to_api(&self) -> Result<api::Options> {
        Ok(api::Options {
            path: self.path.as_ref().map(PathBuf::from),
            level: self
                .level
                .as_deref()
                .map(api::level)
                .transpose()
                .map_err(to_js)?,
            select: self.select.clone().unwrap_or_default(),
            ignore: self.ignore.clone().unwrap_or_default(),
            config: self.config.as_ref().map(PathBuf::from),
        })
    }
}

fn to_js(error: api::Error) -> Error {
    Error::from_reason(error.to_string())
}

fn check(source: &[u8], options: &CheckOptions) -> Result<String> {
    let report = api::check(source, &options.to_api()?).map_err(to_js)?;
    Ok(report.to_json())
}

fn bytes(source: &Either<String, Buffer>) -> &[u8] {
    match source {
        Either::A(text) => text.as_bytes(),
        Either::B(buffer) => buffer,
    }
}

/// The JSON report of checking `source`, on this thread.
#[napi]
pub fn check_json(source: Either<String, Buffer>, options: Option<CheckOptions>) -> Result<String> {
    check(bytes(&source), &options.unwrap_or_default())
}

/// The JSON report of checking the file at `path`, on this thread.
#[napi]
pub fn check_file_json(path: String, options: Option<CheckOptions>) -> Result<String> {
    let options = options.unwrap_or_default().to_api()?;
    let report = api::check_file(&path, &options).map_err(to_js)?;
    Ok(report.to_json())
}

/// A check run on the thread pool.
pub struct CheckTask {
    source: Vec<u8>,
    options: CheckOptions,
}

impl Task for CheckTask {
    type Output = String;
    type JsValue = String;

    fn compute(&mut self) -> Result<String> {
        check(&self.source, &self.options)
    }

    fn resolve(&mut self, _env: Env, report: String) -> Result<String> {
        Ok(report)
    }
}

/// A promise of the JSON report of checking `source` (copied: JavaScript may change a
/// buffer while the check runs).
#[napi]
pub fn check_json_async(
    source: Either<String, Buffer>,
    options: Option<CheckOptions>,
) -> AsyncTask<CheckTask> {
    AsyncTask::new(CheckTask {
        source: bytes(&source).to_vec(),
        options: options.unwrap_or_default(),
    })
}

/// The rules as a JSON array (`x3dcheck rules --format json`).
#[napi]
pub fn rules_json() -> String {
    serde_json::to_string(&api::rules()).expect("the rules serialize")
}
