//! `x3dcheck-bench`: the performance benchmark of DESIGN.md (a program, not a timed test).
//!
//! It generates a large scene deterministically (six 160,000-vertex IndexedTriangleSets,
//! about 86 MB of X3D XML, plus the same scene in X3D JSON), runs the release `x3dcheck`
//! next to it as a child process at each level, and runs `xmllint` on the same file when it
//! is installed, and the floor (read the file and parse every number, nothing else: see
//! `floor.rs`) on one core and on all of them. It prints a Markdown table (median wall
//! time, MB/s, peak RSS, ratios) and the DESIGN.md targets with ✓/✗. `--corpus DIR` times
//! a directory per level instead.
//!
//! ```text
//! cargo run --release --example x3dcheck-bench [-- --runs N --size-scale F --corpus DIR …]
//! ```
//!
//! Progress goes to stderr, the report to stdout. Peak memory needs GNU time
//! (`/usr/bin/time`, Debian package `time`); without it the column says so.

mod floor;
mod measure;
#[cfg(feature = "render")]
mod render;
mod scene;

use std::ffi::{OsStr, OsString};
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use clap::Parser;
use serde_json::Value;

use measure::{median_cores, median_wall, on_path, peak_bytes, wall_range, Sample, Timer};

#[derive(Parser, Debug)]
#[command(
    name = "x3dcheck-bench",
    about = "Times x3dcheck on a generated 86 MB scene (or a directory) and compares it with xmllint"
)]
struct Args {
    /// Timed runs per measurement, after one warm-up run; the median is reported. Given
    /// explicitly, it also sets the runs of `xmllint --schema` (otherwise run once)
    #[arg(long, value_name = "N")]
    runs: Option<usize>,
    /// Scale the vertex count of every shape (1.0: 160,000 vertices, about 86 MB of XML)
    #[arg(long, value_name = "F", default_value_t = 1.0)]
    size_scale: f64,
    /// Generate the scene files again even if they exist (they are kept between runs)
    #[arg(long)]
    regenerate: bool,
    /// Time a directory of X3D files per level instead of the generated scene
    #[arg(long, value_name = "DIR")]
    corpus: Option<PathBuf>,
    /// With --corpus: pass `-j N` to x3dcheck [default: x3dcheck's, all cores]
    #[arg(long, value_name = "N", requires = "corpus")]
    jobs: Option<usize>,
    /// Do not run xmllint
    #[arg(long)]
    no_peers: bool,
    /// Do not run `xmllint --schema` (about 10 s at full size)
    #[arg(long)]
    no_schema: bool,
    /// Do not time `--render` nor measure the quality presets' accuracy
    #[arg(long)]
    no_render: bool,
    /// Image size for rendering the generated scene
    #[arg(long, value_name = "WxH", default_value = "800x600")]
    render_size: x3dcheck::render::ImageSize,
    /// The x3dcheck binary to time [default: the one next to this program]
    #[arg(long, value_name = "PATH")]
    x3dcheck: Option<PathBuf>,
    /// Where the generated scene is kept [default: $TMPDIR/x3dcheck-bench]
    #[arg(long, value_name = "DIR")]
    dir: Option<PathBuf>,
    /// Run the floor on FILE and nothing else (how the benchmark times the floor)
    #[arg(long, value_name = "FILE", hide = true)]
    floor: Option<PathBuf>,
    /// Threads of `--floor`
    #[arg(long, value_name = "N", default_value_t = 1, hide = true)]
    floor_threads: usize,
}

const DEFAULT_RUNS: usize = 5;
const LEVELS: [&str; 3] = ["fast", "standard", "deep"];
const SCHEMA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/oracle/x3d-4.0.xsd");

/// DESIGN.md's reference figures: an 86.5 MB generated scene on a 2-core machine.
const REFERENCE: [(&str, &str, &str); 4] = [
    ("quick-xml events only", "0.07 s", "—"),
    (
        "quick-xml events + parsing every number (the practical floor)",
        "0.23 s",
        "—",
    ),
    ("`xmllint --noout`", "0.77 s", "181 MB"),
    ("`xmllint --schema x3d-4.1.xsd`", "9.9 s", "351 MB"),
];

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("x3dcheck-bench: {message}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &Args) -> Result<(), String> {
    if let Some(file) = &args.floor {
        return floor::run(file, args.floor_threads);
    }
    let runs = args.runs.unwrap_or(DEFAULT_RUNS);
    if runs == 0 {
        return Err("--runs must be at least 1".into());
    }
    if !(args.size_scale.is_finite() && args.size_scale > 0.0) {
        return Err("--size-scale must be a positive number".into());
    }
    let dir = args
        .dir
        .clone()
        .unwrap_or_else(|| std::env::temp_dir().join("x3dcheck-bench"));
    let scratch = dir.join(format!("scratch-{}", std::process::id()));
    fs::create_dir_all(&scratch)
        .map_err(|e| format!("cannot create {}: {e}", scratch.display()))?;
    let result = bench(args, runs, &dir, &scratch);
    let _ = fs::remove_dir_all(&scratch);
    result
}

