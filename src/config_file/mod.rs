//! `x3dcheck.toml`: settings kept with the scenes. For each checked file the closest
//! `x3dcheck.toml` in its directory or an ancestor applies (the search stops at the
//! filesystem root); `--config FILE` names one file for all inputs instead. Standard input
//! is looked up from the current directory.
//!
//! ```toml
//! level = "deep"                    # fast | standard | deep
//! select = ["ROUTE_FIELD_UNKNOWN"]  # only these codes are reported (default: all)
//! ignore = ["PROFILE_MISSING"]      # never reported
//! fail-on = "warning"               # error | warning: the exit code's threshold
//! max-diagnostics = 100             # per file
//! fold = false                      # report each repeat on its own (like --no-fold)
//! normal-tolerance = 0.001          # NORMAL_NOT_UNIT's tolerance on |n| - 1
//!
//! [severity]                        # error | warning | info | hint
//! BACK_MATERIAL_NO_EFFECT = "warning"
//!
//! exclude = ["legacy/**", "build"]  # not searched in directory walks
//!
//! [[per-path-ignores]]              # like ruff's per-file-ignores
//! path = "legacy/**/*.x3d"
//! ignore = ["NODE_DEPRECATED", "FIELD_DEPRECATED"]
//! ```
//!
//! `exclude` is read from the file that applies to a directory argument (the closest
//! upward from it, or `--config`): entries of the walk whose path matches one of its
//! patterns (files, or directories with all they hold) are not searched; a file named on
//! the command line is checked anyway.
//!
//! Per-path and exclude patterns are matched against the checked file's path relative to the
//! directory of the configuration file ([`glob`] says how); a pattern without `/` matches
//! the file name in any directory.
//!
//! The command line wins over the file: `--level`, `--fail-on`, `--max-diagnostics`,
//! `--no-fold` and `--normal-tolerance` replace the file's value, `--select` replaces its
//! `select`, `--ignore` adds to its `ignore`, and `--severity` overrides it code by code.
//! Codes may be given as selectors ([`selector`]: any case, a prefix of whole words such as
//! `BACK_MATERIAL_`, or `ALL`). Unknown keys, levels and severities, and selectors matching
//! no code, are configuration errors (exit 2) naming the file, line and column, with the
//! nearest valid name.

pub mod glob;
pub mod selector;

use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use serde::Deserialize;
use toml::Spanned;

use crate::config::CheckConfig;
use crate::diagnostic::{Level, Severity};
use crate::validate::suggest;
use glob::Glob;
pub use selector::{select, select_codes};

/// The file name searched for.
pub const FILE_NAME: &str = "x3dcheck.toml";

/// A configuration that cannot be used: where and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConfigError {
    pub path: PathBuf,
    /// 1-based; 0 when the error has no place in the file (it could not be read).
    pub line: usize,
    pub column: usize,
    pub message: String,
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let path = self.path.display();
        if self.line == 0 {
            write!(f, "{path}: {}", self.message)
        } else {
            write!(f, "{path}:{}:{}: {}", self.line, self.column, self.message)
        }
    }
}

/// Settings from a file or the command line; `None` and empty mean "not given".
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Settings {
    pub level: Option<Level>,
    pub select: Option<Vec<String>>,
    pub ignore: Vec<String>,
    pub severity: Vec<(String, Severity)>,
    pub fail_on: Option<Severity>,
    pub max_diagnostics: Option<usize>,
    pub fold: Option<bool>,
    pub normal_tolerance: Option<f64>,
}

impl Settings {
    /// Lays these settings over `config` (see the module doc for how each key combines).
    fn apply(&self, config: &mut CheckConfig, fail_on: &mut Severity) {
        if let Some(level) = self.level {
            config.level = level;
        }
        if let Some(select) = &self.select {
            config.select = select.iter().cloned().collect();
        }
        config.ignore.extend(self.ignore.iter().cloned());
        for (code, severity) in &self.severity {
            config.severity.insert(code.clone(), *severity);
        }
        if let Some(level) = self.fail_on {
            *fail_on = level;
        }
        if let Some(max) = self.max_diagnostics {
            config.max_diagnostics = Some(max);
        }
        if let Some(fold) = self.fold {
            config.fold = fold;
        }
        if let Some(tolerance) = self.normal_tolerance {
            config.normal_tolerance = tolerance;
        }
    }
}

