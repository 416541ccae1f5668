//! Running a command and measuring it: wall time by our own clock around the child, and
//! peak resident memory and CPU time from GNU time (`/usr/bin/time -f`, Debian package
//! `time`) when it is installed. The standard library has no `wait4`/`getrusage`, and
//! polling `/proc/<pid>/status` for VmHWM misses the last moments of a child's life, so
//! without GNU time peak memory is reported as not available rather than guessed.

use std::ffi::OsStr;
use std::fs::{self, File};
use std::io;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

const GNU_TIME: &str = "/usr/bin/time";

pub struct Timer {
    /// `/usr/bin/time` if it understands `-o FILE -f FORMAT`.
    time: Option<PathBuf>,
    /// Where GNU time writes its line.
    time_file: PathBuf,
}

/// One run of a command.
#[derive(Clone, Debug)]
pub struct Sample {
    /// Seconds, wall clock.
    pub wall: f64,
    /// Peak resident set size in KiB (GNU time `%M`).
    pub peak_kib: Option<u64>,
    /// User + system CPU seconds (GNU time `%U + %S`).
    pub cpu: Option<f64>,
    /// The exit code; None when killed by a signal.
    pub code: Option<i32>,
}

impl Timer {
    pub fn new(scratch: &Path) -> Timer {
        let time_file = scratch.join("time.txt");
        let mut timer = Timer {
            time: Some(PathBuf::from(GNU_TIME)),
            time_file,
        };
        // Probe: the file may be missing, or a time(1) without -o/-f (busybox).
        let works = Path::new(GNU_TIME).is_file()
            && timer
                .run(OsStr::new("true"), &[], None)
                .is_ok_and(|s| s.code == Some(0) && s.peak_kib.is_some());
        if !works {
            timer.time = None;
        }
        timer
    }

    pub fn measures_memory(&self) -> bool {
        self.time.is_some()
    }

    /// Runs `program args` with stdin and stdout closed (to /dev/null) and stderr into
    /// `stderr_to` (discarded when None).
    pub fn run(
        &self,
        program: &OsStr,
        args: &[&OsStr],
        stderr_to: Option<&Path>,
    ) -> io::Result<Sample> {
        let mut command = match &self.time {
            Some(time) => {
                let _ = fs::remove_file(&self.time_file);
                let mut c = Command::new(time);
                c.arg("-o")
                    .arg(&self.time_file)
                    .arg("-f")
                    .arg("%e %M %U %S")
                    .arg(program);
                c
            }
            None => Command::new(program),
        };
        command
            .args(args)
            .stdin(Stdio::null())
            .stdout(Stdio::null());
        match stderr_to {
            Some(path) => command.stderr(File::create(path)?),
            None => command.stderr(Stdio::null()),
        };
        let start = Instant::now();
        let status = command.status()?;
        let wall = start.elapsed().as_secs_f64();
        let mut sample = Sample {
            wall,
            peak_kib: None,
            cpu: None,
            code: status.code(),
        };
        if self.time.is_some() {
            // GNU time writes "Command exited with non-zero status N" before the line.
            let text = fs::read_to_string(&self.time_file).unwrap_or_default();
            let line = text
                .lines()
                .rev()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("");
            let fields: Vec<&str> = line.split_whitespace().collect();
            if let [_, peak, user, system] = fields[..] {
                sample.peak_kib = peak.parse().ok();
                if let (Ok(u), Ok(s)) = (user.parse::<f64>(), system.parse::<f64>()) {
                    sample.cpu = Some(u + s);
                }
            }
        }
        Ok(sample)
    }
}

/// The median wall time of the samples.
pub fn median_wall(samples: &[Sample]) -> f64 {
    median(samples.iter().map(|s| s.wall).collect())
}

/// The fastest and the slowest wall time.
pub fn wall_range(samples: &[Sample]) -> (f64, f64) {
    let walls = samples.iter().map(|s| s.wall);
    (
        walls.clone().fold(f64::INFINITY, f64::min),
        walls.fold(0.0, f64::max),
    )
}

/// The median CPU use (CPU seconds per wall second), when measured.
pub fn median_cores(samples: &[Sample]) -> Option<f64> {
    let values: Option<Vec<f64>> = samples
        .iter()
        .map(|s| s.cpu.map(|c| c / s.wall.max(1e-9)))
        .collect();
    values.filter(|v| !v.is_empty()).map(median)
}

/// The largest peak RSS of the samples, in bytes.
pub fn peak_bytes(samples: &[Sample]) -> Option<u64> {
    samples
        .iter()
        .map(|s| s.peak_kib.map(|k| k * 1024))
        .collect::<Option<Vec<u64>>>()
        .and_then(|v| v.into_iter().max())
}

/// The median of `values`: the middle one, or the mean of the middle two; NaN for none.
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        (values[n / 2 - 1] + values[n / 2]) / 2.0
    }
}

/// The first `lines` lines of a file, for error messages.
pub fn head(path: &Path, lines: usize) -> String {
    let text = fs::read(path).unwrap_or_default();
    let text = String::from_utf8_lossy(&text[..text.len().min(4096)]);
    text.lines().take(lines).collect::<Vec<_>>().join("\n")
}

/// The executable `name` on PATH.
pub fn on_path(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join(name))
        .find(|p| p.is_file())
}