fn bench(args: &Args, runs: usize, dir: &Path, scratch: &Path) -> Result<(), String> {
    let x3dcheck = find_x3dcheck(args)?;
    let timer = Timer::new(scratch);
    let xmllint = if args.no_peers {
        None
    } else {
        on_path("xmllint")
    };

    let mut out = String::new();
    machine(&mut out, &x3dcheck, xmllint.as_deref(), &timer);
    if let Some(corpus) = &args.corpus {
        corpus_bench(
            &mut out, &timer, &x3dcheck, corpus, args.jobs, runs, scratch,
        )?;
        print!("{out}");
        return Ok(());
    }

    eprintln!("x3dcheck-bench: scene files in {}", dir.display());
    let started = Instant::now();
    let scene = scene::ensure(dir, args.size_scale, args.regenerate)
        .map_err(|e| format!("cannot write the scene in {}: {e}", dir.display()))?;
    let xml_bytes = file_size(&scene.xml)?;
    let json_bytes = file_size(&scene.json)?;
    let classic_bytes = file_size(&scene.classic)?;
    eprintln!(
        "x3dcheck-bench: {} scene ({:.1} s)",
        if scene.generated {
            "generated the"
        } else {
            "reusing the"
        },
        started.elapsed().as_secs_f64()
    );
    let _ = writeln!(
        out,
        "Scene: {} Shapes × IndexedTriangleSet of {} vertices and {} triangles (Coordinate, \
         Normal, TextureCoordinate, index), generator v{}\n\
         - XML:  {} ({} bytes, {:.1} MB)\n\
         - JSON: {} ({} bytes, {:.1} MB)\n\
         - ClassicVRML: {} ({} bytes, {:.1} MB)\n",
        scene::SHAPES,
        thousands(scene.vertices as u64),
        thousands(scene.triangles as u64),
        scene::GENERATOR_VERSION,
        scene.xml.display(),
        thousands(xml_bytes),
        mb(xml_bytes),
        scene.json.display(),
        thousands(json_bytes),
        mb(json_bytes),
        scene.classic.display(),
        thousands(classic_bytes),
        mb(classic_bytes),
    );

    let mut rows: Vec<Row> = Vec::new();
    let mut notes: Vec<String> = Vec::new();

    // x3dcheck on XML, every level.
    let mut xml_stats = None;
    for level in LEVELS {
        eprintln!("x3dcheck-bench: x3dcheck --level {level} (XML) ×{runs}");
        let case = time_x3dcheck(&timer, &x3dcheck, level, &scene.xml, runs, scratch)
            .map_err(|e| format!("x3dcheck --level {level} failed on the XML scene: {e}"))?;
        if level == "standard" {
            xml_stats = case.stats.clone();
            check_stats(
                &case,
                scene::SHAPES as u64,
                (scene.triangles * scene::SHAPES) as u64,
                "XML",
                &mut notes,
            );
        }
        rows.push(Row::x3dcheck(level, "XML", xml_bytes, case));
    }

    // x3dcheck on JSON and on ClassicVRML, when its reader accepts the file.
    let others = [
        ("JSON", "json", &scene.json, json_bytes),
        ("ClassicVRML", "classicvrml", &scene.classic, classic_bytes),
    ];
    for (name, encoding, path, bytes) in others {
        eprintln!("x3dcheck-bench: trying the {name} scene");
        match time_x3dcheck(&timer, &x3dcheck, "standard", path, 1, scratch) {
            Ok(probe)
                if probe.encoding.as_deref() == Some(encoding)
                    && probe.shapes == Some(scene::SHAPES as u64) =>
            {
                for level in LEVELS {
                    eprintln!("x3dcheck-bench: x3dcheck --level {level} ({name}) ×{runs}");
                    let case = time_x3dcheck(&timer, &x3dcheck, level, path, runs, scratch)
                        .map_err(|e| {
                            format!("x3dcheck --level {level} failed on the {name} scene: {e}")
                        })?;
                    if level == "standard" {
                        check_stats(
                            &case,
                            scene::SHAPES as u64,
                            (scene.triangles * scene::SHAPES) as u64,
                            name,
                            &mut notes,
                        );
                        let same = xml_stats.is_some() && xml_stats == case.stats;
                        notes.push(format!(
                            "XML and {name} `stats` in the report: {}",
                            if same { "equal" } else { "DIFFERENT" }
                        ));
                    }
                    rows.push(Row::x3dcheck(level, name, bytes, case));
                }
            }
            Ok(probe) => {
                let why = probe
                    .first_diagnostic
                    .unwrap_or_else(|| "no shapes read".into());
                notes.push(format!(
                    "{name}: not measured (reader not available): {why}"
                ));
            }
            Err(e) => notes.push(format!("{name}: not measured (reader not available): {e}")),
        }
    }

    // Peers.
    let mut noout = None;
    let mut schema_time = None;
    match &xmllint {
        None if args.no_peers => notes.push("xmllint: not run (--no-peers)".into()),
        None => {
            notes.push("xmllint: not measured (not on PATH; Debian package `libxml2-utils`)".into())
        }
        Some(xmllint) => {
            eprintln!("x3dcheck-bench: xmllint --noout ×{runs}");
            let file = scene.xml.as_os_str();
            let case = time_peer(
                &timer,
                xmllint,
                &[OsStr::new("--noout")],
                file,
                true,
                runs,
                scratch,
            )?;
            huge_note(&case, &mut notes);
            let what = format!(
                "`xmllint --noout{}`",
                if case.huge { " --huge" } else { "" }
            );
            let row = Row::peer(Peer::NoOut, what, xml_bytes, case, "well-formed");
            noout = row.ok.then_some(row.median);
            rows.push(row);
            let schema = Path::new(SCHEMA);
            if args.no_schema {
                notes.push("`xmllint --schema`: not run (--no-schema)".into());
            } else if !schema.is_file() {
                notes.push(format!(
                    "`xmllint --schema`: not run ({} is missing)",
                    schema.display()
                ));
            } else {
                let schema_runs = args.runs.unwrap_or(1);
                eprintln!("x3dcheck-bench: xmllint --schema ×{schema_runs} (slow)");
                let argv = [
                    OsStr::new("--noout"),
                    OsStr::new("--nonet"),
                    OsStr::new("--schema"),
                    schema.as_os_str(),
                ];
                let case = time_peer(&timer, xmllint, &argv, file, false, schema_runs, scratch)?;
                huge_note(&case, &mut notes);
                let what = format!(
                    "`xmllint --noout{} --nonet --schema x3d-4.0.xsd`",
                    if case.huge { " --huge" } else { "" }
                );
                let row = Row::peer(Peer::Schema, what, xml_bytes, case, "valid");
                schema_time = row.ok.then_some(row.median);
                rows.push(row);
            }
        }
    }

    // The floor, on one core and on all.
    let this = std::env::current_exe().map_err(|e| format!("cannot find this program: {e}"))?;
    let mut thread_counts = vec![1, cores()];
    thread_counts.dedup();
    for threads in thread_counts {
        eprintln!("x3dcheck-bench: floor on {threads} core(s) ×{runs}");
        let threads_text = OsString::from(threads.to_string());
        let argv = [
            OsStr::new("--floor-threads"),
            threads_text.as_os_str(),
            OsStr::new("--floor"),
        ];
        let case = time_peer(
            &timer,
            &this,
            &argv,
            scene.xml.as_os_str(),
            true,
            runs,
            scratch,
        )?;
        let what = format!(
            "floor: read + parse every number ({threads} core{})",
            if threads == 1 { "" } else { "s" }
        );
        rows.push(Row::peer(
            Peer::Floor(threads),
            what,
            xml_bytes,
            case,
            "numbers read",
        ));
    }

    table(&mut out, &rows, noout, runs, args.runs.unwrap_or(1), &timer);
    targets(&mut out, &rows, noout, schema_time);
    footnotes(&mut out, &rows, &notes, &timer);
    if !args.no_render {
        render_bench(&mut out, args, &timer, &x3dcheck, &scene.xml, runs, scratch)?;
    }
    print!("{out}");
    Ok(())
}

