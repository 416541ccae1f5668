//! Reading files without trusting what they are: the inputs, and the files they name that
//! are read as scenes (external prototypes). A path is opened without blocking (a FIFO
//! would otherwise wait for a writer forever), the opened handle is checked to be a regular
//! file (so a file swapped for a FIFO or device after the walk listed it is caught too), and
//! every read stops one byte past the input limit, so that `/dev/zero` on stdin or a file
//! growing while it is read never holds more than the limit.

use std::fs::{self, File};
use std::io::{self, Read};
use std::path::Path;

/// What reading an input gave.
pub enum Contents {
    Bytes(Vec<u8>),
    /// More than the limit: not kept (reported as LIMIT_EXCEEDED).
    TooLarge,
}

/// Reads the regular file at `path`, or says why not (the kind of file it is, when it is
/// not a regular one).
pub fn read_path(path: &Path, limit: usize) -> Result<Contents, String> {
    let file = open(path).map_err(|e| cannot_read(path, e))?;
    let meta = file.metadata().map_err(|e| cannot_read(path, e))?;
    if !meta.is_file() {
        return Err(format!(
            "cannot read {}: it is {}, not a regular file",
            path.display(),
            kind(&meta.file_type())
        ));
    }
    if meta.len() > limit as u64 {
        return Ok(Contents::TooLarge);
    }
    read_within(file, limit, meta.len() as usize).map_err(|e| cannot_read(path, e))
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
