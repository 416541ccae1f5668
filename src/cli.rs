//! The command line: arguments, finding the inputs (of one shard, `--shard`), checking them
//! in parallel, writing the report, and the exit code — 0 nothing at or above the fail
//! level, 1 something is, 2 usage, I/O or internal failure ("could not be checked" is never
//! "invalid"). `merge` combines JSON reports ([`merge`]); [`progress`] draws the bar.

mod discover;
mod merge;
mod progress;
mod read;

use std::borrow::Cow;
use std::fs;
use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use rayon::prelude::*;

use x3dcheck::check::STDIN_NAME;
use x3dcheck::config::CheckConfig;
use x3dcheck::config_file::{known_code, Effective, Resolver, Settings};
use x3dcheck::model::MAX_INPUT_BYTES;
use x3dcheck::report::{concise, github, human, json, junit, sarif, statistics};
use x3dcheck::report::{FileReport, Summary};
use x3dcheck::shard::Shard;
use x3dcheck::validate::{Level, Rule, Severity, RULES};

#[derive(Parser, Debug)]
#[command(
    name = "x3dcheck",
    version,
    about = "Checks X3D scene documents (XML and JSON encodings) like a compiler",
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true
)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    check: CheckArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// List the rules, or explain one
    Rules {
        /// A rule code, e.g. DEF_DUPLICATE
        code: Option<String>,
    },
    /// Combine JSON reports (e.g. of `--shard K/N` runs) into the report of one run
    Merge(merge::MergeArgs),
}