/// `[[per-path-ignores]]`: codes not reported for the files a pattern matches.
#[derive(Clone, Debug, PartialEq)]
pub struct PerPathIgnore {
    pub pattern: String,
    glob: Glob,
    pub ignore: Vec<String>,
}

/// One parsed `x3dcheck.toml`.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigFile {
    pub path: PathBuf,
    /// The directory per-path patterns are relative to.
    pub dir: PathBuf,
    pub settings: Settings,
    pub per_path_ignores: Vec<PerPathIgnore>,
    /// `exclude`: paths directory walks do not search.
    pub exclude: Vec<Glob>,
}

/// What applies to one checked file.
#[derive(Clone, Debug)]
pub struct Effective {
    pub check: CheckConfig,
    /// Diagnostics at or above this severity make the exit code 1.
    pub fail_on: Severity,
    /// The configuration file used, if any.
    pub file: Option<PathBuf>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct RawFile {
    level: Option<Spanned<String>>,
    select: Option<Vec<Spanned<String>>>,
    ignore: Option<Vec<Spanned<String>>>,
    severity: Option<BTreeMap<Spanned<String>, Spanned<String>>>,
    fail_on: Option<Spanned<String>>,
    max_diagnostics: Option<usize>,
    fold: Option<bool>,
    normal_tolerance: Option<Spanned<f64>>,
    per_path_ignores: Option<Vec<RawPerPath>>,
    exclude: Option<Vec<Spanned<String>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct RawPerPath {
    path: Spanned<String>,
    ignore: Vec<Spanned<String>>,
}

const KEYS: &[&str] = &[
    "level",
    "select",
    "ignore",
    "severity",
    "fail-on",
    "max-diagnostics",
    "fold",
    "normal-tolerance",
    "per-path-ignores",
    "exclude",
    "path",
];

impl ConfigFile {
    pub fn load(path: &Path) -> Result<ConfigFile, ConfigError> {
        let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
            path: path.to_path_buf(),
            line: 0,
            column: 0,
            message: format!("cannot read: {e}"),
        })?;
        ConfigFile::parse(path, &text)
    }

