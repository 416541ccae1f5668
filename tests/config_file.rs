//! `x3dcheck.toml` end to end: found upward from each file (closest wins), `--config`,
//! per-path ignores, errors with file and line, and the command line winning over the file.

mod common;

use common::{scratch, x3dcheck};
use std::process::Output;

/// A DEF_DUPLICATE (error), a PROFILE_MISSING (warning) and a ROUTE_NODE_UNDEFINED (error).
const SCENE: &str = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<X3D version='4.0'>
  <Scene>
    <Shape><Appearance><Material DEF='Red'/></Appearance><Box/></Shape>
    <Shape><Appearance><Material DEF='Red'/></Appearance><Box/></Shape>
    <ROUTE fromNode='Nowhere' fromField='x' toNode='Red' toField='set_diffuseColor'/>
  </Scene>
</X3D>
";

/// The codes reported per file, as `file: CODE` lines, sorted.
fn codes(output: &Output) -> Vec<String> {
    let text = String::from_utf8(output.stdout.clone()).unwrap();
    let mut found: Vec<String> = text
        .lines()
        .filter_map(|l| {
            let file = l.split(':').next()?;
            let code = l.split('[').nth(1)?.split(']').next()?;
            Some(format!("{file}: {code}"))
        })
        .collect();
    found.sort();
    found
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn closest_file_wins_and_per_path_ignores_apply() {
    let dir = scratch(
        "discover",
        &[
            ("x3dcheck.toml", "ignore = ['PROFILE_MISSING']\n"),
            ("top.x3d", SCENE),
            (
                "sub/x3dcheck.toml",
                "ignore = ['DEF_DUPLICATE']\n[[per-path-ignores]]\npath = 'legacy/**/*.x3d'\nignore = ['ROUTE_NODE_UNDEFINED']\n",
            ),
            ("sub/mid.x3d", SCENE),
            ("sub/legacy/old/low.x3d", SCENE),
        ],
    );
    let output = x3dcheck(&dir, &["--format", "concise", "."]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert_eq!(
        codes(&output),
        [
            // The closest file replaces the one above it: PROFILE_MISSING is back below sub/.
            "./sub/legacy/old/low.x3d: PROFILE_MISSING",
            "./sub/mid.x3d: PROFILE_MISSING",
            "./sub/mid.x3d: ROUTE_NODE_UNDEFINED",
            "./top.x3d: DEF_DUPLICATE",
            "./top.x3d: ROUTE_NODE_UNDEFINED",
        ]
    );
}

#[test]
fn explicit_config_applies_to_every_file() {
    let dir = scratch(
        "explicit",
        &[
            ("x3dcheck.toml", "ignore = ['PROFILE_MISSING']\n"),
            (
                "ci.toml",
                "select = ['PROFILE_MISSING']\nfail-on = 'warning'\n",
            ),
            ("a.x3d", SCENE),
            ("sub/b.x3d", SCENE),
        ],
    );
    let output = x3dcheck(
        &dir,
        &[
            "--format",
            "concise",
            "--config",
            "ci.toml",
            "a.x3d",
            "sub/b.x3d",
        ],
    );
    assert_eq!(
        codes(&output),
        ["a.x3d: PROFILE_MISSING", "sub/b.x3d: PROFILE_MISSING"]
    );
    // fail-on = warning from the file: a warning fails the run.
    assert_eq!(output.status.code(), Some(1));
}

#[test]
fn the_command_line_beats_the_file() {
    let dir = scratch(
        "override",
        &[
            (
                "x3dcheck.toml",
                "select = ['PROFILE_MISSING']\nfail-on = 'warning'\n[severity]\nPROFILE_MISSING = 'error'\n",
            ),
            ("a.x3d", SCENE),
        ],
    );
    let from_file = x3dcheck(&dir, &["--format", "concise", "a.x3d"]);
    let text = String::from_utf8(from_file.stdout.clone()).unwrap();
    assert!(text.contains("error[PROFILE_MISSING]"), "{text}");
    let cli = x3dcheck(
        &dir,
        &[
            "--format",
            "concise",
            "--select",
            "DEF_DUPLICATE",
            "--severity",
            "DEF_DUPLICATE=hint",
            "--fail-on",
            "error",
            "a.x3d",
        ],
    );
    assert_eq!(codes(&cli), ["a.x3d: DEF_DUPLICATE"]);
    let text = String::from_utf8(cli.stdout.clone()).unwrap();
    assert!(text.contains("hint[DEF_DUPLICATE]"), "{text}");
    assert_eq!(cli.status.code(), Some(0));
}

#[test]
fn errors_name_file_line_and_the_nearest_name() {
    let dir = scratch(
        "errors",
        &[
            (
                "x3dcheck.toml",
                "level = 'deep'\n\nignore = ['DEF_DUPLICAT']\n",
            ),
            ("a.x3d", SCENE),
        ],
    );
    let output = x3dcheck(&dir, &["a.x3d"]);
    assert_eq!(output.status.code(), Some(2));
    let message = stderr(&output);
    assert!(
        message.contains(
            "x3dcheck.toml:3:11: `DEF_DUPLICAT` is no rule code, code prefix or ALL (did you mean `DEF_DUPLICATE`?)"
        ),
        "{message}"
    );
    // Nothing was checked.
    assert!(output.stdout.is_empty());

    std::fs::write(dir.join("x3dcheck.toml"), "fail_on = 'warning'\n").unwrap();
    let output = x3dcheck(&dir, &["a.x3d"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output)
            .contains("x3dcheck.toml:1:1: unknown key `fail_on` (did you mean `fail-on`?)"),
        "{}",
        stderr(&output)
    );

    let missing = x3dcheck(&dir, &["--config", "nope.toml", "a.x3d"]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(
        stderr(&missing).contains("nope.toml: cannot read"),
        "{}",
        stderr(&missing)
    );
}
