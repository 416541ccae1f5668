//! A large input file mapped read-only instead of read into the heap, and the pages that
//! the passes over it have gone past given back (the [`Progress`] of
//! [`behind`](crate::parse::behind)). Every `unsafe` that mapping needs is here.
//!
//! A private read-only mapping of a file is the file's pages in the page cache, counted in
//! the process's resident memory only while they are mapped in. `madvise(MADV_DONTNEED)`
//! on a part of it unmaps those pages (the page cache keeps them); a later read of that
//! part (a rule or the report looking at a span) maps them in again, with the same bytes.
//! So the text stays addressable for the whole check, as a `&[u8]`, while only what the
//! current pass reads is resident. Giving back is done on Unix; elsewhere (Windows) the
//! file is mapped and nothing is given back.
//!
//! What a mapping assumes: the file does not change while it is mapped. The command line
//! reads its inputs and never writes them (`--fix` reads into the heap, since it rewrites
//! the file), but another program may. One that writes into the file changes the text
//! under the check (the report may then point at text that is not what was checked, as
//! with a file changed between the check and a look at it); one that truncates it makes
//! reading the pages past its new end fault with SIGBUS. That signal, on a page of a live
//! mapping, is caught: the process writes "x3dcheck: an input file shrank while it was
//! read; no report" to standard error and exits with 2, the exit code of a run that could
//! not check its inputs, rather than dying of the signal. Any other SIGBUS is handed back
//! to what handled it before (Rust's runtime, or the default).

use std::fs::File;
use std::io;
use std::ops::Deref;
#[cfg(unix)]
use std::sync::atomic::{AtomicUsize, Ordering};

use memmap2::Mmap;

use crate::parse::Progress;

/// A file mapped read-only.
pub struct Mapped {
    map: Mmap,
    /// Its place in the table of live mappings the SIGBUS handler looks in.
    #[cfg(unix)]
    slot: usize,
}

impl Mapped {
    /// Maps `file` (a regular file, opened for reading, not empty), or None when it cannot
    /// be (no slot left in the table of live mappings: the caller reads it instead).
    pub fn of(file: &File) -> io::Result<Option<Mapped>> {
        // SAFETY: the mapping is read-only and private; what it assumes of the file (that
        // no other program changes it) is in the module doc, with what happens when one
        // truncates it.
        let map = unsafe { Mmap::map(file)? };
        #[cfg(unix)]
        {
            let Some(slot) = live::add(map.as_ptr() as usize, map.len()) else {
                return Ok(None);
            };
            Ok(Some(Mapped { map, slot }))
        }
        #[cfg(not(unix))]
        Ok(Some(Mapped { map }))
    }
}

impl Deref for Mapped {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        &self.map
    }
}

#[cfg(unix)]
impl Drop for Mapped {
    fn drop(&mut self) {
        live::remove(self.slot);
    }
}

/// Pages are given back in blocks of this size and alignment from the mapping's start: a
/// multiple of every page size in use (4 KiB, 16 KiB on Apple silicon, 64 KiB on some ARM
/// servers), so that no system call is needed to learn it.
#[cfg(unix)]
const BLOCK: usize = 64 << 10;

impl Progress for Mapped {
    /// Gives back the whole blocks from the one `behind` starts in to the one it ends in
    /// (not included: the pass is still reading it); nothing when `behind` is not part of
    /// this mapping (text decoded into the heap).
    #[cfg(unix)]
    fn passed(&self, behind: &[u8]) {
        let base = self.map.as_ptr() as usize;
        let at = behind.as_ptr() as usize;
        if at < base || at + behind.len() > base + self.map.len() {
            return;
        }
        let start = (at - base) / BLOCK * BLOCK;
        let end = (at - base + behind.len()) / BLOCK * BLOCK;
        if end > start {
            // SAFETY: the range lies inside the mapping, which is private, read-only and
            // never written, so after MADV_DONTNEED a read of it maps in the file's pages
            // again, the same bytes: no reference into it sees anything else. A failure
            // only leaves the pages resident.
            let _ = unsafe {
                self.map.unchecked_advise_range(
                    memmap2::UncheckedAdvice::DontNeed,
                    start,
                    end - start,
                )
            };
        }
    }