    /// Parses a file's text; `path` names it in errors and anchors per-path patterns.
    pub fn parse(path: &Path, text: &str) -> Result<ConfigFile, ConfigError> {
        let error = |span: Range<usize>, message: String| {
            let (line, column) = line_column(text, span.start);
            ConfigError {
                path: path.to_path_buf(),
                line,
                column,
                message,
            }
        };
        let raw: RawFile = toml::from_str(text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            error(span, toml_message(e.message()))
        })?;
        let codes_of = |selector: &Spanned<String>| -> Result<Vec<String>, ConfigError> {
            select_codes(selector.get_ref()).map_err(|m| error(selector.span(), m))
        };
        let codes = |list: &[Spanned<String>]| -> Result<Vec<String>, ConfigError> {
            let mut codes = Vec::new();
            for selector in list {
                codes.extend(codes_of(selector)?);
            }
            Ok(codes)
        };
        let mut settings = Settings::default();
        if let Some(level) = &raw.level {
            settings.level = Some(parse_level(level.get_ref()).ok_or_else(|| {
                error(
                    level.span(),
                    choice("level", level.get_ref(), &["fast", "standard", "deep"]),
                )
            })?);
        }
        settings.select = raw.select.as_deref().map(codes).transpose()?;
        settings.ignore = raw
            .ignore
            .as_deref()
            .map(codes)
            .transpose()?
            .unwrap_or_default();
        for (key, value) in raw.severity.iter().flatten() {
            let level = Severity::parse(value.get_ref()).ok_or_else(|| {
                let choices = ["error", "warning", "info", "hint"];
                error(value.span(), choice("severity", value.get_ref(), &choices))
            })?;
            for code in codes_of(key)? {
                settings.severity.push((code, level));
            }
        }
        if let Some(fail_on) = &raw.fail_on {
            settings.fail_on = Some(match fail_on.get_ref().as_str() {
                "error" => Severity::Error,
                "warning" => Severity::Warning,
                other => {
                    return Err(error(
                        fail_on.span(),
                        choice("fail-on", other, &["error", "warning"]),
                    ))
                }
            });
        }
        settings.max_diagnostics = raw.max_diagnostics;
        settings.fold = raw.fold;
        if let Some(tolerance) = &raw.normal_tolerance {
            let value = *tolerance.get_ref();
            if !(value.is_finite() && value >= 0.0) {
                let message = format!("normal-tolerance must be a finite number ≥ 0, not {value}");
                return Err(error(tolerance.span(), message));
            }
            settings.normal_tolerance = Some(value);
        }
        let mut per_path_ignores = Vec::new();
        for entry in raw.per_path_ignores.into_iter().flatten() {
            if entry.path.get_ref().trim().is_empty() {
                return Err(error(
                    entry.path.span(),
                    "per-path-ignores: empty `path`".to_string(),
                ));
            }
            per_path_ignores.push(PerPathIgnore {
                glob: Glob::new(entry.path.get_ref()),
                pattern: entry.path.into_inner(),
                ignore: codes(&entry.ignore)?,
            });
        }
        let mut exclude = Vec::new();
        for pattern in raw.exclude.iter().flatten() {
            if pattern.get_ref().trim().is_empty() {
                return Err(error(pattern.span(), "exclude: empty pattern".to_string()));
            }
            exclude.push(Glob::new(pattern.get_ref()));
        }
        let dir = std::path::absolute(path)
            .ok()
            .and_then(|p| p.parent().map(Path::to_path_buf))
            .unwrap_or_default();
        Ok(ConfigFile {
            path: path.to_path_buf(),
            dir,
            settings,
            per_path_ignores,
            exclude,
        })
    }

    /// Whether `exclude` names `path` (absolute), relative to this file's directory.
    pub fn excludes(&self, path: &Path) -> bool {
        let relative = relative_path(&self.dir, path);
        self.exclude.iter().any(|glob| glob.matches(&relative))
    }

    /// The codes the per-path ignores turn off for `file`.
    pub fn ignored_for(&self, file: &Path) -> impl Iterator<Item = &String> {
        let relative = relative_path(&self.dir, file);
        self.per_path_ignores
            .iter()
            .filter(move |p| p.glob.matches(&relative))
            .flat_map(|p| &p.ignore)
    }
}

/// Finds each input's configuration (cached per directory) and lays the command line over it.
pub struct Resolver {
    explicit: Option<Arc<ConfigFile>>,
    cli: Settings,
    by_dir: HashMap<PathBuf, Option<Arc<ConfigFile>>>,
}

impl Resolver {
    /// `explicit` is `--config FILE`; `cli` the settings the command line gave.
    pub fn new(explicit: Option<&Path>, cli: Settings) -> Result<Resolver, ConfigError> {
        let explicit = explicit.map(ConfigFile::load).transpose()?.map(Arc::new);
        Ok(Resolver {
            explicit,
            cli,
            by_dir: HashMap::new(),
        })
    }

    /// What applies to `file` (`None`: standard input, looked up from the current directory).
    pub fn for_file(&mut self, file: Option<&Path>) -> Result<Effective, ConfigError> {
        let absolute = file.and_then(|f| std::path::absolute(f).ok());
        let found = match &self.explicit {
            Some(explicit) => Some(explicit.clone()),
            None => {
                let start = match &absolute {
                    Some(path) => path.parent().map(Path::to_path_buf),
                    None => std::env::current_dir().ok(),
                };
                match start {
                    Some(dir) => self.discover(&dir)?,
                    None => None,
                }
            }
        };
        let mut check = CheckConfig::default();
        let mut fail_on = Severity::Error;
        if let Some(found) = &found {
            found.settings.apply(&mut check, &mut fail_on);
            if let Some(path) = &absolute {
                check.ignore.extend(found.ignored_for(path).cloned());
            }
        }
        self.cli.apply(&mut check, &mut fail_on);
        Ok(Effective {
            check,
            fail_on,
            file: found.map(|f| f.path.clone()),
        })
    }

