//! Applying fixes, in ruff's model: the fixes the rules attach to their findings
//! ([`Fix`](crate::diagnostic::Fix)) are applied to the checked text in order of place, a fix
//! whose edits overlap (or touch) one applied before it is left for the next pass, and the
//! text is checked again, until nothing more applies or [`MAX_PASSES`] is reached.
//!
//! Only a file whose decoded text is its bytes (UTF-8, with or without a byte-order mark,
//! not compressed) is fixed: the edits are offsets into the decoded text, and writing back
//! a gzip stream or a re-encoded file (UTF-16, windows-1252, …) would change bytes no
//! edit touched (compression level, header, unmappable characters), so such a file is
//! reported as not fixable ([`Unwritable`]) and left as it is.

use crate::check::check_document;
use crate::config::CheckConfig;
use crate::diagnostic::Applicability;
use crate::report::{FileReport, Resolved};

/// How often a file is fixed and checked again at most (ruff stops at 100; a fix here
/// never makes another one necessary more than a few times over).
pub const MAX_PASSES: usize = 10;

const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// Why a file with fixes is not fixed.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Unwritable {
    /// gzip-compressed input.
    Compressed,
    /// Text in an encoding other than UTF-8 (decoded to UTF-8 for the check).
    Reencoded,
}

impl std::fmt::Display for Unwritable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Unwritable::Compressed => {
                "fix not applied: compressed input (decompress it, fix it, compress it again)"
            }
            Unwritable::Reencoded => {
                "fix not applied: the file is not UTF-8 (x3dcheck writes back only UTF-8 files; convert it first)"
            }
        })
    }
}

/// What fixing one file gave.
pub struct Fixed {
    /// The report of the text as fixed: what remains.
    pub report: FileReport,
    /// The file's bytes as fixed (the input's when nothing was fixed).
    pub bytes: Vec<u8>,
    /// The decoded text of `bytes`, which the report's positions are in.
    pub text: Vec<u8>,
    /// How many fixes were applied over all passes.
    pub fixed: usize,
    /// Why the file could not be fixed, when it had applicable fixes.
    pub unwritable: Option<Unwritable>,
    /// Whether the last pass still had fixes to apply ([`MAX_PASSES`] reached).
    pub unconverged: bool,
}

impl Fixed {
    pub fn changed(&self, source: &[u8]) -> bool {
        self.bytes != source
    }
}

/// Checks `source` and applies its fixes (unsafe ones when `unsafe_fixes`), checking again
/// after each pass; the report is that of the text as fixed.
pub fn fix_source(path: &str, source: &[u8], config: &CheckConfig, unsafe_fixes: bool) -> Fixed {
    let mut bytes = source.to_vec();
    let mut fixed = 0;
    let mut pass = 0;
    loop {
        let checked = check_document(path, &bytes, config);
        let (report, text) = (checked.report, checked.text.into_owned());
        let mut unwritable = None;
        let mut unconverged = false;
        if report.diagnostics.iter().any(|d| d.fixable(unsafe_fixes)) {
            match writable_prefix(&bytes, &text) {
                Err(why) => unwritable = Some(why),
                Ok(_) if pass == MAX_PASSES => unconverged = true,
                Ok(prefix) => {
                    if let Some((new_text, count)) = apply(&text, &report.diagnostics, unsafe_fixes)
                    {
                        bytes = [prefix, new_text.as_slice()].concat();
                        fixed += count;
                        pass += 1;
                        continue;
                    }
                }
            }
        }
        return Fixed {
            report,
            bytes,
            text,
            fixed,
            unwritable,
            unconverged,
        };
    }
}

/// The bytes before the decoded text in the file (a UTF-8 byte-order mark, or nothing),
/// when the file is that prefix and the text; otherwise why it cannot be written back.
fn writable_prefix<'a>(bytes: &'a [u8], text: &[u8]) -> Result<&'a [u8], Unwritable> {
    if bytes.starts_with(&crate::parse::decode::GZIP_MAGIC) {
        return Err(Unwritable::Compressed);
    }
    match bytes.strip_suffix(text) {
        Some(prefix) if prefix.is_empty() || prefix == UTF8_BOM => Ok(prefix),
        _ => Err(Unwritable::Reencoded),
    }
}

