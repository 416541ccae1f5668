//! Reporting: [`Diagnostic`](crate::diagnostic::Diagnostic)s are resolved once per file ([`resolve`]: line, column, path)
//! into a [`FileReport`], which each format renders: [`human`], [`concise`], [`json`].

pub mod concise;
pub mod github;
pub mod human;
pub mod json;
pub mod junit;
mod line_index;
mod path;
mod resolve;
pub mod sarif;
pub mod statistics;
mod stats;

pub use resolve::{resolve, Related, Resolved, ResolvedEdit, ResolvedFix};
pub use stats::Stats;

use serde::{Deserialize, Serialize};

use crate::diagnostic::Severity;
use crate::model::Encoding;

/// Everything reported for one input.
#[derive(Clone, Debug)]
pub struct FileReport {
    pub path: String,
    pub encoding: Option<Encoding>,
    /// Whether the input was gzip-compressed (positions are in the decompressed text).
    pub compressed: bool,
    pub x3d_version: Option<String>,
    pub profile: Option<String>,
    pub diagnostics: Vec<Resolved>,
    /// Whether `--max-diagnostics` dropped some.
    pub truncated: bool,
    /// Findings that inline `x3dcheck: ignore` comments suppressed (a folded finding counts
    /// as those it stands for).
    pub suppressed: usize,
    pub stats: Stats,
}

/// Diagnostics per severity over the files checked; a folded diagnostic counts as many.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Summary {
    pub files: usize,
    pub errors: usize,
    pub warnings: usize,
    pub infos: usize,
    pub hints: usize,
    /// Findings inline comments suppressed; said only when some were, so that other
    /// reports keep their bytes.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub suppressed: usize,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Summary {
    pub fn of(reports: &[FileReport]) -> Summary {
        let mut summary = Summary {
            files: reports.len(),
            suppressed: reports.iter().map(|r| r.suppressed).sum(),
            ..Summary::default()
        };
        for d in reports.iter().flat_map(|r| &r.diagnostics) {
            let count = match d.severity {
                Severity::Error => &mut summary.errors,
                Severity::Warning => &mut summary.warnings,
                Severity::Info => &mut summary.infos,
                Severity::Hint => &mut summary.hints,
            };
            *count += d.count;
        }
        summary
    }
}
