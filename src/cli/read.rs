//! The command line's side of reading: the input files are read by [`crate::read`]; here
//! standard output is guarded so that a report is never written into nothing.

use std::sync::OnceLock;

pub use crate::read::{open, read_path, read_source, read_stdin, Contents, Source};

static STDOUT_CLOSED: OnceLock<bool> = OnceLock::new();

/// Run first: remembers whether standard output was closed when the program started
/// (`>&-`), for [`stdout_closed`]. Rust's runtime puts /dev/null, opened for reading and
/// writing, on a closed standard descriptor before `main` (so that no file opened later
/// gets it), and a report written there would vanish: that is what is looked for. A shell
/// redirection to /dev/null (`>/dev/null`) opens it for writing only, and stays allowed.
pub fn guard_stdout() {
    let _ = STDOUT_CLOSED.set(stdout_is_runtime_null());
}

#[cfg(unix)]
fn stdout_is_runtime_null() -> bool {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: fcntl and fstat on descriptor 1 with a zeroed stat buffer owned here.
    let (flags, stat) = unsafe {
        let mut stat: libc::stat = std::mem::zeroed();
        (
            libc::fcntl(1, libc::F_GETFL),
            libc::fstat(1, &mut stat).eq(&0).then_some(stat),
        )
    };
    let read_write = flags != -1 && flags & libc::O_ACCMODE == libc::O_RDWR;
    let null = std::fs::metadata("/dev/null").ok();
    match (stat, null) {
        // st_rdev is u64 on Linux but narrower on some other unixes.
        #[allow(clippy::unnecessary_cast)]
        (Some(stat), Some(null)) => {
            read_write
                && stat.st_mode & libc::S_IFMT == libc::S_IFCHR
                && stat.st_rdev as u64 == null.rdev()
        }
        _ => false,
    }
}

#[cfg(not(unix))]
fn stdout_is_runtime_null() -> bool {
    false
}

/// Whether standard output was closed when the program started.
pub fn stdout_closed() -> bool {
    STDOUT_CLOSED.get().copied().unwrap_or(false)
}