/// The render presets: their cost on the generated scene, beside view3dscene's, and their
/// accuracy against a heavily supersampled reference.
#[cfg(feature = "render")]
fn render_bench(
    out: &mut String,
    args: &Args,
    timer: &Timer,
    x3dcheck: &Path,
    scene: &Path,
    runs: usize,
    scratch: &Path,
) -> Result<(), String> {
    x3dcheck::render::prepare_environment();
    render::speed(out, args, timer, x3dcheck, scene, runs, scratch)?;
    render::accuracy(out, scene, args.render_size, runs)
}

#[cfg(not(feature = "render"))]
fn render_bench(
    out: &mut String,
    _: &Args,
    _: &Timer,
    _: &Path,
    _: &Path,
    _: usize,
    _: &Path,
) -> Result<(), String> {
    let _ = writeln!(
        out,
        "\nRendering: not measured (built without the `render` feature)"
    );
    Ok(())
}

/// The x3dcheck binary: `--x3dcheck`, else the one of this example's profile. Under `cargo run`
/// it is built first (same profile), since `cargo run --example x3dcheck-bench` builds only
/// the bench.
fn find_x3dcheck(args: &Args) -> Result<PathBuf, String> {
    if let Some(path) = &args.x3dcheck {
        return if path.is_file() {
            Ok(path.clone())
        } else {
            Err(format!("--x3dcheck {}: no such file", path.display()))
        };
    }
    let exe = std::env::current_exe().map_err(|e| format!("cannot find this program: {e}"))?;
    // Cargo puts an example in `target/PROFILE/examples/`, the binary in `target/PROFILE/`.
    let dir = exe
        .parent()
        .and_then(Path::parent)
        .unwrap_or(Path::new("."))
        .to_path_buf();
    let binary = dir.join(format!("x3dcheck{}", std::env::consts::EXE_SUFFIX));
    let profile = dir.file_name().and_then(|n| n.to_str()).unwrap_or("");
    if let Some(cargo) = std::env::var_os("CARGO") {
        let manifest = concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml");
        let mut build = Command::new(cargo);
        build.args([
            "build",
            "--quiet",
            "--bin",
            "x3dcheck",
            "--manifest-path",
            manifest,
        ]);
        match profile {
            "debug" => {}
            "release" => {
                build.arg("--release");
            }
            other => {
                build.args(["--profile", other]);
            }
        }
        eprintln!("x3dcheck-bench: building x3dcheck ({profile})");
        match build.status() {
            Ok(s) if s.success() => {}
            Ok(s) => eprintln!("x3dcheck-bench: warning: building x3dcheck failed ({s})"),
            Err(e) => eprintln!("x3dcheck-bench: warning: cannot run cargo: {e}"),
        }
    }
    if !binary.is_file() {
        return Err(format!(
            "{} not found: run `cargo run --release --example x3dcheck-bench` (which builds it), \
             or `cargo build --release` first, or pass --x3dcheck PATH",
            binary.display()
        ));
    }
    if profile == "debug" {
        eprintln!(
            "x3dcheck-bench: WARNING: timing a debug build; use `cargo run --release --example x3dcheck-bench`"
        );
    }
    Ok(binary)
}

