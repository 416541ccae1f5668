//! The command line end to end: exit codes, the JSON report's shape and determinism,
//! code validation and the `rules` subcommand.

mod common;

use common::{scratch, stdout, x3dcheck};
use std::process::Command;

const VALID: &str = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<X3D profile='Interchange' version='4.0'><Scene><Shape><Box/></Shape></Scene></X3D>";

const DUPLICATE: &str = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<X3D profile='Interchange' version='4.0'>
  <Scene>
    <Shape><Appearance><Material DEF='Red'/></Appearance><Box/></Shape>
    <Shape><Appearance><Material DEF='Red'/></Appearance><Box/></Shape>
  </Scene>
</X3D>
";

#[test]
fn exit_codes() {
    let dir = scratch("exit", &[("valid.x3d", VALID), ("dup.x3d", DUPLICATE)]);
    let valid = x3dcheck(&dir, &["valid.x3d"]);
    assert_eq!(valid.status.code(), Some(0), "{}", stdout(&valid));
    assert!(stdout(&valid).ends_with("Checked 1 file: 0 errors, 0 warnings, 0 infos, 0 hints\n"));

    let dup = x3dcheck(&dir, &["dup.x3d"]);
    assert_eq!(dup.status.code(), Some(1));
    let text = stdout(&dup);
    assert!(
        text.contains("error[DEF_DUPLICATE]") && text.contains("[dup.x3d:5:39]"),
        "{text}"
    );

    let missing = x3dcheck(&dir, &["valid.x3d", "missing.x3d"]);
    assert_eq!(missing.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&missing.stderr);
    assert!(stderr.contains("cannot read missing.x3d"), "{stderr}");
    // The readable file was still checked.
    assert!(stdout(&missing).contains("Checked 1 file"));
}

#[test]
fn fail_on_and_ignore() {
    let dir = scratch("fail", &[("dup.x3d", DUPLICATE)]);
    let ignored = x3dcheck(&dir, &["--ignore", "DEF_DUPLICATE", "dup.x3d"]);
    assert_eq!(ignored.status.code(), Some(0));
    let lowered = x3dcheck(&dir, &["--severity", "DEF_DUPLICATE=warning", "dup.x3d"]);
    assert_eq!(lowered.status.code(), Some(0));
    let strict = x3dcheck(
        &dir,
        &[
            "--severity=DEF_DUPLICATE=warning",
            "--fail-on",
            "warning",
            "dup.x3d",
        ],
    );
    assert_eq!(strict.status.code(), Some(1));
}

#[test]
fn json_report_shape() {
    let dir = scratch("json", &[("valid.x3d", VALID), ("dup.x3d", DUPLICATE)]);
    let output = x3dcheck(&dir, &["--format", "json", "."]);
    assert_eq!(output.status.code(), Some(1));
    let report: serde_json::Value = serde_json::from_str(&stdout(&output)).unwrap();
    assert_eq!(report["tool"], "x3dcheck");
    assert!(report["version"].is_string());
    let files = report["files"].as_array().unwrap();
    // Directories are walked in path order.
    assert_eq!(files.len(), 2);
    assert!(files[0]["path"].as_str().unwrap().ends_with("dup.x3d"));
    let dup = &files[0];
    for key in [
        "encoding",
        "x3dVersion",
        "profile",
        "diagnostics",
        "truncated",
        "stats",
    ] {
        assert!(dup.get(key).is_some(), "missing {key}");
    }
    assert_eq!(dup["encoding"], "xml");
    assert_eq!(dup["x3dVersion"], "4.0");
    assert_eq!(dup["profile"], "Interchange");
    let d = &dup["diagnostics"][0];
    for key in [
        "code",
        "severity",
        "message",
        "line",
        "column",
        "endLine",
        "endColumn",
        "path",
        "clause",
    ] {
        assert!(d.get(key).is_some(), "missing {key}");
    }
    assert_eq!(d["code"], "DEF_DUPLICATE");
    assert_eq!(d["severity"], "error");
    assert_eq!(
        (d["line"].as_u64(), d["column"].as_u64()),
        (Some(5), Some(39))
    );
    assert_eq!(
        d["path"],
        "/X3D/Scene/Shape[2]/Appearance/Material[@DEF='Red']"
    );
    assert!(d.get("count").is_none());
    let stats = &files[1]["stats"];
    for key in [
        "nodes",
        "nodeTypes",
        "shapes",
        "triangles",
        "lines",
        "points",
        "lights",
        "textures",
        "defs",
        "uses",
        "routes",
    ] {
        assert!(stats.get(key).is_some(), "missing {key}");
    }
    assert_eq!(stats["nodes"], 2);
    assert_eq!(stats["shapes"], 1);
    assert_eq!(report["summary"]["files"], 2);
    assert_eq!(report["summary"]["errors"], 1);
}