    #[cfg(not(unix))]
    fn passed(&self, _: &[u8]) {}
}

/// The live mappings, as (start, length) in a fixed table of atomics: what a signal
/// handler may read (it may not lock or allocate). A slot whose start is 0 is free.
#[cfg(unix)]
mod live {
    use super::*;

    /// More than the files a run checks at once (one per thread of the pool).
    const SLOTS: usize = 64;

    static STARTS: [AtomicUsize; SLOTS] = [const { AtomicUsize::new(0) }; SLOTS];
    static LENGTHS: [AtomicUsize; SLOTS] = [const { AtomicUsize::new(0) }; SLOTS];

    /// Records a mapping; None when every slot is taken.
    pub fn add(start: usize, len: usize) -> Option<usize> {
        sigbus::install();
        (0..SLOTS).find(|&slot| {
            LENGTHS[slot]
                .compare_exchange(0, len, Ordering::AcqRel, Ordering::Relaxed)
                .is_ok()
                && {
                    STARTS[slot].store(start, Ordering::Release);
                    true
                }
        })
    }

    pub fn remove(slot: usize) {
        STARTS[slot].store(0, Ordering::Release);
        LENGTHS[slot].store(0, Ordering::Release);
    }

    /// Whether `address` lies in a live mapping.
    pub fn holds(address: usize) -> bool {
        (0..SLOTS).any(|slot| {
            let start = STARTS[slot].load(Ordering::Acquire);
            let len = LENGTHS[slot].load(Ordering::Acquire);
            start != 0 && (start..start + len).contains(&address)
        })
    }
}

/// The SIGBUS handler: installed once, when the first file is mapped.
#[cfg(unix)]
mod sigbus {
    use std::sync::{Once, OnceLock};

    use super::live;

    const MESSAGE: &[u8] = b"x3dcheck: an input file shrank while it was read; no report\n";

    /// The exit code of a run that could not check its inputs (README, "Exit codes").
    const COULD_NOT_RUN: libc::c_int = 2;

    /// What handled SIGBUS before: restored for a fault that is not in a mapped input.
    static PREVIOUS: OnceLock<libc::sigaction> = OnceLock::new();

    pub fn install() {
        static ONCE: Once = Once::new();
        ONCE.call_once(|| {
            // SAFETY: sigaction with a zeroed, then filled, struct owned here; the handler
            // only calls async-signal-safe functions (write, _exit, sigaction).
            unsafe {
                let mut action: libc::sigaction = std::mem::zeroed();
                let handler: extern "C" fn(libc::c_int, *mut libc::siginfo_t, *mut libc::c_void) =
                    on_sigbus;
                action.sa_sigaction = handler as libc::sighandler_t;
                action.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK;
                libc::sigemptyset(&mut action.sa_mask);
                let mut previous: libc::sigaction = std::mem::zeroed();
                if libc::sigaction(libc::SIGBUS, &action, &mut previous) == 0 {
                    let _ = PREVIOUS.set(previous);
                }
            }
        });
    }

    extern "C" fn on_sigbus(_: libc::c_int, info: *mut libc::siginfo_t, _: *mut libc::c_void) {
        // SAFETY: the kernel hands a valid siginfo_t to an SA_SIGINFO handler.
        let address = unsafe { (*info).si_addr() } as usize;
        if live::holds(address) {
            // SAFETY: write and _exit are async-signal-safe; MESSAGE is a static buffer.
            unsafe {
                libc::write(2, MESSAGE.as_ptr().cast(), MESSAGE.len());
                libc::_exit(COULD_NOT_RUN);
            }
        }
        // Not an input: the previous handler (or the default) gets the fault again when
        // the instruction is retried.
        // SAFETY: sigaction and signal are async-signal-safe; `previous` is the action
        // sigaction returned.
        unsafe {
            if let Some(previous) = PREVIOUS.get() {
                libc::sigaction(libc::SIGBUS, previous, std::ptr::null_mut());
            } else {
                libc::signal(libc::SIGBUS, libc::SIG_DFL);
            }
        }
    }
}