/// What one x3dcheck measurement found.
struct X3dCase {
    samples: Vec<Sample>,
    /// Exit code of the warm-up run.
    code: i32,
    summary: [u64; 4],
    encoding: Option<String>,
    shapes: Option<u64>,
    triangles: Option<u64>,
    stats: Option<Value>,
    first_diagnostic: Option<String>,
}

/// One warm-up run writing the JSON report (read for what was found), then `runs` timed
/// runs writing it to /dev/null.
fn time_x3dcheck(
    timer: &Timer,
    x3dcheck: &Path,
    level: &str,
    input: &Path,
    runs: usize,
    scratch: &Path,
) -> Result<X3dCase, String> {
    let report = scratch.join("report.json");
    let stderr = scratch.join("stderr.txt");
    let _ = fs::remove_file(&report);
    let mut argv = x3dcheck_args(level, &report, input);
    let warm = timer
        .run(x3dcheck.as_os_str(), &argv, Some(&stderr))
        .map_err(|e| format!("cannot run {}: {e}", x3dcheck.display()))?;
    let code = warm.code.unwrap_or(-1);
    if code != 0 && code != 1 {
        return Err(format!("exit code {code}: {}", measure::head(&stderr, 3)));
    }
    let json: Value = fs::read(&report)
        .ok()
        .and_then(|b| serde_json::from_slice(&b).ok())
        .ok_or("the JSON report is missing or unreadable")?;
    let summary = &json["summary"];
    let count = |k: &str| summary[k].as_u64().unwrap_or(0);
    let file = &json["files"][0];
    let stats = file.get("stats").cloned();
    let first_diagnostic = file["diagnostics"].get(0).map(|d| {
        format!(
            "{} at {}:{}: {}",
            d["code"].as_str().unwrap_or("?"),
            d["line"],
            d["column"],
            d["message"].as_str().unwrap_or("")
        )
    });

    let null = OsString::from("/dev/null");
    argv[REPORT_ARG] = null.as_os_str();
    let mut samples = Vec::with_capacity(runs);
    for _ in 0..runs {
        let s = timer
            .run(x3dcheck.as_os_str(), &argv, Some(&stderr))
            .map_err(|e| format!("cannot run {}: {e}", x3dcheck.display()))?;
        if s.code != Some(code) {
            return Err(format!("exit code changed from {code} to {:?}", s.code));
        }
        samples.push(s);
    }
    Ok(X3dCase {
        samples,
        code,
        summary: [
            count("errors"),
            count("warnings"),
            count("infos"),
            count("hints"),
        ],
        encoding: file["encoding"].as_str().map(str::to_string),
        shapes: file["stats"]["shapes"].as_u64(),
        triangles: file["stats"]["triangles"].as_u64(),
        stats,
        first_diagnostic,
    })
}

fn check_stats(case: &X3dCase, shapes: u64, triangles: u64, what: &str, notes: &mut Vec<String>) {
    if case.shapes != Some(shapes) || case.triangles != Some(triangles) {
        notes.push(format!(
            "WARNING: the {what} report counts {:?} shapes and {:?} triangles, not {shapes} and {triangles}",
            case.shapes, case.triangles
        ));
    }
}

#[derive(Copy, Clone, PartialEq, Eq)]
enum Peer {
    NoOut,
    Schema,
    /// The floor program on this many threads.
    Floor(usize),
}