#[derive(Args, Debug)]
struct CheckArgs {
    /// Files, or directories searched for scenes (.x3d .x3dv .x3dj .wrl, compressed .x3dz
    /// .x3dvz .x3djz .wrz and *.gz, and .json files holding an X3D object), honouring
    /// .gitignore and skipping hidden folders; `-` reads stdin
    #[arg(value_name = "PATH", required = true)]
    paths: Vec<PathBuf>,
    /// Do not search paths matching GLOB in directories (repeatable; also `exclude` in
    /// x3dcheck.toml)
    #[arg(long, value_name = "GLOB")]
    exclude: Vec<String>,
    /// List the files that would be checked, and check none
    #[arg(long)]
    show_files: bool,
    /// What to check [default: standard]
    #[arg(long, value_enum)]
    level: Option<Level>,
    /// Report format
    #[arg(long, value_enum, default_value_t = Format::Human)]
    format: Format,
    /// Write the report to FILE instead of stdout
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Report only these codes
    #[arg(long, value_delimiter = ',', value_name = "CODE,...")]
    select: Vec<String>,
    /// Do not report these codes
    #[arg(long, value_delimiter = ',', value_name = "CODE,...")]
    ignore: Vec<String>,
    /// Change the severity of codes (error, warning, info, hint)
    #[arg(long, value_delimiter = ',', value_name = "CODE=LEVEL,...")]
    severity: Vec<String>,
    /// Exit with 1 when a diagnostic of this severity or above is reported [default: error]
    #[arg(long, value_enum)]
    fail_on: Option<FailOn>,
    /// At most N diagnostics per file
    #[arg(long, value_name = "N")]
    max_diagnostics: Option<usize>,
    /// Report each repeat of a finding on one field on its own instead of folding them
    #[arg(long)]
    no_fold: bool,
    /// Print per code how many findings and files instead of the findings (human, concise
    /// or json format)
    #[arg(long)]
    statistics: bool,
    /// Use this configuration for every input instead of the x3dcheck.toml found upward
    /// from each file
    #[arg(long, value_name = "FILE")]
    config: Option<PathBuf>,
    /// How far a normal's length may differ from 1 (NORMAL_NOT_UNIT, deep level) [default: 0.01]
    #[arg(long, value_name = "F")]
    normal_tolerance: Option<f64>,
    /// Files checked in parallel (default: all cores)
    #[arg(short, long, value_name = "N")]
    jobs: Option<usize>,
    /// Check only shard K of N (1 ≤ K ≤ N), for CI jobs that split a tree
    ///
    /// A file's shard depends on its path alone: the path relative to the directory
    /// argument it was found under (as given, for a file named directly), with `/` as
    /// separator and no `.` components, is hashed with SHA-256; the first 8 bytes of the
    /// hash as a big-endian number, mod N, plus 1, is the shard. stdin is in shard 1.
    /// `x3dcheck merge` combines the shards' JSON reports.
    #[arg(long, value_name = "K/N")]
    shard: Option<Shard>,
    /// No colours in the human format
    #[arg(long)]
    no_color: bool,
    #[command(flatten)]
    render: x3dcheck::render::RenderArgs,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Human,
    Concise,
    Json,
    /// SARIF 2.1.0, for code-scanning services
    Sarif,
    /// GitHub Actions workflow commands (annotations)
    Github,
    /// JUnit XML, for CI test dashboards
    Junit,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum FailOn {
    Error,
    Warning,
}

const USAGE: u8 = 2;

pub fn run(cli: Cli) -> ExitCode {
    read::guard_stdout();
    let result = match cli.command {
        Some(Command::Rules { code }) => rules(code.as_deref()),
        Some(Command::Merge(args)) => merge::merge(&args),
        None => check(&cli.check),
    };
    match result {
        Ok(code) => code,
        Err(message) => {
            eprintln!("x3dcheck: {message}");
            ExitCode::from(USAGE)
        }
    }
}

fn check(args: &CheckArgs) -> Result<ExitCode, String> {
    check_statistics_format(args.statistics, args.format)?;
    let mut resolver =
        Resolver::new(args.config.as_deref(), settings(args)?).map_err(|e| e.to_string())?;
    let color = !args.no_color
        && args.output.is_none()
        && io::stdout().is_terminal()
        && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let discover::Found { inputs, mut failed } =
        discover::find_inputs(&args.paths, args.shard, &args.exclude, &mut resolver)?;
    if args.show_files {
        let list: String = inputs
            .iter()
            .map(|i| format!("{}\n", input_name(i)))
            .collect();
        write_output(args.output.as_deref(), &list)?;
        return Ok(ExitCode::from(if failed { USAGE } else { 0 }));
    }
    for output in [&args.output, &args.render.render].into_iter().flatten() {
        refuse_input_as_output(&inputs, output)?;
    }
    // Configuration errors stop the run before anything is checked.
    let configs = inputs
        .iter()
        .map(|input| match input {
            Input::Stdin => resolver.for_file(None),
            Input::File { path, root } => resolver.for_file(Some(path)).map(|mut effective| {
                effective.check.root = Some(root.clone());
                effective
            }),
        })
        .collect::<Result<Vec<Effective>, _>>()
        .map_err(|e| e.to_string())?;
    let text_format = (!args.statistics).then_some(args.format);
    if args.render.render.is_some() && inputs.len() != 1 {
        return Err("--render takes exactly one input scene".to_string());
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()
        .map_err(|e| format!("cannot start worker threads: {e}"))?;
    let progress = progress::Progress::start(inputs.len(), args.output.is_some());
    let outcomes: Vec<Outcome> = pool.install(|| {
        inputs
            .par_iter()
            .zip(&configs)
            .map(|(input, config)| {
                let outcome = check_input(input, &config.check, text_format, color, &args.render);
                progress.file_done();
                outcome
            })
            .collect()
    });
    progress.finish();

    let mut reports = Vec::with_capacity(outcomes.len());
    let mut fail_levels = Vec::with_capacity(outcomes.len());
    let mut text = String::new();
    for (outcome, config) in outcomes.into_iter().zip(&configs) {
        match outcome {
            Ok((report, rendered)) => {
                text.push_str(&rendered);
                reports.push(report);
                fail_levels.push(config.fail_on);
            }
            Err(message) => {
                eprintln!("x3dcheck: {message}");
                failed = true;
            }
        }
    }
    let report = ReportOutput {
        format: args.format,
        statistics: args.statistics,
        shard: args.shard,
        output: args.output.as_deref(),
    };
    let fails = report.write(&reports, &fail_levels, text)?;
    Ok(ExitCode::from(if failed { USAGE } else { u8::from(fails) }))
}

fn check_statistics_format(statistics: bool, format: Format) -> Result<(), String> {
    if statistics && !matches!(format, Format::Human | Format::Concise | Format::Json) {
        return Err("--statistics prints with the human, concise or json format".to_string());
    }
    Ok(())
}

/// How the report of a run (or of a merge) is written.
struct ReportOutput<'a> {
    format: Format,
    statistics: bool,
    /// The part of a split the run checked, said in the JSON report.
    shard: Option<Shard>,
    output: Option<&'a Path>,
}

impl ReportOutput<'_> {
    /// Writes the report of `reports`, after `text`: the files' own text in the human,
    /// concise and github formats. Whether a file has a diagnostic at or above its fail
    /// level (`fail_levels[i]` is that of `reports[i]`).
    fn write(
        &self,
        reports: &[FileReport],
        fail_levels: &[Severity],
        mut text: String,
    ) -> Result<bool, String> {
        let summary = Summary::of(reports);
        match (self.statistics, self.format) {
            (true, Format::Json) => {
                text = statistics::render_json(&statistics::of(reports), reports)
            }
            (true, _) => {
                text = statistics::render_text(&statistics::of(reports));
                text.push_str(&human::summary_line(&summary));
                text.push('\n');
            }
            (false, Format::Json) => text = json::render(reports, self.shard),
            (false, Format::Sarif) => text = sarif::render(reports),
            (false, Format::Junit) => text = junit::render(reports, fail_levels),
            (false, Format::Github) => {}
            (false, Format::Human | Format::Concise) => {
                text.push_str(&human::summary_line(&summary));
                text.push('\n');
            }
        }
        write_output(self.output, &text)?;
        Ok(reports
            .iter()
            .zip(fail_levels)
            .any(|(r, &level)| r.diagnostics.iter().any(|d| d.severity >= level)))
    }
}

