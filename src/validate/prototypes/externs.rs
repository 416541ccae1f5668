//! External prototypes resolved (deep level): which ProtoDeclare each ExternProtoDeclare's
//! url names, in a local file of the tree being checked.
//!
//! The url's entries are tried in order, as a browser tries them (19775-1 4.4.5.3, 9.2.1):
//! the first that names a readable local file declaring the prototype wins. The prototype
//! is the top-level ProtoDeclare the `#Name` fragment names, else the file's first one
//! (prototypes nested in a body are local to it). A url that is only `#Name` names a
//! prototype of this document. Local paths resolve as texture urls do
//! (`Resolver`): relative to the document's directory, never outside the tree being
//! checked (the checking root, else the document's directory), and network URLs are never
//! fetched. Library files are read once per batch ([`crate::library::Libraries`]).
//!
//! [`Externs`] is the table the rules use: EXTERNPROTO_NOT_FOUND and
//! EXTERNPROTO_INTERFACE_MISMATCH report on it, PROTO_CYCLE follows its prototypes across
//! files, and VALIDATION_INCOMPLETE no longer says the body of a resolved one is
//! unchecked. Instantiating a resolved prototype reads its body through
//! [`Externs::declaration`].

use std::collections::{HashMap, VecDeque};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::config::CheckConfig;
use crate::library::{Libraries, Library};
use crate::limits::MAX_LIBRARY_FILES;
use crate::model::{Document, ExternalPrototypes, LibraryFile, ProtoDecl, Scope};
use crate::parse::KeepValues;
use crate::validate::texturing::files::{Resolution, Resolver};

/// What one ExternProtoDeclare's url led to.
#[derive(Clone, Debug)]
pub enum Resolved {
    /// The ProtoDeclare it names: index `proto` of the protos of `library`'s document, or of
    /// this document when `library` is None (a `#Name` url).
    Found {
        library: Option<Arc<Library>>,
        proto: usize,
        /// The url entry that named it, as written.
        url: String,
    },
    /// Local files the url names exist, but none declares the prototype (the first such
    /// entry, and why: no ProtoDeclare of the name, or not a scene at all).
    NotFound {
        url: String,
        path: PathBuf,
        why: String,
    },
    /// No entry names a local file of the tree that could be read: network URLs, files
    /// outside the tree or missing, a document read from standard input.
    Unresolved,
}

/// What each ExternProtoDeclare of a document resolves to, by prototype index (None for
/// ProtoDeclares, and for every prototype below the deep level).
#[derive(Clone, Debug, Default)]
pub struct Externs {
    by_proto: Vec<Option<Resolved>>,
}

impl Externs {
    /// Resolves the ExternProtoDeclares of `doc`, read from `file` (None: standard input,
    /// whose relative urls do not resolve).
    pub fn resolve(doc: &Document, file: Option<&Path>, config: &CheckConfig) -> Externs {
        if !doc.protos.iter().any(|p| p.external) {
            return Externs::default();
        }
        let Some((tree, base)) = Tree::of(file, config) else {
            return Externs {
                by_proto: doc
                    .protos
                    .iter()
                    .map(|p| p.external.then_some(Resolved::Unresolved))
                    .collect(),
            };
        };
        tree.externs(doc, &base)
    }

    /// Whether any ExternProtoDeclare resolved.
    pub fn any_found(&self) -> bool {
        self.by_proto
            .iter()
            .any(|r| matches!(r, Some(Resolved::Found { .. })))
    }

    /// What prototype `proto` (an ExternProtoDeclare) resolves to; None for a ProtoDeclare
    /// or below the deep level.
    pub fn get(&self, proto: usize) -> Option<&Resolved> {
        self.by_proto.get(proto).and_then(Option::as_ref)
    }

    /// The declaration an ExternProtoDeclare resolves to, with the document it is in (`doc`
    /// itself for a `#Name` url) and that document's library file (None for `doc`).
    pub fn declaration<'a>(
        &'a self,
        doc: &'a Document,
        proto: usize,
    ) -> Option<(&'a Document, &'a ProtoDecl, Option<&'a Arc<Library>>)> {
        let Some(Resolved::Found { library, proto, .. }) = self.get(proto) else {
            return None;
        };
        let in_doc = match library {
            Some(library) => library.document.as_ref()?,
            None => doc,
        };
        Some((in_doc, in_doc.protos.get(*proto)?, library.as_ref()))
    }
}

/// The tree external prototypes are resolved in: the checked document's, shared by every
/// library file it reaches.
pub struct Tree<'a> {
    /// The directory no file outside of which is read.
    pub root: PathBuf,
    pub libraries: &'a Libraries,
    pub keep: KeepValues,
}

