//! The command line: arguments, finding the inputs, checking them in parallel, writing the
//! report, and the exit code — 0 nothing at or above the fail level, 1 something is,
//! 2 usage, I/O or internal failure ("could not be checked" is never "invalid").

use std::borrow::Cow;
use std::fs;
use std::io::{self, IsTerminal, Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use rayon::prelude::*;

use x3dcheck::config::CheckConfig;
use x3dcheck::model::MAX_INPUT_BYTES;
use x3dcheck::report::{concise, human, json, FileReport, Summary};
use x3dcheck::validate::{find_rule, Level, Rule, Severity, RULES};

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
}

#[derive(Args, Debug)]
struct CheckArgs {
    /// Files, or directories searched recursively for .x3d, .x3dj and .json files; `-` reads stdin
    #[arg(value_name = "PATH", required = true)]
    paths: Vec<PathBuf>,
    /// What to check
    #[arg(long, value_enum, default_value_t = Level::Standard)]
    level: Level,
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
    /// Exit with 1 when a diagnostic of this severity or above is reported
    #[arg(long, value_enum, default_value_t = FailOn::Error)]
    fail_on: FailOn,
    /// At most N diagnostics per file
    #[arg(long, value_name = "N")]
    max_diagnostics: Option<usize>,
    /// Files checked in parallel (default: all cores)
    #[arg(short, long, value_name = "N")]
    jobs: Option<usize>,
    /// No colours in the human format
    #[arg(long)]
    no_color: bool,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Human,
    Concise,
    Json,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum FailOn {
    Error,
    Warning,
}

const USAGE: u8 = 2;

pub fn run(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Some(Command::Rules { code }) => rules(code.as_deref()),
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
    let config = config(args)?;
    let color = !args.no_color
        && args.output.is_none()
        && io::stdout().is_terminal()
        && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let (inputs, mut failed) = find_inputs(&args.paths);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()
        .map_err(|e| format!("cannot start worker threads: {e}"))?;
    let outcomes: Vec<Outcome> = pool.install(|| {
        inputs
            .par_iter()
            .map(|input| check_input(input, &config, args.format, color))
            .collect()
    });

    let mut reports = Vec::with_capacity(outcomes.len());
    let mut text = String::new();
    for outcome in outcomes {
        match outcome {
            Ok((report, rendered)) => {
                text.push_str(&rendered);
                reports.push(report);
            }
            Err(message) => {
                eprintln!("x3dcheck: {message}");
                failed = true;
            }
        }
    }
    let summary = Summary::of(&reports);
    match args.format {
        Format::Json => text = json::render(&reports),
        Format::Human | Format::Concise => {
            text.push_str(&human::summary_line(&summary));
            text.push('\n');
        }
    }
    write_output(args.output.as_deref(), &text)?;

    let fail_level = match args.fail_on {
        FailOn::Error => Severity::Error,
        FailOn::Warning => Severity::Warning,
    };
    let fails = reports
        .iter()
        .flat_map(|r| &r.diagnostics)
        .any(|d| d.severity >= fail_level);
    Ok(ExitCode::from(if failed { USAGE } else { u8::from(fails) }))
}

fn config(args: &CheckArgs) -> Result<CheckConfig, String> {
    let mut config = CheckConfig {
        level: args.level,
        max_diagnostics: args.max_diagnostics,
        ..CheckConfig::default()
    };
    for code in &args.select {
        config
            .select
            .insert(known_rule(code, "--select")?.code.to_string());
    }
    for code in &args.ignore {
        config
            .ignore
            .insert(known_rule(code, "--ignore")?.code.to_string());
    }
    for item in &args.severity {
        let (code, level) = item
            .split_once('=')
            .ok_or_else(|| format!("--severity takes CODE=LEVEL, not `{item}`"))?;
        let code = known_rule(code, "--severity")?.code;
        let level = Severity::parse(level).ok_or_else(|| {
            format!("unknown severity `{level}` for {code} (error, warning, info or hint)")
        })?;
        config.severity.insert(code.to_string(), level);
    }
    Ok(config)
}

/// The rule of a code, or a usage error naming the nearest code.
fn known_rule(code: &str, option: &str) -> Result<&'static Rule, String> {
    if let Some(rule) = find_rule(code) {
        return Ok(rule);
    }
    let wanted = code.to_ascii_uppercase();
    let nearest = RULES
        .iter()
        .map(|r| (strsim::jaro_winkler(&wanted, r.code), r.code))
        .filter(|(score, _)| *score > 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let hint = nearest.map_or(String::new(), |(_, c)| format!(" (did you mean `{c}`?)"));
    Err(format!(
        "{option}: unknown rule code `{code}`{hint}; `x3dcheck rules` lists the codes"
    ))
}

enum Input {
    Stdin(Vec<u8>),
    File(PathBuf),
}

/// The inputs in argument order, each directory's files sorted by path. Unreadable paths
/// are reported here (and make the exit code 2); the rest are still checked.
fn find_inputs(paths: &[PathBuf]) -> (Vec<Input>, bool) {
    let mut inputs = Vec::new();
    let mut failed = false;
    let mut fail = |path: &Path, error: io::Error| {
        eprintln!("x3dcheck: cannot read {}: {error}", path.display());
        failed = true;
    };
    for path in paths {
        if path.as_os_str() == "-" {
            match read_stdin() {
                Ok(bytes) => inputs.push(Input::Stdin(bytes)),
                Err(e) => fail(Path::new("<stdin>"), e),
            }
            continue;
        }
        match fs::metadata(path) {
            Ok(meta) if meta.is_dir() => {
                let mut files = Vec::new();
                walk(path, &mut files, &mut fail);
                files.sort();
                inputs.extend(files.into_iter().map(Input::File));
            }
            Ok(_) => inputs.push(Input::File(path.clone())),
            Err(e) => fail(path, e),
        }
    }
    (inputs, failed)
}

/// Collects X3D files under `dir`. Symlinked directories are not followed (no loops);
/// symlinked files are taken.
fn walk(dir: &Path, files: &mut Vec<PathBuf>, fail: &mut impl FnMut(&Path, io::Error)) {
    let entries = match fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) => return fail(dir, e),
    };
    for entry in entries {
        let entry = match entry {
            Ok(entry) => entry,
            Err(e) => {
                fail(dir, e);
                continue;
            }
        };
        let path = entry.path();
        match entry.file_type() {
            Ok(t) if t.is_dir() => walk(&path, files, fail),
            Ok(t) if t.is_file() || (t.is_symlink() && path.is_file()) => {
                if is_x3d_name(&path) {
                    files.push(path);
                }
            }
            Ok(_) => {}
            Err(e) => fail(&path, e),
        }
    }
}