fn fail_level(fail_on: FailOn) -> Severity {
    match fail_on {
        FailOn::Error => Severity::Error,
        FailOn::Warning => Severity::Warning,
    }
}

/// The settings the command line gives; they win over x3dcheck.toml.
fn settings(args: &CheckArgs) -> Result<Settings, String> {
    let code = |code: &str, option: &str| {
        known_code(code)
            .map(|r| r.code.to_string())
            .map_err(|e| format!("{option}: {e}"))
    };
    let mut settings = Settings {
        level: args.level,
        fail_on: args.fail_on.map(fail_level),
        max_diagnostics: args.max_diagnostics,
        fold: args.no_fold.then_some(false),
        ..Settings::default()
    };
    if !args.select.is_empty() {
        let select = args.select.iter().map(|c| code(c, "--select"));
        settings.select = Some(select.collect::<Result<_, _>>()?);
    }
    for c in &args.ignore {
        settings.ignore.push(code(c, "--ignore")?);
    }
    for item in &args.severity {
        let (c, level) = item
            .split_once('=')
            .ok_or_else(|| format!("--severity takes CODE=LEVEL, not `{item}`"))?;
        let c = code(c, "--severity")?;
        let level = Severity::parse(level).ok_or_else(|| {
            format!("unknown severity `{level}` for {c} (error, warning, info or hint)")
        })?;
        settings.severity.push((c, level));
    }
    if let Some(tolerance) = args.normal_tolerance {
        if !(tolerance.is_finite() && tolerance >= 0.0) {
            return Err(format!(
                "--normal-tolerance takes a finite number ≥ 0, not {tolerance}"
            ));
        }
        settings.normal_tolerance = Some(tolerance);
    }
    Ok(settings)
}

/// The rule of a code, or a usage error naming the nearest code.
fn known_rule(code: &str, option: &str) -> Result<&'static Rule, String> {
    known_code(code).map_err(|e| format!("{option}: {e}"))
}

use discover::Input;

fn input_name(input: &Input) -> String {
    match input {
        Input::Stdin => STDIN_NAME.to_string(),
        Input::File { path, .. } => path.display().to_string(),
    }
}

/// The bytes of a file (a report to merge) within the input limit, or why not.
fn read_file(path: &Path) -> Result<Vec<u8>, String> {
    match read::read_path(path, MAX_INPUT_BYTES)? {
        read::Contents::Bytes(bytes) => Ok(bytes),
        read::Contents::TooLarge => Err(format!(
            "cannot read {}: larger than {MAX_INPUT_BYTES} bytes, the most x3dcheck reads",
            path.display()
        )),
    }
}

/// A checked file with its rendered text, or why it could not be checked.
type Outcome = Result<(FileReport, String), String>;

/// `format` is the format rendered per file (`None`: nothing, `--statistics`).
fn check_input(
    input: &Input,
    config: &CheckConfig,
    format: Option<Format>,
    color: bool,
    render: &x3dcheck::render::RenderArgs,
) -> Outcome {
    let name = input_name(input);
    let contents = match input {
        Input::Stdin => read::read_stdin(MAX_INPUT_BYTES)?,
        Input::File { path, .. } => read::read_path(path, MAX_INPUT_BYTES)?,
    };
    let bytes = match contents {
        read::Contents::Bytes(bytes) => bytes,
        read::Contents::TooLarge => {
            let report = x3dcheck::check::check_too_large(&name, config);
            let text = render_text(&report, &[], format, color);
            return Ok((report, text));
        }
    };
    // A panic in a rule is an internal failure of this file, not of the run.
    let failure = format!("internal error while checking {name}");
    // A document to render keeps its values at every level.
    let config = if render.render.is_some() {
        Cow::Owned(CheckConfig {
            render: true,
            ..config.clone()
        })
    } else {
        Cow::Borrowed(config)
    };
    std::panic::catch_unwind(move || {
        let x3dcheck::check::Checked {
            mut report,
            document,
            text: source,
        } = x3dcheck::check::check_document(&name, &bytes, &config);
        let path = Path::new(&name);
        let preview =
            x3dcheck::render::prepare(render, path, &source, document.as_ref(), &mut report)?;
        drop(document);
        let text = render_text(&report, &source, format, color);
        // The preview no longer needs the document or its source.
        drop(source);
        drop(bytes);
        if let Some(preview) = preview {
            preview.save()?;
        }
        Ok((report, text))
    })
    .map_err(|_| failure)?
}

