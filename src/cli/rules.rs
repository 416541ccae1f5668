//! `x3dcheck rules [SELECTOR] [--format text|json]`: the rule table, fitted to 100 columns
//! (each rule's summary wrapped on the lines below its code), one rule's documentation, or
//! the rules as JSON for tools.

use crate::api::RuleInfo;
use crate::config_file::select;
use crate::diagnostic::Rule;
use crate::validate::RULES;
use clap::{Args, ValueEnum};

#[derive(Args, Debug)]
pub struct RulesArgs {
    /// A rule code, a prefix of codes (e.g. BACK_MATERIAL_) or ALL, in any case; one code
    /// prints its documentation
    selector: Option<String>,
    /// Output format: a table (or one rule's documentation), or JSON for tools
    #[arg(long, value_enum, default_value_t = RulesFormat::Text)]
    format: RulesFormat,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum RulesFormat {
    Text,
    /// An array of {code, severity, level, versions, clause, summary, doc}
    Json,
}

/// The width the table fits in.
const WIDTH: usize = 100;
/// The indent of the summary lines under a rule's code.
const SUMMARY_INDENT: &str = "    ";

/// The text `x3dcheck rules` prints.
pub fn rules(args: &RulesArgs) -> Result<String, String> {
    let selected = match &args.selector {
        None => RULES.to_vec(),
        Some(selector) => select(selector).map_err(|e| format!("rules: {e}"))?,
    };
    Ok(match (args.format, &selected[..]) {
        (RulesFormat::Json, _) => json_list(&selected),
        (RulesFormat::Text, [one]) => explain(one),
        (RulesFormat::Text, _) => table(&selected),
    })
}

fn json_list(rules: &[&Rule]) -> String {
    let list: Vec<RuleInfo> = rules.iter().map(|rule| RuleInfo::of(rule)).collect();
    let mut text = serde_json::to_string_pretty(&list).expect("strings serialize");
    text.push('\n');
    text
}

/// A line per rule with its code, severity, level, versions and clause (the clause
/// wrapped in its column), then its summary wrapped at [`WIDTH`] under it.
fn table(rules: &[&Rule]) -> String {
    let header = ["CODE", "SEVERITY", "LEVEL", "VERSIONS", "CLAUSE"];
    let rows: Vec<[String; 4]> = rules
        .iter()
        .map(|r| {
            [
                r.code.to_string(),
                r.severity.to_string(),
                r.level.as_str().to_string(),
                r.versions.to_string(),
            ]
        })
        .collect();
    let widths: Vec<usize> = (0..4)
        .map(|column| {
            rows.iter()
                .map(|row| row[column].chars().count())
                .chain([header[column].len()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let clause_start: usize = widths.iter().map(|w| w + 2).sum();
    let clause_width = WIDTH.saturating_sub(clause_start).max(16);
    let line = |cells: &[&str], clause: &str| {
        let mut text = String::new();
        for (cell, width) in cells.iter().zip(&widths) {
            text.push_str(&format!("{cell:width$}  "));
        }
        for (i, part) in textwrap::wrap(clause, clause_width).iter().enumerate() {
            if i > 0 {
                text.push('\n');
                text.push_str(&" ".repeat(clause_start));
            }
            text.push_str(part);
        }
        let mut text = text.trim_end().to_string();
        text.push('\n');
        text
    };
    let mut out = line(&header[..4], header[4]);
    for (rule, row) in rules.iter().zip(&rows) {
        let cells: Vec<&str> = row.iter().map(String::as_str).collect();
        out.push_str(&line(&cells, rule.clause));
        let options = textwrap::Options::new(WIDTH)
            .initial_indent(SUMMARY_INDENT)
            .subsequent_indent(SUMMARY_INDENT);
        for part in textwrap::wrap(&rule.summary(), options) {
            out.push_str(&part);
            out.push('\n');
        }
    }
    out
}

fn explain(rule: &Rule) -> String {
    format!(
        "{}\nseverity: {}  level: {}  versions: {}  clause: {}\n\n{}",
        rule.code,
        rule.severity,
        rule.level.as_str(),
        rule.versions,
        rule.clause,
        RuleInfo::of(rule).doc
    )
}
