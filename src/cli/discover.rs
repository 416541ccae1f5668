//! Finding the inputs, like ruff: a directory is walked with the `ignore` crate (ripgrep's
//! walker), which honours `.gitignore`, `.ignore` and git's exclude files (in a repository
//! or not) and skips hidden files and folders; `--exclude` and the configuration's
//! `exclude` prune more. A walk takes every X3D and VRML file name ([`is_scene_name`]) and
//! a `.json` file only when its top-level object has an `X3D` member, an HTML page
//! (`.html`, `.htm`, `.xhtml`) only when it holds an X3D island; a file named on the
//! command line is always checked. A file reached twice (two arguments, a link) is checked
//! once.
//!
//! Entries a walk cannot read are reported, never passed over: a link leading nowhere or in
//! a circle, a FIFO, socket or device with a scene's name (refused when it is read, see
//! [`super::read`]). A link to a file outside the directory being walked is not followed
//! and is reported as not checked: the references of a scene (Inline, textures) are not
//! read outside that tree either, and naming the file on the command line checks it.

use std::collections::HashSet;
use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};

use ignore::WalkBuilder;

use crate::batch::file_root;
use crate::config_file::glob::Glob;
use crate::config_file::Resolver;
use crate::parse::decode::GZIP_MAGIC;
use crate::shard::Shard;

use super::read;

pub enum Input {
    Stdin,
    /// A file, with the directory tree its references (textures, Inlines) may be read from.
    File {
        path: PathBuf,
        root: PathBuf,
    },
}

/// The extensions of scene files a walk takes (any case), also with `.gz` after them.
const SCENE_EXTENSIONS: &[&str] = &[
    "x3d", "x3dv", "x3dj", "wrl", "x3dz", "x3dvz", "x3djz", "wrz",
];

/// Bytes of a `.json` file read to tell whether it is X3D.
const SNIFF_BYTES: u64 = 64 * 1024;

/// What the walks found and whether something could not be read (exit code 2).
pub struct Found {
    pub inputs: Vec<Input>,
    pub failed: bool,
    /// Every file the arguments name or the walks find, of every shard: an Inline's file
    /// among them is reported as an input, not as an inlined file (`inlined.rs`).
    pub listed: Vec<PathBuf>,
}

/// The inputs in argument order, each directory's files sorted by path; with a shard, only
/// those in it. What cannot be read is reported here on stderr. Err: a configuration error,
/// or nothing found at all.
pub fn find_inputs(
    paths: &[PathBuf],
    shard: Option<Shard>,
    exclude: &[String],
    resolver: &mut Resolver,
) -> Result<Found, String> {
    let mut found = Found {
        inputs: Vec::new(),
        failed: false,
        listed: Vec::new(),
    };
    let mut seen = HashSet::new();
    let mut stdin_taken = false;
    let mut any = false;
    for path in paths {
        if path.as_os_str() == "-" {
            any = true;
            if !stdin_taken && shard.is_none_or(|s| s.holds_stdin()) {
                found.inputs.push(Input::Stdin);
            }
            stdin_taken = true;
            continue;
        }
        let meta = match fs::metadata(path) {
            Ok(meta) => meta,
            Err(e) => {
                report(&mut found, format!("cannot read {}: {e}", path.display()));
                continue;
            }
        };
        if !meta.is_dir() {
            any = true;
            found.listed.push(path.clone());
            if shard.is_none_or(|s| s.holds(path)) && first_time(&mut seen, path) {
                found.inputs.push(Input::File {
                    path: path.clone(),
                    root: file_root(path),
                });
            }
            continue;
        }
        let config = resolver.file_for_dir(path).map_err(|e| e.to_string())?;
        let excludes = Excludes::new(exclude, config.as_deref());
        let mut files = walk(path, excludes, &mut found);
        any |= !files.is_empty();
        found.listed.extend(files.iter().cloned());
        if let Some(shard) = shard {
            files.retain(|file| shard.holds(file.strip_prefix(path).unwrap_or(file)));
        }
        files.sort();
        files.retain(|file| first_time(&mut seen, file));
        found
            .inputs
            .extend(files.into_iter().map(|file| Input::File {
                path: file,
                root: path.clone(),
            }));
    }
    if !any && !found.failed {
        return Err(format!(
            "no X3D files found in {} (looked for {} and their .gz forms, .json files \
             holding an X3D object and HTML pages holding X3D)",
            paths
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", "),
            SCENE_EXTENSIONS
                .iter()
                .map(|e| format!(".{e}"))
                .collect::<Vec<_>>()
                .join(" ")
        ));
    }
    Ok(found)
}

fn report(found: &mut Found, message: String) {
    eprintln!("x3dcheck: {message}");
    found.failed = true;
}

/// Whether `path` leads to a file not taken yet (by its identity, so links and `..` count).
fn first_time(seen: &mut HashSet<super::FileId>, path: &Path) -> bool {
    match super::file_id(path) {
        Ok(id) => seen.insert(id),
        Err(_) => true, // Reported when it is read.
    }
}