/// The text of one file's report in the formats written per file (`source`: the decoded
/// text the report's positions are in).
fn render_text(report: &FileReport, source: &[u8], format: Option<Format>, color: bool) -> String {
    match format {
        Some(Format::Human) => human::render(report, source, color),
        Some(Format::Concise) => concise::render(report),
        Some(Format::Github) => github::render(report),
        Some(Format::Json | Format::Sarif | Format::Junit) | None => String::new(),
    }
}

/// Inputs are only read: an output file (`-o`, `--render`) that is one of them, by any
/// name or link, is refused before anything is checked or written.
fn refuse_input_as_output(inputs: &[Input], output: &Path) -> Result<(), String> {
    let Ok(output_file) = file_id(output) else {
        return Ok(()); // Does not exist yet, so it is no input.
    };
    for input in inputs {
        if let Input::File { path, .. } = input {
            if file_id(path).is_ok_and(|id| id == output_file) {
                return Err(format!(
                    "{} is an input file; it would be overwritten by the output",
                    output.display()
                ));
            }
        }
    }
    Ok(())
}

/// What makes two paths one file: device and inode on Unix (symlinks, `..` and hard links
/// all lead to one), the canonical path elsewhere.
#[cfg(unix)]
type FileId = (u64, u64);
#[cfg(not(unix))]
type FileId = PathBuf;

#[cfg(unix)]
fn file_id(path: &Path) -> io::Result<FileId> {
    use std::os::unix::fs::MetadataExt;
    let meta = fs::metadata(path)?;
    Ok((meta.dev(), meta.ino()))
}

#[cfg(not(unix))]
fn file_id(path: &Path) -> io::Result<FileId> {
    path.canonicalize()
}

fn write_output(output: Option<&Path>, text: &str) -> Result<(), String> {
    match output {
        Some(path) => {
            fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
        }
        None if read::stdout_closed() => {
            Err("cannot write the report: standard output is closed".to_string())
        }
        None => io::stdout()
            .lock()
            .write_all(text.as_bytes())
            .map_err(|e| format!("cannot write the report: {e}")),
    }
}

fn rules(code: Option<&str>) -> Result<ExitCode, String> {
    let text = match code {
        None => rule_table(),
        Some(code) => explain(known_rule(code, "rules")?),
    };
    write_output(None, &text)?;
    Ok(ExitCode::SUCCESS)
}

fn rule_table() -> String {
    let summaries: Vec<String> = RULES.iter().map(|r| r.summary()).collect();
    let mut rows = vec![["CODE", "SEVERITY", "LEVEL", "VERSIONS", "CLAUSE", "SUMMARY"]];
    rows.extend(RULES.iter().zip(&summaries).map(|(r, summary)| {
        let (severity, level) = (r.severity.as_str(), r.level.as_str());
        [
            r.code,
            severity,
            level,
            r.versions,
            r.clause,
            summary.as_str(),
        ]
    }));
    let widths: Vec<usize> = (0..5)
        .map(|column| rows.iter().map(|row| row[column].len()).max().unwrap_or(0))
        .collect();
    let mut out = String::new();
    for row in rows {
        for (cell, width) in row.iter().zip(&widths) {
            out.push_str(&format!("{cell:width$}  "));
        }
        out.push_str(row[5]);
        out.push('\n');
    }
    out
}

fn explain(rule: &Rule) -> String {
    let mut out = format!(
        "{}\nseverity: {}  level: {}  versions: {}  clause: {}\n\n",
        rule.code,
        rule.severity,
        rule.level.as_str(),
        rule.versions,
        rule.clause
    );
    for line in rule.doc.lines() {
        out.push_str(line.strip_prefix(' ').unwrap_or(line));
        out.push('\n');
    }
    out
}
