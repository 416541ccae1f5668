//! `--shard K/N` and `x3dcheck merge` end to end: shards are disjoint, cover every file and
//! follow the documented rule; the merge of a split's JSON reports is the unsharded run's
//! report, byte for byte, in every format merge writes; what does not merge is refused.

mod common;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Output;

use common::{scratch, stdout, x3dcheck};
use serde_json::Value;
use sha2::{Digest, Sha256};

fn project() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// The `path`s of the files of a JSON report, in report order.
fn report_files(text: &str) -> Vec<String> {
    let report: Value = serde_json::from_str(text).unwrap();
    report["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["path"].as_str().unwrap().to_string())
        .collect()
}

/// Runs `--shard k/n` for every k of `n` over `target` (in `dir`), writing the JSON reports
/// into `out` (`shard-k.json`); the extra `args` come first.
fn split(dir: &Path, target: &str, n: u32, args: &[&str], out: &Path) -> Vec<PathBuf> {
    (1..=n)
        .map(|k| {
            let report = out.join(format!("shard-{k}.json"));
            let shard = format!("{k}/{n}");
            let mut argv = args.to_vec();
            argv.extend(["--format", "json", "--shard", &shard, "-o"]);
            argv.push(report.to_str().unwrap());
            argv.push(target);
            let output = x3dcheck(dir, &argv);
            assert!(
                matches!(output.status.code(), Some(0 | 1)),
                "{shard}: {}",
                stderr(&output)
            );
            report
        })
        .collect()
}

fn merge(dir: &Path, args: &[&str], reports: &[PathBuf]) -> Output {
    let mut argv = vec!["merge"];
    argv.extend(args);
    argv.extend(reports.iter().map(|r| r.to_str().unwrap()));
    x3dcheck(dir, &argv)
}

/// The shard of a key by the rule `--help` and the README give, computed here on its own.
fn documented_shard(key: &str, n: u64) -> u64 {
    let digest = Sha256::digest(key.as_bytes());
    u64::from_be_bytes(digest[..8].try_into().unwrap()) % n + 1
}

#[test]
fn the_shards_of_the_corpus_merge_into_the_unsharded_report() {
    let corpus = "../shared/corpus";
    let out = scratch("shard-corpus", &[]);
    let whole = x3dcheck(project(), &["--format", "json", corpus]);
    // Piped stderr: no progress bar, and the corpus is read without errors.
    assert_eq!(stderr(&whole), "");
    let whole_text = stdout(&whole);
    let all_files = report_files(&whole_text);
    assert!(all_files.len() > 1000, "{}", all_files.len());

    let shards = split(project(), corpus, 3, &[], &out);
    let mut seen = BTreeSet::new();
    for (k, report) in shards.iter().enumerate() {
        let text = std::fs::read_to_string(report).unwrap();
        let json: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(json["shard"]["index"], k + 1);
        assert_eq!(json["shard"]["count"], 3);
        let files = report_files(&text);
        assert!(!files.is_empty(), "shard {} is empty", k + 1);
        for file in files {
            let key = file.strip_prefix("../shared/corpus/").unwrap();
            assert_eq!(documented_shard(key, 3), k as u64 + 1, "{file}");
            assert!(seen.insert(file.clone()), "{file} is in two shards");
        }
    }
    assert_eq!(
        seen,
        all_files.iter().cloned().collect(),
        "the shards miss files"
    );

    let merged = merge(project(), &[], &shards);
    assert_eq!(
        merged.status.code(),
        whole.status.code(),
        "{}",
        stderr(&merged)
    );
    assert!(stdout(&merged) == whole_text, "merged JSON differs");

    let whole_sarif = x3dcheck(project(), &["--format", "sarif", corpus]);
    let merged_sarif = merge(project(), &["--format", "sarif"], &shards);
    assert!(
        stdout(&merged_sarif) == stdout(&whole_sarif),
        "merged SARIF differs"
    );
}

/// Over the rule fixtures (every code, related places, folded repeats, all severities).
#[test]
fn merge_writes_every_format_as_the_unsharded_run_does() {
    let rules = "corpus/rules";
    let out = scratch("shard-formats", &[]);
    let shards = split(project(), rules, 2, &[], &out);
    let formats: [&[&str]; 7] = [
        &["--format", "json"],
        &["--format", "sarif"],
        &["--format", "junit"],
        &["--format", "github"],
        &["--format", "concise"],
        &["--format", "json", "--statistics"],
        &["--format", "concise", "--statistics"],
    ];
    for format in formats {
        let mut argv = format.to_vec();
        argv.push(rules);
        let whole = x3dcheck(project(), &argv);
        let merged = merge(project(), format, &shards);
        assert_eq!(merged.status.code(), whole.status.code(), "{format:?}");
        assert!(stdout(&merged) == stdout(&whole), "{format:?} differs");
    }
    // The human statistics table needs no source text.
    let whole = x3dcheck(project(), &["--statistics", rules]);
    let merged = merge(project(), &["--statistics", "--format", "human"], &shards);
    assert_eq!(stdout(&merged), stdout(&whole));

    let written = out.join("merged.json");
    let to_file = merge(project(), &["-o", written.to_str().unwrap()], &shards);
    assert!(to_file.stdout.is_empty());
    assert_eq!(
        std::fs::read(&written).unwrap(),
        x3dcheck(project(), &["--format", "json", rules]).stdout
    );
}

#[test]
fn merge_exit_codes_follow_fail_on() {
    let rules = "corpus/rules";
    let out = scratch("shard-exit", &[]);
    let warnings_only = ["--select", "NODE_DEPRECATED"];
    let shards = split(project(), rules, 2, &warnings_only, &out);
    for (fail_on, code) in [("error", 0), ("warning", 1)] {
        let whole = x3dcheck(
            project(),
            &["--select", "NODE_DEPRECATED", "--fail-on", fail_on, rules],
        );
        assert_eq!(whole.status.code(), Some(code));
        let merged = merge(project(), &["--fail-on", fail_on], &shards);
        assert_eq!(merged.status.code(), Some(code), "--fail-on {fail_on}");
    }
}

fn scene(version: &str) -> String {
    format!("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<X3D profile='Interchange' version='{version}'><Scene><Shape><Box/></Shape></Scene></X3D>\n")
}

#[test]
fn a_new_file_moves_no_other_and_named_files_keep_their_path() {
    let valid = scene("4.0");
    let names: Vec<String> = (0..12)
        .map(|i| format!("sub{}/scene{i}.x3d", i % 3))
        .collect();
    let files: Vec<(&str, &str)> = names.iter().map(|n| (n.as_str(), valid.as_str())).collect();
    let dir = scratch("shard-stable", &files);
    let shard_of_each = |dir: &Path| {
        let mut shard_of = std::collections::BTreeMap::new();
        for k in 1..=3 {
            let output = x3dcheck(
                dir,
                &["--format", "json", "--shard", &format!("{k}/3"), "."],
            );
            assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
            for file in report_files(&stdout(&output)) {
                assert!(shard_of.insert(file.clone(), k).is_none(), "{file} twice");
            }
        }
        shard_of
    };
    let before = shard_of_each(&dir);
    assert_eq!(before.len(), names.len());
    for (file, k) in &before {
        assert_eq!(documented_shard(file.strip_prefix("./").unwrap(), 3), *k);
    }
    for i in 12..20 {
        let file = dir.join(format!("sub{}/scene{i}.x3d", i % 4));
        std::fs::create_dir_all(file.parent().unwrap()).unwrap();
        std::fs::write(file, &valid).unwrap();
    }
    let after = shard_of_each(&dir);
    assert_eq!(after.len(), 20);
    for (file, k) in &before {
        assert_eq!(after[file], *k, "{file} moved");
    }

    // A file named directly is keyed by the path as given, `.` components and `\` aside.
    for given in ["sub1/scene4.x3d", "./sub1/./scene4.x3d"] {
        for k in 1..=3 {
            let output = x3dcheck(
                &dir,
                &["--format", "json", "--shard", &format!("{k}/3"), given],
            );
            let files = report_files(&stdout(&output));
            let expected = documented_shard("sub1/scene4.x3d", 3) == k;
            assert_eq!(files.len(), usize::from(expected), "{given} in {k}/3");
        }
    }
    // The same relative path under another directory argument is in the same shard.
    let k = documented_shard("scene4.x3d", 3);
    let output = x3dcheck(
        &dir,
        &["--format", "json", "--shard", &format!("{k}/3"), "sub1"],
    );
    assert!(report_files(&stdout(&output)).contains(&"sub1/scene4.x3d".to_string()));
}

#[test]
fn stdin_is_in_shard_one() {
    let dir = scratch("shard-stdin", &[]);
    // stdin is empty here: a report for `<stdin>` all the same.
    let first = x3dcheck(&dir, &["--format", "json", "--shard", "1/2", "-"]);
    assert_eq!(report_files(&stdout(&first)), ["<stdin>"]);
    let second = x3dcheck(&dir, &["--format", "json", "--shard", "2/2", "-"]);
    assert_eq!(second.status.code(), Some(0));
    assert!(report_files(&stdout(&second)).is_empty());
}

#[test]
fn shards_must_be_k_of_n() {
    let dir = scratch("shard-usage", &[("a.x3d", &scene("4.0"))]);
    for bad in ["0/3", "4/3", "1/0", "2", "one/two"] {
        let output = x3dcheck(&dir, &["--shard", bad, "a.x3d"]);
        assert_eq!(output.status.code(), Some(2), "{bad}");
        assert!(
            stderr(&output).contains("--shard"),
            "{bad}: {}",
            stderr(&output)
        );
    }
}

#[test]
fn merge_refuses_what_does_not_merge() {
    let files: Vec<(String, String)> = (0..8)
        .map(|i| {
            (
                format!("s{i}.x3d"),
                scene(if i % 2 == 0 { "4.0" } else { "9.9" }),
            )
        })
        .collect();
    let files: Vec<(&str, &str)> = files
        .iter()
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect();
    let dir = scratch("merge-refuse", &files);
    // Reports outside the checked tree, where the walk would take them for X3D JSON.
    let out = scratch("merge-refuse-out", &[]);
    std::fs::create_dir(out.join("halves")).unwrap();
    std::fs::create_dir(out.join("thirds")).unwrap();
    let halves = split(&dir, ".", 2, &[], &out.join("halves"));
    let thirds = split(&dir, ".", 3, &[], &out.join("thirds"));
    let write = |name: &str, text: &str| {
        std::fs::write(out.join(name), text).unwrap();
        out.join(name)
    };
    let whole = write(
        "whole.json",
        &stdout(&x3dcheck(&dir, &["--format", "json", "."])),
    );
    let whole_text = std::fs::read_to_string(&whole).unwrap();
    let other_version = write(
        "old.json",
        &whole_text.replacen(
            &format!("\"version\": \"{}\"", env!("CARGO_PKG_VERSION")),
            "\"version\": \"0.0.0\"",
            1,
        ),
    );
    let sarif = write(
        "report.sarif",
        &stdout(&x3dcheck(&dir, &["--format", "sarif", "."])),
    );
    let statistics = write(
        "statistics.json",
        &stdout(&x3dcheck(&dir, &["--format", "json", "--statistics", "."])),
    );
    let not_json = write("notes.json", "checked by hand\n");
    let [h1, h2] = [halves[0].clone(), halves[1].clone()];

    let cases: Vec<(Vec<PathBuf>, &[&str], &str)> = vec![
        (vec![not_json.clone()], &[], "notes.json: not JSON"),
        (vec![sarif], &[], "not an x3dcheck JSON report"),
        (vec![statistics], &[], "--statistics report"),
        (vec![other_version], &[], "written by x3dcheck 0.0.0"),
        (vec![whole.clone(), whole.clone()], &[], "is in two reports"),
        (vec![h1.clone()], &[], "shard 2/2 is missing"),
        (vec![h1.clone(), h1.clone()], &[], "both shard 1/2"),
        (vec![h1.clone(), thirds[1].clone()], &[], "different splits"),
        (vec![h1.clone(), whole.clone()], &[], "not a shard report"),
        (
            vec![h1.clone(), h2.clone()],
            &["--format", "human"],
            "human format",
        ),
        (vec![dir.join("missing.json")], &[], "cannot read"),
    ];
    for (reports, args, message) in cases {
        let output = merge(&dir, args, &reports);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{message}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).contains(message),
            "{message}: {}",
            stderr(&output)
        );
        assert!(output.stdout.is_empty(), "{message}");
    }
    // The halves themselves do merge, into the whole.
    let merged = merge(&dir, &[], &[h2, h1]);
    assert_eq!(merged.status.code(), Some(1), "{}", stderr(&merged));
    assert!(stdout(&merged) == whole_text);
}
