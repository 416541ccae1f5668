//! Helpers shared by the integration tests: scratch directories, running the binary, and
//! the real corpus beside the repository. Each test binary uses a part of them.
#![allow(dead_code)]

pub mod summary;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A fresh directory per test (and per test binary: the process id differs) holding
/// `files`, whose names may contain subdirectories.
pub fn scratch(test: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("x3dcheck-test-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in files {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    dir
}

/// Runs the x3dcheck binary in `dir`.
pub fn x3dcheck(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_x3dcheck"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).unwrap()
}

/// The files of `../shared/corpus` whose extension is one of `extensions` (any case),
/// sorted by path.
pub fn corpus_files(extensions: &[&str]) -> Vec<PathBuf> {
    files_under(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus"),
        extensions,
    )
}

/// The files under `root` whose extension is one of `extensions` (any case), sorted by
/// path.
pub fn files_under(root: &Path, extensions: &[&str]) -> Vec<PathBuf> {
    assert!(root.is_dir(), "{} is missing", root.display());
    let mut files = Vec::new();
    let mut dirs = vec![root.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if entry.file_type().unwrap().is_dir() {
                dirs.push(path);
            } else if path
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| extensions.contains(&e.to_ascii_lowercase().as_str()))
            {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// The findings of `code` in the rule fixture `fixture` (a path under `corpus/rules/`),
/// checked at the deep level.
pub fn fixture_findings(fixture: &str, code: &str) -> Vec<x3dcheck::report::Resolved> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("corpus/rules")
        .join(fixture);
    let config = x3dcheck::config::CheckConfig {
        level: x3dcheck::diagnostic::Level::Deep,
        ..x3dcheck::config::CheckConfig::default()
    };
    let report = x3dcheck::check_source(fixture, &std::fs::read(path).unwrap(), &config);
    report
        .diagnostics
        .into_iter()
        .filter(|d| d.code == code)
        .collect()
}
