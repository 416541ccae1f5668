//! The native half of the `x3dcheck` Python package: [`x3dcheck::api`] and the command line
//! behind four functions that take and give strings. `python/x3dcheck/__init__.py` turns
//! the JSON into typed objects. Checking runs with the GIL released.

use std::ffi::OsString;
use std::path::PathBuf;

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use x3dcheck::api;

create_exception!(
    _native,
    CheckError,
    PyException,
    "Nothing was checked: why is the message."
);

fn options(
    path: Option<PathBuf>,
    level: Option<&str>,
    select: Vec<String>,
    ignore: Vec<String>,
    config: Option<PathBuf>,
) -> PyResult<api::Options> {
    Ok(api::Options {
        path,
        level: level.map(api::level).transpose().map_err(to_py)?,
        select,
        ignore,
        config,
    })
}

fn to_py(error: api::Error) -> PyErr {
    CheckError::new_err(error.to_string())
}

/// The JSON report of checking `source` (bytes).
#[pyfunction]
#[pyo3(signature = (source, path=None, level=None, select=Vec::new(), ignore=Vec::new(), config=None))]
fn check(
    py: Python<'_>,
    source: &[u8],
    path: Option<PathBuf>,
    level: Option<&str>,
    select: Vec<String>,
    ignore: Vec<String>,
    config: Option<PathBuf>,
) -> PyResult<String> {
    let options = options(path, level, select, ignore, config)?;
    py.detach(|| api::check(source, &options))
        .map(|report| report.to_json())
        .map_err(to_py)
}

/// The JSON report of checking the file at `path`.
#[pyfunction]
#[pyo3(signature = (path, level=None, select=Vec::new(), ignore=Vec::new(), config=None))]
fn check_file(
    py: Python<'_>,
    path: PathBuf,
    level: Option<&str>,
    select: Vec<String>,
    ignore: Vec<String>,
    config: Option<PathBuf>,
) -> PyResult<String> {
    let options = options(None, level, select, ignore, config)?;
    py.detach(|| api::check_file(&path, &options))
        .map(|report| report.to_json())
        .map_err(to_py)
}

/// The rules as a JSON array (`x3dcheck rules --format json`).
#[pyfunction]
fn rules_json() -> String {
    serde_json::to_string(&api::rules()).expect("the rules serialize")
}

/// Runs the command line with `argv` (program name first); returns its exit code.
#[pyfunction]
fn main(py: Python<'_>, argv: Vec<OsString>) -> u8 {
    py.detach(|| x3dcheck::cli::main(argv))
}

#[pymodule]
fn _native(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add("CheckError", module.py().get_type::<CheckError>())?;
    module.add_function(wrap_pyfunction!(check, module)?)?;
    module.add_function(wrap_pyfunction!(check_file, module)?)?;
    module.add_function(wrap_pyfunction!(rules_json, module)?)?;
    module.add_function(wrap_pyfunction!(main, module)?)?;
    Ok(())
}
