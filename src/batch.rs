//! What a run over a batch of files needs beyond checking each one, below both the command
//! line and the library API that run one: the tree a file's references may be read from
//! ([`file_root`]), the codes that selectors name ([`codes`]), and the files Inlines load
//! that the batch does not list ([`check_inlined`]).

mod inlined;

use std::path::{Path, PathBuf};

use crate::config_file::select_codes;

pub use inlined::{check_inlined, Batch};

/// The tree a file named on the command line may read references from: the current
/// directory when the file lies in it (textures in a sibling `../textures` folder are
/// common), else the file's own directory. A directory argument is its own root.
pub fn file_root(file: &Path) -> PathBuf {
    let directory = file
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    match (std::env::current_dir(), directory.canonicalize()) {
        (Ok(current), Ok(directory)) if directory.starts_with(&current) => current,
        _ => directory.to_path_buf(),
    }
}

/// The codes `selectors` select, in order; an error names `option` and the selector that
/// matches no code.
pub fn codes<S: AsRef<str>>(selectors: &[S], option: &str) -> Result<Vec<String>, String> {
    let mut codes = Vec::new();
    for selector in selectors {
        codes.extend(select_codes(selector.as_ref()).map_err(|e| format!("{option}: {e}"))?);
    }
    Ok(codes)
}