#[test]
fn output_is_deterministic() {
    let dir = scratch("same", &[("valid.x3d", VALID), ("dup.x3d", DUPLICATE)]);
    for format in ["json", "human", "concise"] {
        let first = x3dcheck(&dir, &["--format", format, "-j", "2", "."]);
        let second = x3dcheck(&dir, &["--format", format, "-j", "1", "."]);
        assert_eq!(first.stdout, second.stdout, "{format}");
    }
}

#[test]
fn output_file() {
    let dir = scratch("output", &[("dup.x3d", DUPLICATE)]);
    let output = x3dcheck(
        &dir,
        &["--format", "concise", "-o", "report.txt", "dup.x3d"],
    );
    assert_eq!(output.status.code(), Some(1));
    assert!(output.stdout.is_empty());
    let report = std::fs::read_to_string(dir.join("report.txt")).unwrap();
    assert!(
        report.starts_with("dup.x3d:5:39: error[DEF_DUPLICATE] "),
        "{report}"
    );
}

#[test]
fn unknown_codes_are_usage_errors() {
    let dir = scratch("codes", &[("valid.x3d", VALID)]);
    let output = x3dcheck(&dir, &["--select", "DEF_DUPLICAT", "valid.x3d"]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("did you mean `DEF_DUPLICATE`"), "{stderr}");
    assert_eq!(
        x3dcheck(&dir, &["--severity", "DEF_DUPLICATE=fatal", "valid.x3d"])
            .status
            .code(),
        Some(2)
    );
}

#[test]
fn rules() {
    let dir = scratch("rules", &[]);
    let list = x3dcheck(&dir, &["rules"]);
    assert_eq!(list.status.code(), Some(0));
    assert!(stdout(&list)
        .lines()
        .any(|l| l.starts_with("DEF_DUPLICATE ")));
    let one = x3dcheck(&dir, &["rules", "DEF_DUPLICATE"]);
    assert_eq!(one.status.code(), Some(0));
    let text = stdout(&one);
    assert!(
        text.starts_with("DEF_DUPLICATE\n") && text.contains("## What it does\n"),
        "{text}"
    );
    assert_eq!(
        x3dcheck(&dir, &["rules", "NO_SUCH_RULE"]).status.code(),
        Some(2)
    );
}

#[test]
fn a_directory_without_scenes_is_an_error() {
    let dir = scratch("empty", &[("notes.txt", "not a scene")]);
    let output = x3dcheck(&dir, &["."]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("no X3D files found in ."));
}

#[cfg(unix)]
#[test]
fn symlinked_directories_are_not_followed() {
    let dir = scratch("links", &[("a.x3d", VALID)]);
    std::os::unix::fs::symlink(&dir, dir.join("loop")).unwrap();
    let output = x3dcheck(&dir, &["."]);
    assert_eq!(output.status.code(), Some(0));
    assert!(stdout(&output).contains("Checked 1 file:"));
}

#[test]
fn stdin() {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_x3dcheck"))
        .args(["--format", "concise", "-"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(DUPLICATE.as_bytes())
        .unwrap();
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(1));
    assert!(stdout(&output).starts_with("<stdin>:5:39: error[DEF_DUPLICATE] "));
}

#[test]
fn max_diagnostics_truncates() {
    let three = DUPLICATE.replace("  </Scene>", "    <Group DEF='Red'/>\n  </Scene>");
    let dir = scratch("max", &[("three.x3d", &three)]);
    let output = x3dcheck(
        &dir,
        &["--format", "json", "--max-diagnostics", "1", "three.x3d"],
    );
    let report: serde_json::Value = serde_json::from_str(&stdout(&output)).unwrap();
    assert_eq!(
        report["files"][0]["diagnostics"].as_array().unwrap().len(),
        1
    );
    assert_eq!(report["files"][0]["truncated"], true);
}
