//! A document being made and the findings made on the way, each limit of
//! [`crate::limits`] reported once: what the [`Builder`](super::Builder) writes while a
//! reader reads, and what instantiating prototypes (`model::instantiate`) writes after.

use super::rules::LIMIT_EXCEEDED;
use super::{Document, Encoding, FieldRef, NodeId, NodeKind, Span};
use crate::diagnostic::Diagnostic;
use crate::limits::MAX_DIAGNOSTICS;
use crate::schema::{self, Version};

/// A limit of [`crate::limits`] that building a document enforces.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Limit {
    Depth,
    Nodes,
    FieldsPerNode,
    FieldValues,
    Diagnostics,
    /// Found by the XML reader: entities declared in the DOCTYPE expand too far.
    EntityExpansion,
    /// Instantiating prototypes copies too much or nests too deep.
    Instances,
}

pub struct Draft {
    pub(super) doc: Document,
    diagnostics: Vec<Diagnostic>,
    /// The limits already reported: each is reported once per document.
    reported: Vec<Limit>,
}

impl Draft {
    pub fn new(encoding: Encoding) -> Draft {
        Draft::of(Document::new(encoding))
    }

    /// A finished document, to instantiate its prototypes again (with external
    /// prototypes resolved).
    pub fn of(doc: Document) -> Draft {
        Draft {
            doc,
            diagnostics: Vec::new(),
            reported: Vec::new(),
        }
    }

    pub fn doc(&self) -> &Document {
        &self.doc
    }

    pub fn doc_mut(&mut self) -> &mut Document {
        &mut self.doc
    }

    /// Keeps a finding; past [`MAX_DIAGNOSTICS`] they are dropped (and that is reported).
    pub fn report(&mut self, diagnostic: Diagnostic) {
        if self.diagnostics.len() < MAX_DIAGNOSTICS {
            self.diagnostics.push(diagnostic);
        } else {
            let message = format!(
                "more than {MAX_DIAGNOSTICS} findings while reading this document; the rest are not reported"
            );
            self.exceeded(Limit::Diagnostics, diagnostic.span, message);
        }
    }

    /// Reports a limit of [`crate::limits`] at `span`, once per document and kind.
    pub fn exceeded(&mut self, limit: Limit, span: Span, message: String) {
        if !self.reported.contains(&limit) {
            self.reported.push(limit);
            self.diagnostics
                .push(Diagnostic::new(&LIMIT_EXCEEDED, span, message));
        }
    }

    /// The version whose schema applies (set the document's version first).
    pub fn version(&self) -> Version {
        self.doc.schema_version()
    }
    /// What a node type name means: the document version's type, another version's, or none.
    pub fn node_kind(&self, name: &str) -> NodeKind {
        let version = self.version();
        if let Some(def) = schema::schema(version).node(name) {
            return NodeKind::Known { def, version };
        }
        // Newest first, so that a 3.x document using a 4.x node gets the 4.x definition.
        for other in Version::ALL.into_iter().rev() {
            if let Some(def) = schema::schema(other).node(name) {
                return NodeKind::Known {
                    def,
                    version: other,
                };
            }
        }
        NodeKind::Unknown {
            name: name.to_string(),
        }
    }

    /// What a field name means on a node: a field the node declares itself (Script,
    /// shaders), its type's field in the document's version, the same type's field in
    /// another version, a field declared by its ProtoDeclare, or none.
    pub fn field_ref(&self, node: NodeId, name: &str) -> FieldRef {
        let declared = &self.doc.node(node).declared;
        if let Some(decl) = declared.iter().find(|d| d.name.text == name) {
            return FieldRef::Declared {
                name: name.to_string(),
                ty: decl.ty,
            };
        }
        match &self.doc.node(node).kind {
            NodeKind::Known { def, .. } => {
                let version = self.version();
                let in_version = schema::schema(version).node(def.name);
                if let Some(field) = in_version.and_then(|d| d.field(name)) {
                    return FieldRef::Schema {
                        def: field,
                        version,
                    };
                }
                for other in Version::ALL.into_iter().rev() {
                    let node_def = schema::schema(other).node(def.name);
                    if let Some(field) = node_def.and_then(|d| d.field(name)) {
                        return FieldRef::Schema {
                            def: field,
                            version: other,
                        };
                    }
                }
            }
            NodeKind::ProtoInstance { proto, .. } => {
                let declared = proto.and_then(|p| {
                    self.doc.protos[p]
                        .interface
                        .iter()
                        .find(|f| f.name.text == name)
                });
                return FieldRef::Declared {
                    name: name.to_string(),
                    ty: declared.and_then(|f| f.ty),
                };
            }
            NodeKind::Unknown { .. } => {}
        }
        FieldRef::Unknown {
            name: name.to_string(),
        }
    }
    /// The document and the findings, with nothing more done.
    pub fn into_parts(self) -> (Document, Vec<Diagnostic>) {
        (self.doc, self.diagnostics)
    }
}