struct PeerCase {
    samples: Vec<Sample>,
    code: i32,
    message: String,
    /// `--huge` was needed: the first run hit one of libxml2's default size limits.
    huge: bool,
    /// What the run without `--huge` said.
    refused: String,
}

/// Times `program args file`. libxml2 2.9 refuses inputs whose lookahead passes 10 MB
/// ("Huge input lookup") unless given `--huge`; when the first run fails that way, every
/// run uses `--huge` (the same checks, without the limits).
fn time_peer(
    timer: &Timer,
    program: &Path,
    args: &[&OsStr],
    file: &OsStr,
    warm_up: bool,
    runs: usize,
    scratch: &Path,
) -> Result<PeerCase, String> {
    let stderr = scratch.join("peer-stderr.txt");
    let run = |huge: bool| {
        let mut argv: Vec<&OsStr> = Vec::with_capacity(args.len() + 2);
        argv.push(args[0]);
        if huge {
            argv.push(OsStr::new("--huge"));
        }
        argv.extend(&args[1..]);
        argv.push(file);
        timer
            .run(program.as_os_str(), &argv, Some(&stderr))
            .map_err(|e| format!("cannot run {}: {e}", program.display()))
    };
    let mut first = run(false)?;
    let mut huge = false;
    let mut refused = String::new();
    if first.code != Some(0) {
        let said = measure::head(&stderr, 1);
        if said.to_ascii_lowercase().contains("huge") {
            huge = true;
            refused = said;
            first = run(true)?;
        }
    }
    let mut samples = Vec::with_capacity(runs);
    if !warm_up {
        samples.push(first);
    }
    while samples.len() < runs {
        samples.push(run(huge)?);
    }
    let code = samples.last().and_then(|s| s.code).unwrap_or(-1);
    Ok(PeerCase {
        samples,
        code,
        message: measure::head(&stderr, 1),
        huge,
        refused,
    })
}

fn huge_note(case: &PeerCase, notes: &mut Vec<String>) {
    if case.huge {
        let said = case
            .refused
            .rsplit(" : ")
            .next()
            .unwrap_or(&case.refused)
            .trim();
        let note = format!(
            "xmllint refuses this file without `--huge` (\"{said}\": a default size limit of \
             libxml2), so it is timed with `--huge`"
        );
        if !notes.contains(&note) {
            notes.push(note);
        }
    }
}

/// One line of the table.
struct Row {
    what: String,
    /// "XML", "JSON", "ClassicVRML" or "" for peers.
    encoding: &'static str,
    level: Option<&'static str>,
    bytes: u64,
    median: f64,
    /// The fastest and slowest run.
    range: (f64, f64),
    runs: usize,
    peak: Option<u64>,
    /// Median (user + system CPU time) / wall time: how many cores it kept busy.
    cores: Option<f64>,
    found: String,
    /// The run did what it should (exit 0/1 for x3dcheck, 0 for peers).
    ok: bool,
    peer: Option<Peer>,
}

impl Row {
    fn x3dcheck(level: &'static str, encoding: &'static str, bytes: u64, case: X3dCase) -> Row {
        let [e, w, i, h] = case.summary;
        Row {
            what: format!("`x3dcheck --level {level}` ({encoding})"),
            encoding,
            level: Some(level),
            bytes,
            median: median_wall(&case.samples),
            range: wall_range(&case.samples),
            runs: case.samples.len(),
            peak: peak_bytes(&case.samples),
            cores: median_cores(&case.samples),
            found: format!("{e} E, {w} W, {i} I, {h} H (exit {})", case.code),
            ok: true,
            peer: None,
        }
    }

    fn peer(peer: Peer, what: String, bytes: u64, case: PeerCase, success: &str) -> Row {
        let found = if case.code == 0 {
            success.to_string()
        } else {
            format!("exit {}: {}", case.code, case.message)
        };
        Row {
            what,
            encoding: "XML",
            level: None,
            bytes,
            median: median_wall(&case.samples),
            range: wall_range(&case.samples),
            runs: case.samples.len(),
            peak: peak_bytes(&case.samples),
            cores: median_cores(&case.samples),
            found,
            ok: case.code == 0,
            peer: Some(peer),
        }
    }
}

