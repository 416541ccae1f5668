//! The command line: arguments, finding the inputs (of one shard, `--shard`), checking them
//! in parallel, writing the report, and the exit code — 0 nothing at or above the fail
//! level, 1 something is, 2 usage, I/O or internal failure ("could not be checked" is never
//! "invalid"). [`main`] runs it. Inside: `merge` combines JSON reports, `rules` lists the
//! rules, `progress` draws the bar, `color` decides on colour, `settings` shows what applies.

mod color;
mod discover;
mod generate;
mod merge;
mod progress;
mod read;
mod render_notes;
mod rules;
mod settings;

use std::borrow::Cow;
use std::fs;
use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};

use clap::{Args, Parser, Subcommand, ValueEnum};
use rayon::prelude::*;

use crate::batch::{self, codes};
use crate::check::STDIN_NAME;
use crate::config::CheckConfig;
use crate::config_file::{Effective, Resolver, Settings};
use crate::diagnostic::{Level, Severity};
use crate::fix;
use crate::model::MAX_INPUT_BYTES;
use crate::report::{concise, github, human, json, junit, sarif, statistics};
use crate::report::{FileReport, Summary};
use crate::shard::Shard;
use crate::validate::RULES;

use color::{ColorChoice, ColorEnv};

#[derive(Parser, Debug)]
#[command(
    name = "x3dcheck",
    version,
    about = "Checks X3D scene documents (XML, JSON, ClassicVRML and VRML97, gzip-compressed or not) like a compiler",
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    after_help = EXIT_CODES
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    check: CheckArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// List the rules, or explain one
    Rules(rules::RulesArgs),
    /// Combine JSON reports (e.g. of `--shard K/N` runs) into the report of one run
    Merge(merge::MergeArgs),
    /// Run the language server (LSP over stdin/stdout) for editors
    Server,
    /// Write a shell completion script to stdout (bash, zsh, fish, elvish, powershell)
    Completions(generate::CompletionsArgs),
    /// Write the manual page (roff) to stdout: `x3dcheck manpage > x3dcheck.1`
    Manpage,
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
    /// Report only these codes: each a code, a prefix of codes (BACK_MATERIAL_) or ALL, in
    /// any case
    #[arg(long, value_delimiter = ',', value_name = "CODE,...")]
    select: Vec<String>,
    /// Do not report these codes (codes, prefixes or ALL, as --select)
    #[arg(long, value_delimiter = ',', value_name = "CODE,...")]
    ignore: Vec<String>,
    /// Change the severity of codes (error, warning, info, hint); codes as --select
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
    /// When to colour the human report: `auto` colours on a terminal unless NO_COLOR,
    /// CLICOLOR=0 or TERM=dumb says otherwise, and anywhere when CLICOLOR_FORCE or
    /// FORCE_COLOR asks
    #[arg(long, value_enum, value_name = "WHEN", default_value_t = ColorChoice::Auto)]
    color: ColorChoice,
    /// Same as --color never
    #[arg(long, hide = true)]
    no_color: bool,
    /// Print the findings only: no summary line and no progress bar
    #[arg(short, long)]
    quiet: bool,
    /// Exit with 0 even when findings reach the fail level (2 still reports a failure)
    #[arg(long)]
    exit_zero: bool,
    /// The file name standard input (`-`) is checked as: the report names it, references
    /// (deep level) are resolved from its directory and x3dcheck.toml is looked up from there
    #[arg(long, value_name = "NAME")]
    stdin_filename: Option<PathBuf>,
    /// Print the settings that apply to the first input, and the x3dcheck.toml they come
    /// from, instead of checking
    #[arg(long)]
    show_settings: bool,
    /// Apply the safe fixes (and unsafe ones with --unsafe-fixes) and write each fixed file
    /// in place (stdin: the fixed text to stdout, the report to stderr); the report shows
    /// what remains
    #[arg(long, conflicts_with_all = ["render", "diff"])]
    fix: bool,
    /// Also apply fixes that may change what the scene shows or which browsers load it
    /// (with --fix or --diff; otherwise they count as fixable in the report)
    #[arg(long)]
    unsafe_fixes: bool,
    /// Print a unified diff of what --fix would change and write nothing (exit 1 when
    /// something would change)
    #[arg(long, conflicts_with = "render")]
    diff: bool,
    #[command(flatten)]
    render: crate::render::RenderArgs,
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

const EXIT_CODES: &str = "\
Exit codes:
  0  no finding at or above the fail level (--fail-on), or --exit-zero
  1  a finding at or above the fail level
  2  a usage or configuration error, an input that could not be read, or an internal failure";

