//! What `cargo install --locked --path .` installs and ships: the x3dcheck binary alone
//! (the benchmark is an example), a release profile without debug information (the
//! `profiling` profile keeps it), the licence files Cargo.toml names, and the pre-commit
//! hook. `.ci/run` also installs it for real and looks at what was installed.

use std::path::Path;

mod common;

fn repository_file(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn manifest() -> toml::Table {
    repository_file("Cargo.toml").parse().unwrap()
}

#[test]
fn the_only_binary_is_x3dcheck() {
    let manifest = manifest();
    let bins: Vec<&str> = manifest["bin"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["name"].as_str().unwrap())
        .collect();
    assert_eq!(bins, ["x3dcheck"]);
    // Cargo would also find binaries in src/bin/ by itself.
    assert!(!Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("src/bin")
        .exists());
    let examples = manifest["example"].as_array().unwrap();
    assert!(examples
        .iter()
        .any(|e| e["name"].as_str() == Some("x3dcheck-bench")));
}

#[test]
fn release_builds_carry_no_debug_information() {
    let manifest = manifest();
    let profiles = manifest["profile"].as_table().unwrap();
    let debug = profiles
        .get("release")
        .and_then(|release| release.get("debug"));
    assert!(
        matches!(
            debug,
            None | Some(toml::Value::Boolean(false)) | Some(toml::Value::Integer(0))
        ),
        "{debug:?}"
    );
    let profiling = profiles["profiling"].as_table().unwrap();
    assert_eq!(profiling["inherits"].as_str(), Some("release"));
    assert!(profiling.contains_key("debug"));
}

#[test]
fn the_licences_cargo_toml_names_are_there() {
    let manifest = manifest();
    assert_eq!(
        manifest["package"]["license"].as_str(),
        Some("MIT OR Apache-2.0")
    );
    let mit = repository_file("LICENSE-MIT");
    assert!(mit.contains("Copyright (c) 2026 the x3dcheck developers"));
    assert!(mit.contains("Permission is hereby granted, free of charge"));
    let apache = repository_file("LICENSE-APACHE");
    assert!(apache.contains("Apache License\n                        Version 2.0, January 2004"));
    assert!(apache.contains("END OF TERMS AND CONDITIONS"));
}

#[test]
fn the_pre_commit_hook_runs_x3dcheck_on_scene_files() {
    let hooks = repository_file(".pre-commit-hooks.yaml");
    for line in ["- id: x3dcheck", "  entry: x3dcheck", "  language: rust"] {
        assert!(hooks.lines().any(|l| l == line), "{line}:\n{hooks}");
    }
    let files = hooks
        .lines()
        .find_map(|l| l.strip_prefix("  files: "))
        .unwrap();
    // The hook takes what a directory walk takes: the extensions of
    // src/cli/discover.rs's SCENE_EXTENSIONS in any case, each also with `.gz` after it.
    let alternation = files
        .strip_prefix(r"'(?i)\.(")
        .and_then(|f| f.strip_suffix(r")(\.gz)?$'"))
        .unwrap_or_else(|| panic!("files: {files}"));
    let hooked: Vec<&str> = alternation.split('|').collect();
    let discover = repository_file("src/cli/discover.rs");
    let walked = discover
        .split_once("const SCENE_EXTENSIONS: &[&str] = &[")
        .and_then(|(_, rest)| rest.split_once("];"))
        .map(|(list, _)| list)
        .unwrap();
    let walked: Vec<&str> = walked
        .split(',')
        .map(|e| e.trim().trim_matches('"'))
        .filter(|e| !e.is_empty())
        .collect();
    assert_eq!(hooked, walked);
}

fn x3dcheck_stdout(args: &[&str]) -> String {
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_x3dcheck"))
        .args(args)
        .output()
        .unwrap();
    assert!(output.status.success(), "x3dcheck {args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}

/// The completion scripts know the subcommands and the options, in every shell's form.
#[test]
fn completions_cover_the_options_in_each_shell() {
    let bash = x3dcheck_stdout(&["completions", "bash"]);
    assert!(bash.contains("complete -F _x3dcheck"), "{bash}");
    assert!(bash.contains("--level") && bash.contains("rules"), "{bash}");
    // The values of an enumerated option are offered too.
    assert!(bash.contains("sarif"), "{bash}");
    let zsh = x3dcheck_stdout(&["completions", "zsh"]);
    assert!(zsh.starts_with("#compdef x3dcheck"), "{zsh}");
    let fish = x3dcheck_stdout(&["completions", "fish"]);
    assert!(
        fish.contains("complete -c x3dcheck") && fish.contains("-l level"),
        "{fish}"
    );
}

/// The manual page is roff for section 1 and lists the options and the exit codes.
#[test]
fn the_manual_page_lists_options_and_exit_codes() {
    let page = x3dcheck_stdout(&["manpage"]);
    assert!(page.contains(".TH x3dcheck 1"), "{page}");
    assert!(page.contains("\\-\\-level"), "{page}");
    assert!(page.contains("Exit codes:"), "{page}");
}

/// The `run: |` script of the action.yml step named `step`, unindented.
fn action_step_script(step: &str) -> String {
    let action = repository_file("action.yml");
    let start = action
        .find(&format!("- name: {step}\n"))
        .unwrap_or_else(|| panic!("action.yml has no step {step}"));
    let mut lines = action[start..]
        .lines()
        .skip_while(|l| !l.trim_start().starts_with("run: |"));
    let run = lines.next().unwrap();
    let indent = run.len() - run.trim_start().len() + 2;
    lines
        .take_while(|l| l.trim().is_empty() || l.len() - l.trim_start().len() >= indent)
        .map(|l| l.get(indent..).unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The action's check step, run as GitHub runs it (bash, the inputs in the environment,
/// x3dcheck on PATH): annotations and exit 1 for a bad scene; with SARIF, the report
/// written and the exit code kept for the last step.
#[test]
fn the_github_action_checks_and_keeps_the_exit_code() {
    let script = action_step_script("Check the scenes");
    let dir = common::scratch("action", &[]);
    let bad = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus/rules/DEF_DUPLICATE");
    let bin_dir = Path::new(env!("CARGO_BIN_EXE_x3dcheck")).parent().unwrap();
    let path = format!(
        "{}:{}",
        bin_dir.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let run = |format: &str| {
        std::process::Command::new("bash")
            .args(["-c", &script])
            .current_dir(&dir)
            .env("PATH", &path)
            .env("FORMAT", format)
            .env("PATHS", &bad)
            .env("ARGS", "--color never")
            .env("SARIF_FILE", dir.join("out.sarif"))
            .env("GITHUB_OUTPUT", dir.join("github_output"))
            .output()
            .unwrap()
    };
    let github = run("github");
    let annotations = String::from_utf8_lossy(&github.stdout);
    assert_eq!(github.status.code(), Some(1), "{github:?}");
    assert!(annotations.contains("::error file="), "{annotations}");
    assert!(annotations.contains("DEF_DUPLICATE"), "{annotations}");

    let sarif = run("sarif");
    assert_eq!(sarif.status.code(), Some(0), "{sarif:?}");
    let report = std::fs::read_to_string(dir.join("out.sarif")).unwrap();
    assert!(report.contains("\"ruleId\": \"DEF_DUPLICATE\""), "{report}");
    let outputs = std::fs::read_to_string(dir.join("github_output")).unwrap();
    assert_eq!(outputs.trim(), "exit-code=1");
}

#[test]
fn the_wheel_hook_matches_the_source_hook_and_pins_this_version() {
    // pre-commit/ is what a mirror repository holds once the wheel is published: the same
    // hook as the root's but `language: python`, installing the wheel of this version.
    let source = repository_file(".pre-commit-hooks.yaml");
    let wheel = repository_file("pre-commit/.pre-commit-hooks.yaml");
    let hook_lines = |hooks: &str| -> Vec<String> {
        hooks
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with("  language: "))
            .map(str::to_owned)
            .collect()
    };
    assert_eq!(hook_lines(&wheel), hook_lines(&source));
    assert!(wheel.lines().any(|l| l == "  language: python"), "{wheel}");

    // The wheel's version is its crate's (pyproject.toml: `dynamic = ["version"]`).
    let bindings: toml::Table = repository_file("bindings/python/Cargo.toml")
        .parse()
        .unwrap();
    let version = bindings["package"]["version"].as_str().unwrap().to_owned();
    let project: toml::Table = repository_file("pre-commit/pyproject.toml")
        .parse()
        .unwrap();
    let project = project["project"].as_table().unwrap();
    assert_eq!(project["version"].as_str(), Some(version.as_str()));
    let dependencies = project["dependencies"].as_array().unwrap();
    assert_eq!(dependencies.len(), 1);
    assert_eq!(
        dependencies[0].as_str(),
        Some(format!("x3dcheck=={version}").as_str())
    );
}