fn table(
    out: &mut String,
    rows: &[Row],
    noout: Option<f64>,
    runs: usize,
    schema_runs: usize,
    timer: &Timer,
) {
    let _ = writeln!(
        out,
        "| what | time (median) | min–max | MB/s | CPU use | peak RSS | RSS / file size | vs `xmllint --noout` | found |"
    );
    let _ = writeln!(out, "|---|--:|--:|--:|--:|--:|--:|--:|---|");
    for row in rows {
        let ratio = match noout {
            None => "—".to_string(),
            Some(_) if row.peer == Some(Peer::NoOut) => "1× (itself)".to_string(),
            Some(reference) => speed_ratio(reference, row.median),
        };
        let _ = writeln!(
            out,
            "| {} | {}{} | {} | {} | {} | {} | {} | {} | {} |",
            row.what,
            seconds(row.median),
            if row.runs == runs {
                String::new()
            } else {
                format!(
                    " ({} run{})",
                    row.runs,
                    if row.runs == 1 { "" } else { "s" }
                )
            },
            if row.runs == 1 {
                "—".to_string()
            } else {
                format!(
                    "{}–{}",
                    seconds_bare(row.range.0),
                    seconds_bare(row.range.1)
                )
            },
            throughput(row.bytes, row.median),
            row.cores.map_or("n/a".to_string(), |c| format!("{c:.2}")),
            row.peak
                .map_or(memory_na(timer), |p| format!("{:.0} MB", mb(p))),
            row.peak.map_or("—".to_string(), |p| format!(
                "{:.2}×",
                p as f64 / row.bytes as f64
            )),
            ratio,
            row.found,
        );
    }
    let schema = if rows.iter().any(|r| r.peer == Some(Peer::Schema)) {
        format!(
            " (the schema validation: {schema_runs} run{}, no warm-up)",
            if schema_runs == 1 { "" } else { "s" }
        )
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        "\nTime: median wall clock of {runs} run{} after one warm-up run{schema}; min–max: the \
         fastest and the slowest run, in seconds; MB = 10⁶ bytes; CPU use: median (user + \
         system CPU time) / wall time, in cores; peak RSS: the child's \
         maximum resident set (GNU time `%M`), largest over the runs. found: x3dcheck's \
         diagnostics by severity (error, warning, info, hint).",
        if runs == 1 { "" } else { "s" }
    );
}

fn targets(out: &mut String, rows: &[Row], noout: Option<f64>, schema: Option<f64>) {
    let _ = writeln!(out, "\nTargets (DESIGN.md, Performance):");
    let find = |encoding: &str, level: &str| {
        rows.iter()
            .find(|r| r.peer.is_none() && r.encoding == encoding && r.level == Some(level))
    };
    let standard = find("XML", "standard").map(|r| r.median);
    let mark = |ok: bool| if ok { "✓" } else { "✗" };

    let line = |out: &mut String, text: &str, value: Option<(bool, String)>| {
        let _ = match value {
            Some((ok, v)) => writeln!(out, "- {} {text}: {v}", mark(ok)),
            None => writeln!(out, "- – {text}: not measured"),
        };
    };
    line(
        out,
        "standard ≤ 0.25× the time of `xmllint --noout`",
        standard
            .zip(noout)
            .map(|(s, x)| (s / x <= 0.25, format!("{:.2}×", s / x))),
    );
    line(
        out,
        "standard ≥ 20× faster than `xmllint --schema`",
        standard
            .zip(schema)
            .map(|(s, x)| (x / s >= 20.0, format!("{:.1}×", x / s))),
    );
    let floor = rows
        .iter()
        .find(|r| r.peer == Some(Peer::Floor(1)) && r.ok)
        .map(|r| r.median);
    line(
        out,
        "fast within 1.2× of the one-core floor",
        find("XML", "fast").zip(floor).map(|(f, floor)| {
            let r = f.median / floor;
            (r <= 1.2, format!("{r:.2}×"))
        }),
    );
    let per_encoding = |limit: f64, ratio: &dyn Fn(&str) -> Option<f64>| {
        let mut ok = true;
        let mut found = Vec::new();
        for encoding in ["XML", "JSON", "ClassicVRML"] {
            if let Some(r) = ratio(encoding) {
                ok &= r <= limit;
                found.push(format!("{r:.2}× ({encoding})"));
            }
        }
        (!found.is_empty()).then(|| (ok, found.join(", ")))
    };
    line(
        out,
        "deep ≤ 1.3× standard",
        per_encoding(1.3, &|encoding| {
            let (d, s) = find(encoding, "deep").zip(find(encoding, "standard"))?;
            Some(d.median / s.median)
        }),
    );
    line(
        out,
        "peak memory ≤ 1.5× the file at standard",
        per_encoding(1.5, &|encoding| {
            let s = find(encoding, "standard")?;
            Some(s.peak? as f64 / s.bytes as f64)
        }),
    );
    let xml = find("XML", "standard").map(|r| r.median);
    line(
        out,
        "JSON and ClassicVRML within 1.2× of XML (standard)",
        per_encoding(1.2, &|encoding| {
            let other = find(encoding, "standard")?;
            (encoding != "XML").then_some(other.median / xml?)
        }),
    );
}

