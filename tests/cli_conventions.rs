//! Terminal and CI conventions of the command line: `--color` and the colour variables,
//! `--quiet`, `--exit-zero`, `--stdin-filename`, the exit codes in `--help`, code
//! selectors, `--show-settings`, no summary for files never read, and `x3dcheck rules`
//! fitting 100 columns (or JSON).

mod common;

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output, Stdio};

use common::{scratch, stdout};

const DUPLICATE: &str = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<X3D profile='Interchange' version='4.0'>
  <Scene>
    <Shape><Appearance><Material DEF='Red'/></Appearance><Box/></Shape>
    <Shape><Appearance><Material DEF='Red'/></Appearance><Box/></Shape>
  </Scene>
</X3D>
";

const VALID: &str = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<X3D profile='Interchange' version='4.0'><Scene><Shape><Box/></Shape></Scene></X3D>\n";

/// A scene whose texture is `tex.png` beside it.
const TEXTURED: &str = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<X3D profile='Interchange' version='4.0'><Scene><Shape><Appearance><Material/>
<ImageTexture url='\"tex.png\"'/></Appearance><Box/></Shape></Scene></X3D>
";

/// The variables that decide on colour, removed so that each case sets its own.
const COLOR_VARIABLES: &[&str] = &[
    "NO_COLOR",
    "CLICOLOR",
    "CLICOLOR_FORCE",
    "FORCE_COLOR",
    "TERM",
    "CI",
    "GITHUB_ACTIONS",
    "TF_BUILD",
    "BUILDKITE",
];

/// Runs x3dcheck in `dir` with `env` set (after removing the colour variables) and `stdin`.
fn run(dir: &Path, args: &[&str], env: &[(&str, &str)], stdin: &[u8]) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_x3dcheck"));
    command
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    for name in COLOR_VARIABLES {
        command.env_remove(name);
    }
    command.envs(env.iter().copied());
    let mut child = command.spawn().unwrap();
    child.stdin.take().unwrap().write_all(stdin).unwrap();
    child.wait_with_output().unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

const ESCAPE: &str = "\x1b[";

#[test]
fn color_into_a_pipe_follows_the_flag_then_the_variables() {
    let dir = scratch("color-pipe", &[("dup.x3d", DUPLICATE)]);
    let colored = |args: &[&str], env: &[(&str, &str)]| {
        let mut all = vec!["dup.x3d"];
        all.extend_from_slice(args);
        let output = run(&dir, &all, env, b"");
        assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
        stdout(&output).contains(ESCAPE)
    };
    assert!(!colored(&[], &[]), "a pipe: no colour");
    assert!(colored(&[], &[("FORCE_COLOR", "1")]));
    assert!(colored(&[], &[("CLICOLOR_FORCE", "1")]));
    assert!(!colored(&[], &[("CLICOLOR_FORCE", "0")]));
    assert!(!colored(&[], &[("FORCE_COLOR", "0")]));
    assert!(
        !colored(&[], &[("NO_COLOR", "1"), ("FORCE_COLOR", "1")]),
        "NO_COLOR wins"
    );
    assert!(colored(&[], &[("FORCE_COLOR", "1"), ("CLICOLOR", "0")]));
    assert!(colored(&["--color", "always"], &[("NO_COLOR", "1")]));
    assert!(!colored(&["--color", "never"], &[("FORCE_COLOR", "1")]));
    assert!(!colored(&["--no-color"], &[("FORCE_COLOR", "1")]));
}

