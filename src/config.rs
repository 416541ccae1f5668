//! What to check and how to weigh it: the level, which codes run, severity overrides and
//! the fail level. Built from the command line (and, later, `x3dcheck.toml`).

use std::collections::{HashMap, HashSet};

use crate::diagnostic::{Level, Rule, Severity};

#[derive(Clone, Debug)]
pub struct CheckConfig {
    pub level: Level,
    /// When not empty, only these codes are reported.
    pub select: HashSet<String>,
    pub ignore: HashSet<String>,
    pub severity: HashMap<String, Severity>,
    /// Per file: further diagnostics are dropped and the report says it truncated.
    pub max_diagnostics: Option<usize>,
    /// Fold repeats of one code on one field into one diagnostic (`--no-fold` clears it).
    pub fold: bool,
    /// How far a normal's length may differ from 1 before NORMAL_NOT_UNIT (deep level).
    pub normal_tolerance: f64,
    /// The directory tree the deep level may read referenced files from (textures,
    /// Inlines). None: the checked file's own directory and below.
    pub root: Option<std::path::PathBuf>,
    /// Whether the document [`check_document`] hands back will be rendered (`--render`).
    /// At the fast level, unless it will, numeric MF values are checked as they are read
    /// and not kept (see [`crate::model::Summary`]); the other levels keep them anyway.
    ///
    /// [`check_document`]: crate::check::check_document
    pub render: bool,
    /// Which X3D island of an HTML page (1-based) [`check_document`] hands back as the
    /// document (`--island`); every island is checked.
    ///
    /// [`check_document`]: crate::check::check_document
    pub island: usize,
    /// The prototype libraries read so far (deep level): one cache for every file of a
    /// batch, so that a library many scenes name is read once. Cloning the configuration
    /// shares it.
    pub libraries: crate::library::Libraries,
}

impl Default for CheckConfig {
    fn default() -> CheckConfig {
        CheckConfig {
            level: Level::Standard,
            select: HashSet::new(),
            ignore: HashSet::new(),
            severity: HashMap::new(),
            max_diagnostics: None,
            fold: true,
            normal_tolerance: 0.01,
            root: None,
            render: false,
            island: 1,
            libraries: crate::library::Libraries::default(),
        }
    }
}

impl CheckConfig {
    /// Whether diagnostics of this code are reported at all.
    pub fn enabled(&self, code: &str) -> bool {
        (self.select.is_empty() || self.select.contains(code)) && !self.ignore.contains(code)
    }

    /// What the reader keeps of numeric MF values: summaries at the fast level when the
    /// document is not rendered, every number otherwise.
    pub fn keep_values(&self) -> crate::parse::KeepValues {
        if self.level == Level::Fast && !self.render {
            crate::parse::KeepValues::Summaries
        } else {
            crate::parse::KeepValues::All
        }
    }

    /// Whether a rule's check runs: enabled, and at or below the configured level.
    pub fn runs(&self, rule: &Rule) -> bool {
        rule.level <= self.level && self.enabled(rule.code)
    }

    /// The severity a diagnostic is reported with: the user's override, else its own.
    pub fn severity_of(&self, code: &str, own: Severity) -> Severity {
        self.severity.get(code).copied().unwrap_or(own)
    }
}
