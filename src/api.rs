//! The library API: a scene in memory (or a file) checked as the command line checks it,
//! into the command line's JSON report as a typed, serde-serializable value. The Python and
//! Node.js packages (`bindings/`) call these functions and nothing else.
//!
//! [`check`] is `x3dcheck - --stdin-filename PATH --format json` without the process: the
//! same settings (the x3dcheck.toml found upward from `path`, or [`Options::config`], under
//! the options given here), the same rules ([`crate::check::check_source`]), the files
//! Inlines load reported after the input at the deep level, and the same report:
//! [`Report::to_json`] is the command line's bytes.
//!
//! ```
//! use x3dcheck::api::{check, Options, Severity};
//!
//! let scene = br#"<X3D profile="Interchange" version="4.0"><Scene>
//!   <Shape><IndexedFaceSet coordIndex="0 1 5 -1"><Coordinate point="0 0 0 1 0 0 0 1 0"/></IndexedFaceSet></Shape>
//! </Scene></X3D>"#;
//! let report = check(scene, &Options::default())?;
//! let first = &report.files[0].diagnostics[0];
//! assert_eq!((first.code.as_str(), first.severity), ("INDEX_OUT_OF_RANGE", Severity::Error));
//! println!("{}:{}: {}", first.line, first.column, first.message);
//! # Ok::<(), x3dcheck::api::Error>(())
//! ```

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::batch::{self, codes, file_root, Batch};
use crate::check::{check_source, check_too_large, STDIN_NAME};
use crate::config_file::{Resolver, Settings};
use crate::diagnostic::Rule;
use crate::library::Libraries;
use crate::limits::MAX_INPUT_BYTES;
use crate::read::{read_path, Contents};
use crate::report::{sarif, FileReport};
use crate::validate::RULES;

pub use crate::diagnostic::{Level, Severity};
pub use crate::report::json::{Diagnostic, Edit, File, Fix, RelatedPlace, Report};
pub use crate::report::Summary;

/// What to check, as the command line's options say it. The default checks like
/// `x3dcheck -` with no options.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// The name the input is reported under (`<stdin>` when None). Its directory is where
    /// the x3dcheck.toml that applies is looked up, and where the deep level reads Inlines,
    /// textures and prototype libraries from, as for `--stdin-filename`.
    pub path: Option<PathBuf>,
    /// `--level` (None: the x3dcheck.toml's, else standard).
    pub level: Option<Level>,
    /// `--select`: codes, prefixes of codes or `ALL`, in any case.
    pub select: Vec<String>,
    /// `--ignore`, as `select`.
    pub ignore: Vec<String>,
    /// `--config`: this x3dcheck.toml instead of the one found upward from `path`.
    pub config: Option<PathBuf>,
}

/// Why nothing was checked: a selector matching no code, an x3dcheck.toml that is wrong,
/// a file that cannot be read, or an internal failure. Findings are never errors.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct Error(String);

/// Checks `source` (a scene in any encoding x3dcheck reads, compressed or not).
pub fn check(source: &[u8], options: &Options) -> Result<Report, Error> {
    Ok(Report::of(&check_reports(source, options)?, None))
}

/// Checks `source` as [`check`] does, into the SARIF 2.1.0 log `--format sarif` prints.
pub fn check_sarif(source: &[u8], options: &Options) -> Result<String, Error> {
    Ok(sarif::render(&check_reports(source, options)?, &RULES))
}

fn check_reports(source: &[u8], options: &Options) -> Result<Vec<FileReport>, Error> {
    if source.len() > MAX_INPUT_BYTES {
        check_input(Input::TooLarge, options)
    } else {
        check_input(Input::Bytes(source), options)
    }
}

/// Reads the file at `path` within x3dcheck's input limit and checks it as
/// `x3dcheck PATH --format json` does; `options.path` is ignored.
///
/// ```
/// # let dir = std::env::temp_dir().join(format!("x3dcheck-doc-{}", std::process::id()));
/// # std::fs::create_dir_all(&dir).unwrap();
/// # std::env::set_current_dir(&dir).unwrap();
/// # std::fs::write("scene.x3d", "<X3D version='4.0'><Scene><Box size='-1 1 1'/></Scene></X3D>").unwrap();
/// use x3dcheck::api::{check_file, Options};
///
/// let report = check_file("scene.x3d", &Options::default())?;
/// for d in &report.files[0].diagnostics {
///     println!("{}:{}: {}[{}] {}", d.line, d.column, d.severity, d.code, d.message);
/// }
/// # assert!(!report.files[0].diagnostics.is_empty());
/// # std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), x3dcheck::api::Error>(())
/// ```
pub fn check_file(path: impl AsRef<Path>, options: &Options) -> Result<Report, Error> {
    let path = path.as_ref();
    let options = Options {
        path: Some(path.to_path_buf()),
        ..options.clone()
    };
    let files = match read_path(path, MAX_INPUT_BYTES).map_err(Error)? {
        Contents::Bytes(bytes) => check_input(Input::Bytes(&bytes), &options),
        Contents::TooLarge => check_input(Input::TooLarge, &options),
    }?;
    Ok(Report::of(&files, None))
}

