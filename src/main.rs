//! The `x3dcheck` command; everything it does is in [`x3dcheck::cli`], which the Python
//! package's `x3dcheck` command runs too.

fn main() -> std::process::ExitCode {
    return_freed_memory();
    std::process::ExitCode::from(x3dcheck::cli::main(std::env::args_os()))
}

/// glibc raises its mmap threshold to the size of each large block freed (up to 32 MB), so
/// after the document's arrays are freed, the draw list's and the software GPU driver's
/// arrays of a few MB come from the heap, whose freed middle is never given back: about
/// 30 MB more peak RSS when rendering the benchmark scene (README, "Render memory").
/// Setting the threshold fixes it at glibc's initial 128 KiB.
///
/// Fixing it also fixes the trim threshold at 128 KiB: a heap gives back its free top
/// beyond that at every free. The software driver allocates several MB for each render
/// pass on its own thread's heap and frees them when the pass is drawn, so that heap was
/// given back and faulted in again at every pass (benchmark scene, fast: 540,000 page
/// faults against 99,000, 2.0 s of system time against 0.4 s). A heap now keeps up to
/// 16 MiB of free top, which the next pass reuses; 8 MiB is not enough (270,000 page
/// faults). It costs about 1 MB of peak RSS when rendering (fast), none when checking.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn return_freed_memory() {
    // SAFETY: mallopt only sets allocator parameters; called before any thread starts.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 128 * 1024);
        libc::mallopt(libc::M_TRIM_THRESHOLD, 16 * 1024 * 1024);
    }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn return_freed_memory() {}