/// On a terminal (a pseudo-terminal made by util-linux `script`), colour is on by default
/// and off under NO_COLOR, CLICOLOR=0 and TERM=dumb.
#[test]
fn color_on_a_terminal_honours_no_color_clicolor_and_dumb_terminals() {
    if Command::new("script").arg("--version").output().is_err() {
        // util-linux is part of every Debian/Ubuntu install; elsewhere this is not checked.
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED color_on_a_terminal_…: no `script` command for a pseudo-terminal"
        );
        return;
    }
    let dir = scratch("color-tty", &[("dup.x3d", DUPLICATE)]);
    let colored = |env: &[(&str, &str)]| {
        let command = format!("{} dup.x3d", env!("CARGO_BIN_EXE_x3dcheck"));
        let mut all = vec![("TERM", "xterm")];
        all.extend_from_slice(env);
        let mut script = Command::new("script");
        script
            .current_dir(&dir)
            .args(["-qec", &command, "/dev/null"])
            .stdin(Stdio::null());
        for name in COLOR_VARIABLES {
            script.env_remove(name);
        }
        script.envs(all);
        let output = script.output().unwrap();
        let text = stdout(&output);
        assert!(text.contains("DEF_DUPLICATE"), "{text}");
        text.contains(ESCAPE)
    };
    assert!(colored(&[]), "a terminal: colour");
    assert!(!colored(&[("NO_COLOR", "1")]));
    assert!(!colored(&[("CLICOLOR", "0")]));
    assert!(!colored(&[("TERM", "dumb")]));
}

#[test]
fn quiet_prints_the_findings_only() {
    let dir = scratch("quiet", &[("dup.x3d", DUPLICATE), ("valid.x3d", VALID)]);
    let output = run(&dir, &["--quiet", "dup.x3d"], &[], b"");
    assert_eq!(output.status.code(), Some(1));
    let text = stdout(&output);
    assert!(text.contains("error[DEF_DUPLICATE]"), "{text}");
    assert!(!text.contains("Checked"), "{text}");
    let output = run(&dir, &["-q", "--format", "concise", "valid.x3d"], &[], b"");
    assert_eq!(
        (output.status.code(), stdout(&output)),
        (Some(0), String::new())
    );
    let output = run(&dir, &["dup.x3d", "--format", "concise"], &[], b"");
    assert!(
        stdout(&output).contains("Checked 1 file"),
        "without --quiet"
    );
}

#[test]
fn exit_zero_keeps_failures_at_2() {
    let dir = scratch("exit-zero", &[("dup.x3d", DUPLICATE)]);
    let output = run(&dir, &["--exit-zero", "dup.x3d"], &[], b"");
    assert_eq!(output.status.code(), Some(0));
    assert!(stdout(&output).contains("error[DEF_DUPLICATE]"));
    let output = run(&dir, &["--exit-zero", "dup.x3d", "missing.x3d"], &[], b"");
    assert_eq!(output.status.code(), Some(2));
}

#[test]
fn stdin_filename_names_the_document_and_places_it() {
    let dir = scratch(
        "stdin-filename",
        &[
            (
                "scenes/x3dcheck.toml",
                "ignore = ['PROFILE_MISSING']\n[severity]\nDEF_DUPLICATE = 'warning'\n",
            ),
            ("scenes/a.x3d", TEXTURED),
            ("other/notes.txt", ""),
        ],
    );
    image::RgbaImage::new(2, 2)
        .save(dir.join("scenes/tex.png"))
        .unwrap();
    let deep = |args: &[&str], stdin: &str| {
        let mut all = vec!["-", "--level", "deep", "--format", "concise"];
        all.extend_from_slice(args);
        let output = run(&dir, &all, &[], stdin.as_bytes());
        (output.status.code(), stdout(&output))
    };
    // Named as scenes/a.x3d, tex.png is found beside it.
    let (code, text) = deep(&["--stdin-filename", "scenes/a.x3d"], TEXTURED);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        !text.contains("URL_UNRESOLVED") && !text.contains("VALIDATION_INCOMPLETE"),
        "{text}"
    );
    // Named in another directory, it is not.
    let (code, text) = deep(&["--stdin-filename", "other/a.x3d"], TEXTURED);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.starts_with("other/a.x3d:3:") && text.contains("warning[URL_UNRESOLVED]"),
        "{text}"
    );
    // Unnamed, relative references are not followed.
    let (_, text) = deep(&[], TEXTURED);
    assert!(
        text.starts_with("<stdin>:") && text.contains("VALIDATION_INCOMPLETE"),
        "{text}"
    );
    // The x3dcheck.toml beside the name applies: DEF_DUPLICATE is a warning there.
    let (code, text) = deep(&["--stdin-filename", "scenes/dup.x3d"], DUPLICATE);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains("scenes/dup.x3d:5:39: warning[DEF_DUPLICATE]"),
        "{text}"
    );
    let (code, _) = deep(&["--stdin-filename", "dup.x3d"], DUPLICATE);
    assert_eq!(code, Some(1), "no x3dcheck.toml above ./dup.x3d");
}