fn footnotes(out: &mut String, rows: &[Row], notes: &[String], timer: &Timer) {
    let _ = writeln!(out);
    let _ = writeln!(out, "- Load average at the end: {}", load_average());
    for note in notes {
        let _ = writeln!(out, "- {note}");
    }
    if !timer.measures_memory() {
        let _ = writeln!(
            out,
            "- peak memory: n/a (install the `time` package: GNU time at /usr/bin/time measures it)"
        );
    }
    let peers = rows.iter().any(|r| r.peer == Some(Peer::NoOut));
    if peers && rows.iter().any(|r| r.encoding == "JSON") {
        let _ = writeln!(
            out,
            "- The JSON rows are compared with `xmllint --noout` on the XML file of the same scene."
        );
    }
    let _ = writeln!(
        out,
        "\nFor reference only, DESIGN.md's figures (86.5 MB generated scene, another 2-core \
         machine), beside this run's:\n"
    );
    let _ = writeln!(out, "| what | DESIGN.md time | DESIGN.md peak | this run |");
    let _ = writeln!(out, "|---|--:|--:|--:|");
    for (what, time, peak) in REFERENCE {
        let peer = if what.starts_with("`xmllint --noout`") {
            Some(Peer::NoOut)
        } else if what.starts_with("`xmllint --schema") {
            Some(Peer::Schema)
        } else {
            None
        };
        let here = peer.and_then(|p| rows.iter().find(|r| r.peer == Some(p)));
        let here = here.map_or("—".to_string(), |r| {
            format!(
                "{} / {}",
                seconds(r.median),
                r.peak
                    .map_or(memory_na(timer), |p| format!("{:.0} MB", mb(p)))
            )
        });
        let _ = writeln!(out, "| {what} | {time} | {peak} | {here} |");
    }
}

/// The share of the report's files with a VALIDATION_INCOMPLETE that is not about a network
/// URL or a language other than ECMAScript and GLSL (by the words of those notes).
fn incomplete_share(json: &Value) -> String {
    let Some(files) = json["files"].as_array() else {
        return "—".to_string();
    };
    let within_reach = |message: &str| {
        !(message.contains("network URL")
            || message.contains(", which x3dcheck does not check")
            || (message.contains("language \"") && !message.contains("language \"\"")))
    };
    let incomplete = files
        .iter()
        .filter(|file| {
            file["diagnostics"].as_array().is_some_and(|found| {
                found.iter().any(|d| {
                    d["code"] == "VALIDATION_INCOMPLETE"
                        && d["message"].as_str().is_some_and(within_reach)
                })
            })
        })
        .count();
    format!(
        "{incomplete} ({:.1}%)",
        100.0 * incomplete as f64 / files.len().max(1) as f64
    )
}

/// `--corpus DIR`: the whole directory per level in one x3dcheck run (all cores).
fn corpus_bench(
    out: &mut String,
    timer: &Timer,
    x3dcheck: &Path,
    corpus: &Path,
    jobs: Option<usize>,
    runs: usize,
    scratch: &Path,
) -> Result<(), String> {
    if !corpus.is_dir() {
        return Err(format!("--corpus {}: not a directory", corpus.display()));
    }
    let (files, bytes) = x3d_files(corpus);
    let _ = writeln!(
        out,
        "Corpus: {} ({} X3D files by name, {:.1} MB)\n",
        corpus.display(),
        files,
        mb(bytes)
    );
    let _ = writeln!(
        out,
        "| level | files | time (median) | files/s | MB/s | CPU use | peak RSS | errors | warnings | infos | hints | incomplete | exit |"
    );
    let _ = writeln!(out, "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|");
    let report = scratch.join("report.json");
    let stderr = scratch.join("stderr.txt");
    let jobs = jobs.map(|n| n.to_string());
    for level in LEVELS {
        eprintln!(
            "x3dcheck-bench: x3dcheck --level {level} {} ×{runs}",
            corpus.display()
        );
        let _ = fs::remove_file(&report);
        let mut argv = x3dcheck_args(level, &report, corpus);
        if let Some(jobs) = &jobs {
            argv.extend([OsStr::new("-j"), OsStr::new(jobs)]);
        }
        let warm = timer
            .run(x3dcheck.as_os_str(), &argv, Some(&stderr))
            .map_err(|e| format!("cannot run {}: {e}", x3dcheck.display()))?;
        let json: Option<Value> = fs::read(&report)
            .ok()
            .and_then(|b| serde_json::from_slice(&b).ok());
        let Some(json) = json else {
            let _ = writeln!(
                out,
                "| {level} | — | — | — | — | — | — | — | — | — | — | — | {} ({}) |",
                warm.code.unwrap_or(-1),
                measure::head(&stderr, 1)
            );
            continue;
        };
        let summary = &json["summary"];
        let count = |k: &str| summary[k].as_u64().unwrap_or(0);
        let null = OsString::from("/dev/null");
        argv[REPORT_ARG] = null.as_os_str();
        let samples = (0..runs)
            .map(|_| timer.run(x3dcheck.as_os_str(), &argv, Some(&stderr)))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| format!("cannot run {}: {e}", x3dcheck.display()))?;
        let median = median_wall(&samples);
        let checked = count("files");
        let _ = writeln!(
            out,
            "| {level} | {checked} | {} | {:.0} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            seconds(median),
            checked as f64 / median,
            throughput(bytes, median),
            median_cores(&samples).map_or("n/a".to_string(), |c| format!("{c:.2} cores")),
            peak_bytes(&samples).map_or(memory_na(timer), |p| format!("{:.0} MB", mb(p))),
            count("errors"),
            count("warnings"),
            count("infos"),
            count("hints"),
            incomplete_share(&json),
            warm.code.map_or("signal".to_string(), |c| c.to_string()),
        );
    }
    let _ = writeln!(
        out,
        "\nOne x3dcheck run per level over the whole directory ({}); time: median wall clock of {runs} \
         runs after one warm-up run; CPU use: (user + system CPU time) / wall time, of {} cores; \
         MB = 10⁶ bytes of .x3d/.x3dj/.json files; incomplete: the share of files with a \
         VALIDATION_INCOMPLETE that is not about a network URL or another language (issue 16's \
         measure); exit 2 means some file could not be checked.",
        jobs.as_ref()
            .map_or("all cores".to_string(), |n| format!("-j {n}")),
        cores()
    );
    Ok(())
}

