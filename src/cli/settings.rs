//! `--show-settings`: what applies to an input — the x3dcheck.toml found for it (or none)
//! with the command line laid over it — printed as TOML one could paste into an
//! x3dcheck.toml.

use std::fmt::Write as _;

use crate::config_file::Effective;

/// The settings `effective` holds for the input named `name`.
pub fn show(name: &str, effective: &Effective) -> String {
    let check = &effective.check;
    let mut out = format!("# Settings for {name}\n");
    match &effective.file {
        Some(file) => {
            let _ = writeln!(
                out,
                "# from {}, with the command line over it",
                file.display()
            );
        }
        None => out
            .push_str("# no x3dcheck.toml found: the defaults, with the command line over them\n"),
    }
    if let Some(root) = &check.root {
        let _ = writeln!(
            out,
            "# referenced files (deep level) are read from within {}",
            root.display()
        );
    }
    let _ = writeln!(out, "level = \"{}\"", check.level.as_str());
    let _ = writeln!(
        out,
        "select = {}{}",
        list(&check.select),
        if check.select.is_empty() {
            "  # empty: every code"
        } else {
            ""
        }
    );
    let _ = writeln!(out, "ignore = {}", list(&check.ignore));
    let _ = writeln!(out, "fail-on = \"{}\"", effective.fail_on);
    match check.max_diagnostics {
        Some(max) => {
            let _ = writeln!(out, "max-diagnostics = {max}");
        }
        None => out.push_str("# max-diagnostics: no limit\n"),
    }
    let _ = writeln!(out, "fold = {}", check.fold);
    let _ = writeln!(out, "normal-tolerance = {:?}", check.normal_tolerance);
    out.push_str("\n[severity]\n");
    let mut overrides: Vec<_> = check.severity.iter().collect();
    overrides.sort();
    for (code, severity) in overrides {
        let _ = writeln!(out, "{code} = \"{severity}\"");
    }
    out
}

/// A TOML array of codes, sorted.
fn list<'a>(codes: impl IntoIterator<Item = &'a String>) -> String {
    let mut codes: Vec<&String> = codes.into_iter().collect();
    codes.sort();
    let quoted: Vec<String> = codes.iter().map(|c| format!("\"{c}\"")).collect();
    format!("[{}]", quoted.join(", "))
}