/// The patterns that prune a walk: `--exclude`, relative to the current directory, and
/// the `exclude` of the configuration file, relative to its directory.
#[derive(Clone)]
struct Excludes {
    cli: Vec<Glob>,
    current_dir: PathBuf,
    config: Option<std::sync::Arc<crate::config_file::ConfigFile>>,
}

impl Excludes {
    fn new(cli: &[String], config: Option<&crate::config_file::ConfigFile>) -> Excludes {
        Excludes {
            cli: cli.iter().map(|p| Glob::new(p)).collect(),
            current_dir: std::env::current_dir().unwrap_or_default(),
            config: config.map(|c| std::sync::Arc::new(c.clone())),
        }
    }

    fn excludes(&self, path: &Path) -> bool {
        let Ok(absolute) = std::path::absolute(path) else {
            return false;
        };
        let relative = absolute
            .strip_prefix(&self.current_dir)
            .unwrap_or(&absolute);
        let relative = relative
            .components()
            .map(|c| c.as_os_str().to_string_lossy())
            .collect::<Vec<_>>()
            .join("/");
        self.cli.iter().any(|glob| glob.matches(&relative))
            || self.config.as_ref().is_some_and(|c| c.excludes(&absolute))
    }
}

/// The scene files under `dir`; what cannot be read is reported into `found`.
fn walk(dir: &Path, excludes: Excludes, found: &mut Found) -> Vec<PathBuf> {
    let tree = dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf());
    let walker = WalkBuilder::new(dir)
        .standard_filters(true)
        .require_git(false)
        .follow_links(false)
        .filter_entry(move |entry| entry.depth() == 0 || !excludes.excludes(entry.path()))
        .build();
    let mut files = Vec::new();
    for entry in walker {
        let entry = match entry {
            Ok(entry) => entry,
            Err(error) if error.io_error().is_some() => {
                report(found, format!("cannot read {error}"));
                continue;
            }
            // A bad pattern in an ignore file: the walk goes on without it.
            Err(error) => {
                eprintln!("x3dcheck: warning: {error}");
                continue;
            }
        };
        let path = entry.path();
        let Some(file_type) = entry.file_type() else {
            continue;
        };
        if file_type.is_dir() || !(is_scene_name(path) || is_json_name(path) || is_html_name(path))
        {
            continue;
        }
        if file_type.is_symlink() {
            match path.canonicalize() {
                Err(e) => {
                    report(
                        found,
                        format!(
                            "cannot read {}: a symbolic link that leads nowhere readable ({e})",
                            path.display()
                        ),
                    );
                    continue;
                }
                Ok(target) if !target.starts_with(&tree) => {
                    report(
                        found,
                        format!(
                            "not checked: {} is a symbolic link to {}, outside {}; name it \
                             on the command line to check it",
                            path.display(),
                            target.display(),
                            dir.display()
                        ),
                    );
                    continue;
                }
                Ok(_) => {}
            }
        }
        let html_island = || is_html_name(path) && holds_island(path);
        if is_scene_name(path) || (is_json_name(path) && is_x3d_json(path)) || html_island() {
            files.push(path.to_path_buf());
        }
    }
    files
}

/// `.x3d`, `.x3dv`, `.x3dj`, `.wrl`, their compressed forms `.x3dz`, `.x3dvz`, `.x3djz`,
/// `.wrz`, and any of them followed by `.gz`.
pub fn is_scene_name(path: &Path) -> bool {
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or_default();
    let name = name.to_ascii_lowercase();
    let name = name.strip_suffix(".gz").unwrap_or(&name);
    SCENE_EXTENSIONS
        .iter()
        .any(|e| name.strip_suffix(e).is_some_and(|stem| stem.ends_with('.')))
}

fn is_json_name(path: &Path) -> bool {
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or_default();
    let name = name.to_ascii_lowercase();
    name.ends_with(".json") || name.ends_with(".json.gz")
}

fn is_html_name(path: &Path) -> bool {
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or_default()
        .to_ascii_lowercase();
    [".html", ".htm", ".xhtml"]
        .iter()
        .any(|e| name.ends_with(e))
}

/// Bytes of an HTML page read to tell whether it holds X3D.
const PAGE_SNIFF_BYTES: u64 = 16 * 1024 * 1024;

/// Whether an HTML page found in a walk holds an X3D island: an `<x3d>` or `<x3d-canvas>`
/// tag (any case) in its first [`PAGE_SNIFF_BYTES`]. What cannot be opened as a regular
/// file is taken, to be reported when it is read.
fn holds_island(path: &Path) -> bool {
    let Ok(file) = read::open(path) else {
        return true;
    };
    if !file.metadata().is_ok_and(|m| m.is_file()) {
        return true;
    }
    let mut page = Vec::new();
    if file.take(PAGE_SNIFF_BYTES).read_to_end(&mut page).is_err() {
        return true;
    }
    has_island_tag(&page)
}

fn has_island_tag(page: &[u8]) -> bool {
    memchr::memchr_iter(b'<', page).any(|at| {
        let rest = &page[at + 1..];
        rest.len() > 3
            && rest[..3].eq_ignore_ascii_case(b"x3d")
            && (matches!(rest[3], b'>' | b'/' | b'-') || rest[3].is_ascii_whitespace())
    })
}

