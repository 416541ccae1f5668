//! The clause a finding cites where it is not its rule's (the concise reports the fixture
//! snapshots pin do not show it): a sequencer's KEY_DECREASING cites 30.3.1
//! X3DSequencerNode, an interpolator's 19.2.2.

use std::path::Path;

use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;

/// The message and clause of each finding of `code` in a fixture scene.
fn cited(fixture: &str, code: &str) -> Vec<(String, String)> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("corpus/rules")
        .join(fixture);
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let report = x3dcheck::check_source(fixture, &std::fs::read(path).unwrap(), &config);
    report
        .diagnostics
        .into_iter()
        .filter(|d| d.code == code)
        .map(|d| (d.message, d.clause.to_string()))
        .collect()
}

#[test]
fn sequencer_keys_cite_the_sequencer_clause() {
    let sequencers = cited("KEY_DECREASING/fail_sequencer.x3d", "KEY_DECREASING");
    assert_eq!(sequencers.len(), 2, "{sequencers:?}");
    assert!(
        sequencers.iter().all(|(_, clause)| clause == "30.3.1"),
        "{sequencers:?}"
    );
    let interpolators = cited("KEY_DECREASING/fail.x3d", "KEY_DECREASING");
    assert_eq!(interpolators.len(), 2, "{interpolators:?}");
    assert!(
        interpolators.iter().all(|(_, clause)| clause == "19.2.2"),
        "{interpolators:?}"
    );
}
