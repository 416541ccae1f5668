//! Vectors for the numbers of long values, backed by huge pages where the kernel offers
//! them on request (Linux's transparent huge pages in `madvise` mode, the common
//! default). The numbers of a large scene are tens of MB written once, front to back; in
//! 4 KiB pages each page is a fault of its own (the benchmark scene: 26,000 faults at the
//! standard level, about a quarter of its CPU time), in 2 MiB pages one in 512.

/// Below this no huge page fits: one needs 2 MiB of address range aligned to 2 MiB.
const HUGE_BYTES: usize = 2 << 20;

/// `Vec::with_capacity(capacity)`, its buffer advised to use huge pages when it is large.
pub fn with_capacity<T>(capacity: usize) -> Vec<T> {
    let v: Vec<T> = Vec::with_capacity(capacity);
    let bytes = v.capacity() * size_of::<T>();
    if bytes >= HUGE_BYTES {
        advise_huge(v.as_ptr().cast(), bytes);
    }
    v
}

#[cfg(target_os = "linux")]
fn advise_huge(start: *const u8, bytes: usize) {
    // madvise takes page-aligned ranges: the whole pages inside the buffer.
    const PAGE: usize = 4096;
    let first = (start as usize).next_multiple_of(PAGE);
    let end = (start as usize + bytes) & !(PAGE - 1);
    if end > first {
        // SAFETY: the range lies inside the vector's own allocation, and MADV_HUGEPAGE
        // changes only how its pages are backed, never their contents. An error (a kernel
        // without transparent huge pages) leaves 4 KiB pages, which is what we had.
        unsafe {
            libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge(_: *const u8, _: usize) {}
