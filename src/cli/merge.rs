//! `x3dcheck merge REPORT.json...`: combines JSON reports, typically those of the
//! `--shard K/N` runs of a CI pipeline, into the report one unsharded run gives: the files
//! in path order (the order of a directory argument's walk; with several PATH arguments an
//! unsharded run lists them in argument order instead), the summary counted again.
//!
//! It writes every format that does not need the source text; the human format shows each
//! finding's source lines, which a JSON report does not carry, so it is refused (with
//! `--statistics`, whose table needs no source, it is allowed). Re-reading the sources
//! instead was rejected: they may have changed since the check, and the carets would then
//! point at the wrong text.
//!
//! What does not merge is refused with exit code 2: input that is not a JSON report of this
//! version, a file in two reports, and an incomplete or mixed split (shard reports must be
//! all N shards of one split: a lost shard would otherwise pass a pipeline unnoticed). The
//! fail level is `--fail-on` (default error) for every file: the reports do not record the
//! `fail-on` of the x3dcheck.toml files the checks used.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::{Path, PathBuf};

use clap::Args;

use crate::report::json::{self, ReadReport};
use crate::report::{concise, github, FileReport};
use crate::shard::Shard;
use crate::validate::RULES;

use super::{check_statistics_format, fail_level, read_file, FailOn, Format, ReportOutput};

#[derive(Args, Debug)]
pub struct MergeArgs {
    /// Reports written by `x3dcheck --format json` (of this version)
    #[arg(value_name = "REPORT.json", required = true)]
    reports: Vec<PathBuf>,
    /// Report format (not human: the reports do not carry the source lines it shows)
    #[arg(long, value_enum, default_value_t = Format::Json)]
    format: Format,
    /// Write the report to FILE instead of stdout
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Exit with 1 when a diagnostic of this severity or above is reported
    #[arg(long, value_enum, default_value_t = FailOn::Error)]
    fail_on: FailOn,
    /// Print per code how many findings and files instead of the findings (human, concise
    /// or json format)
    #[arg(long)]
    statistics: bool,
}

pub fn merge(args: &MergeArgs) -> Result<u8, String> {
    check_statistics_format(args.statistics, args.format)?;
    if args.format == Format::Human && !args.statistics {
        return Err(
            "merge cannot write the human format: it shows each finding's source \
                    lines, which JSON reports do not carry (use --format concise, or check \
                    the files again)"
                .to_string(),
        );
    }
    let mut inputs = Vec::with_capacity(args.reports.len());
    for path in &args.reports {
        let bytes = read_file(path)?;
        let text = std::str::from_utf8(&bytes)
            .map_err(|e| format!("{}: not UTF-8 text: {e}", path.display()))?;
        let report = json::read(text, &RULES).map_err(|e| format!("{}: {e}", path.display()))?;
        inputs.push((path.as_path(), report));
    }
    check_split(&inputs)?;
    let files = combine(inputs)?;

    let fail_levels = vec![fail_level(args.fail_on); files.len()];
    let text: String = match (args.statistics, args.format) {
        (false, Format::Concise) => files.iter().map(concise::render).collect(),
        (false, Format::Github) => files.iter().map(github::render).collect(),
        _ => String::new(),
    };
    let output = ReportOutput {
        format: args.format,
        statistics: args.statistics,
        summary: true,
        shard: None,
        output: args.output.as_deref(),
        to_stderr: false,
        fixes: None,
        unsafe_fixes: false,
    };
    let fails = output.write(&files, &fail_levels, text)?;
    Ok(u8::from(fails))
}

/// Shard reports merge only as a whole split: all of one N, each K once, none missing.
fn check_split(inputs: &[(&Path, ReadReport)]) -> Result<(), String> {
    let Some((first_path, first)) = inputs
        .iter()
        .find_map(|(path, report)| Some((path, report.shard?)))
    else {
        return Ok(());
    };
    let mut seen: BTreeMap<u32, &Path> = BTreeMap::new();
    for (path, report) in inputs {
        let shard = report.shard.ok_or_else(|| {
            format!(
                "{} is shard {first} of a split, but {} is not a shard report: merge the \
                 shard reports of one split",
                first_path.display(),
                path.display()
            )
        })?;
        if shard.count != first.count {
            return Err(format!(
                "{} is shard {shard}, {} shard {first}: shards of different splits",
                path.display(),
                first_path.display()
            ));
        }
        if let Some(other) = seen.insert(shard.index, path) {
            return Err(format!(
                "{} and {} are both shard {shard}",
                other.display(),
                path.display()
            ));
        }
    }
    let missing: Vec<String> = (1..=first.count)
        .filter(|k| !seen.contains_key(k))
        .take(5)
        .map(|index| Shard { index, ..first }.to_string())
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    let absent = first.count as usize - seen.len();
    let more = if absent > missing.len() { ", …" } else { "" };
    let (noun, verb) = if absent == 1 {
        ("shard", "is")
    } else {
        ("shards", "are")
    };
    Err(format!(
        "{noun} {}{more} {verb} missing: the merge would not be the report of the whole tree",
        missing.join(", ")
    ))
}

/// The files of all reports in path order. A file may appear twice in one report (an
/// unsharded run given it twice lists it twice), not in two.
fn combine(inputs: Vec<(&Path, ReadReport)>) -> Result<Vec<FileReport>, String> {
    let mut owner: HashMap<&str, &Path> = HashMap::new();
    for (path, report) in &inputs {
        let mut own = HashSet::new();
        for file in report.files.iter().map(|f| f.path.as_str()) {
            if !own.insert(file) {
                continue;
            }
            if let Some(other) = owner.insert(file, path) {
                return Err(format!(
                    "{file} is in two reports: {} and {}",
                    other.display(),
                    path.display()
                ));
            }
        }
    }
    let mut files: Vec<FileReport> = inputs.into_iter().flat_map(|(_, r)| r.files).collect();
    // The order of `find_inputs`: paths compared by components, stably.
    files.sort_by(|a, b| Path::new(&a.path).cmp(Path::new(&b.path)));
    Ok(files)
}
