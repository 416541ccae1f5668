//! Inline scenes resolved (deep level): which local file each Inline node loads.
//!
//! The url's entries are tried in order, as a browser tries them (19775-1 9.2.1, 9.4.2):
//! the first that names a readable local file of the tree being checked is the one loaded,
//! whatever it holds. Local paths resolve as texture and ExternProtoDeclare urls do
//! (`Resolver`): relative to the document's directory, never outside the tree, and
//! network URLs are never fetched. The file is read once per batch
//! ([`crate::library::Libraries`]), and the batch checks it as a scene of its own.
//!
//! An Inline with `load FALSE` is resolved too: the file is named, and `load` is an
//! inputOutput field that an event may set TRUE (9.4.2), when the browser loads it.

use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

use crate::config::CheckConfig;
use crate::library::Library;
use crate::model::{Document, NodeId};
use crate::validate::prototypes::externs::Tree;
use crate::validate::texturing::files::{not_fetched, Resolution, Resolver};

/// What one Inline's url led to.
#[derive(Clone, Debug)]
pub enum InlineTarget {
    /// The first entry naming a readable local file of the tree, and that file.
    Loaded { library: Arc<Library>, url: String },
    /// No entry names a readable local file: why the first entry that is out of reach is
    /// (None: the local files named are all missing, which URL_UNRESOLVED reports).
    Unreached(Option<Unreached>),
}

/// Why an url entry is not read.
#[derive(Clone, Debug)]
pub enum Unreached {
    Network(String),
    Outside(String),
    /// A relative url of a document read from standard input.
    NoBase,
    /// The scene is written into the url (`data:`).
    Data,
}

impl Unreached {
    pub fn text(&self) -> String {
        match self {
            Unreached::Network(url) => not_fetched(url),
            Unreached::Outside(url) => {
                format!("\"{url}\" is outside the directory tree being checked and is not read")
            }
            Unreached::NoBase => {
                "relative URLs of a document read from standard input are not resolved".to_string()
            }
            Unreached::Data => "a scene in a data: URL is not checked".to_string(),
        }
    }
}

/// What each Inline node of a document loads (deep level; empty below it).
#[derive(Clone, Debug, Default)]
pub struct Inlines {
    by_node: HashMap<NodeId, InlineTarget>,
}

impl Inlines {
    /// Resolves the Inlines of `doc`, read from `file` (None: standard input).
    pub fn resolve(doc: &Document, file: Option<&Path>, config: &CheckConfig) -> Inlines {
        if !doc.nodes.iter().any(|n| n.is_a("Inline")) {
            return Inlines::default();
        }
        let base = file.map(|file| match file.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => dir,
            _ => Path::new("."),
        });
        let root = config
            .root
            .clone()
            .or_else(|| base.map(Path::to_path_buf))
            .unwrap_or_default();
        let tree = Tree {
            root,
            libraries: &config.libraries,
            keep: config.keep_values(),
        };
        Inlines::in_tree(doc, base, &tree, true)
    }

    /// The Inlines of `doc`, a document in directory `base` of `tree`. `checked`: whether
    /// the files they load are to be checked by the batch (the Inlines of a checked scene;
    /// not those of a file only followed to look for cycles).
    pub fn in_tree(doc: &Document, base: Option<&Path>, tree: &Tree, checked: bool) -> Inlines {
        let resolver = Resolver::new(base, Some(&tree.root));
        let mut by_node = HashMap::new();
        for (id, node) in doc.iter() {
            if !node.is_a("Inline") {
                continue;
            }
            let Some(urls) = node.value("url").and_then(|v| v.as_strings()) else {
                continue;
            };
            if urls.is_empty() {
                continue;
            }
            by_node.insert(id, target(urls, &resolver, tree, checked));
        }
        Inlines { by_node }
    }

    /// What Inline `node` loads; None for another node, one without url, or below the
    /// deep level.
    pub fn get(&self, node: NodeId) -> Option<&InlineTarget> {
        self.by_node.get(&node)
    }

    /// Every Inline with what it loads, in document order.
    pub fn iter(&self) -> Vec<(NodeId, &InlineTarget)> {
        let mut all: Vec<(NodeId, &InlineTarget)> =
            self.by_node.iter().map(|(id, t)| (*id, t)).collect();
        all.sort_by_key(|(id, _)| *id);
        all
    }
}

fn target(urls: &[String], resolver: &Resolver, tree: &Tree, checked: bool) -> InlineTarget {
    let mut unreached = None;
    for url in urls {
        match resolver.resolve(url) {
            Resolution::Local(path) => {
                let library = if checked {
                    tree.libraries.get_inlined(&path, &tree.root, tree.keep)
                } else {
                    tree.libraries.get(&path, tree.keep)
                };
                return InlineTarget::Loaded {
                    library,
                    url: url.clone(),
                };
            }
            Resolution::Network(_) => {
                unreached.get_or_insert(Unreached::Network(url.clone()));
            }
            Resolution::Outside(_) => {
                unreached.get_or_insert(Unreached::Outside(url.clone()));
            }
            Resolution::NoBase => {
                unreached.get_or_insert(Unreached::NoBase);
            }
            Resolution::Inline => {
                unreached.get_or_insert(Unreached::Data);
            }
            Resolution::Missing { .. } => {}
        }
    }
    InlineTarget::Unreached(unreached)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Level;

    #[test]
    fn the_first_local_file_is_loaded_and_read_once() {
        let dir = std::env::temp_dir().join(format!("x3dcheck-inlines-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("child.x3d"),
            "<X3D version='4.0'><Scene><Group DEF='G'/><EXPORT localDEF='G'/></Scene></X3D>",
        )
        .unwrap();
        let main = "<X3D version='4.0'><Scene>\
             <Inline DEF='A' url='\"missing.x3d\" \"child.x3d\"'/>\
             <Inline DEF='B' url='\"child.x3d\"' load='false'/>\
             <Inline DEF='C' url='\"https://example.com/c.x3d\" \"gone.x3d\"'/>\
             <Inline DEF='D' url='\"gone.x3d\"'/>\
             </Scene></X3D>";
        let doc = crate::parse::read(main.as_bytes()).document.unwrap();
        let config = CheckConfig {
            level: Level::Deep,
            ..CheckConfig::default()
        };
        let inlines = Inlines::resolve(&doc, Some(&dir.join("main.x3d")), &config);
        let loaded: Vec<bool> = inlines
            .iter()
            .iter()
            .map(|(_, t)| matches!(t, InlineTarget::Loaded { .. }))
            .collect();
        assert_eq!(loaded, [true, true, false, false]);
        assert!(matches!(
            inlines.iter()[2].1,
            InlineTarget::Unreached(Some(Unreached::Network(_)))
        ));
        assert!(matches!(inlines.iter()[3].1, InlineTarget::Unreached(None)));
        assert_eq!(config.libraries.len(), 1, "one file, read once");
        assert_eq!(config.libraries.inlined().len(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