/// Files x3dcheck would take from `dir` (by extension, as the CLI does) and their size.
fn x3d_files(dir: &Path) -> (u64, u64) {
    let mut files = 0;
    let mut bytes = 0;
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        let Ok(entries) = fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            match entry.file_type() {
                Ok(t) if t.is_dir() => stack.push(path),
                Ok(_) => {
                    let x3d = path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
                        ["x3d", "x3dj", "json"]
                            .iter()
                            .any(|x| e.eq_ignore_ascii_case(x))
                    });
                    if let (true, Ok(meta)) = (x3d, fs::metadata(&path)) {
                        if meta.is_file() {
                            files += 1;
                            bytes += meta.len();
                        }
                    }
                }
                Err(_) => {}
            }
        }
    }
    (files, bytes)
}

/// The machine, the date and the tools' versions.
fn machine(out: &mut String, x3dcheck: &Path, xmllint: Option<&Path>, timer: &Timer) {
    let cpu = fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let version = |program: &Path, arg: &str| -> String {
        Command::new(program)
            .arg(arg)
            .output()
            .ok()
            .map(|o| {
                let text = if o.stdout.is_empty() {
                    o.stderr
                } else {
                    o.stdout
                };
                String::from_utf8_lossy(&text)
                    .lines()
                    .next()
                    .unwrap_or("")
                    .trim()
                    .to_string()
            })
            .unwrap_or_default()
    };
    let _ = writeln!(
        out,
        "Machine: {} cores (nproc), {cpu}; {} (UTC); load average at start: {}\n\
         x3dcheck: {} ({})\n\
         xmllint: {}\n\
         peak memory: {}\n",
        cores(),
        today(),
        load_average(),
        version(x3dcheck, "--version"),
        x3dcheck.display(),
        xmllint.map_or("not on PATH".to_string(), |x| version(x, "--version")),
        if timer.measures_memory() {
            "GNU time (/usr/bin/time -f %M)"
        } else {
            "n/a (install the 'time' package)"
        },
    );
}

/// The 1-minute load average: other processes competing for the cores skew the times.
fn load_average() -> String {
    fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|t| t.split_whitespace().next().map(str::to_string))
        .unwrap_or_else(|| "n/a".into())
}

fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// Today's date from the system clock (days since 1970 to a civil date, H. Hinnant).
fn today() -> String {
    let secs = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let z = secs.div_euclid(86_400) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}")
}

fn file_size(path: &Path) -> Result<u64, String> {
    fs::metadata(path)
        .map(|m| m.len())
        .map_err(|e| format!("cannot read {}: {e}", path.display()))
}

fn mb(bytes: u64) -> f64 {
    bytes as f64 / 1e6
}

fn seconds(s: f64) -> String {
    if s < 10.0 {
        format!("{s:.3} s")
    } else {
        format!("{s:.1} s")
    }
}

/// Seconds without the unit, for ranges.
fn seconds_bare(s: f64) -> String {
    seconds(s).trim_end_matches(" s").to_string()
}

fn throughput(bytes: u64, seconds: f64) -> String {
    let v = mb(bytes) / seconds;
    if v >= 100.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.1}")
    }
}

/// How much faster `time` is than `reference`.
fn speed_ratio(reference: f64, time: f64) -> String {
    if time <= reference {
        format!("{:.1}× faster", reference / time)
    } else {
        format!("{:.1}× slower", time / reference)
    }
}

fn memory_na(timer: &Timer) -> String {
    if timer.measures_memory() {
        "—".into()
    } else {
        "n/a".into()
    }
}

fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// Where `x3dcheck_args` puts the report path: timed runs after the first write to the
/// null device instead.
const REPORT_ARG: usize = 5;

/// `x3dcheck --level LEVEL --format json -o REPORT INPUT`.
fn x3dcheck_args<'a>(level: &'a str, report: &'a Path, input: &'a Path) -> Vec<&'a OsStr> {
    vec![
        OsStr::new("--level"),
        OsStr::new(level),
        OsStr::new("--format"),
        OsStr::new("json"),
        OsStr::new("-o"),
        report.as_os_str(),
        input.as_os_str(),
    ]
}
