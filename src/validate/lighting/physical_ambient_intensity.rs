//! PHYSICAL_AMBIENT_INTENSITY: ambientIntensity in a scene lit only physically.

use crate::diagnostic::Diagnostic;
use crate::model::{Document, NodeId};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a light with `ambientIntensity` > 0 in a scene whose lit shapes all use
    /// PhysicalMaterial, so that no shape uses the Phong model (Material or
    /// TwoSidedMaterial) where ambient light counts. Unlit shapes do not count: no
    /// material, UnlitMaterial, line and point geometry (17.2.2.4), and shapes whose
    /// Appearance has shaders (17.2: the shader replaces the lighting model).
    ///
    /// Nothing is reported when the scene has no lit shape, or when part of it cannot be
    /// seen: an Inline, an ExternProtoDeclare, or a material or appearance that is a
    /// ProtoInstance or of an unknown type.
    ///
    /// ## Why it matters
    /// 17.2.1: "In the physical lighting model, the ambientIntensity value is unused. Future
    /// specification versions may introduce a use for it, therefore we recommend leaving it
    /// at 0 (default) in case of physical rendering, to avoid future changes."
    ///
    /// ## Example
    /// ```xml
    /// <PointLight ambientIntensity='0.3'/>
    /// <Shape><Appearance><PhysicalMaterial/></Appearance><Sphere/></Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 17.2.1 Light source semantics.
    pub static PHYSICAL_AMBIENT_INTENSITY = {
        severity: Hint,
        level: Standard,
        clause: "17.2.1",
        versions: "4.x",
        check: Some(check),
    }
}

/// How a shape is lit, as far as this rule cares.
#[derive(PartialEq)]
enum Lighting {
    Unlit,
    Phong,
    Physical,
    Unknown,
}

/// Geometry that represents lines or points, which is not lit (17.2, NOTE).
const LINE_AND_POINT_GEOMETRY: &[&str] = &[
    "IndexedLineSet",
    "LineSet",
    "PointSet",
    "Polyline2D",
    "Polypoint2D",
    "Arc2D",
    "Circle2D",
];

fn lighting(doc: &Document, shape: NodeId) -> Lighting {
    let node = doc.node(shape);
    if node.is_connected("appearance") || node.is_connected("geometry") {
        return Lighting::Unknown;
    }
    if node
        .child("geometry")
        .is_some_and(|g| LINE_AND_POINT_GEOMETRY.contains(&doc.node(g).type_name()))
    {
        return Lighting::Unlit;
    }
    let Some(appearance) = node.child("appearance") else {
        return Lighting::Unlit;
    };
    let appearance = doc.node(appearance);
    if appearance.def().is_none() || appearance.is_connected("material") {
        return Lighting::Unknown;
    }
    if !appearance.children("shaders").is_empty() {
        return Lighting::Unlit;
    }
    let Some(material) = appearance.child("material") else {
        return Lighting::Unlit;
    };
    match doc.node(material).type_name() {
        "UnlitMaterial" => Lighting::Unlit,
        "Material" | "TwoSidedMaterial" => Lighting::Phong,
        "PhysicalMaterial" => Lighting::Physical,
        _ => Lighting::Unknown,
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let doc = ctx.doc;
    if doc.protos.iter().any(|p| p.external) || doc.nodes_of_type("Inline").next().is_some() {
        return;
    }
    let mut physical = false;
    for (id, node) in doc.iter() {
        if !node.is_a("X3DShapeNode") {
            continue;
        }
        match lighting(doc, id) {
            Lighting::Physical => physical = true,
            Lighting::Unlit => {}
            Lighting::Phong | Lighting::Unknown => return,
        }
    }
    if !physical {
        return;
    }
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !node.is_a("X3DLightNode") || node.is_connected("ambientIntensity") {
            continue;
        }
        let Some(entry) = node.entry("ambientIntensity") else {
            continue;
        };
        if entry
            .value
            .as_floats()
            .and_then(|v| v.first())
            .is_some_and(|a| *a > 0.0)
        {
            found.push((id, entry.span, node.type_name().to_string()));
        }
    }
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &PHYSICAL_AMBIENT_INTENSITY,
                span,
                format!(
                    "{type_name}.ambientIntensity is unused: every lit shape of the scene uses PhysicalMaterial"
                ),
            )
            .node(id)
            .help("leave ambientIntensity at 0 for physical rendering (17.2.1)"),
        );
    }
}