#[test]
fn help_lists_the_exit_codes() {
    let dir = scratch("help", &[]);
    let text = stdout(&run(&dir, &["--help"], &[], b""));
    let codes = text
        .split("Exit codes:")
        .nth(1)
        .unwrap_or_else(|| panic!("{text}"));
    for code in ["0  ", "1  ", "2  "] {
        assert!(
            codes.lines().any(|l| l.trim_start().starts_with(code)),
            "{text}"
        );
    }
    assert!(codes.contains("--exit-zero"), "{text}");
}

#[test]
fn codes_are_selected_in_any_case_by_prefix_or_all() {
    let dir = scratch(
        "selectors",
        &[
            ("dup.x3d", DUPLICATE),
            ("toml/x3dcheck.toml", "ignore = ['def_']\n"),
            ("toml/dup.x3d", DUPLICATE),
        ],
    );
    let code = |args: &[&str]| {
        let output = run(&dir, args, &[], b"");
        (output.status.code(), stdout(&output), stderr(&output))
    };
    assert_eq!(code(&["--select", "def_duplicate", "dup.x3d"]).0, Some(1));
    assert_eq!(code(&["--select", "DEF_", "dup.x3d"]).0, Some(1));
    assert_eq!(code(&["--select", "BACK_MATERIAL_", "dup.x3d"]).0, Some(0));
    assert_eq!(code(&["--ignore", "all", "dup.x3d"]).0, Some(0));
    assert_eq!(code(&["--severity", "DEF=warning", "dup.x3d"]).0, Some(0));
    assert_eq!(
        code(&["toml/dup.x3d"]).0,
        Some(0),
        "a prefix in x3dcheck.toml"
    );
    let (status, text, errors) = code(&["--select", "BACK_MATERIAL_NOTHING", "dup.x3d"]);
    assert_eq!(status, Some(2), "{text}");
    assert!(
        errors.contains("`BACK_MATERIAL_NOTHING` is no rule code"),
        "{errors}"
    );
    assert!(text.is_empty(), "{text}");
    let (status, _, errors) = code(&["--ignore", "DEF_DUPLICAT", "dup.x3d"]);
    assert_eq!(status, Some(2));
    assert!(errors.contains("did you mean `DEF_DUPLICATE`?"), "{errors}");
    let (status, text, _) = code(&["--show-settings", "--select", "back_material_", "dup.x3d"]);
    assert_eq!(status, Some(0));
    let select = text.lines().find(|l| l.starts_with("select = ")).unwrap();
    assert!(
        select.contains("\"BACK_MATERIAL_CLASS_MISMATCH\""),
        "{select}"
    );
    assert!(!select.contains("DEF_DUPLICATE"), "{select}");
}

