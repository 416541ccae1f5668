//! Reading files without trusting what they are: the inputs, and the files they name that
//! are read as scenes (external prototypes). A path is opened without blocking (a FIFO
//! would otherwise wait for a writer forever), the opened handle is checked to be a regular
//! file (so a file swapped for a FIFO or device after the walk listed it is caught too), and
//! every read stops one byte past the input limit, so that `/dev/zero` on stdin or a file
//! growing while it is read never holds more than the limit.
//!
//! A file to check of [`MAP_BYTES`] or more is mapped instead ([`read_source`], [`Mapped`]),
//! so that the passes over its text can give back what they have read.

mod mapped;

use std::fs::{self, File};
use std::io::{self, Read};
use std::ops::Deref;
use std::path::Path;

pub use mapped::Mapped;

use crate::parse::Progress;

/// What reading an input gave.
pub enum Contents<B = Vec<u8>> {
    Bytes(B),
    /// More than the limit: not kept (reported as LIMIT_EXCEEDED).
    TooLarge,
}

/// Files to check this large or larger are mapped rather than read. Below it, reading is
/// as fast and the copy small: the common case, an editor checking the file it saves.
pub const MAP_BYTES: u64 = 8 << 20;

/// The bytes of an input to check: read into the heap, or mapped.
pub enum Source {
    Heap(Vec<u8>),
    Mapped(Mapped),
}

impl Source {
    /// What to tell how far the passes over the text have got: a mapping gives back the
    /// pages they have read (see [`crate::parse::behind`]).
    pub fn progress(&self) -> &dyn Progress {
        match self {
            Source::Heap(_) => &(),
            Source::Mapped(mapped) => mapped,
        }
    }
}

impl Deref for Source {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        match self {
            Source::Heap(bytes) => bytes,
            Source::Mapped(mapped) => mapped,
        }
    }
}

/// Reads the regular file at `path` as [`read_path`] does, but maps it when it has
/// [`MAP_BYTES`] or more.
pub fn read_source(path: &Path, limit: usize) -> Result<Contents<Source>, String> {
    let (file, len) = open_regular(path, limit)?;
    let Some(len) = len else {
        return Ok(Contents::TooLarge);
    };
    if len >= MAP_BYTES {
        if let Some(mapped) = Mapped::of(&file).map_err(|e| cannot_read(path, e))? {
            // The file may have grown since its length was read.
            if mapped.len() > limit {
                return Ok(Contents::TooLarge);
            }
            return Ok(Contents::Bytes(Source::Mapped(mapped)));
        }
    }
    Ok(
        match read_within(file, limit, len as usize).map_err(|e| cannot_read(path, e))? {
            Contents::Bytes(bytes) => Contents::Bytes(Source::Heap(bytes)),
            Contents::TooLarge => Contents::TooLarge,
        },
    )
}

/// Reads the regular file at `path`, or says why not (the kind of file it is, when it is
/// not a regular one).
pub fn read_path(path: &Path, limit: usize) -> Result<Contents, String> {
    let (file, len) = open_regular(path, limit)?;
    let Some(len) = len else {
        return Ok(Contents::TooLarge);
    };
    read_within(file, limit, len as usize).map_err(|e| cannot_read(path, e))
}

/// The regular file at `path`, opened, and its length (None: more than `limit`), or why
/// not (the kind of file it is, when it is not a regular one).
fn open_regular(path: &Path, limit: usize) -> Result<(File, Option<u64>), String> {
    let file = open(path).map_err(|e| cannot_read(path, e))?;
    let meta = file.metadata().map_err(|e| cannot_read(path, e))?;
    if !meta.is_file() {
        return Err(format!(
            "cannot read {}: it is {}, not a regular file",
            path.display(),
            kind(&meta.file_type())
        ));
    }
    let len = meta.len();
    Ok((file, (len <= limit as u64).then_some(len)))
}

/// Reads standard input, whatever it is (a pipe, a terminal, a device), within `limit`.
pub fn read_stdin(limit: usize) -> Result<Contents, String> {
    read_within(io::stdin().lock(), limit, 0).map_err(|e| format!("cannot read <stdin>: {e}"))
}

/// Reads at most `limit` + 1 bytes; `expected` sizes the buffer.
pub fn read_within(reader: impl Read, limit: usize, expected: usize) -> io::Result<Contents> {
    let mut bytes = Vec::with_capacity(expected.min(limit).saturating_add(1));
    reader.take(limit as u64 + 1).read_to_end(&mut bytes)?;
    Ok(if bytes.len() > limit {
        Contents::TooLarge
    } else {
        Contents::Bytes(bytes)
    })
}

#[cfg(unix)]
pub fn open(path: &Path) -> io::Result<File> {
    use std::os::unix::fs::OpenOptionsExt;
    fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)
}

#[cfg(not(unix))]
pub fn open(path: &Path) -> io::Result<File> {
    File::open(path)
}

/// "cannot read PATH: why", naming what the path is when opening it failed because of
/// that (a socket cannot be opened; a link may lead nowhere or in a circle).
fn cannot_read(path: &Path, error: io::Error) -> String {
    let what = match (fs::symlink_metadata(path), fs::metadata(path)) {
        (Ok(link), Err(_)) if link.file_type().is_symlink() => {
            format!("a symbolic link that leads nowhere readable ({error})")
        }
        (_, Ok(meta)) if !meta.is_file() && !meta.is_dir() => {
            format!("it is {}, not a regular file", kind(&meta.file_type()))
        }
        _ => error.to_string(),
    };
    format!("cannot read {}: {what}", path.display())
}

/// What a file that is not a regular file is.
pub fn kind(file_type: &fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if file_type.is_socket() {
            return "a socket";
        }
        if file_type.is_char_device() {
            return "a character device";
        }
        if file_type.is_block_device() {
            return "a block device";
        }
    }
    if file_type.is_dir() {
        "a directory"
    } else if file_type.is_symlink() {
        "a symbolic link"
    } else {
        "a special file"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_reader_stops_one_byte_past_the_limit() {
        // io::repeat never ends, like /dev/zero or a stream on stdin.
        let counted = CountingReader(io::repeat(b'x'), 0);
        let mut counted = counted;
        let contents = read_within(&mut counted, 1000, 0).unwrap();
        assert!(matches!(contents, Contents::TooLarge));
        assert_eq!(counted.1, 1001);
        let contents = read_within(&b"<X3D/>"[..], 6, 6).unwrap();
        assert!(matches!(contents, Contents::Bytes(b) if b == b"<X3D/>"));
    }

    struct CountingReader<R>(R, usize);

    impl<R: Read> Read for CountingReader<R> {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            let n = self.0.read(buf)?;
            self.1 += n;
            Ok(n)
        }
    }
}
