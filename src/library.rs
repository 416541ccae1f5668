//! Files other scenes load: the prototype libraries ExternProtoDeclare statements name and
//! the scenes Inline nodes name, read and parsed once per batch however many scenes name
//! them.
//!
//! A [`Libraries`] cache is shared by every file of a batch (the command line puts one
//! handle into each file's [`CheckConfig`](crate::config::CheckConfig)); files are checked in
//! parallel, and a file two of them need at once is read by one while the other waits
//! for it. A file is read like an input (any encoding, gzip, within
//! [`MAX_INPUT_BYTES`]) and parsed here, not checked: the
//! scenes that load it read its prototypes, exports and Inlines. An inlined file's own
//! findings are those of checking it as a scene of its own, with its own version and
//! profile: the command line checks every inlined file the batch does not list from the
//! parsed file kept here ([`Libraries::inlined`], [`crate::check::check_library`]). Only
//! the deep level reads these files, and only inside the tree being checked (see
//! `validate::prototypes::externs` and `validate::networking::inlines`).

use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

use crate::diagnostic::Diagnostic;
use crate::limits::MAX_INPUT_BYTES;
use crate::model::{Document, Encoding, Span};
use crate::parse::{self, KeepValues};
use crate::read::{self, Contents};

/// One library file as read.
#[derive(Debug)]
pub struct Library {
    /// The canonical path it was read from.
    pub path: PathBuf,
    /// The decoded text (UTF-8) the document's spans are offsets into.
    pub text: Vec<u8>,
    /// The scene read from it; None when it is no X3D or VRML scene (or was not read).
    pub document: Option<Document>,
    /// Why there is no document: the file could not be read, is too large, or is not a
    /// scene.
    pub failure: Option<String>,
    /// What decoding and reading it reported (the first findings of its own report).
    pub read_findings: Vec<Diagnostic>,
    pub encoding: Option<Encoding>,
    /// Whether it was gzip-compressed.
    pub compressed: bool,
}

impl Library {
    /// `line:column` (1-based) of a place in the library, for messages in the scene that
    /// names it.
    pub fn line_column(&self, span: Span) -> (usize, usize) {
        let at = (span.start as usize).min(self.text.len());
        let before = &self.text[..at];
        let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
        let line_start = before
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |i| i + 1);
        let column = String::from_utf8_lossy(&before[line_start..])
            .chars()
            .count()
            + 1;
        (line, column)
    }

    fn read(path: &Path, keep: KeepValues) -> Library {
        let failed = |failure: String| Library {
            path: path.to_path_buf(),
            text: Vec::new(),
            document: None,
            failure: Some(failure),
            read_findings: Vec::new(),
            encoding: None,
            compressed: false,
        };
        let bytes = match read::read_path(path, MAX_INPUT_BYTES) {
            Ok(Contents::Bytes(bytes)) => bytes,
            Ok(Contents::TooLarge) => {
                return failed(format!("it is larger than {MAX_INPUT_BYTES} bytes"))
            }
            Err(message) => return failed(message),
        };
        let decoded = parse::decode(&bytes);
        let compressed = decoded.compressed;
        if let Some(failure) = decoded.failure {
            return Library {
                failure: Some(failure.message.clone()),
                text: decoded.text.into_owned(),
                read_findings: vec![failure],
                compressed,
                ..failed(String::new())
            };
        }
        let text = decoded.text.into_owned();
        let parsed = parse::read_with(&text, keep);
        let failure = parsed
            .document
            .is_none()
            .then(|| "it is not an X3D or VRML scene".to_string());
        Library {
            path: path.to_path_buf(),
            text,
            document: parsed.document,
            failure,
            read_findings: parsed.diagnostics,
            encoding: parsed.encoding,
            compressed,
        }
    }
}

/// A library being read or read: filled once, by the first file that needs it, while
/// others wait.
type Slot = Arc<OnceLock<Arc<Library>>>;

/// The libraries read so far in a batch, by canonical path. Cloning shares the cache.
#[derive(Clone, Default)]
pub struct Libraries {
    read: Arc<Mutex<HashMap<PathBuf, Slot>>>,
    /// The files read as Inline scenes, each with the tree it was reached in.
    inlined: Arc<Mutex<BTreeMap<PathBuf, PathBuf>>>,
}

impl std::fmt::Debug for Libraries {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let count = self.read.lock().map(|m| m.len()).unwrap_or_default();
        write!(f, "Libraries({count} read)")
    }
}

impl Libraries {
    /// The library at `path` (canonical, a regular file inside the tree being checked),
    /// read and parsed on first use. `keep` is what the reader keeps of numeric values (the
    /// first caller's choice holds for the batch).
    pub fn get(&self, path: &Path, keep: KeepValues) -> Arc<Library> {
        let slot = {
            // A panic elsewhere while the map was held leaves it usable: entries are only
            // ever added whole.
            let mut read = self.read.lock().unwrap_or_else(|e| e.into_inner());
            read.entry(path.to_path_buf()).or_default().clone()
        };
        slot.get_or_init(|| Arc::new(Library::read(path, keep)))
            .clone()
    }

    /// [`Libraries::get`] for a file an Inline loads, inside the tree `root`: the batch
    /// will check it as a scene of its own ([`Libraries::inlined`]).
    pub fn get_inlined(&self, path: &Path, root: &Path, keep: KeepValues) -> Arc<Library> {
        self.inlined
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .entry(path.to_path_buf())
            .or_insert_with(|| root.to_path_buf());
        self.get(path, keep)
    }

    /// The files read as Inline scenes so far, by path, each with its tree and its
    /// contents: (canonical path, root, library).
    pub fn inlined(&self) -> Vec<(PathBuf, PathBuf, Arc<Library>)> {
        let inlined = self
            .inlined
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone();
        inlined
            .into_iter()
            .map(|(path, root)| {
                let library = self.get(&path, KeepValues::All);
                (path, root, library)
            })
            .collect()
    }

    /// How many files were read (for tests of the cache).
    pub fn len(&self) -> usize {
        self.read.lock().map(|m| m.len()).unwrap_or_default()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_library_is_read_once_and_shared() {
        let dir = std::env::temp_dir().join(format!("x3dcheck-lib-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("lib.x3d");
        std::fs::write(
            &path,
            "<X3D version='4.0'><Scene><ProtoDeclare name='P'><ProtoBody><Group/></ProtoBody></ProtoDeclare></Scene></X3D>",
        )
        .unwrap();
        let libraries = Libraries::default();
        let shared = libraries.clone();
        let first = libraries.get(&path, KeepValues::All);
        let second = shared.get(&path, KeepValues::All);
        assert!(Arc::ptr_eq(&first, &second));
        assert_eq!(libraries.len(), 1);
        assert_eq!(first.document.as_ref().unwrap().protos[0].name.text, "P");
        assert_eq!(
            first.line_column(first.document.as_ref().unwrap().protos[0].name.span),
            (1, 47)
        );
        let missing = libraries.get(&dir.join("none.x3d"), KeepValues::All);
        assert!(missing.document.is_none() && missing.failure.is_some());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
