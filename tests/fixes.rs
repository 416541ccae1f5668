//! `--fix`, `--unsafe-fixes` and `--diff` (issue 17): each fix on a scene of
//! `corpus/rules/CODE/`, copied to a temporary directory, fixed by the binary and compared
//! with the expected text `corpus/rules/CODE/fixed-SCENE.txt`, byte for byte (so the bytes
//! outside the edits are pinned as the input's); a second `--fix` changes nothing;
//! `--diff` writes nothing; unsafe
//! fixes need their flag; stdin's fixed text goes to stdout; compressed input is not fixed.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};

fn corpus(code: &str, scene: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("corpus/rules")
        .join(code)
        .join(scene)
}

/// A fresh temporary directory for one call: tests run in parallel and several copy the
/// same scene, so each call gets its own number.
fn temp_dir(name: &str) -> PathBuf {
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!(
        "x3dcheck-fixes-{}-{call}-{name}",
        std::process::id()
    ));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn x3dcheck(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_x3dcheck"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

/// Copies the scene into a temporary directory; its path there.
fn copy(code: &str, scene: &str) -> (PathBuf, PathBuf) {
    let dir = temp_dir(&format!("{code}-{scene}"));
    let target = dir.join(scene);
    fs::copy(corpus(code, scene), &target).unwrap();
    (dir, target)
}

/// Fixes a copy of `corpus/rules/CODE/SCENE` with `flags`, checks it against
/// `fixed-SCENE.txt` (every byte: those outside the edits stay the input's) and checks
/// that a second run changes nothing; returns the first run's stdout.
fn fixes_to_expected(code: &str, scene: &str, flags: &[&str]) -> String {
    let (dir, target) = copy(code, scene);
    let before = fs::read(&target).unwrap();
    let mut args = vec!["--fix"];
    args.extend_from_slice(flags);
    args.push(scene);
    let first = x3dcheck(&args, &dir);
    let after = fs::read(&target).unwrap();
    let expected = fs::read(corpus(code, &format!("fixed-{scene}.txt"))).unwrap();
    assert_eq!(
        String::from_utf8_lossy(&after),
        String::from_utf8_lossy(&expected),
        "{code}/{scene} fixed; stdout:\n{}\nstderr:\n{}",
        String::from_utf8_lossy(&first.stdout),
        String::from_utf8_lossy(&first.stderr)
    );
    assert_ne!(before, after, "{code}/{scene}: nothing was fixed");
    let second = x3dcheck(&args, &dir);
    assert_eq!(
        fs::read(&target).unwrap(),
        after,
        "{code}/{scene}: a second --fix changed it"
    );
    let stdout = String::from_utf8_lossy(&second.stdout);
    assert!(stdout.contains("Fixed 0 findings"), "{stdout}");
    fs::remove_dir_all(dir).unwrap();
    String::from_utf8_lossy(&first.stdout).into_owned()
}

#[test]
fn a_node_name_with_a_case_slip_is_renamed_in_each_encoding() {
    for scene in ["fail.x3d", "fail_case.x3dj", "fail_case.x3dv"] {
        let out = fixes_to_expected("NODE_UNKNOWN", scene, &[]);
        assert!(out.contains("Fixed "), "{out}");
    }
}

#[test]
fn a_field_name_with_a_case_slip_is_renamed_in_each_encoding() {
    for scene in ["fail.x3d", "fail_case.x3dj", "fail_case.x3dv"] {
        fixes_to_expected("FIELD_UNKNOWN", scene, &[]);
    }
}

#[test]
fn missing_component_statements_are_declared_in_each_encoding() {
    for scene in [
        "fail.x3d",
        "fail2.x3d",
        "fail_head.x3d",
        "fail_component_statement.x3d",
        "fail.x3dj",
        "fail.x3dv",
    ] {
        let out = fixes_to_expected("COMPONENT_LEVEL_INSUFFICIENT", scene, &[]);
        assert!(
            !out.contains("COMPONENT_LEVEL_INSUFFICIENT"),
            "{scene}: {out}"
        );
    }
}

#[test]
fn two_sided_material_becomes_material_and_back_material_with_unsafe_fixes() {
    for scene in ["fail.x3d", "fail_same_sides.x3d", "fail.x3dj", "fail.x3dv"] {
        let out = fixes_to_expected("NODE_DEPRECATED", scene, &["--unsafe-fixes"]);
        assert!(!out.contains("NODE_DEPRECATED"), "{scene}: {out}");
    }
}

/// The `fail_doctype` scenes name the old version's DTD and schemas in their header, which
/// the fix raises too; the same names in a `meta` of the head stay as written.
#[test]
fn the_version_is_raised_with_unsafe_fixes() {
    let scenes = [
        "fail.x3d",
        "fail.x3dj",
        "fail.x3dv",
        "fail_doctype.x3d",
        "fail_doctype.x3dj",
    ];
    for scene in scenes {
        let out = fixes_to_expected("NODE_NOT_IN_VERSION", scene, &["--unsafe-fixes"]);
        assert!(!out.contains("NODE_NOT_IN_VERSION"), "{scene}: {out}");
    }
}

#[test]
fn deprecated_texture_properties_fields_are_removed_with_unsafe_fixes() {
    for scene in ["fail.x3d", "fail.x3dj", "fail.x3dv"] {
        let out = fixes_to_expected("FIELD_DEPRECATED", scene, &["--unsafe-fixes"]);
        assert!(!out.contains("FIELD_DEPRECATED"), "{scene}: {out}");
    }
}

#[test]
fn unsafe_fixes_need_their_flag() {
    let (dir, target) = copy("NODE_DEPRECATED", "fail.x3d");
    let before = fs::read(&target).unwrap();
    let out = x3dcheck(&["--fix", "fail.x3d"], &dir);
    assert_eq!(fs::read(&target).unwrap(), before);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("Fixed 0 findings"), "{stdout}");
    assert!(
        stdout.contains("0 fixable with --fix (1 more with --unsafe-fixes)"),
        "{stdout}"
    );
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_report_marks_fixable_findings_and_counts_them() {
    let (dir, _) = copy("NODE_UNKNOWN", "fail.x3d");
    let out = x3dcheck(&["fail.x3d"], &dir);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("error[NODE_UNKNOWN]: [*] `material`"),
        "{stdout}"
    );
    assert!(stdout.contains("1 fixable with --fix\n"), "{stdout}");
    let json = x3dcheck(&["--format", "json", "fail.x3d"], &dir);
    let report: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let fix = &report["files"][0]["diagnostics"][0]["fix"];
    assert_eq!(fix["applicability"], "safe", "{report}");
    assert_eq!(fix["edits"][0]["content"], "Material");
    assert_eq!(
        fix["edits"].as_array().unwrap().len(),
        1,
        "self-closed: no end tag"
    );
    let sarif = x3dcheck(&["--format", "sarif", "fail.x3d"], &dir);
    let sarif: serde_json::Value = serde_json::from_slice(&sarif.stdout).unwrap();
    let replacement =
        &sarif["runs"][0]["results"][0]["fixes"][0]["artifactChanges"][0]["replacements"][0];
    assert_eq!(
        replacement["insertedContent"]["text"], "Material",
        "{sarif}"
    );
    assert_eq!(replacement["deletedRegion"]["startLine"], 6);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn diff_prints_the_change_and_writes_nothing() {
    let (dir, target) = copy("FIELD_UNKNOWN", "fail.x3d");
    let before = fs::read(&target).unwrap();
    let out = x3dcheck(&["--diff", "fail.x3d"], &dir);
    assert_eq!(fs::read(&target).unwrap(), before, "--diff wrote the file");
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.starts_with("--- a/fail.x3d\n+++ b/fail.x3d\n"),
        "{stdout}"
    );
    assert!(
        stdout.contains("-        <Material diffusecolor='1 0 0'/>\n"),
        "{stdout}"
    );
    assert!(
        stdout.contains("+        <Material diffuseColor='1 0 0'/>\n"),
        "{stdout}"
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("Would fix 1 finding in 1 file"), "{stderr}");
    // Nothing to change: no diff, exit 0.
    let (clean_dir, _) = copy("FIELD_UNKNOWN", "pass.x3d");
    let clean = x3dcheck(&["--diff", "pass.x3d"], &clean_dir);
    assert_eq!(clean.status.code(), Some(0));
    assert!(clean.stdout.is_empty());
    fs::remove_dir_all(dir).unwrap();
    fs::remove_dir_all(clean_dir).unwrap();
}

