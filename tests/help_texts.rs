//! Help lines whose advice depends on the case (the concise reports the fixture snapshots
//! pin show no help): FACE_NOT_CONVEX does not suggest `convex='false'` for a face that is
//! not planar, and X3D_VERSION_MISSING names the version it checks against.

mod common;

/// The help of each finding of `code` in a fixture scene, checked at the deep level.
fn helps(fixture: &str, code: &str) -> Vec<String> {
    common::fixture_findings(fixture, code)
        .into_iter()
        .map(|d| d.help.unwrap_or_default())
        .collect()
}

#[test]
fn convex_false_is_suggested_for_concave_faces_only() {
    let helps = helps("FACE_NOT_CONVEX/fail.x3d", "FACE_NOT_CONVEX");
    assert_eq!(helps.len(), 2, "{helps:?}");
    assert!(helps[0].starts_with("set convex='false'"), "{}", helps[0]);
    assert!(
        helps[1].starts_with("split the faces into planar ones"),
        "{}",
        helps[1]
    );
    assert!(helps[1].contains("undefined either way"), "{}", helps[1]);
}

#[test]
fn a_missing_version_is_checked_against_the_one_the_header_names() {
    for (fixture, version, source) in [
        ("X3D_VERSION_MISSING/fail_doctype.x3d", "3.0", "DOCTYPE"),
        (
            "X3D_VERSION_MISSING/fail_schema_location.x3dj",
            "3.3",
            "schema location",
        ),
    ] {
        let helps = helps(fixture, "X3D_VERSION_MISSING");
        assert_eq!(
            helps,
            [format!("add version='{version}': the {source} names X3D {version}, so the scene is checked against {version}")],
            "{fixture}"
        );
    }
    let helps = helps("X3D_VERSION_MISSING/fail.x3d", "X3D_VERSION_MISSING");
    assert!(helps[0].ends_with("checking against 4.1"), "{helps:?}");
}