fn is_x3d_name(path: &Path) -> bool {
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
        ["x3d", "x3dj", "json"]
            .iter()
            .any(|x| e.eq_ignore_ascii_case(x))
    })
}

fn read_stdin() -> io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    io::stdin()
        .lock()
        .take(MAX_INPUT_BYTES as u64 + 1)
        .read_to_end(&mut bytes)?;
    if bytes.len() > MAX_INPUT_BYTES {
        return Err(too_large());
    }
    Ok(bytes)
}

fn read_file(path: &Path) -> io::Result<Vec<u8>> {
    if fs::metadata(path)?.len() > MAX_INPUT_BYTES as u64 {
        return Err(too_large());
    }
    fs::read(path)
}

fn too_large() -> io::Error {
    io::Error::other(format!(
        "larger than {MAX_INPUT_BYTES} bytes, the most x3dcheck reads"
    ))
}

/// A checked file with its rendered text, or why it could not be checked.
type Outcome = Result<(FileReport, String), String>;

fn check_input(input: &Input, config: &CheckConfig, format: Format, color: bool) -> Outcome {
    let (name, bytes) = match input {
        Input::Stdin(bytes) => ("<stdin>".to_string(), Cow::Borrowed(&bytes[..])),
        Input::File(path) => {
            let name = path.display().to_string();
            match read_file(path) {
                Ok(bytes) => (name, Cow::Owned(bytes)),
                Err(e) => return Err(format!("cannot read {name}: {e}")),
            }
        }
    };
    // A panic in a rule is an internal failure of this file, not of the run.
    std::panic::catch_unwind(|| {
        let report = x3dcheck::check_source(&name, &bytes, config);
        let text = match format {
            Format::Human => human::render(&report, &bytes, color),
            Format::Concise => concise::render(&report),
            Format::Json => String::new(),
        };
        (report, text)
    })
    .map_err(|_| format!("internal error while checking {name}"))
}

fn write_output(output: Option<&Path>, text: &str) -> Result<(), String> {
    match output {
        Some(path) => {
            fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
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
        [r.code, severity, level, r.versions, r.clause, summary.as_str()]
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
