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
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn return_freed_memory() {
    // SAFETY: mallopt only sets an allocator parameter; called before any thread starts.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 128 * 1024);
    }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn return_freed_memory() {}
