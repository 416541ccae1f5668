//! What `cargo install --locked --path .` installs and ships: the x3dcheck binary alone
//! (the benchmark is an example), a release profile without debug information (the
//! `profiling` profile keeps it), the licence files Cargo.toml names, and the pre-commit
//! hook. `.ci/run` also installs it for real and looks at what was installed.

use std::path::Path;

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
