//! The JSON report of DESIGN.md: pretty-printed, deterministic (same input, same bytes).
//! [`read`] reads it back (for `x3dcheck merge`) through the same types, so that a report
//! read and written again is the same bytes.
//!
//! Beyond DESIGN.md's example: a diagnostic's `index`, `indices`, `value`, `help`,
//! `related` (other places that explain it: `line`, `column`, `message`) and `count` appear
//! when set (`count` when above 1), and so does `fix` (`title`, `applicability` `safe` or
//! `unsafe`, and `edits`: `line`, `column`, `endLine`, `endColumn`, `content`); a report of a `--shard K/N` run says which shard it
//! is (`"shard": { "index": K, "count": N }`).

use serde::{Deserialize, Serialize};

use super::resolve::VRML97_GRAMMAR;
use super::{FileReport, Related, Resolved, ResolvedEdit, ResolvedFix, Stats, Summary};
use crate::diagnostic::{find_rule_in, Applicability, Rule, Severity};
use crate::model::{Encoding, Span};
use crate::schema::clauses::SEQUENCER_KEYS;
use crate::shard::Shard;

const TOOL: &str = "x3dcheck";
const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The JSON report: what `x3dcheck --format json` prints, and what
/// [`crate::api::check`] returns. Fields are those of DESIGN.md; serializing it with
/// [`Report::to_json`] gives the command line's bytes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Report {
    /// Always `x3dcheck`.
    pub tool: String,
    /// The version of x3dcheck that wrote it.
    pub version: String,
    /// The part of a split (`--shard K/N`) the run checked.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// The inputs, then the files their Inlines load (deep level), in that order.
    pub files: Vec<File>,
    pub summary: Summary,
}

/// The report of one file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct File {
    /// The name the file was checked under.
    pub path: String,
    /// The encoding read (`xml`, `json`, `classicvrml`, `vrml97`); None when it is no scene.
    pub encoding: Option<Encoding>,
    /// Whether it was gzip-compressed (positions are in the decompressed text). Said only
    /// when true, so that reports of uncompressed input keep their bytes.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub compressed: bool,
    pub x3d_version: Option<String>,
    pub profile: Option<String>,
    /// In the order of their places in the file.
    pub diagnostics: Vec<Diagnostic>,
    /// Whether `max-diagnostics` dropped some.
    pub truncated: bool,
    /// Findings inline comments suppressed; said only when some were.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub suppressed: usize,
    pub stats: Stats,
}

/// One finding.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct Diagnostic {
    /// The rule's code (`x3dcheck rules CODE` explains it).
    pub code: String,
    pub severity: Severity,
    pub message: String,
    /// 1-based; columns count Unicode scalar values.
    pub line: usize,
    pub column: usize,
    /// Where the finding's place ends (exclusive).
    pub end_line: usize,
    pub end_column: usize,
    /// The structural path of the node or field (`/X3D/Scene/Shape[0]/Appearance`).
    pub path: String,
    /// The ISO/IEC 19775-1 clause the rule enforces (or the node type's subclause).
    pub clause: String,
    /// The index of the offending value in an MF field.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub index: Option<usize>,
    /// For a folded finding, the first indices it stands for.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub indices: Vec<usize>,
    /// The offending value, as written.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<String>,
    /// How to resolve it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub help: Option<String>,
    /// Other places that explain it ("first defined here").
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub related: Vec<RelatedPlace>,
    /// How many findings a folded one stands for (said when above 1).
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub count: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fix: Option<Fix>,
}

/// A finding's fix: what it does, whether `--fix` applies it (`safe`) or only
/// `--unsafe-fixes` (`unsafe`), and its edits in the decoded text.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fix {
    pub title: String,
    pub applicability: Applicability,
    pub edits: Vec<Edit>,
}

/// The text from (line, column) to (endLine, endColumn), exclusive, becomes `content`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct Edit {
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    pub content: String,
}

/// Another place that explains a finding.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RelatedPlace {
    pub line: usize,
    pub column: usize,
    pub message: String,
}

fn one() -> usize {
    1
}

fn is_one(count: &usize) -> bool {
    *count == 1
}

fn is_zero(count: &usize) -> bool {
    *count == 0
}

impl From<&Resolved> for Diagnostic {
    fn from(d: &Resolved) -> Diagnostic {
        Diagnostic {
            code: d.code.into(),
            severity: d.severity,
            message: d.message.clone(),
            line: d.line,
            column: d.column,
            end_line: d.end_line,
            end_column: d.end_column,
            path: d.path.clone(),
            clause: d.clause.into(),
            index: d.index,
            indices: d.indices.clone(),
            value: d.value.clone(),
            help: d.help.clone(),
            related: d
                .related
                .iter()
                .map(|r| RelatedPlace {
                    line: r.line,
                    column: r.column,
                    message: r.label.clone(),
                })
                .collect(),
            count: d.count,
            fix: d.fix.as_ref().map(|fix| Fix {
                title: fix.title.clone(),
                applicability: fix.applicability,
                edits: fix
                    .edits
                    .iter()
                    .map(|e| Edit {
                        line: e.line,
                        column: e.column,
                        end_line: e.end_line,
                        end_column: e.end_column,
                        content: e.replacement.clone(),
                    })
                    .collect(),
            }),
        }
    }
}

