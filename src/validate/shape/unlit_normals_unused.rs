//! UNLIT_NORMALS_UNUSED: normals or a normalTexture that no lit Shape uses.

use std::collections::HashMap;

use crate::diagnostic::Diagnostic;
use crate::model::texture_mapping::texture_coordinates;
use crate::model::{ChildRef, Document, Node, NodeId};
use crate::validate::Ctx;

/// TextureCoordinateGenerator modes computed from normals (18.4.8 Table 18.6): the two
/// 12.4.10 names, and the sphere modes, which also read the vertex normals.
const NORMAL_MODES: &[&str] = &[
    "CAMERASPACENORMAL",
    "CAMERASPACEREFLECTIONVECTOR",
    "SPHERE",
    "SPHERE-LOCAL",
    "SPHERE-REFLECT",
    "SPHERE-REFLECT-LOCAL",
];

crate::declare_rule! {
    /// ## What it does
    /// Reports normals that nothing uses because every Shape they reach is unlit:
    /// - a geometry's `normal` node, when every Shape using that geometry is unlit;
    /// - an UnlitMaterial's `normalTexture`, when every Shape using that material is unlit.
    ///
    /// A Shape is unlit when it has no Appearance, or its Appearance's material is NULL or
    /// an UnlitMaterial (and backMaterial NULL or an UnlitMaterial). It still needs normals,
    /// and so counts as using them, when its Appearance has `shaders`, or its geometry's
    /// list of texture coordinates holds a TextureCoordinateGenerator whose mode reads
    /// normals (CAMERASPACENORMAL, CAMERASPACEREFLECTIONVECTOR, as 12.4.10 names, and the
    /// SPHERE modes, which Table 18.6 also defines from normals), or anything about it is
    /// not known from the document (prototype instances, `IS`). Nodes that no Shape uses
    /// are not judged.
    ///
    /// ## Why it matters
    /// 12.4.10: "Normal vectors information is not useful for the calculation of unlit
    /// material. Implementations can ignore the normal vectors provided in the geometry
    /// node … and in the normalTexture field." The data costs file size and loading time
    /// for nothing, or the author expected lighting that does not happen.
    ///
    /// ## Example
    /// ```xml
    /// <Shape>
    ///   <Appearance><UnlitMaterial/></Appearance>
    ///   <IndexedFaceSet coordIndex='0 1 2'>
    ///     <Coordinate point='0 0 0 1 0 0 0 1 0'/>
    ///     <Normal vector='0 0 1'/>
    ///   </IndexedFaceSet>
    /// </Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.10 UnlitMaterial; 17.2.2.4 Unlit lighting model.
    pub static UNLIT_NORMALS_UNUSED = {
        severity: Hint,
        level: Standard,
        clause: "12.4.10",
        versions: "4.x",
        check: Some(check),
    }
}

/// Whether any Shape using a node may read normals, in first-use order.
#[derive(Default)]
struct Uses {
    order: Vec<NodeId>,
    needed: HashMap<NodeId, bool>,
}

impl Uses {
    fn add(&mut self, node: NodeId, needs_normals: bool) {
        let entry = self.needed.entry(node).or_insert_with(|| {
            self.order.push(node);
            false
        });
        *entry |= needs_normals;
    }

    fn unused(&self) -> impl Iterator<Item = NodeId> + '_ {
        self.order.iter().copied().filter(|n| !self.needed[n])
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let doc = ctx.doc;
    let (mut geometries, mut materials) = (Uses::default(), Uses::default());
    for (_, shape) in doc.iter().filter(|(_, n)| n.is_a("X3DShapeNode")) {
        let Some(&geometry) = shape.children("geometry").first() else {
            continue;
        };
        let needs = needs_normals(doc, shape, geometry.node);
        geometries.add(geometry.node, needs);
        if let Some(appearance) = shape.child("appearance") {
            for field in ["material", "backMaterial"] {
                if let Some(m) = doc.node(appearance).child(field) {
                    materials.add(m, needs);
                }
            }
        }
    }
    let mut found: Vec<(NodeId, ChildRef, String)> = Vec::new();
    for g in geometries.unused() {
        let node = doc.node(g);
        if let Some(&normal) = node.children("normal").first() {
            found.push((
                g,
                normal,
                format!(
                    "the normals of this {} are unused: every Shape using it is unlit",
                    node.type_name()
                ),
            ));
        }
    }
    for m in materials.unused() {
        let node = doc.node(m);
        if !node.is_a("UnlitMaterial") {
            continue;
        }
        if let Some(&texture) = node.children("normalTexture").first() {
            found.push((
                m,
                texture,
                "UnlitMaterial.normalTexture is unused: unlit shading reads no normals".to_string(),
            ));
        }
    }
    for (node, child, message) in found {
        ctx.report(
            Diagnostic::new(&UNLIT_NORMALS_UNUSED, child.span, message)
                .node(node)
                .help("remove it, or use a lit material (Material, PhysicalMaterial)"),
        );
    }
}

/// Whether a Shape may read normals: lit, shaded, generating texture coordinates from
/// normals, or not fully known from the document.
fn needs_normals(doc: &Document, shape: &Node, geometry: NodeId) -> bool {
    if shape.is_connected("appearance") || shape.is_connected("geometry") {
        return true;
    }
    if let Some(appearance) = shape.child("appearance") {
        let a = doc.node(appearance);
        if a.def().is_none() || !a.connects.is_empty() || !a.children("shaders").is_empty() {
            return true;
        }
        let lit = ["material", "backMaterial"].iter().any(|field| {
            a.child(field).is_some_and(|m| {
                !doc.node(m).is_a("UnlitMaterial") || !doc.node(m).connects.is_empty()
            })
        });
        if lit {
            return true;
        }
    }
    let list = texture_coordinates(doc, geometry);
    list.opaque
        || list.items.iter().any(|c| {
            let generator = doc.node(c.node);
            generator.is_a("TextureCoordinateGenerator")
                && (generator.is_connected("mode")
                    || doc
                        .string_of(c.node, "mode")
                        .is_some_and(|m| NORMAL_MODES.contains(&m.as_str())))
        })
}