impl Tree<'_> {
    /// The tree of the document read from `file` (None: standard input, whose relative
    /// urls do not resolve), with the document's directory.
    pub fn of<'c>(file: Option<&Path>, config: &'c CheckConfig) -> Option<(Tree<'c>, PathBuf)> {
        let base = match file?.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => dir,
            _ => Path::new("."),
        };
        Some((Tree::in_dir(base, config), base.to_path_buf()))
    }

    /// The tree of a document in directory `base`: the checking root, else `base`.
    pub fn in_dir<'c>(base: &Path, config: &'c CheckConfig) -> Tree<'c> {
        Tree {
            root: config.root.clone().unwrap_or_else(|| base.to_path_buf()),
            libraries: &config.libraries,
            keep: config.keep_values(),
        }
    }

    /// The externs of `doc`, a document in directory `base` of the tree.
    pub fn externs(&self, doc: &Document, base: &Path) -> Externs {
        let resolver = Resolver::new(Some(base), Some(&self.root));
        let by_proto = doc
            .protos
            .iter()
            .map(|p| p.external.then(|| self.resolve(doc, p, &resolver)))
            .collect();
        Externs { by_proto }
    }

    fn resolve(&self, doc: &Document, proto: &ProtoDecl, resolver: &Resolver) -> Resolved {
        let mut not_found = None;
        for url in &proto.url {
            let fragment = url.split_once('#').map(|(_, name)| name.trim());
            if url.trim().starts_with('#') {
                if let Some(index) = top_level(doc, fragment) {
                    return Resolved::Found {
                        library: None,
                        proto: index,
                        url: url.clone(),
                    };
                }
                continue;
            }
            let Resolution::Local(path) = resolver.resolve(url) else {
                continue;
            };
            let library = self.libraries.get(&path, self.keep);
            let Some(library_doc) = &library.document else {
                let why = library.failure.clone().unwrap_or_default();
                not_found.get_or_insert((url.clone(), path, why));
                continue;
            };
            match top_level(library_doc, fragment) {
                Some(index) => {
                    return Resolved::Found {
                        library: Some(library.clone()),
                        proto: index,
                        url: url.clone(),
                    }
                }
                None => {
                    let why = match fragment {
                        Some(name) => format!("it declares no top-level ProtoDeclare `{name}`"),
                        None => "it declares no top-level ProtoDeclare".to_string(),
                    };
                    not_found.get_or_insert((url.clone(), path, why));
                }
            }
        }
        match not_found {
            Some((url, path, why)) => Resolved::NotFound { url, path, why },
            None => Resolved::Unresolved,
        }
    }
}

/// The library files a document's external prototypes reach, through the libraries' own
/// ExternProtoDeclares too (at most [`MAX_LIBRARY_FILES`]), with what each prototype of
/// each file resolves to. File 0 is the document, file `k ≥ 1` is `libraries[k - 1]`.
pub struct Reached {
    pub libraries: Vec<Arc<Library>>,
    /// Per file, per prototype: the ProtoDeclare an ExternProtoDeclare resolves to.
    pub resolved: Vec<Vec<Option<(usize, usize)>>>,
    /// Where [`MAX_LIBRARY_FILES`] stopped the walk: (file, prototype) not followed.
    pub exceeded: Option<(usize, usize)>,
}

impl Reached {
    /// Walks from `doc` (read from `own`, canonical, when known), whose ExternProtoDeclares
    /// resolved to `externs`; libraries' own resolve in `tree`.
    pub fn walk(doc: &Document, externs: &Externs, tree: &Tree, own: Option<PathBuf>) -> Reached {
        let mut reached = Reached {
            libraries: Vec::new(),
            resolved: Vec::new(),
            exceeded: None,
        };
        let mut by_path: HashMap<PathBuf, usize> = own.into_iter().map(|p| (p, 0)).collect();
        let mut pending = VecDeque::from([externs.clone()]);
        while let Some(externs) = pending.pop_front() {
            let file = reached.resolved.len();
            let count = match file {
                0 => doc.protos.len(),
                _ => reached.libraries[file - 1]
                    .document
                    .as_ref()
                    .map_or(0, |d| d.protos.len()),
            };
            let mut resolved = vec![None; count];
            for (proto, slot) in resolved.iter_mut().enumerate() {
                let Some(Resolved::Found {
                    library,
                    proto: target,
                    ..
                }) = externs.get(proto)
                else {
                    continue;
                };
                let Some(library) = library else {
                    *slot = Some((file, *target));
                    continue;
                };
                if let Some(&known) = by_path.get(&library.path) {
                    *slot = Some((known, *target));
                    continue;
                }
                let Some(library_doc) = &library.document else {
                    continue;
                };
                if reached.libraries.len() + 1 >= MAX_LIBRARY_FILES {
                    reached.exceeded.get_or_insert((file, proto));
                    continue;
                }
                reached.libraries.push(library.clone());
                let index = reached.libraries.len();
                by_path.insert(library.path.clone(), index);
                let base = library.path.parent().unwrap_or(Path::new("."));
                // Files are numbered in the order they are found, and walked in that order.
                pending.push_back(tree.externs(library_doc, base));
                *slot = Some((index, *target));
            }
            reached.resolved.push(resolved);
        }
        reached
    }