impl Report {
    /// The report of checked files. `shard`: the part of a split this run checked, if any.
    pub fn of(reports: &[FileReport], shard: Option<Shard>) -> Report {
        Report {
            tool: TOOL.into(),
            version: VERSION.into(),
            shard,
            files: reports.iter().map(File::from).collect(),
            summary: Summary::of(reports),
        }
    }

    /// The report as `x3dcheck --format json` prints it: pretty-printed, with a trailing
    /// newline.
    pub fn to_json(&self) -> String {
        // Plain structs with string keys: serializing cannot fail.
        let mut text = serde_json::to_string_pretty(self).expect("the report serializes");
        text.push('\n');
        text
    }
}

impl From<&FileReport> for File {
    fn from(r: &FileReport) -> File {
        File {
            path: r.path.clone(),
            encoding: r.encoding,
            compressed: r.compressed,
            x3d_version: r.x3d_version.clone(),
            profile: r.profile.clone(),
            diagnostics: r.diagnostics.iter().map(Diagnostic::from).collect(),
            truncated: r.truncated,
            suppressed: r.suppressed,
            stats: r.stats.clone(),
        }
    }
}

/// The whole report, with a trailing newline. `shard`: the part of a split this run
/// checked, if any.
pub fn render(reports: &[FileReport], shard: Option<Shard>) -> String {
    Report::of(reports, shard).to_json()
}

/// A report read back.
#[derive(Debug)]
pub struct ReadReport {
    pub shard: Option<Shard>,
    pub files: Vec<FileReport>,
}

#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("not JSON: {0}")]
    NotJson(serde_json::Error),
    #[error("not an x3dcheck JSON report (one of `x3dcheck --format json`)")]
    NotReport,
    #[error("a --statistics report, which lists no files")]
    Statistics,
    #[error("written by x3dcheck {0}, this is {VERSION}: reports merge only within one version")]
    Version(String),
    #[error("not a valid x3dcheck {VERSION} report: {0}")]
    Invalid(serde_json::Error),
    #[error("{0}")]
    Inconsistent(String),
}

/// Just enough of any JSON to tell what it is.
#[derive(Deserialize)]
struct Header {
    tool: Option<serde_json::Value>,
    version: Option<serde_json::Value>,
    statistics: Option<serde::de::IgnoredAny>,
}