    /// The configuration file that applies to the directory `dir`: `--config`, else the
    /// closest upward from it.
    pub fn file_for_dir(&mut self, dir: &Path) -> Result<Option<Arc<ConfigFile>>, ConfigError> {
        match &self.explicit {
            Some(explicit) => Ok(Some(explicit.clone())),
            None => match std::path::absolute(dir) {
                Ok(dir) => self.discover(&dir),
                Err(_) => Ok(None),
            },
        }
    }

    /// The closest `x3dcheck.toml` in `dir` or an ancestor.
    fn discover(&mut self, dir: &Path) -> Result<Option<Arc<ConfigFile>>, ConfigError> {
        let mut visited = Vec::new();
        let mut current = Some(dir);
        let found = loop {
            let Some(here) = current else {
                break None;
            };
            if let Some(known) = self.by_dir.get(here) {
                break known.clone();
            }
            visited.push(here.to_path_buf());
            let candidate = here.join(FILE_NAME);
            if candidate.is_file() {
                break Some(Arc::new(ConfigFile::load(&candidate)?));
            }
            current = here.parent();
        };
        for dir in visited {
            self.by_dir.insert(dir, found.clone());
        }
        Ok(found)
    }
}

fn parse_level(text: &str) -> Option<Level> {
    Some(match text {
        "fast" => Level::Fast,
        "standard" => Level::Standard,
        "deep" => Level::Deep,
        _ => return None,
    })
}

/// "unknown level `dep` (did you mean `deep`?); one of fast, standard, deep".
fn choice(what: &str, given: &str, choices: &[&'static str]) -> String {
    // A prefix (`warn`) first, then the nearest spelling.
    let prefixed: Vec<&str> = choices
        .iter()
        .copied()
        .filter(|c| !given.is_empty() && c.starts_with(given))
        .collect();
    let nearest = match prefixed[..] {
        [only] => Some(only),
        _ => suggest::did_you_mean(given, choices.iter().copied()),
    };
    let hint = nearest.map_or(String::new(), |c| format!(" (did you mean `{c}`?)"));
    format!(
        "unknown {what} `{given}`{hint}; one of {}",
        choices.join(", ")
    )
}

/// The toml crate's message, with "did you mean" for an unknown key.
fn toml_message(message: &str) -> String {
    let message = message.trim();
    let Some(rest) = message.strip_prefix("unknown field `") else {
        return message.to_string();
    };
    let key = rest.split('`').next().unwrap_or_default();
    match suggest::help(key, KEYS.iter().copied()) {
        Some(help) => format!("unknown key `{key}` ({help})"),
        None => format!(
            "unknown key `{key}`; the keys are {}",
            KEYS[..10].join(", ")
        ),
    }
}

/// 1-based line and column (in characters) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[line_start..].chars().count() + 1)
}