#[test]
fn show_settings_prints_what_applies_and_where_it_comes_from() {
    let dir = scratch(
        "show-settings",
        &[
            (
                "scenes/x3dcheck.toml",
                "level = 'deep'\nignore = ['PROFILE_MISSING']\nmax-diagnostics = 5\n\
                 [severity]\nDEF_DUPLICATE = 'info'\n\
                 [[per-path-ignores]]\npath = 'old/*.x3d'\nignore = ['NODE_DEPRECATED']\n",
            ),
            ("scenes/old/dup.x3d", DUPLICATE),
        ],
    );
    let output = run(
        &dir,
        &[
            "--show-settings",
            "--fail-on",
            "warning",
            "scenes/old/dup.x3d",
        ],
        &[],
        b"",
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stdout(&output);
    let toml_path = dir.join("scenes/x3dcheck.toml");
    let expected = format!(
        "# Settings for scenes/old/dup.x3d\n\
         # from {}, with the command line over it\n",
        toml_path.display()
    );
    assert!(text.starts_with(&expected), "{text}");
    for line in [
        "level = \"deep\"",
        "ignore = [\"NODE_DEPRECATED\", \"PROFILE_MISSING\"]",
        "fail-on = \"warning\"",
        "max-diagnostics = 5",
        "DEF_DUPLICATE = \"info\"",
    ] {
        assert!(text.lines().any(|l| l == line), "{line}:\n{text}");
    }
    // What it prints is TOML.
    let body: String = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect();
    body.parse::<toml::Table>()
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    // No x3dcheck.toml upward: said so.
    let output = run(
        &dir,
        &["--show-settings", "-", "--stdin-filename", "a.x3d"],
        &[],
        b"",
    );
    let text = stdout(&output);
    assert!(
        text.contains("# Settings for a.x3d\n# no x3dcheck.toml found"),
        "{text}"
    );
}

#[test]
fn files_never_read_get_no_summary_line() {
    let dir = scratch("never-read", &[("valid.x3d", VALID)]);
    for format in ["human", "concise"] {
        let output = run(&dir, &["missing.x3d", "--format", format], &[], b"");
        assert_eq!(output.status.code(), Some(2));
        assert_eq!(stdout(&output), "", "{format}");
        assert!(
            stderr(&output).contains("missing.x3d"),
            "{}",
            stderr(&output)
        );
    }
    let output = run(&dir, &["missing.x3d", "valid.x3d"], &[], b"");
    assert_eq!(output.status.code(), Some(2));
    assert!(stdout(&output).ends_with("Checked 1 file: 0 errors, 0 warnings, 0 infos, 0 hints\n"));
}

#[test]
fn the_rule_table_fits_100_columns_with_whole_summaries() {
    let dir = scratch("rules-width", &[]);
    let output = run(&dir, &["rules"], &[], b"");
    assert_eq!(output.status.code(), Some(0));
    let text = stdout(&output);
    let widest = text.lines().map(|l| l.chars().count()).max().unwrap();
    assert!(widest <= 100, "a line of {widest} columns:\n{text}");
    let rules = &x3dcheck::validate::RULES;
    for rule in rules.iter() {
        assert!(
            text.lines()
                .any(|l| l.starts_with(&format!("{} ", rule.code))),
            "{} missing",
            rule.code
        );
    }
    // FIELD_OUT_OF_RANGE's summary, wrapped but whole.
    let joined = text.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        joined.contains("(e.g. light `intensity` is `[0,1]` in 3.x and `[0,∞)` in 4.x)."),
        "{text}"
    );
    // A prefix lists its family only.
    let family = stdout(&run(&dir, &["rules", "back_material_"], &[], b""));
    let codes: Vec<&str> = family
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with(' '))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(
        codes.len() > 1 && codes.iter().all(|c| c.starts_with("BACK_MATERIAL_")),
        "{family}"
    );
    // One code: its documentation.
    let one = stdout(&run(&dir, &["rules", "def_duplicate"], &[], b""));
    assert!(one.starts_with("DEF_DUPLICATE\nseverity: error"), "{one}");
}

#[test]
fn rules_as_json_for_tools() {
    let dir = scratch("rules-json", &[]);
    let output = run(&dir, &["rules", "--format", "json"], &[], b"");
    assert_eq!(output.status.code(), Some(0));
    let list: Vec<serde_json::Value> = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(list.len(), x3dcheck::validate::RULES.len());
    let range = list
        .iter()
        .find(|r| r["code"] == "FIELD_OUT_OF_RANGE")
        .unwrap();
    for key in ["severity", "level", "versions", "clause", "summary", "doc"] {
        assert!(range[key].is_string(), "{key}: {range}");
    }
    assert!(
        range["summary"].as_str().unwrap().ends_with("in 4.x)."),
        "{range}"
    );
    assert!(range["doc"].as_str().unwrap().contains("## What it does"));
    let one = run(
        &dir,
        &["rules", "DEF_DUPLICATE", "--format", "json"],
        &[],
        b"",
    );
    let list: Vec<serde_json::Value> = serde_json::from_slice(&one.stdout).unwrap();
    assert_eq!(list.len(), 1);
    let unknown = run(&dir, &["rules", "NO_SUCH_CODE"], &[], b"");
    assert_eq!(unknown.status.code(), Some(2));
}