/// Applies the fixes of `diagnostics` to `text`, in order of place: safe ones, and unsafe
/// ones when `unsafe_fixes`. A fix that overlaps or touches one applied before it is
/// skipped (the next pass sees it again), as is a fix equal to one applied (two findings
/// asking for the same statement); a fix whose edits fall outside the text or between the
/// bytes of a character is never applied. The new text and how many fixes were applied,
/// or None when none was.
pub fn apply(
    text: &[u8],
    diagnostics: &[Resolved],
    unsafe_fixes: bool,
) -> Option<(Vec<u8>, usize)> {
    let mut fixes: Vec<_> = diagnostics
        .iter()
        .filter(|d| d.fixable(unsafe_fixes))
        .filter_map(|d| d.fix.as_ref())
        .filter(|f| !f.edits.is_empty() && f.edits.iter().all(|e| within(text, e.span)))
        .collect();
    fixes.sort_by_key(|f| {
        let start = f.edits.iter().map(|e| e.span.start).min();
        (start, f.applicability == Applicability::Unsafe)
    });
    let mut out = Vec::with_capacity(text.len());
    let mut last_end: Option<usize> = None;
    let mut applied: Vec<&crate::report::ResolvedFix> = Vec::new();
    for fix in fixes {
        if applied.iter().any(|a| a.edits == fix.edits) {
            continue;
        }
        let mut edits: Vec<_> = fix.edits.iter().collect();
        edits.sort_by_key(|e| (e.span.start, e.span.end));
        let first = edits[0].span.start as usize;
        if last_end.is_some_and(|end| end >= first)
            || edits
                .windows(2)
                .any(|w| w[0].span.end > w[1].span.start || w[0].span == w[1].span)
        {
            continue;
        }
        let mut at = last_end.unwrap_or(0);
        for edit in edits {
            out.extend_from_slice(&text[at..edit.span.start as usize]);
            out.extend_from_slice(edit.replacement.as_bytes());
            at = edit.span.end as usize;
        }
        last_end = Some(at);
        applied.push(fix);
    }
    let end = last_end?;
    out.extend_from_slice(&text[end..]);
    Some((out, applied.len()))
}

/// Whether `span` lies in `text` and starts and ends on character boundaries.
fn within(text: &[u8], span: crate::diagnostic::Span) -> bool {
    let (start, end) = (span.start as usize, span.end as usize);
    let boundary = |at: usize| at == text.len() || (text[at] as i8) >= -0x40;
    start <= end && end <= text.len() && boundary(start) && boundary(end)
}

/// A unified diff (3 lines of context) of `old` → `new`, as `diff -u` prints it, headed
/// by `path`; empty when they are equal.
pub fn unified_diff(path: &str, old: &[u8], new: &[u8]) -> String {
    let (old, new) = (String::from_utf8_lossy(old), String::from_utf8_lossy(new));
    if old == new {
        return String::new();
    }
    similar::TextDiff::from_lines(old.as_ref(), new.as_ref())
        .unified_diff()
        .context_radius(3)
        .header(&format!("a/{path}"), &format!("b/{path}"))
        .to_string()
}

/// The summary of fixable findings: "3 fixable with --fix (1 more with --unsafe-fixes)",
/// or with `--unsafe-fixes` "4 fixable with --fix --unsafe-fixes"; None when there are none.
pub fn fixable_line(reports: &[FileReport], unsafe_fixes: bool) -> Option<String> {
    let all = reports.iter().flat_map(|r| &r.diagnostics);
    let safe = all.clone().filter(|d| d.fixable(false)).count();
    let with_unsafe = all.filter(|d| d.fixable(true)).count();
    if unsafe_fixes {
        return (with_unsafe > 0)
            .then(|| format!("{with_unsafe} fixable with --fix --unsafe-fixes"));
    }
    match (safe, with_unsafe - safe) {
        (0, 0) => None,
        (safe, 0) => Some(format!("{safe} fixable with --fix")),
        (safe, more) => Some(format!(
            "{safe} fixable with --fix ({more} more with --unsafe-fixes)"
        )),
    }
}

/// The text a run says it fixed: "Fixed 3 findings." (ruff's "Found …, fixed …").
pub fn fixed_line(fixed: usize) -> String {
    let plural = if fixed == 1 { "" } else { "s" };
    format!("Fixed {fixed} finding{plural}")
}
