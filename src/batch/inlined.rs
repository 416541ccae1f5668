//! The files Inlines load that the batch does not list: checked as scenes of their own and
//! reported under their own paths, once per batch.
//!
//! At the deep level a checked scene reads each local Inline's file through the batch's
//! cache ([`Libraries`]), which notes it. After the listed inputs are checked, each noted
//! file that is not itself an input (of any shard, by any path: compared canonically) is
//! checked from the parsed file the cache holds — not read again — with the settings of
//! the x3dcheck.toml that applies to it and the tree it was reached in, and added to the
//! report: a single-file run reports its inlined files' findings with their own paths and
//! source text. Checking an inlined file may reach further Inlines, checked in the next
//! round until none is new. A file listed as an input is reported once, as that input.
//!
//! With `--shard K/N`, an inlined file outside the inputs is reported only by the shard
//! its own path (relative to the tree it was reached in) belongs to, when that shard
//! reaches it.

use std::collections::HashSet;
use std::panic::RefUnwindSafe;
use std::path::{Component, Path, PathBuf};

use rayon::prelude::*;

use crate::config_file::{Effective, Resolver};
use crate::library::Libraries;
use crate::report::FileReport;
use crate::shard::Shard;

/// One inlined file's report, its text in the per-file formats, and its configuration.
pub struct InlinedReport {
    pub report: FileReport,
    pub text: String,
    pub effective: Effective,
}

/// What the batch knows about its inputs.
pub struct Batch<'a> {
    pub libraries: &'a Libraries,
    /// Every listed file (of every shard).
    pub listed: &'a [PathBuf],
    pub shard: Option<Shard>,
    /// A report's text in the formats written per file, from the report and the source
    /// text its positions are in (empty where nothing is written per file).
    pub text: &'a (dyn Fn(&FileReport, &[u8]) -> String + Sync + RefUnwindSafe),
}

/// Checks the inlined files the batch does not list, round after round; Err for a file
/// whose configuration is wrong or whose check failed (reported as not checked).
pub fn check_inlined(batch: &Batch, resolver: &mut Resolver) -> Vec<Result<InlinedReport, String>> {
    let mut outcomes = Vec::new();
    if batch.libraries.inlined().is_empty() {
        return outcomes;
    }
    let mut done: HashSet<PathBuf> = batch
        .listed
        .iter()
        .filter_map(|p| p.canonicalize().ok())
        .collect();
    let cwd = std::env::current_dir()
        .and_then(|d| d.canonicalize())
        .unwrap_or_default();
    loop {
        let round: Vec<_> = batch
            .libraries
            .inlined()
            .into_iter()
            .filter(|(path, _, _)| done.insert(path.clone()))
            .filter(|(path, root, _)| in_shard(batch.shard, path, root))
            .collect();
        if round.is_empty() {
            return outcomes;
        }
        // Configuration first (the resolver is not shared between threads), then the checks.
        let prepared: Vec<_> = round
            .into_iter()
            .map(|(path, root, library)| {
                let name = display_name(&cwd, &path);
                let effective = resolver
                    .for_file(Some(Path::new(&name)))
                    .map(|mut effective| {
                        effective.check.root = Some(root);
                        effective.check.libraries = batch.libraries.clone();
                        effective
                    })
                    .map_err(|e| e.to_string());
                (name, library, effective)
            })
            .collect();
        let checked: Vec<Result<InlinedReport, String>> = prepared
            .into_par_iter()
            .map(|(name, library, effective)| {
                let effective = effective?;
                let failure = format!("internal error while checking {name}");
                std::panic::catch_unwind(|| {
                    let report = crate::check::check_library(&name, &library, &effective.check);
                    let text = (batch.text)(&report, &library.text);
                    (report, text)
                })
                .map(|(report, text)| InlinedReport {
                    report,
                    text,
                    effective,
                })
                .map_err(|_| failure)
            })
            .collect();
        outcomes.extend(checked);
    }
}

fn in_shard(shard: Option<Shard>, path: &Path, root: &Path) -> bool {
    let root = root.canonicalize().unwrap_or_else(|_| root.to_path_buf());
    shard.is_none_or(|s| s.holds(path.strip_prefix(&root).unwrap_or(path)))
}

/// A file's name in the report: relative to the working directory (with `..` where it is
/// not below it), as the inputs named relatively are.
fn display_name(cwd: &Path, path: &Path) -> String {
    let common = cwd
        .components()
        .zip(path.components())
        .take_while(|(a, b)| a == b)
        .count();
    // Only the root in common: an absolute path says more than a row of `..`.
    if common <= 1 {
        return path.display().to_string();
    }
    let mut relative = PathBuf::new();
    for _ in cwd.components().skip(common) {
        relative.push(Component::ParentDir);
    }
    for part in path.components().skip(common) {
        relative.push(part);
    }
    relative.display().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_relative_to_the_working_directory() {
        let cwd = Path::new("/work/main");
        assert_eq!(
            display_name(cwd, Path::new("/work/main/a/b.x3d")),
            "a/b.x3d"
        );
        assert_eq!(
            display_name(cwd, Path::new("/work/shared/c.x3d")),
            "../shared/c.x3d"
        );
        assert_eq!(display_name(cwd, Path::new("/tmp/d.x3d")), "/tmp/d.x3d");
    }
}
