//! INLINE_CYCLE: a file loads itself through Inlines and external prototypes.

use std::collections::{HashMap, VecDeque};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::inlines::{InlineTarget, Inlines};
use crate::diagnostic::Diagnostic;
use crate::library::Library;
use crate::limits::MAX_LIBRARY_FILES;
use crate::model::rules::LIMIT_EXCEEDED;
use crate::model::{Document, Span};
use crate::validate::prototypes::externs::{Resolved, Tree};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// At the deep level, reports an Inline or ExternProtoDeclare of the checked file that
    /// loads, directly or through the Inlines and ExternProtoDeclares of the files it
    /// loads, the checked file itself. Each such Inline or ExternProtoDeclare is reported
    /// once, with the shortest chain of files back to this one. A file loads the scene of
    /// each Inline (the first url entry naming a readable local file of the tree, as
    /// Inline files are resolved) and the library file of each ExternProtoDeclare (the
    /// file that declares the prototype, as EXTERNPROTO_INTERFACE_MISMATCH resolves it).
    /// Network URLs are never fetched, so a cycle through one is not seen.
    ///
    /// An Inline with `load FALSE` counts: its file is named, and an event setting `load`
    /// TRUE loads it (19775-1 9.4.2). A cycle that does not pass through the checked file
    /// (this file loads `a`, which loads `b`, which loads `a`) is reported in those files'
    /// own reports. A prototype instantiating itself within files is PROTO_CYCLE; two
    /// library files whose ExternProtoDeclares name each other are this rule's finding
    /// as well, even when no prototype instantiates itself: following the catalogue, an
    /// ExternProtoDeclare counts as loading the whole file it names.
    ///
    /// ## Why it matters
    /// Each loaded scene is a new copy of the inlined file's nodes (9.4.2), so a file that
    /// inlines itself asks the browser for an endless nesting of scenes: browsers stop
    /// with an error, hang, or run out of memory.
    ///
    /// ## Example
    /// `room.x3d`:
    /// ```xml
    /// <Inline url='"house.x3d"'/>
    /// ```
    /// where `house.x3d` holds `<Inline url='"room.x3d"'/>`.
    ///
    /// ## Use instead
    /// Inline the parts from a file that inlines none of its ancestors.
    ///
    /// ## Clause
    /// 19775-1 9.4.2 Inline (the url names a scene whose nodes become the Inline's
    /// children), 4.4.5 External prototype semantics.
    /// > "The transformation hierarchy shall be a directed acyclic graph" (14772-1 4.4.4)
    ///
    /// The sentence goes on "; results are undefined if a node in the transformation
    /// hierarchy is its own ancestor" (read in GPAC's copy of 14772-1 4.4.4, issue 33).
    /// The severity is the one ../shared/RULES.md gives the code (error), which is API;
    /// the "shall" above is what the file breaks.
    ///
    /// The inlined scene's nodes are the Inline's children, so a scene that inlines itself
    /// makes the Inline its own ancestor. (A library cycle of EXTERNPROTOs is a prototype
    /// instantiated in its own implementation, PROTO_CYCLE's sentence.)
    pub static INLINE_CYCLE = {
        severity: Error,
        level: Deep,
        clause: "9.4.2",
        versions: "all",
        check: Some(check),
    }
}

/// A file the search reached: the file it was reached from (None for the start) and its
/// name for messages.
struct Reached {
    from: Option<PathBuf>,
}

/// The files each file loads, found as the search needs them.
struct Loads<'a> {
    tree: Tree<'a>,
    loads: HashMap<PathBuf, Vec<PathBuf>>,
    exceeded: bool,
}

impl Loads<'_> {
    fn of(&mut self, library: &Arc<Library>) -> Vec<PathBuf> {
        if let Some(loads) = self.loads.get(&library.path) {
            return loads.clone();
        }
        if self.loads.len() >= MAX_LIBRARY_FILES {
            self.exceeded = true;
            return Vec::new();
        }
        let loads = match &library.document {
            Some(doc) => {
                let base = library.path.parent().unwrap_or(Path::new("."));
                let inlines = Inlines::in_tree(doc, Some(base), &self.tree, false);
                let externs = self.tree.externs(doc, base);
                files_loaded(doc, &inlines, &externs)
                    .into_iter()
                    .map(|(_, _, l)| l.path.clone())
                    .collect()
            }
            None => Vec::new(),
        };
        self.loads.insert(library.path.clone(), loads.clone());
        loads
    }

    fn library(&self, path: &Path) -> Arc<Library> {
        self.tree.libraries.get(path, self.tree.keep)
    }
}