/// The `x3dcheck` command run with `args` (the program name first, as
/// [`std::env::args_os`] gives them): what the binary does, and what the Python package's
/// `x3dcheck` command calls. Call it before starting threads: it sets up the environment the
/// renderer's graphics driver reads. On `--help`, `--version` and usage errors it prints
/// and exits the process, as the binary does. Returns the exit code.
pub fn main<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    // Before any thread starts: changing the environment later would race with readers.
    crate::render::prepare_environment();
    run(Cli::parse_from(args))
}

fn run(cli: Cli) -> u8 {
    read::guard_stdout();
    let result = match cli.command {
        Some(Command::Rules(args)) => rules::rules(&args)
            .and_then(|text| write_output(None, &text))
            .map(|()| 0),
        Some(Command::Merge(args)) => merge::merge(&args),
        Some(Command::Server) => crate::lsp::run().map(|()| 0),
        Some(Command::Completions(args)) => generate::completions(&args),
        Some(Command::Manpage) => generate::manpage(),
        None => check(&cli.check),
    };
    match result {
        Ok(code) => code,
        Err(message) => {
            eprintln!("x3dcheck: {message}");
            USAGE
        }
    }
}

fn check(args: &CheckArgs) -> Result<u8, String> {
    check_statistics_format(args.statistics, args.format)?;
    let mut resolver =
        Resolver::new(args.config.as_deref(), settings(args)?).map_err(|e| e.to_string())?;
    let color_choice = if args.no_color {
        ColorChoice::Never
    } else {
        args.color
    };
    let terminal = args.output.is_none() && io::stdout().is_terminal();
    let color = color::use_color(color_choice, &ColorEnv::from_process(), terminal);
    let stdin_name = args
        .stdin_filename
        .as_ref()
        .map_or(STDIN_NAME.to_string(), |name| name.display().to_string());
    let discover::Found {
        inputs,
        mut failed,
        listed,
    } = discover::find_inputs(&args.paths, args.shard, &args.exclude, &mut resolver)?;
    if args.show_files {
        let list: String = inputs
            .iter()
            .map(|i| format!("{}\n", input_name(i)))
            .collect();
        write_output(args.output.as_deref(), &list)?;
        return Ok(if failed { USAGE } else { 0 });
    }
    for output in [&args.output, &args.render.render].into_iter().flatten() {
        refuse_input_as_output(&inputs, output)?;
    }
    // One cache of prototype libraries for the whole batch: a library many scenes name is
    // read once.
    let libraries = crate::library::Libraries::default();
    // Configuration errors stop the run before anything is checked.
    let mut configs = inputs
        .iter()
        .map(|input| match input {
            Input::Stdin => match &args.stdin_filename {
                None => resolver.for_file(None),
                Some(name) => resolver.for_file(Some(name)).map(|mut effective| {
                    effective.check.root = Some(batch::file_root(name));
                    effective
                }),
            },
            Input::File { path, root } => resolver.for_file(Some(path)).map(|mut effective| {
                effective.check.root = Some(root.clone());
                effective
            }),
        })
        .collect::<Result<Vec<Effective>, _>>()
        .map_err(|e| e.to_string())?;
    for effective in &mut configs {
        effective.check.libraries = libraries.clone();
    }
    if args.show_settings {
        let (Some(input), Some(effective)) = (inputs.first(), configs.first()) else {
            return Err("--show-settings: no input to show the settings of".to_string());
        };
        let name = match input {
            Input::Stdin => stdin_name.clone(),
            Input::File { path, .. } => path.display().to_string(),
        };
        write_output(None, &settings::show(&name, effective))?;
        return Ok(if failed { USAGE } else { 0 });
    }
    let text_format = (!args.statistics).then_some(args.format);
    if args.render.render.is_some() && inputs.len() != 1 {
        return Err("--render takes exactly one input scene".to_string());
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()
        .map_err(|e| format!("cannot start worker threads: {e}"))?;
    let fixing = Fixing::of(args);
    let progress = progress::Progress::start(inputs.len(), args.output.is_some(), args.quiet);
    let outcomes: Vec<Outcome> = pool.install(|| {
        inputs
            .par_iter()
            .zip(&configs)
            .map(|(input, config)| {
                let outcome = check_input(
                    input,
                    &stdin_name,
                    &config.check,
                    Presentation {
                        format: text_format,
                        color,
                        unsafe_fixes: args.unsafe_fixes,
                    },
                    &args.render,
                    fixing,
                );
                progress.file_done();
                outcome
            })
            .collect()
    });
    progress.finish();
    // The files Inlines load that no input is: checked from the files read for the
    // Inlines, after the inputs.
    let inlined_shown = Presentation {
        format: text_format,
        color,
        unsafe_fixes: false,
    };
    let batch = batch::Batch {
        libraries: &libraries,
        listed: &listed,
        shard: args.shard,
        text: &|report, source| render_text(report, source, &(), inlined_shown),
    };
    let inlined = pool.install(|| batch::check_inlined(&batch, &mut resolver));

    let mut reports = Vec::with_capacity(outcomes.len() + inlined.len());
    let mut fail_levels = Vec::with_capacity(outcomes.len());
    let mut text = String::new();
    let mut fixes = FixTotals::default();
    for (outcome, config) in outcomes.into_iter().zip(&configs) {
        match outcome {
            Ok(checked) => {
                if let Some(message) = checked.render_failure {
                    eprintln!("x3dcheck: {message}");
                    failed = true;
                }
                if let Some(fixed) = checked.fixed {
                    fixes.add(fixed);
                }
                text.push_str(&checked.text);
                reports.push(checked.report);
                fail_levels.push(config.fail_on);
            }
            Err(message) => {
                eprintln!("x3dcheck: {message}");
                failed = true;
            }
        }
    }
    for outcome in inlined {
        match outcome {
            Ok(checked) => {
                text.push_str(&checked.text);
                reports.push(checked.report);
                fail_levels.push(checked.effective.fail_on);
            }
            Err(message) => {
                eprintln!("x3dcheck: {message}");
                failed = true;
            }
        }
    }
    if let Some(Fixing { diff: true, .. }) = fixing {
        // ruff's --diff: the diffs alone on stdout, what they fix on stderr.
        write_output(args.output.as_deref(), &fixes.diffs)?;
        if !args.quiet {
            eprintln!("{}", fixes.would_fix_line());
        }
        return Ok(if failed {
            USAGE
        } else {
            u8::from(fixes.changed_files > 0)
        });
    }
    // stdin fixed: its text goes to stdout, so the report goes to stderr (unless -o).
    let report_to_stderr = fixes.stdin_text.is_some() && args.output.is_none();
    if let Some(fixed_stdin) = &fixes.stdin_text {
        write_bytes(fixed_stdin)?;
    }
    let report = ReportOutput {
        format: args.format,
        statistics: args.statistics,
        // A summary of no file at all, when the inputs could not be read, would read
        // like a clean run.
        summary: !(args.quiet || failed && reports.is_empty()),
        shard: args.shard,
        output: args.output.as_deref(),
        to_stderr: report_to_stderr,
        fixes: fixing.map(|_| fixes.fixed),
        unsafe_fixes: args.unsafe_fixes,
    };
    let fails = report.write(&reports, &fail_levels, text)?;
    Ok(if failed {
        USAGE
    } else {
        u8::from(fails && !args.exit_zero)
    })
}

/// `--fix` or `--diff`, and whether unsafe fixes apply.
#[derive(Copy, Clone, Debug)]
struct Fixing {
    /// `--diff`: show, do not write.
    diff: bool,
    unsafe_fixes: bool,
}

impl Fixing {
    fn of(args: &CheckArgs) -> Option<Fixing> {
        (args.fix || args.diff).then_some(Fixing {
            diff: args.diff,
            unsafe_fixes: args.unsafe_fixes,
        })
    }
}

/// What fixing did to one input.
struct FileFixes {
    fixed: usize,
    /// Whether the file's text changed.
    changed: bool,
    /// `--diff`: the file's unified diff.
    diff: String,
    /// Standard input under `--fix`: the fixed text (unchanged when nothing applied).
    stdin_text: Option<Vec<u8>>,
}

/// What fixing did to all inputs.
#[derive(Default)]
struct FixTotals {
    fixed: usize,
    changed_files: usize,
    diffs: String,
    stdin_text: Option<Vec<u8>>,
}

impl FixTotals {
    fn add(&mut self, file: FileFixes) {
        self.fixed += file.fixed;
        self.changed_files += usize::from(file.changed);
        self.diffs.push_str(&file.diff);
        if file.stdin_text.is_some() {
            self.stdin_text = file.stdin_text;
        }
    }

    /// `Would fix 3 findings in 2 files` (`--diff`).
    fn would_fix_line(&self) -> String {
        let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
        format!(
            "Would fix {} in {}",
            plural(self.fixed, "finding"),
            plural(self.changed_files, "file")
        )
    }
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
    /// Whether the human and concise formats and statistics tables end with the summary line.
    summary: bool,
    /// The part of a split the run checked, said in the JSON report.
    shard: Option<Shard>,
    output: Option<&'a Path>,
    /// Write to stderr rather than stdout (which holds fixed stdin), when `output` is None.
    to_stderr: bool,
    /// Under `--fix`: how many fixes were applied, said after the summary line.
    fixes: Option<usize>,
    /// `--unsafe-fixes`: unsafe fixes count as fixable in the summary.
    unsafe_fixes: bool,
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
                text = statistics::render_text(&statistics::of(reports), &RULES);
                if self.summary {
                    text.push_str(&human::summary_line(&summary));
                    text.push('\n');
                }
            }
            (false, Format::Json) => text = json::render(reports, self.shard),
            (false, Format::Sarif) => text = sarif::render(reports, &RULES),
            (false, Format::Junit) => text = junit::render(reports, fail_levels),
            (false, Format::Github) => {}
            (false, Format::Human | Format::Concise) => {
                if self.summary {
                    text.push_str(&human::summary_line(&summary));
                    text.push('\n');
                    if let Some(fixed) = self.fixes {
                        text.push_str(&fix::fixed_line(fixed));
                        text.push('\n');
                    }
                    if let Some(line) = fix::fixable_line(reports, self.unsafe_fixes) {
                        text.push_str(&line);
                        text.push('\n');
                    }
                }
            }
        }
        if self.to_stderr && self.output.is_none() {
            eprint!("{text}");
        } else {
            write_output(self.output, &text)?;
        }
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
    let mut settings = Settings {
        level: args.level,
        fail_on: args.fail_on.map(fail_level),
        max_diagnostics: args.max_diagnostics,
        fold: args.no_fold.then_some(false),
        ..Settings::default()
    };
    if !args.select.is_empty() {
        settings.select = Some(codes(&args.select, "--select")?);
    }
    settings.ignore = codes(&args.ignore, "--ignore")?;
    for item in &args.severity {
        let (selector, level) = item
            .split_once('=')
            .ok_or_else(|| format!("--severity takes CODE=LEVEL, not `{item}`"))?;
        let level = Severity::parse(level).ok_or_else(|| {
            format!("unknown severity `{level}` for {selector} (error, warning, info or hint)")
        })?;
        for code in codes(&[selector], "--severity")? {
            settings.severity.push((code, level));
        }
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

/// Bytes read into the heap, as a [`read::Source`].
fn heap(contents: read::Contents) -> read::Contents<read::Source> {
    match contents {
        read::Contents::Bytes(bytes) => read::Contents::Bytes(read::Source::Heap(bytes)),
        read::Contents::TooLarge => read::Contents::TooLarge,
    }
}

/// A checked file with its rendered text, or why it could not be checked.
type Outcome = Result<Checked, String>;

struct Checked {
    report: FileReport,
    text: String,
    /// Why `--render` made no image (the report is written all the same).
    render_failure: Option<String>,
    /// Under `--fix` or `--diff`: what fixing did.
    fixed: Option<FileFixes>,
}

/// How a file's report is shown.
#[derive(Copy, Clone)]
struct Presentation {
    /// The format rendered per file (`None`: nothing, `--statistics`).
    format: Option<Format>,
    color: bool,
    /// `--unsafe-fixes`: unsafe fixes are marked fixable.
    unsafe_fixes: bool,
}

/// `stdin_name`: the name standard input is checked as.
fn check_input(
    input: &Input,
    stdin_name: &str,
    config: &CheckConfig,
    shown: Presentation,
    render: &crate::render::RenderArgs,
    fixing: Option<Fixing>,
) -> Outcome {
    let name = match input {
        Input::Stdin => stdin_name.to_string(),
        Input::File { path, .. } => path.display().to_string(),
    };
    // Under --fix the file is rewritten, so it is read, not mapped.
    let contents = match input {
        Input::File { path, .. } if fixing.is_none() => read::read_source(path, MAX_INPUT_BYTES)?,
        Input::File { path, .. } => heap(read::read_path(path, MAX_INPUT_BYTES)?),
        Input::Stdin => heap(read::read_stdin(MAX_INPUT_BYTES)?),
    };
    let bytes = match contents {
        read::Contents::Bytes(bytes) => bytes,
        read::Contents::TooLarge => {
            let report = crate::check::check_too_large(&name, config);
            let text = render_text(&report, &[], &(), shown);
            return Ok(Checked {
                report,
                text,
                render_failure: None,
                fixed: None,
            });
        }
    };
    // A panic in a rule is an internal failure of this file, not of the run.
    let failure = format!("internal error while checking {name}");
    // A document to render keeps its values at every level.
    let config = if render.render.is_some() {
        Cow::Owned(CheckConfig {
            render: true,
            island: render.island as usize,
            ..config.clone()
        })
    } else {
        Cow::Borrowed(config)
    };
    if let Some(fixing) = fixing {
        return std::panic::catch_unwind(|| {
            fix_input(input, &name, &bytes, &config, shown, fixing)
        })
        .map_err(|_| failure)?;
    }
    std::panic::catch_unwind(move || {
        let progress = bytes.progress();
        let crate::check::Checked {
            mut report,
            document,
            text: source,
        } = crate::check::check_document_with_progress(&name, &bytes, &config, progress);
        let root = config.root.as_deref();
        // A file's source is freed before the scene is flattened, and read again only when
        // the renderer has notes to place; standard input cannot be read again.
        let (preview, text) = match input {
            Input::File { path, .. } if render.render.is_some() => {
                let mut text = render_text(&report, &source, progress, shown);
                let checked = render_notes::Fingerprint::of(&source, progress);
                drop(source);
                drop(bytes);
                let preview = crate::render::prepare_unresolved(
                    render,
                    Path::new(&name),
                    root,
                    document.as_ref(),
                )
                .and_then(|unresolved| match (unresolved, &document) {
                    (Some(unresolved), Some(doc)) => render_notes::place(
                        unresolved,
                        path,
                        &checked,
                        doc,
                        &mut report,
                        &mut text,
                        shown,
                    )
                    .map(Some),
                    _ => Ok(None),
                });
                (preview, text)
            }
            _ => {
                // A file that cannot be drawn keeps its report: the findings say why.
                let preview = crate::render::prepare(
                    render,
                    Path::new(&name),
                    root,
                    &source,
                    document.as_ref(),
                    &mut report,
                );
                let text = render_text(&report, &source, progress, shown);
                drop(source);
                drop(bytes);
                (preview, text)
            }
        };
        // The preview no longer needs the document.
        drop(document);
        let render_failure = match preview {
            Ok(Some(preview)) => preview.save().err(),
            Ok(None) => None,
            Err(message) => Some(message),
        };
        Ok(Checked {
            report,
            text,
            render_failure,
            fixed: None,
        })
    })
    .map_err(|_| failure)?
}

/// Fixes one input (`--fix`, `--diff`): writes a changed file in place under `--fix`
/// (standard input's text is handed back for stdout instead), or makes its diff; the report
/// is of the text as fixed.
fn fix_input(
    input: &Input,
    name: &str,
    bytes: &[u8],
    config: &CheckConfig,
    shown: Presentation,
    fixing: Fixing,
) -> Outcome {
    let fixed = fix::fix_source(name, bytes, config, fixing.unsafe_fixes);
    if let Some(why) = fixed.unwritable {
        eprintln!("x3dcheck: {name}: {why}");
    }
    if fixed.unconverged {
        eprintln!(
            "x3dcheck: {name}: fixes still apply after {} passes; run again",
            fix::MAX_PASSES
        );
    }
    let changed = fixed.changed(bytes);
    let mut file = FileFixes {
        fixed: fixed.fixed,
        changed,
        diff: String::new(),
        stdin_text: None,
    };
    match (fixing.diff, input) {
        (true, _) => file.diff = fix::unified_diff(name, bytes, &fixed.bytes),
        (false, Input::Stdin) => file.stdin_text = Some(fixed.bytes.clone()),
        (false, Input::File { path, .. }) if changed => fs::write(path, &fixed.bytes)
            .map_err(|e| format!("cannot write the fixed {}: {e}", path.display()))?,
        (false, Input::File { .. }) => {}
    }
    let text = if fixing.diff {
        String::new()
    } else {
        render_text(&fixed.report, &fixed.text, &(), shown)
    };
    Ok(Checked {
        report: fixed.report,
        text,
        render_failure: None,
        fixed: Some(file),
    })
}

/// The text of one file's report in the formats written per file (`source`: the decoded
/// text the report's positions are in; `progress`: told how far a pass over it has got).
fn render_text(
    report: &FileReport,
    source: &[u8],
    progress: &dyn crate::parse::Progress,
    shown: Presentation,
) -> String {
    match shown.format {
        Some(Format::Human) => {
            human::render_marked(report, source, progress, shown.color, shown.unsafe_fixes)
        }
        Some(Format::Concise) => concise::render_marked(report, shown.unsafe_fixes),
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

/// Writes fixed standard input to stdout.
fn write_bytes(bytes: &[u8]) -> Result<(), String> {
    if read::stdout_closed() {
        return Err("cannot write the fixed text: standard output is closed".to_string());
    }
    io::stdout()
        .lock()
        .write_all(bytes)
        .map_err(|e| format!("cannot write the fixed text: {e}"))
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