/// `level` by its name: `fast`, `standard` or `deep`, in any case.
pub fn level(name: &str) -> Result<Level, Error> {
    clap::ValueEnum::from_str(name, true)
        .map_err(|_| Error(format!("unknown level `{name}` (fast, standard or deep)")))
}

/// One rule, as `x3dcheck rules --format json` lists it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RuleInfo {
    pub code: &'static str,
    pub severity: Severity,
    pub level: Level,
    /// The X3D versions it applies to: `all`, `4.x`, `4.1`.
    pub versions: &'static str,
    pub clause: &'static str,
    /// Its first sentence.
    pub summary: String,
    /// Its documentation, in Markdown.
    pub doc: String,
}

impl RuleInfo {
    pub fn of(rule: &Rule) -> RuleInfo {
        RuleInfo {
            code: rule.code,
            severity: rule.severity,
            level: rule.level,
            versions: rule.versions,
            clause: rule.clause,
            summary: rule.summary(),
            doc: doc_text(rule),
        }
    }
}

/// The documentation as Markdown, without the one-space indent of doc comments.
fn doc_text(rule: &Rule) -> String {
    let mut out = String::new();
    for line in rule.doc.lines() {
        out.push_str(line.strip_prefix(' ').unwrap_or(line));
        out.push('\n');
    }
    out
}

/// Every rule, in catalogue order.
pub fn rules() -> Vec<RuleInfo> {
    RULES.iter().map(|rule| RuleInfo::of(rule)).collect()
}

/// What is checked: the bytes, or an input beyond the limit (reported as LIMIT_EXCEEDED).
enum Input<'a> {
    Bytes(&'a [u8]),
    TooLarge,
}

/// The reports of the input and of the files its Inlines load.
fn check_input(input: Input, options: &Options) -> Result<Vec<FileReport>, Error> {
    let config_error = |e: crate::config_file::ConfigError| Error(e.to_string());
    let mut resolver =
        Resolver::new(options.config.as_deref(), settings(options)?).map_err(config_error)?;
    let name = options
        .path
        .as_ref()
        .map_or(STDIN_NAME.to_string(), |p| p.display().to_string());
    let libraries = Libraries::default();
    let mut effective = resolver
        .for_file(options.path.as_deref())
        .map_err(config_error)?;
    effective.check.root = options.path.as_deref().map(file_root);
    effective.check.libraries = libraries.clone();
    // A panic in a rule is an internal failure of this check, as on the command line.
    let report = catch_unwind(AssertUnwindSafe(|| match input {
        Input::Bytes(bytes) => check_source(&name, bytes, &effective.check),
        Input::TooLarge => check_too_large(&name, &effective.check),
    }))
    .map_err(|_| Error(format!("internal error while checking {name}")))?;
    let listed: Vec<PathBuf> = options.path.iter().cloned().collect();
    let mut files = vec![report];
    // Reported as a run of one unsharded batch reports them; no text is written per file.
    let batch = Batch {
        libraries: &libraries,
        listed: &listed,
        shard: None,
        text: &|_, _| String::new(),
    };
    for inlined in batch::check_inlined(&batch, &mut resolver) {
        files.push(inlined.map_err(Error)?.report);
    }
    Ok(files)
}

/// The command line's settings of `options`.
fn settings(options: &Options) -> Result<Settings, Error> {
    Ok(Settings {
        level: options.level,
        select: (!options.select.is_empty())
            .then(|| codes(&options.select, "select"))
            .transpose()
            .map_err(Error)?,
        ignore: codes(&options.ignore, "ignore").map_err(Error)?,
        ..Settings::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &[u8] = b"<X3D profile='Interchange' version='4.0'><Scene><Shape><IndexedFaceSet coordIndex='0 1 5 -1'><Coordinate point='0 0 0 1 0 0 0 1 0'/></IndexedFaceSet></Shape></Scene></X3D>";

    #[test]
    fn a_scene_in_memory_is_reported_as_stdin() {
        let report = check(SCENE, &Options::default()).unwrap();
        assert_eq!(report.files.len(), 1);
        assert_eq!(report.files[0].path, STDIN_NAME);
        assert_eq!(report.summary.errors, 1);
        assert_eq!(report.files[0].diagnostics[0].code, "INDEX_OUT_OF_RANGE");
    }

    #[test]
    fn select_and_ignore_take_selectors() {
        let ignored = Options {
            ignore: vec!["index_".to_string()],
            ..Options::default()
        };
        assert!(check(SCENE, &ignored).unwrap().files[0]
            .diagnostics
            .is_empty());
        let wrong = Options {
            select: vec!["NO_SUCH_CODE".to_string()],
            ..Options::default()
        };
        assert!(check(SCENE, &wrong)
            .unwrap_err()
            .to_string()
            .starts_with("select: `NO_SUCH_CODE` is no rule code"));
    }

    #[test]
    fn levels_are_named_as_on_the_command_line() {
        assert_eq!(level("Deep"), Ok(Level::Deep));
        assert!(level("thorough").is_err());
    }

    #[test]
    fn rules_are_the_catalogue() {
        assert_eq!(rules().len(), RULES.len());
    }
}