/// The files a document loads: each Inline's and ExternProtoDeclare's place, what it
/// is, and the file.
fn files_loaded(
    doc: &Document,
    inlines: &Inlines,
    externs: &crate::validate::prototypes::externs::Externs,
) -> Vec<(Span, String, Arc<Library>)> {
    let mut loaded = Vec::new();
    for (id, target) in inlines.iter() {
        if let InlineTarget::Loaded { library, .. } = target {
            let node = doc.node(id);
            let what = match &node.def_name {
                Some(def) => format!("Inline `{}`", def.text),
                None => "Inline".to_string(),
            };
            let span = node.entry("url").map_or(node.name_span, |e| e.span);
            loaded.push((span, what, library.clone()));
        }
    }
    for (index, proto) in doc.protos.iter().enumerate() {
        if let Some(Resolved::Found {
            library: Some(library),
            ..
        }) = externs.get(index)
        {
            let what = format!("ExternProtoDeclare `{}`", proto.name.text);
            loaded.push((proto.name.span, what, library.clone()));
        }
    }
    loaded
}

fn check(ctx: &mut Ctx) {
    let (Some(file), Some(base)) = (ctx.file, ctx.base) else {
        return;
    };
    let starts = files_loaded(ctx.doc, &ctx.inlines, &ctx.externs);
    if starts.is_empty() {
        return;
    }
    let Ok(own) = file.canonicalize() else {
        return;
    };
    let mut loads = Loads {
        tree: Tree::in_dir(base, ctx.config),
        loads: HashMap::new(),
        exceeded: false,
    };
    let mut found = Vec::new();
    for (span, what, library) in &starts {
        if let Some(chain) = path_back(&mut loads, library, &own) {
            let names: Vec<String> = std::iter::once(&own)
                .chain(&chain)
                .map(|p| name(p))
                .collect();
            let message = if chain.len() == 1 {
                format!("{what} loads this file itself: {}", names.join(" → "))
            } else {
                let others = chain.len() - 1;
                let files = if others == 1 { "file" } else { "files" };
                format!(
                    "{what} loads this file again through {others} other {files}: {}",
                    names.join(" → ")
                )
            };
            found.push(Diagnostic::new(&INLINE_CYCLE, *span, message));
        }
    }
    if loads.exceeded {
        found.push(Diagnostic::new(
            &LIMIT_EXCEEDED,
            starts[0].0,
            format!(
                "Inlines and external prototypes load more than {MAX_LIBRARY_FILES} files from here; the rest are not followed (INLINE_CYCLE)"
            ),
        ));
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// The shortest chain of files from `start` (loaded by the checked file) back to `own`,
/// `start` first and `own` last; None when there is none.
fn path_back(loads: &mut Loads, start: &Arc<Library>, own: &Path) -> Option<Vec<PathBuf>> {
    let mut reached: HashMap<PathBuf, Reached> = HashMap::new();
    reached.insert(start.path.clone(), Reached { from: None });
    let mut queue = VecDeque::from([start.path.clone()]);
    while let Some(path) = queue.pop_front() {
        if path == own {
            let mut chain = vec![path.clone()];
            let mut at = &path;
            while let Some(from) = &reached[at].from {
                chain.push(from.clone());
                at = from;
            }
            chain.reverse();
            return Some(chain);
        }
        let library = loads.library(&path);
        for next in loads.of(&library) {
            if !reached.contains_key(&next) {
                reached.insert(
                    next.clone(),
                    Reached {
                        from: Some(path.clone()),
                    },
                );
                queue.push_back(next);
            }
        }
    }
    None
}

/// A file's name for the chain.
fn name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}