    /// The resolution as the model's instantiation takes it; library names relative to
    /// `base` (the checked document's directory).
    pub fn prototypes(&self, base: Option<&Path>) -> ExternalPrototypes<'_> {
        ExternalPrototypes {
            libraries: self
                .libraries
                .iter()
                .filter_map(|library| {
                    Some(LibraryFile {
                        doc: library.document.as_ref()?,
                        text: &library.text,
                        name: display_path(base, &library.path),
                        path: library.path.clone(),
                    })
                })
                .collect(),
            resolved: self.resolved.clone(),
        }
    }
}

/// The document with the instances of its external prototypes instantiated from the
/// library files their urls resolve to (`externs`), and the limits that instantiating
/// reached; the document as it was, and None, when no external prototype resolves.
pub fn instantiate(
    doc: Document,
    file: Option<&Path>,
    config: &CheckConfig,
    externs: &Externs,
) -> (Document, Option<Vec<crate::diagnostic::Diagnostic>>) {
    if !externs.any_found() {
        return (doc, None);
    }
    let Some((tree, base)) = Tree::of(file, config) else {
        return (doc, None);
    };
    let own = file.and_then(|f| f.canonicalize().ok());
    let reached = Reached::walk(&doc, externs, &tree, own);
    let (doc, found) = crate::model::instantiate_with(doc, &reached.prototypes(Some(&base)));
    (doc, Some(found))
}

/// A library's path for messages: relative to the checked document's directory when it is
/// below it, else as it is.
pub fn display_path(base: Option<&Path>, path: &Path) -> String {
    let canonical_base = base.and_then(|b| b.canonicalize().ok());
    canonical_base
        .and_then(|b| path.strip_prefix(b).ok().map(Path::to_path_buf))
        .unwrap_or_else(|| path.to_path_buf())
        .display()
        .to_string()
}

/// The top-level ProtoDeclare (not an ExternProtoDeclare, not nested in a body) named
/// `name`, else the first.
fn top_level(doc: &Document, name: Option<&str>) -> Option<usize> {
    doc.protos.iter().position(|p| {
        !p.external && p.scope == Scope::Scene && name.is_none_or(|n| p.name.text == n)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Level;

    fn scene(body: &str) -> String {
        format!("<X3D version='4.0'><Scene>{body}</Scene></X3D>")
    }

    #[test]
    fn urls_resolve_in_order_to_the_named_top_level_prototype() {
        let dir = std::env::temp_dir().join(format!("x3dcheck-externs-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(
            dir.join("sub/lib.x3d"),
            scene(
                "<ProtoDeclare name='A'><ProtoBody><ProtoDeclare name='Inner'><ProtoBody><Group/></ProtoBody></ProtoDeclare><Group/></ProtoBody></ProtoDeclare>\
                 <ProtoDeclare name='B'><ProtoBody><Group/></ProtoBody></ProtoDeclare>",
            ),
        )
        .unwrap();
        let main = scene(
            "<ExternProtoDeclare name='X' url='\"http://example.com/lib.x3d#B\" \"sub/lib.x3d#B\"'/>\
             <ExternProtoDeclare name='Y' url='\"sub/lib.x3d\"'/>\
             <ExternProtoDeclare name='Z' url='\"sub/lib.x3d#Inner\" \"missing.x3d\"'/>\
             <ExternProtoDeclare name='W' url='\"https://example.com/w.x3d\"'/>\
             <ExternProtoDeclare name='V' url='\"#Local\"'/>\
             <ProtoDeclare name='Local'><ProtoBody><Group/></ProtoBody></ProtoDeclare>",
        );
        let doc = crate::parse::read(main.as_bytes()).document.unwrap();
        let config = CheckConfig {
            level: Level::Deep,
            ..CheckConfig::default()
        };
        let externs = Externs::resolve(&doc, Some(&dir.join("main.x3d")), &config);
        let found = |p: usize| match externs.get(p) {
            Some(Resolved::Found { proto, library, .. }) => Some((*proto, library.is_some())),
            _ => None,
        };
        assert_eq!(
            found(0),
            Some((2, true)),
            "B is the third prototype of the file"
        );
        assert_eq!(found(1), Some((0, true)), "no fragment: the first");
        assert!(
            matches!(externs.get(2), Some(Resolved::NotFound { why, .. }) if why.contains("`Inner`")),
            "a nested prototype is not visible: {:?}",
            externs.get(2)
        );
        assert!(matches!(externs.get(3), Some(Resolved::Unresolved)));
        assert_eq!(found(4), Some((5, false)));
        assert!(externs.get(5).is_none(), "a ProtoDeclare");
        assert_eq!(config.libraries.len(), 1, "one file, read once");
        let (_, decl, _) = externs.declaration(&doc, 0).unwrap();
        assert_eq!(decl.name.text, "B");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