/// Reads a report written by [`render`] of this version, whose codes are those of `rules`
/// (the catalogue). Spans are not in the report: the diagnostics read have empty spans at
/// 0, which the formats that need them (human, with the source) must not be given.
pub fn read(text: &str, rules: &[&'static Rule]) -> Result<ReadReport, ReadError> {
    let header: Header = serde_json::from_str(text).map_err(|e| match e.classify() {
        serde_json::error::Category::Data => ReadError::NotReport,
        _ => ReadError::NotJson(e),
    })?;
    if header.tool.as_ref().and_then(|t| t.as_str()) != Some(TOOL) {
        return Err(ReadError::NotReport);
    }
    if header.statistics.is_some() {
        return Err(ReadError::Statistics);
    }
    match header.version.as_ref().and_then(|v| v.as_str()) {
        Some(VERSION) => {}
        Some(other) => return Err(ReadError::Version(other.to_string())),
        None => return Err(ReadError::NotReport),
    }
    let report: Report = serde_json::from_str(text).map_err(ReadError::Invalid)?;
    if let Some(shard) = report.shard {
        Shard::new(shard.index, shard.count).map_err(ReadError::Inconsistent)?;
    }
    let files = report
        .files
        .into_iter()
        .map(|file| file_report(file, rules))
        .collect::<Result<Vec<_>, _>>()?;
    if Summary::of(&files) != report.summary {
        return Err(ReadError::Inconsistent(
            "its summary does not count its diagnostics".to_string(),
        ));
    }
    Ok(ReadReport {
        shard: report.shard,
        files,
    })
}

fn file_report(file: File, rules: &[&'static Rule]) -> Result<FileReport, ReadError> {
    let diagnostics = file
        .diagnostics
        .into_iter()
        .map(|d| {
            let rule = find_rule_in(rules, &d.code).ok_or_else(|| {
                ReadError::Inconsistent(format!("{}: unknown code {}", file.path, d.code))
            })?;
            Ok(Resolved {
                code: rule.code,
                severity: d.severity,
                message: d.message,
                line: d.line,
                column: d.column,
                end_line: d.end_line,
                end_column: d.end_column,
                path: d.path,
                // A finding on a node cites that node type's subclause; a VRML97 syntax
                // finding, 14772-1's grammar; a sequencer's decreasing key, 30.3.1.
                clause: crate::schema::clauses::known_subclause(&d.clause)
                    .or((d.clause == VRML97_GRAMMAR).then_some(VRML97_GRAMMAR))
                    .or((d.clause == SEQUENCER_KEYS).then_some(SEQUENCER_KEYS))
                    .unwrap_or(rule.clause),
                index: d.index,
                indices: d.indices,
                value: d.value,
                help: d.help,
                related: d
                    .related
                    .into_iter()
                    .map(|r| Related {
                        line: r.line,
                        column: r.column,
                        label: r.message,
                        span: Span::default(),
                    })
                    .collect(),
                count: d.count,
                span: Span::default(),
                fix: d.fix.map(|fix| ResolvedFix {
                    title: fix.title,
                    applicability: fix.applicability,
                    edits: fix
                        .edits
                        .into_iter()
                        .map(|e| ResolvedEdit {
                            line: e.line,
                            column: e.column,
                            end_line: e.end_line,
                            end_column: e.end_column,
                            replacement: e.content,
                            span: Span::default(),
                        })
                        .collect(),
                }),
            })
        })
        .collect::<Result<Vec<_>, ReadError>>()?;
    Ok(FileReport {
        path: file.path,
        encoding: file.encoding,
        compressed: file.compressed,
        x3d_version: file.x3d_version,
        profile: file.profile,
        diagnostics,
        truncated: file.truncated,
        suppressed: file.suppressed,
        stats: file.stats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::resolve;
    use crate::validate::{find_rule, RULES};

    fn report() -> FileReport {
        let source = b"<X3D>\n  <Scene>\n    <Shape/>\n  </Scene>\n</X3D>\n";
        let rule = find_rule("DEF_DUPLICATE").unwrap();
        let folded = crate::diagnostic::Diagnostic {
            indices: vec![3, 7],
            count: 2,
            ..crate::diagnostic::Diagnostic::new(
                rule,
                Span { start: 12, end: 19 },
                "a \"quoted\"\n",
            )
        };
        let diagnostics = [
            crate::diagnostic::Diagnostic::new(rule, Span { start: 20, end: 28 }, "DEF `A` again")
                .related(Span { start: 6, end: 13 }, "first defined here")
                .help("rename it")
                .value("A")
                .index(2),
            folded,
        ];
        FileReport {
            path: "dir/ü scene.x3d".to_string(),
            encoding: Some(Encoding::Xml),
            compressed: true,
            x3d_version: Some("4.0".to_string()),
            profile: None,
            diagnostics: resolve(&diagnostics, source, &(), None),
            truncated: true,
            suppressed: 0,
            stats: Stats::default(),
        }
    }

    #[test]
    fn a_report_read_back_renders_the_same_bytes() {
        let reports = [report(), report()];
        let shard = Some(Shard::new(2, 3).unwrap());
        let text = render(&reports, shard);
        assert!(text.contains("\"related\": [") && text.contains("\"index\": 2"));
        let read = read(&text, &RULES).unwrap();
        assert_eq!(read.shard, shard);
        assert_eq!(render(&read.files, shard), text);
        assert_eq!(read.files[0].diagnostics[0].related[0].line, 2);
    }

    #[test]
    fn what_is_not_a_report_is_refused() {
        let text = render(&[report()], None);
        let error = |text: &str| read(text, &RULES).unwrap_err().to_string();
        assert!(error("{").starts_with("not JSON"), "{}", error("{"));
        assert!(error("[1]").starts_with("not an x3dcheck"));
        assert!(error("{\"version\": \"2.1.0\", \"runs\": []}").starts_with("not an x3dcheck"));
        assert!(error("{\"tool\": \"x3dcheck\", \"statistics\": []}").contains("--statistics"));
        let old = text.replacen(VERSION, "0.0.1", 1);
        assert!(
            error(&old).contains("written by x3dcheck 0.0.1"),
            "{}",
            error(&old)
        );
        let extra = text.replacen("\"truncated\"", "\"extra\": 1, \"truncated\"", 1);
        assert!(
            error(&extra).contains("unknown field `extra`"),
            "{}",
            error(&extra)
        );
        let code = text.replacen("\"DEF_DUPLICATE\"", "\"NO_SUCH_CODE\"", 1);
        assert!(error(&code).contains("unknown code NO_SUCH_CODE"));
        let summary = text.replacen("\"errors\": 3", "\"errors\": 2", 1);
        assert!(error(&summary).contains("summary"), "{}", error(&summary));
        let shard = text.replacen(
            "\"files\"",
            "\"shard\": {\"index\": 4, \"count\": 3}, \"files\"",
            1,
        );
        assert!(error(&shard).contains("4/3"), "{}", error(&shard));
    }
}
