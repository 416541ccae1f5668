//! The clause a finding cites where it is not its rule's (the concise reports the fixture
//! snapshots pin do not show it): a sequencer's KEY_DECREASING cites 30.3.1
//! X3DSequencerNode, an interpolator's 19.2.2.

mod common;

/// The message and clause of each finding of `code` in a fixture scene.
fn cited(fixture: &str, code: &str) -> Vec<(String, String)> {
    common::fixture_findings(fixture, code)
        .into_iter()
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