/// Whether a `.json` file found in a walk is an X3D input: its top-level object has an
/// `X3D` member within its first [`SNIFF_BYTES`] (decompressed). What cannot be opened as a
/// regular file is taken, to be reported when it is read.
fn is_x3d_json(path: &Path) -> bool {
    let Ok(file) = read::open(path) else {
        return true;
    };
    if !file.metadata().is_ok_and(|m| m.is_file()) {
        return true;
    }
    let mut head = Vec::new();
    if file.take(SNIFF_BYTES).read_to_end(&mut head).is_err() {
        return true;
    }
    if head.starts_with(&GZIP_MAGIC) {
        let mut inflated = Vec::new();
        let decoder = flate2::read::MultiGzDecoder::new(&head[..]);
        // A stream cut at SNIFF_BYTES ends in an error after what it could inflate.
        let _ = decoder.take(SNIFF_BYTES).read_to_end(&mut inflated);
        head = inflated;
    }
    has_x3d_member(&head)
}

/// Whether the JSON object `head` begins has an `X3D` member before `head` ends.
fn has_x3d_member(head: &[u8]) -> bool {
    let text = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    x3d_member_at(text).unwrap_or(false)
}

fn x3d_member_at(text: &[u8]) -> Option<bool> {
    let mut at = skip_space(text, 0);
    if text.get(at) != Some(&b'{') {
        return Some(false);
    }
    at += 1;
    loop {
        at = skip_space(text, at);
        if text.get(at) != Some(&b'"') {
            return Some(false);
        }
        let end = string_end(text, at)?;
        if &text[at + 1..end - 1] == b"X3D" {
            return Some(true);
        }
        at = skip_space(text, end);
        if text.get(at) != Some(&b':') {
            return Some(false);
        }
        at = skip_space(text, value_end(text, at + 1)?);
        if text.get(at) != Some(&b',') {
            return Some(false);
        }
        at += 1;
    }
}

fn skip_space(text: &[u8], mut at: usize) -> usize {
    while text.get(at).is_some_and(u8::is_ascii_whitespace) {
        at += 1;
    }
    at
}

/// The index after the string that starts at `at` (a `"`).
fn string_end(text: &[u8], at: usize) -> Option<usize> {
    let mut i = at + 1;
    loop {
        match text.get(i)? {
            b'\\' => i += 2,
            b'"' => return Some(i + 1),
            _ => i += 1,
        }
    }
}

/// The index after the value that starts at or after `at`.
fn value_end(text: &[u8], at: usize) -> Option<usize> {
    let mut i = skip_space(text, at);
    match text.get(i)? {
        b'"' => string_end(text, i),
        b'{' | b'[' => {
            let mut depth = 0usize;
            loop {
                match text.get(i)? {
                    b'"' => {
                        i = string_end(text, i)?;
                        continue;
                    }
                    b'{' | b'[' => depth += 1,
                    b'}' | b']' => {
                        depth -= 1;
                        if depth == 0 {
                            return Some(i + 1);
                        }
                    }
                    _ => {}
                }
                i += 1;
            }
        }
        _ => {
            let scalar = |b: &u8| !matches!(b, b',' | b'}' | b']') && !b.is_ascii_whitespace();
            while text.get(i).is_some_and(scalar) {
                i += 1;
            }
            text.get(i).map(|_| i)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn html_pages_are_taken_when_they_hold_an_island() {
        assert!(has_island_tag(b"<body><X3D width='3'><Scene>"));
        assert!(has_island_tag(b"<body><x3d-canvas src='a.x3d'>"));
        assert!(has_island_tag(b"<p>\n<x3d>"));
        assert!(!has_island_tag(b"<body><x3dom-note><p>x3d</p>"));
        assert!(is_html_name(Path::new("a/b.XHTML")));
    }

    #[test]
    fn x3d_json_is_told_by_its_top_level_member() {
        assert!(has_x3d_member(br#"{"X3D": {}}"#));
        assert!(has_x3d_member(
            b"\xEF\xBB\xBF {\n \"$schema\": \"x\", \"X3D\": {"
        ));
        let nested = br#"{"a": {"X3D": 1}, "b": [1, "X3D", {"c": "}"}], "X3D": {}}"#;
        assert!(has_x3d_member(nested));
        assert!(!has_x3d_member(
            br#"{"name": "x3d-thing", "version": "1.0"}"#
        ));
        assert!(!has_x3d_member(br#"{"a": {"X3D": 1}}"#));
        assert!(!has_x3d_member(br#"["X3D"]"#));
        assert!(!has_x3d_member(br#"{"a": "cut off"#));
    }

    #[test]
    fn scene_names_include_compressed_forms() {
        for name in [
            "a.x3d", "a.X3DV", "a.x3dj", "a.wrl", "a.x3dz", "a.wrz", "a.x3d.gz",
        ] {
            assert!(is_scene_name(Path::new(name)), "{name}");
        }
        for name in ["a.json", "x3d", "a.gz", "a.x3dx", "a.ax3d"] {
            assert!(!is_scene_name(Path::new(name)), "{name}");
        }
    }
}
