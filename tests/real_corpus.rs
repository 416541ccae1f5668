//! Every real scene of `../shared/corpus` is checked without a panic, and every diagnostic
//! has a place. The corpus is read from beside the repository, never copied in.

mod common;

use common::corpus_files;
use std::time::{Duration, Instant};

use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;

/// Generous: the largest corpus file takes milliseconds; this only catches hangs.
const MAX_SECONDS_PER_FILE: u64 = 20;

/// Checks every corpus file with one of `extensions`; how many there were.
fn check_all(extensions: &[&str]) -> usize {
    let files = corpus_files(extensions);
    assert!(!files.is_empty());
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let mut problems = Vec::new();
    for path in &files {
        let source = std::fs::read(path).unwrap();
        let started = Instant::now();
        let name = path.display().to_string();
        let result = std::panic::catch_unwind(|| x3dcheck::check_source(&name, &source, &config));
        let Ok(report) = result else {
            problems.push(format!("{name}: panicked"));
            continue;
        };
        if started.elapsed() > Duration::from_secs(MAX_SECONDS_PER_FILE) {
            problems.push(format!("{name}: took {:?}", started.elapsed()));
        }
        for d in &report.diagnostics {
            if d.line == 0
                || d.column == 0
                || d.path.is_empty()
                || d.clause.is_empty()
                || d.message.is_empty()
            {
                problems.push(format!(
                    "{name}: {} lacks a place, path, clause or message: {d:?}",
                    d.code
                ));
            }
        }
        let json = x3dcheck::report::json::render(std::slice::from_ref(&report), None);
        if let Err(e) = serde_json::from_str::<serde_json::Value>(&json) {
            problems.push(format!("{name}: JSON report does not parse: {e}"));
        }
    }
    assert!(
        problems.is_empty(),
        "{} of {} files:\n{}",
        problems.len(),
        files.len(),
        problems.join("\n")
    );
    files.len()
}

#[test]
fn every_xml_scene_is_checked_cleanly() {
    check_all(&["x3d"]);
}

#[test]
fn every_json_scene_is_checked_cleanly() {
    check_all(&["json", "x3dj"]);
}

/// Castle Game Engine's demo models in ClassicVRML and VRML97 (and gzip: ENCODING_UNSUPPORTED
/// until the gzip reader lands, a diagnostic with a place like any other).
#[test]
fn every_classic_and_vrml97_scene_is_checked_cleanly() {
    let scenes = check_all(&["x3dv", "wrl", "gz", "x3dvz", "wrz"]);
    assert_eq!(scenes, 357, "castle-demo-models-classic holds 357 scenes");
}
