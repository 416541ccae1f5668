//! IMPORT statements resolved (deep level): the node of the inlined file each one names.
//!
//! 19775-1 4.9.2: `IMPORT inlineDEF.importedDEF AS name` names an Inline DEF'd in the
//! statement's name scope and a name its file EXPORTs (its `AS`, else its `localDEF`,
//! 4.9.3); the imported node takes the name `AS`, else `importedDEF`, in the importing
//! scope, where ROUTEs may name it. IMPORT_INLINE_UNDEFINED reports the statements that
//! name no Inline (at every level, through [`named_inline`]), IMPORT_UNRESOLVED those
//! that name no export; the ROUTE rules check ROUTEs to and from the nodes found.

use std::sync::Arc;

use super::inlines::{InlineTarget, Inlines, Unreached};
use crate::library::Library;
use crate::model::{Document, Import, NodeId, Scope};

/// What one IMPORT statement leads to.
#[derive(Clone, Debug)]
pub enum ImportTarget {
    /// The exported node, in the inlined file.
    Node { library: Arc<Library>, node: NodeId },
    /// The inlineDEF names no node of the scope, or one that is no Inline: what it names.
    NoInline(Option<String>),
    /// The inlined file exports no such name: the names it exports.
    NotExported {
        library: Arc<Library>,
        exported: Vec<String>,
    },
    /// The inlined file exports the name, but its localDEF names no node there (that
    /// file's EXPORT_UNDEFINED).
    ExportUndefined,
    /// The Inline's file is not read: why (None: its local files are missing).
    Unread(Option<Unreached>),
    /// The Inline's file is read but is no scene x3dcheck reads.
    NotScene { library: Arc<Library> },
}

/// What each IMPORT of a document leads to, by statement (empty below the deep level).
#[derive(Clone, Debug, Default)]
pub struct Imports {
    by_statement: Vec<ImportTarget>,
}

impl Imports {
    pub fn resolve(doc: &Document, inlines: &Inlines) -> Imports {
        let by_statement = doc
            .imports
            .iter()
            .map(|import| resolve(doc, inlines, import))
            .collect();
        Imports { by_statement }
    }

    /// What the `index`-th IMPORT of the document leads to.
    pub fn get(&self, index: usize) -> Option<&ImportTarget> {
        self.by_statement.get(index)
    }

    /// The node `name` stands for in `scope` through an IMPORT of `doc`: the inlined
    /// file's document and the node in it.
    pub fn node<'a>(
        &'a self,
        doc: &Document,
        scope: Scope,
        name: &str,
    ) -> Option<(&'a Library, &'a Document, NodeId)> {
        let index = doc
            .imports
            .iter()
            .position(|i| i.scope == scope && i.local_name().text == name)?;
        match self.by_statement.get(index)? {
            ImportTarget::Node { library, node } => {
                Some((library, library.document.as_ref()?, *node))
            }
            _ => None,
        }
    }
}

/// The Inline an IMPORT's `inlineDEF` names in the statement's scope; else what the name
/// names instead (None: no node of the scope), as [`ImportTarget::NoInline`] holds it.
/// Decided within this file, at every level.
pub fn named_inline(doc: &Document, import: &Import) -> Result<NodeId, Option<String>> {
    let named = doc
        .defs
        .get(&(import.scope, import.inline_def.text.clone()))
        .copied();
    match named {
        Some(id) if doc.node(id).is_a("Inline") => Ok(id),
        _ => Err(named.map(|id| doc.node(id).type_name().to_string())),
    }
}

fn resolve(doc: &Document, inlines: &Inlines, import: &Import) -> ImportTarget {
    let inline = match named_inline(doc, import) {
        Ok(inline) => inline,
        Err(named) => return ImportTarget::NoInline(named),
    };
    let library = match inlines.get(inline) {
        Some(InlineTarget::Loaded { library, .. }) => library,
        Some(InlineTarget::Unreached(why)) => return ImportTarget::Unread(why.clone()),
        None => return ImportTarget::Unread(None),
    };
    let Some(inlined) = &library.document else {
        return ImportTarget::NotScene {
            library: library.clone(),
        };
    };
    let exports = || inlined.exports.iter().filter(|e| e.scope == Scope::Scene);
    let Some(export) = exports().find(|e| e.exported_name().text == import.imported_def.text)
    else {
        return ImportTarget::NotExported {
            library: library.clone(),
            exported: exports().map(|e| e.exported_name().text.clone()).collect(),
        };
    };
    match inlined
        .defs
        .get(&(Scope::Scene, export.local_def.text.clone()))
    {
        Some(&node) => ImportTarget::Node {
            library: library.clone(),
            node,
        },
        None => ImportTarget::ExportUndefined,
    }
}
