//! Long numeric values parsed on several threads. The text is cut at separators into
//! pieces, every piece is parsed on its own (the first straight into the value's sink, the
//! others into vectors of their own), and the pieces' numbers are appended in order. The
//! first error is that of the first piece that has one: the error a one-piece parse meets
//! first, since it stops there. Errors that depend on what came before (a misplaced comma,
//! which depends on how many numbers precede it) are found by the caller once the pieces'
//! counts are known.

use std::ops::Range;

use rayon::prelude::*;

use super::number::is_separator;
use crate::model::Sink;

/// Values shorter than this are parsed on one thread: below about a megabyte, handing
/// the pieces to other threads costs more than it saves.
pub const SPLIT_BYTES: usize = 1 << 20;

/// The piece size for a value of `len` bytes on the `threads()` threads of the pool, or
/// `None` to parse it in one piece: about two pieces per thread, so that a thread that
/// finishes early (or was busy with another file) takes another, and none below half of
/// [`SPLIT_BYTES`]. Short values do not ask for the thread count.
pub fn piece_size(len: usize, threads: impl FnOnce() -> usize) -> Option<usize> {
    if len < SPLIT_BYTES {
        return None;
    }
    let threads = threads();
    (threads > 1).then(|| len.div_ceil(2 * threads).max(SPLIT_BYTES / 2))
}

/// Ranges covering `s` in order, each at least `piece` bytes long but the last, each but
/// the last ending at a separator, so that no token is cut.
pub fn pieces(s: &[u8], piece: usize) -> Vec<Range<usize>> {
    let piece = piece.max(1);
    let mut out = Vec::with_capacity(s.len() / piece + 1);
    let mut start = 0;
    while s.len() - start > piece {
        let mut end = start + piece;
        while end < s.len() && !is_separator(s[end]) {
            end += 1;
        }
        out.push(start..end);
        start = end;
    }
    // The last token may have run to the end: no empty piece after it.
    if start < s.len() || out.is_empty() {
        out.push(start..s.len());
    }
    out
}

/// Parses the pieces of `s` into `values` on the current pool: `scan_first` reads the
/// tokens of the first range into `values`, `scan` those of another range into a vector
/// (two functions, so that each is compiled for its sink). Returns each piece with the
/// number of scalars before it, or the first piece's error.
pub fn scan_pieces<T, S, E>(
    s: &[u8],
    piece: usize,
    values: &mut S,
    scan_first: impl FnOnce(Range<usize>, &mut S) -> Result<(), E> + Send,
    scan: impl Fn(Range<usize>, &mut Vec<T>) -> Result<(), E> + Sync,
) -> Result<Vec<(Range<usize>, usize)>, E>
where
    T: Copy + Send + 'static,
    S: Sink<T> + Send,
    E: Send,
{
    let ranges = pieces(s, piece);
    let (first, rest) = ranges
        .split_first()
        .expect("pieces() returns at least one range");
    let (head, tail) = rayon::join(
        || scan_first(first.clone(), values),
        || {
            rest.par_iter()
                .map(|range| {
                    let mut own = scratch::take::<T>(range.len());
                    scan(range.clone(), &mut own).map(|()| own)
                })
                .collect::<Vec<_>>()
        },
    );
    head?;
    let mut counted = Vec::with_capacity(ranges.len());
    counted.push((first.clone(), 0));
    for (range, numbers) in rest.iter().zip(tail) {
        counted.push((range.clone(), values.count()));
        let numbers = numbers?;
        values.extend_from(&numbers);
        scratch::give_back(numbers);
    }
    Ok(counted)
}

/// The vectors the pieces after the first are parsed into, kept from one long value to
/// the next. Each would otherwise be a new allocation of its own pages (glibc maps blocks
/// this large afresh, see `main.rs`), and every page of it a fault: 10,000 of the 26,000
/// page faults of the benchmark scene at the standard level, most of its system time.
pub mod scratch {
    use std::any::Any;
    use std::sync::Mutex;

    /// Enough for the pieces of one value on a machine of eight threads: about two
    /// pieces per thread, the first not among them.
    const KEEP: usize = 16;
    /// Vectors larger than this are dropped, not kept: the pool holds at most `KEEP` of
    /// these, what pieces of half a megabyte to a few megabytes of text need.
    const KEEP_BYTES: usize = 4 << 20;

    static POOL: Mutex<Vec<Box<dyn Any + Send>>> = Mutex::new(Vec::new());

    /// An empty vector for the numbers of a piece of `text_len` bytes.
    pub fn take<T: Send + 'static>(text_len: usize) -> Vec<T> {
        // Four bytes of text a number: a guess that rarely grows.
        let capacity = text_len / 4 + 1;
        let kept = POOL.lock().ok().and_then(|mut pool| {
            let at = pool.iter().position(|v| v.is::<Vec<T>>())?;
            Some(pool.swap_remove(at))
        });
        match kept.and_then(|v| v.downcast::<Vec<T>>().ok()) {
            Some(mut v) => {
                v.reserve(capacity);
                *v
            }
            None => crate::model::text::huge_vec::with_capacity(capacity),
        }
    }

    /// Keeps `v`'s memory for a later piece.
    pub fn give_back<T: Send + 'static>(mut v: Vec<T>) {
        if v.capacity() * size_of::<T>() > KEEP_BYTES {
            return;
        }
        v.clear();
        if let Ok(mut pool) = POOL.lock() {
            if pool.len() < KEEP {
                pool.push(Box::new(v));
            }
        }
    }

    /// Frees what the pool keeps: once the values are read, before memory matters more.
    pub fn release() {
        if let Ok(mut pool) = POOL.lock() {
            *pool = Vec::new();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_end_at_separators() {
        let s = b"1.5 22 333,4444\t5 6";
        for piece in 1..s.len() + 2 {
            let ranges = pieces(s, piece);
            assert_eq!(ranges.first().unwrap().start, 0);
            assert_eq!(ranges.last().unwrap().end, s.len());
            for pair in ranges.windows(2) {
                assert_eq!(pair[0].end, pair[1].start);
                assert!(is_separator(s[pair[0].end]), "{piece}: {ranges:?}");
            }
        }
    }

    #[test]
    fn small_values_or_one_thread_are_one_piece() {
        assert_eq!(piece_size(SPLIT_BYTES - 1, || 8), None);
        assert_eq!(piece_size(100 * SPLIT_BYTES, || 1), None);
        assert_eq!(piece_size(SPLIT_BYTES, || 2), Some(SPLIT_BYTES / 2));
        assert_eq!(piece_size(8 * SPLIT_BYTES, || 2), Some(2 * SPLIT_BYTES));
    }
}
