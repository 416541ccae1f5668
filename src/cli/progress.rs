//! The progress bar of a long batch, on stderr. It is drawn only when a person watches the
//! run: stderr is a terminal and the report goes to the terminal too or to `-o FILE` (not
//! into a pipe or a redirected stdout, nor in CI logs); and only for a batch still running
//! after [`DELAY`], so quick runs never flash a bar. It is cleared before the report is
//! written, so it never mixes with it. `--quiet` leaves it out. It has no colours: nothing
//! for `NO_COLOR` or `--color never` to switch off.

use std::io::{self, IsTerminal};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// How long a batch runs before its bar appears.
const DELAY: Duration = Duration::from_secs(1);
/// How often a shown bar redraws its clock while no file completes.
const TICK: Duration = Duration::from_millis(250);

pub struct Progress {
    /// None when no bar may be drawn.
    bar: Option<ProgressBar>,
    started: Instant,
    shown: AtomicBool,
}

impl Progress {
    /// The progress of a batch of `files`; `report_to_file`: the report goes to `-o FILE`;
    /// `quiet`: nothing but the findings is wanted (`--quiet`).
    pub fn start(files: usize, report_to_file: bool, quiet: bool) -> Progress {
        let watched =
            !quiet && io::stderr().is_terminal() && (report_to_file || io::stdout().is_terminal());
        let bar = (watched && files > 1).then(|| {
            let bar =
                ProgressBar::with_draw_target(Some(files as u64), ProgressDrawTarget::hidden());
            let style = ProgressStyle::with_template(
                "{bar:30} {pos}/{len} files checked, {elapsed} (about {eta} left)",
            )
            .expect("the template is valid")
            .progress_chars("=> ");
            bar.set_style(style);
            bar
        });
        Progress {
            bar,
            started: Instant::now(),
            shown: AtomicBool::new(false),
        }
    }

    /// Counts a checked file (from any worker thread); shows the bar once the batch has run
    /// for [`DELAY`].
    pub fn file_done(&self) {
        let Some(bar) = &self.bar else {
            return;
        };
        bar.inc(1);
        if !self.shown.load(Ordering::Relaxed)
            && self.started.elapsed() >= DELAY
            && !self.shown.swap(true, Ordering::Relaxed)
        {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            bar.enable_steady_tick(TICK);
        }
    }

    /// Removes the bar from the terminal.
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
