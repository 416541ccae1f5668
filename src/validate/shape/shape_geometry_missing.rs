//! SHAPE_GEOMETRY_MISSING: a Shape without geometry.

use crate::diagnostic::{Diagnostic, Span};
use crate::model::{Document, Node};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Shape (any X3DShapeNode but ParticleSystem, whose geometry field is used
    /// only with geometryType "GEOMETRY") whose `geometry` is NULL. Not reported when the
    /// geometry comes from outside the document's static content: a field connected by
    /// `IS` in a ProtoBody, or a ROUTE to the Shape's `geometry`/`set_geometry`; nor when
    /// the Shape holds a node of unknown type or a prototype instance, which may be the
    /// geometry under another name (an xj3d `Face`), or, on a web page, one of the
    /// library's own nodes (X3DOM's `<plane>`, reported as X3DOM_EXTENSION).
    ///
    /// ## Why it matters
    /// 12.4.8: "If the geometry field is NULL, the object is not drawn." Usually the
    /// geometry was misplaced or its containerField is wrong.
    ///
    /// ## Example
    /// ```xml
    /// <Shape><Appearance><Material/></Appearance></Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.8 Shape.
    pub static SHAPE_GEOMETRY_MISSING = {
        severity: Info,
        level: Standard,
        clause: "12.4.8",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !node.is_a("X3DShapeNode")
            || node.is_a("ParticleSystem")
            || !node.children("geometry").is_empty()
            || node.is_connected("geometry")
        {
            continue;
        }
        let opaque_child = node.fields.iter().any(|e| {
            e.schema_def().is_none()
                || e.value
                    .as_nodes()
                    .is_some_and(|nodes| nodes.iter().any(|c| doc.node(c.node).def().is_none()))
        });
        if opaque_child || holds_library_node(doc, node) {
            continue;
        }
        let routed = node.def_name.as_ref().is_some_and(|def| {
            doc.routes.iter().any(|r| {
                r.scope == node.scope
                    && r.to_node.text == def.text
                    && matches!(r.to_field.text.as_str(), "geometry" | "set_geometry")
            })
        });
        if !routed {
            found.push((id, node.name_span, node.type_name().to_string()));
        }
    }
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &SHAPE_GEOMETRY_MISSING,
                span,
                format!("{type_name} has no geometry and is not drawn"),
            )
            .node(id),
        );
    }
}

/// Whether one of the page library's own nodes, left out by the reader, lies in `shape`
/// outside its other children (so it may be the geometry: X3DOM's `<plane>`).
fn holds_library_node(doc: &Document, shape: &Node) -> bool {
    let within = |inner: Span, outer: Span| outer.start <= inner.start && inner.end <= outer.end;
    doc.library_nodes.iter().any(|&element| {
        within(element, shape.span)
            && !shape.fields.iter().any(|e| {
                e.value.as_nodes().is_some_and(|nodes| {
                    nodes.iter().any(|c| within(element, doc.node(c.node).span))
                })
            })
    })
}
