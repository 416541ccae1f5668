//! Letting go of the text behind a pass. A large input file is mapped rather than read into
//! the heap ([`crate::read`]), and the pages of it that a pass over the text has gone past
//! can be given back to the kernel while the pass goes on; a later look at a span (a rule,
//! the report) reads them again from the file. So every pass over the whole text (the
//! UTF-8 check, the readers, the JSON reader's two passes, the line index of the report)
//! tells a [`Progress`] how far it has got, every [`STEP`] bytes, through a [`Pass`]. What
//! the progress does with that is its owner's business: a mapped file drops those pages
//! (`crate::read::mapped`), text in the heap (`()`) does nothing.
//!
//! The readers depend on nothing above the model, so the progress is a trait of theirs,
//! implemented above them.

/// How often a pass tells its progress: often enough that what it has read and not yet
/// given back stays a few megabytes, rarely enough that telling costs nothing measurable.
pub const STEP: usize = 4 << 20;

/// Told how far a pass over the text has got.
pub trait Progress: Sync {
    /// `behind`, a part of the text, has been read, and the pass will not come back to it
    /// or to what lies before it (another pass, or a look at a span, may).
    fn passed(&self, behind: &[u8]);
}

/// Text in the heap: nothing to give back.
impl Progress for () {
    fn passed(&self, _: &[u8]) {}
}

/// One pass over `text`, telling its progress every [`STEP`] bytes.
pub struct Pass<'a> {
    text: &'a [u8],
    progress: &'a dyn Progress,
    /// Where the last part told ended.
    told: usize,
}

impl<'a> Pass<'a> {
    pub fn new(text: &'a [u8], progress: &'a dyn Progress) -> Pass<'a> {
        Pass {
            text,
            progress,
            told: 0,
        }
    }

    /// The pass has read everything before `at`: told once it is a [`STEP`] past the last
    /// time. Cheap enough to call for every token.
    #[inline]
    pub fn reached(&mut self, at: usize) {
        if at >= self.told + STEP {
            self.tell(at);
        }
    }

    #[cold]
    fn tell(&mut self, at: usize) {
        let at = at.min(self.text.len());
        self.progress.passed(&self.text[self.told..at]);
        self.told = at;
    }
}

/// Where text that should be UTF-8 is not.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct NotUtf8 {
    /// The offset of the first byte that is not part of a character.
    pub valid_up_to: usize,
    /// How many bytes make up the bad sequence; None when the text ends inside a character.
    pub error_len: Option<usize>,
}

/// `text` as a string, checked to be UTF-8 a [`STEP`] at a time (telling `progress`),
/// with the error [`std::str::from_utf8`] gives for it.
pub fn utf8<'t>(text: &'t [u8], progress: &dyn Progress) -> Result<&'t str, NotUtf8> {
    let mut pass = Pass::new(text, progress);
    let mut at = 0;
    while at < text.len() {
        let end = (at + STEP).min(text.len());
        match std::str::from_utf8(&text[at..end]) {
            Ok(_) => at = end,
            Err(error) => match error.error_len() {
                // A character cut by the step's end is checked again whole in the next.
                None if end < text.len() => at += error.valid_up_to(),
                error_len => {
                    return Err(NotUtf8 {
                        valid_up_to: at + error.valid_up_to(),
                        error_len,
                    })
                }
            },
        }
        pass.reached(at);
    }
    // SAFETY: every byte of `text` was found to be part of a UTF-8 character: the steps
    // cover it in order, and each starts where the one before ended on a character
    // boundary. (A mapped file that another program changes after this is outside what
    // `crate::read::mapped` allows, as for every other assumption made about the text.)
    Ok(unsafe { std::str::from_utf8_unchecked(text) })
}

/// Whether `needle` occurs in `text`, looked for a [`STEP`] at a time (telling `progress`).
pub fn contains(text: &[u8], needle: &[u8], progress: &dyn Progress) -> bool {
    let mut pass = Pass::new(text, progress);
    let mut at = 0;
    loop {
        // Steps overlap by the needle's length less one, so that none is cut.
        let end = (at + STEP + needle.len()).min(text.len());
        if memchr::memmem::find(&text[at..end], needle).is_some() {
            return true;
        }
        if end == text.len() {
            return false;
        }
        at = end + 1 - needle.len().max(1);
        pass.reached(at);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    /// Records what it was told, as (start, end) offsets into `text`.
    struct Recorded<'t> {
        text: &'t [u8],
        parts: Mutex<Vec<(usize, usize)>>,
    }

    impl Progress for Recorded<'_> {
        fn passed(&self, behind: &[u8]) {
            let start = behind.as_ptr() as usize - self.text.as_ptr() as usize;
            self.parts
                .lock()
                .unwrap()
                .push((start, start + behind.len()));
        }
    }

    #[test]
    fn a_pass_tells_consecutive_parts_a_step_apart() {
        let text = vec![b'a'; 3 * STEP + 10];
        let recorded = Recorded {
            text: &text,
            parts: Mutex::new(Vec::new()),
        };
        let mut pass = Pass::new(&text, &recorded);
        for at in (0..text.len()).step_by(1000) {
            pass.reached(at);
        }
        pass.reached(usize::MAX);
        let parts = recorded.parts.into_inner().unwrap();
        assert_eq!(parts.len(), 3);
        assert_eq!(parts[0].0, 0);
        assert_eq!(parts.last().unwrap().1, text.len());
        for pair in parts.windows(2) {
            assert_eq!(pair[0].1, pair[1].0);
            assert!(pair[1].1 - pair[1].0 >= STEP || pair[1].1 == text.len());
        }
    }

    #[test]
    fn utf8_in_steps_is_from_utf8() {
        // Characters of every length across every step boundary, then errors near one.
        let mut text = "é€😀a".repeat(STEP / 3).into_bytes();
        assert_eq!(utf8(&text, &()), Ok(std::str::from_utf8(&text).unwrap()));
        let whole = |text: &[u8]| {
            std::str::from_utf8(text).map(|_| ()).map_err(|e| NotUtf8 {
                valid_up_to: e.valid_up_to(),
                error_len: e.error_len(),
            })
        };
        for at in [STEP - 2, STEP - 1, STEP, STEP + 1, 2 * STEP + 3] {
            let mut bad = text.clone();
            bad[at] = 0xFF;
            assert_eq!(utf8(&bad, &()).map(|_| ()), whole(&bad), "at {at}");
        }
        // Ending inside a character.
        text.truncate(STEP + 1);
        assert_eq!(utf8(&text, &()).map(|_| ()), whole(&text));
    }

    #[test]
    fn contains_finds_a_needle_across_a_step_boundary() {
        for at in [0, STEP - 5, STEP - 1, STEP, 2 * STEP + 7] {
            let mut text = vec![b' '; 3 * STEP];
            text[at..at + 9].copy_from_slice(b"x3dcheck:");
            assert!(contains(&text, b"x3dcheck:", &()), "at {at}");
            text[at] = b' ';
            assert!(!contains(&text, b"x3dcheck:", &()), "at {at}");
        }
        assert!(!contains(b"", b"x3dcheck:", &()));
    }
}