#[test]
fn stdin_is_fixed_to_stdout_and_reported_on_stderr() {
    let source = fs::read(corpus("FIELD_UNKNOWN", "fail.x3d")).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_x3dcheck"))
        .args(["--fix", "-"])
        .env("NO_COLOR", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(&source).unwrap();
    let out = child.wait_with_output().unwrap();
    let expected = fs::read(corpus("FIELD_UNKNOWN", "fixed-fail.x3d.txt")).unwrap();
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&expected)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("Fixed 1 finding"), "{stderr}");
}

#[test]
fn compressed_input_is_not_fixed() {
    let dir = temp_dir("gzip");
    let source = fs::read(corpus("FIELD_UNKNOWN", "fail.x3d")).unwrap();
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(&source).unwrap();
    let compressed = gz.finish().unwrap();
    fs::write(dir.join("scene.x3dz"), &compressed).unwrap();
    let out = x3dcheck(&["--fix", "scene.x3dz"], &dir);
    assert_eq!(fs::read(dir.join("scene.x3dz")).unwrap(), compressed);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("fix not applied: compressed input"),
        "{stderr}"
    );
    assert_eq!(out.status.code(), Some(1), "the finding remains");
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_utf8_byte_order_mark_is_kept() {
    let dir = temp_dir("bom");
    let source = fs::read(corpus("FIELD_UNKNOWN", "fail.x3d")).unwrap();
    fs::write(
        dir.join("bom.x3d"),
        [b"\xEF\xBB\xBF".as_slice(), &source].concat(),
    )
    .unwrap();
    x3dcheck(&["--fix", "bom.x3d"], &dir);
    let expected = fs::read(corpus("FIELD_UNKNOWN", "fixed-fail.x3d.txt")).unwrap();
    assert_eq!(
        fs::read(dir.join("bom.x3d")).unwrap(),
        [b"\xEF\xBB\xBF".as_slice(), &expected].concat()
    );
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_report_output_may_not_be_an_input_under_fix() {
    let (dir, target) = copy("FIELD_UNKNOWN", "fail.x3d");
    let before = fs::read(&target).unwrap();
    let out = x3dcheck(&["--fix", "fail.x3d", "-o", "fail.x3d"], &dir);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(fs::read(&target).unwrap(), before);
    fs::remove_dir_all(dir).unwrap();
}
