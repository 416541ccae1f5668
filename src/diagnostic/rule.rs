//! What a rule is: its stable code, default severity, level and clause, and its docs.
//! Each rule lives in a file of its own and is declared with [`declare_rule!`], whose doc
//! comment is the single source of the rustdoc page, `x3dcheck rules CODE` and the docs.

use std::fmt;

use serde::{Deserialize, Serialize};

#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Hint,
    Info,
    Warning,
    Error,
}

impl Severity {
    pub fn parse(text: &str) -> Option<Severity> {
        Some(match text {
            "error" => Severity::Error,
            "warning" => Severity::Warning,
            "info" => Severity::Info,
            "hint" => Severity::Hint,
            _ => return None,
        })
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
            Severity::Hint => "hint",
        }
    }
}

impl fmt::Display for Severity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// How much checking is done: each level runs every rule of the levels below it.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// Syntax and schema.
    Fast,
    /// Adds cross-node semantics.
    Standard,
    /// Adds numeric analysis of geometry data and reading referenced files.
    Deep,
}

impl Level {
    pub fn as_str(self) -> &'static str {
        match self {
            Level::Fast => "fast",
            Level::Standard => "standard",
            Level::Deep => "deep",
        }
    }
}

/// A rule as the catalogue lists it. Rules found while reading (syntax, DEF/USE) are
/// reported by the readers and the model builder; the others have a check function in
/// [`crate::validate`] ([`crate::validate::Check`]).
pub struct Rule {
    pub code: &'static str,
    pub severity: Severity,
    pub level: Level,
    /// ISO/IEC 19775-1 clause (or 19776 encoding clause) the rule enforces.
    pub clause: &'static str,
    /// X3D versions where it applies, as the catalogue writes them: `all`, `4.x`, `4.1`.
    pub versions: &'static str,
    /// The rule's documentation (Markdown: What it does / Why it matters / Example / Clause).
    pub doc: &'static str,
}

impl Rule {
    /// The first sentence under "What it does", for listings.
    pub fn summary(&self) -> String {
        let paragraph: Vec<&str> = self
            .doc
            .lines()
            .map(str::trim)
            .skip_while(|l| l.is_empty() || l.starts_with('#'))
            .take_while(|l| !l.is_empty())
            .collect();
        let text = paragraph.join(" ");
        first_sentence(&text).to_string()
    }
}

/// The rule of `code` among `rules`: the catalogue, which the registry in
/// [`crate::validate`] holds and hands to those below it that print rules (the formats).
pub fn find_rule_in(rules: &[&'static Rule], code: &str) -> Option<&'static Rule> {
    rules.iter().copied().find(|rule| rule.code == code)
}

/// Abbreviations whose full stop ends no sentence (compared without case).
const ABBREVIATIONS: &[&str] = &["e.g", "i.e", "etc", "cf", "vs", "approx", "resp"];

/// `text` up to the full stop that ends its first sentence: one followed by a space or the
/// end, outside brackets and `code`, and not closing an abbreviation such as "e.g.".
fn first_sentence(text: &str) -> &str {
    let (mut depth, mut in_code) = (0usize, false);
    for (i, c) in text.char_indices() {
        match c {
            '`' => in_code = !in_code,
            '(' | '[' if !in_code => depth += 1,
            ')' | ']' if !in_code => depth = depth.saturating_sub(1),
            '.' if depth == 0 && !in_code => {
                let ends_word = text[i + 1..].chars().next().is_none_or(char::is_whitespace);
                let word = text[..i].rsplit([' ', '(']).next().unwrap_or_default();
                let abbreviation = ABBREVIATIONS.iter().any(|a| a.eq_ignore_ascii_case(word));
                if ends_word && !abbreviation {
                    return &text[..=i];
                }
            }
            _ => {}
        }
    }
    text
}

impl fmt::Debug for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.code)
    }
}

/// Declares a rule: `declare_rule! { /// docs… pub static CODE = { severity, level, clause,
/// versions } }`. With `check: Some(f)` after `versions` it also declares the module's
/// `CHECK` ([`crate::validate::Check`]), which runs `f`: one rule per module.
#[macro_export]
macro_rules! declare_rule {
    (
        $(#[doc = $doc:literal])*
        pub static $code:ident = {
            severity: $severity:ident,
            level: $level:ident,
            clause: $clause:literal,
            versions: $versions:literal $(,)?
        }
    ) => {
        $(#[doc = $doc])*
        pub static $code: $crate::diagnostic::Rule = $crate::diagnostic::Rule {
            code: stringify!($code),
            severity: $crate::diagnostic::Severity::$severity,
            level: $crate::diagnostic::Level::$level,
            clause: $clause,
            versions: $versions,
            doc: concat!($($doc, "\n"),*),
        };
    };
    (
        $(#[doc = $doc:literal])*
        pub static $code:ident = {
            severity: $severity:ident,
            level: $level:ident,
            clause: $clause:literal,
            versions: $versions:literal,
            check: Some($check:expr) $(,)?
        }
    ) => {
        $crate::declare_rule! {
            $(#[doc = $doc])*
            pub static $code = {
                severity: $severity,
                level: $level,
                clause: $clause,
                versions: $versions,
            }
        }

        /// This module's rule with its check function, for the registry.
        pub static CHECK: $crate::validate::Check = $crate::validate::Check {
            rule: &$code,
            run: Some($check),
        };
    };
}

#[cfg(test)]
mod tests {
    use super::first_sentence;

    #[test]
    fn sentences_end_at_full_stops_outside_brackets_code_and_abbreviations() {
        let text = "Reports a value (e.g. `a. b` is [0,∞) in 4.x). Then more.";
        assert_eq!(
            first_sentence(text),
            "Reports a value (e.g. `a. b` is [0,∞) in 4.x)."
        );
        assert_eq!(
            first_sentence("Uses i.e. this, etc. too. Next."),
            "Uses i.e. this, etc. too."
        );
        assert_eq!(first_sentence("Version 3.3 only."), "Version 3.3 only.");
        assert_eq!(first_sentence("No full stop"), "No full stop");
    }
}