/// `file` relative to `dir` with `/` separators, or the whole path when it lies elsewhere.
fn relative_path(dir: &Path, file: &Path) -> String {
    let relative = file.strip_prefix(dir).unwrap_or(file);
    relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy())
        .filter(|c| c != "/" && c != "\\")
        .collect::<Vec<_>>()
        .join("/")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<ConfigFile, ConfigError> {
        ConfigFile::parse(Path::new("/p/x3dcheck.toml"), text)
    }

    #[test]
    fn every_key() {
        let file = parse(
            "level = 'deep'\nselect = ['DEF_DUPLICATE']\nignore = ['PROFILE_MISSING']\n\
             fail-on = 'warning'\nmax-diagnostics = 7\nfold = false\nnormal-tolerance = 0.5\n\
             [severity]\nDEF_DUPLICATE = 'info'\n\
             [[per-path-ignores]]\npath = 'old/*.x3d'\nignore = ['NODE_UNKNOWN']\n",
        )
        .unwrap();
        let s = &file.settings;
        assert_eq!(s.level, Some(Level::Deep));
        assert_eq!(
            s.select.as_deref(),
            Some(&["DEF_DUPLICATE".to_string()][..])
        );
        assert_eq!(s.ignore, ["PROFILE_MISSING"]);
        assert_eq!(s.severity, [("DEF_DUPLICATE".to_string(), Severity::Info)]);
        assert_eq!(s.fail_on, Some(Severity::Warning));
        assert_eq!(
            (s.max_diagnostics, s.fold, s.normal_tolerance),
            (Some(7), Some(false), Some(0.5))
        );
        assert_eq!(file.dir, Path::new("/p"));
        let ignored: Vec<_> = file.ignored_for(Path::new("/p/old/a.x3d")).collect();
        assert_eq!(ignored, ["NODE_UNKNOWN"]);
        assert_eq!(file.ignored_for(Path::new("/p/new/a.x3d")).count(), 0);
    }

    #[test]
    fn errors_name_the_line_and_the_nearest_name() {
        let e = parse("level = 'deep'\nlevl = 'fast'\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 1), "{e}");
        assert!(e.message.contains("did you mean `level`?"), "{e}");
        let e = parse("ignore = [\n  'DEF_DUPLCATE',\n]\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3), "{e}");
        assert!(e.message.contains("did you mean `DEF_DUPLICATE`?"), "{e}");
        let e = parse("[severity]\nDEF_DUPLICATE = 'warn'\n").unwrap_err();
        assert_eq!(e.line, 2, "{e}");
        assert!(e.message.contains("did you mean `warning`?"), "{e}");
        let e = parse("level = 'dep'").unwrap_err();
        assert!(e.message.contains("did you mean `deep`?"), "{e}");
        let e = parse("[[per-path-ignores]]\npath = 'a'\nignores = []\n").unwrap_err();
        assert_eq!(e.line, 3, "{e}");
        assert!(e.message.contains("did you mean `ignore`?"), "{e}");
        for bad in ["nan", "inf", "-inf", "-0.5"] {
            let e = parse(&format!("normal-tolerance = {bad}")).unwrap_err();
            assert!(e.message.contains("finite number"), "{bad}: {e}");
        }
        assert!(parse("max-diagnostics = -1").is_err());
        assert!(parse("level = ").is_err());
    }

    #[test]
    fn codes_are_selectors() {
        let file = parse(
            "select = ['back_material_']\nignore = ['Def_Duplicate']\n\
             [severity]\nALL = 'hint'\n",
        )
        .unwrap();
        let s = &file.settings;
        let select = s.select.as_deref().unwrap();
        assert!(select.len() > 1 && select.iter().all(|c| c.starts_with("BACK_MATERIAL_")));
        assert_eq!(s.ignore, ["DEF_DUPLICATE"]);
        assert_eq!(s.severity.len(), crate::validate::RULES.len());
        let e = parse("\nselect = ['BACK_MATERIAL_X']\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 11), "{e}");
    }

    #[test]
    fn the_command_line_wins() {
        let file = parse("level = 'deep'\nselect = ['DEF_DUPLICATE']\nignore = ['PROFILE_MISSING']\nfold = false\n")
            .unwrap();
        let cli = Settings {
            level: Some(Level::Fast),
            ignore: vec!["NODE_UNKNOWN".into()],
            fold: Some(true),
            ..Settings::default()
        };
        let (mut check, mut fail_on) = (CheckConfig::default(), Severity::Error);
        file.settings.apply(&mut check, &mut fail_on);
        cli.apply(&mut check, &mut fail_on);
        assert_eq!(check.level, Level::Fast);
        assert!(check.fold);
        assert!(check.select.contains("DEF_DUPLICATE"));
        assert!(check.ignore.contains("PROFILE_MISSING") && check.ignore.contains("NODE_UNKNOWN"));
    }

    #[test]
    fn line_columns_count_characters() {
        assert_eq!(line_column("a\nüb", 4), (2, 2));
        assert_eq!(line_column("", 10), (1, 1));
    }
}
