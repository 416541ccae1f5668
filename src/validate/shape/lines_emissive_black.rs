//! LINES_EMISSIVE_BLACK: lines or points drawn black by a Material's emissiveColor.

use super::analysis::shape_pairs;
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::Ctx;

/// The geometries 11.4 colours with the Material's emissiveColor when they have no Color.
const LINE_AND_POINT_SETS: &[&str] = &["LineSet", "IndexedLineSet", "PointSet"];

crate::declare_rule! {
    /// ## What it does
    /// Reports, per Shape, a LineSet, IndexedLineSet or PointSet without a `color` node whose
    /// Appearance has a Material with a black `emissiveColor` (the default 0 0 0) and a
    /// `diffuseColor` that is not black (a black diffuseColor says black was meant). Not
    /// reported when the geometry has normals in X3D 4.x (17.2.2: "Geometry nodes that
    /// represent lines or points do not support lighting if the normal vectors for them
    /// are not provided", so with normals they are lit), or the Appearance has `shaders`
    /// or a `texture` (point sprites, 12.4.7), or a field involved is connected by `IS` or
    /// is the destination of a ROUTE (the scene sets the colour at run time).
    ///
    /// ## Why it matters
    /// 11.4: "If the color field is NULL and there is a Material defined for the Appearance
    /// affecting this LineSet, the emissiveColor of the Material shall be used to draw the
    /// lines": lines and points are not lit, so setting only diffuseColor draws them black,
    /// invisible on a dark background.
    ///
    /// ## Example
    /// ```xml
    /// <Shape>
    ///   <Appearance><Material diffuseColor='1 0 0'/></Appearance>
    ///   <LineSet vertexCount='2'><Coordinate point='0 0 0 1 0 0'/></LineSet>
    /// </Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.4 Node reference (IndexedLineSet, LineSet, PointSet); 17.2.2.
    pub static LINES_EMISSIVE_BLACK = {
        severity: Hint,
        level: Standard,
        clause: "11.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let changed = |id, field| set_elsewhere(doc, &routed, id, field);
    let mut found = Vec::new();
    for pair in shape_pairs(doc) {
        let geometry = doc.node(pair.geometry);
        let Some(appearance) = pair.appearance.map(|a| doc.node(a)) else {
            continue;
        };
        if !LINE_AND_POINT_SETS.contains(&geometry.type_name())
            || geometry.child("color").is_some()
            || changed(pair.geometry, "color")
            || (ctx.version.is_4x()
                && (geometry.child("normal").is_some() || changed(pair.geometry, "normal")))
            || !appearance.children("shaders").is_empty()
            || appearance.child("texture").is_some()
        {
            continue;
        }
        let Some(&material) = appearance.children("material").first() else {
            continue;
        };
        let m = doc.node(material.node);
        if !m.is_a("Material") || changed(material.node, "emissiveColor") {
            continue;
        }
        let black = |field: &str| {
            doc.value_of(material.node, field)
                .and_then(|v| {
                    v.as_floats()
                        .map(|c| c.len() == 3 && c.iter().all(|&x| x == 0.0))
                })
                .unwrap_or(false)
        };
        if black("emissiveColor")
            && !black("diffuseColor")
            && !changed(material.node, "diffuseColor")
        {
            found.push((
                pair.shape,
                pair.geometry_ref.span,
                material.span,
                geometry.type_name().to_string(),
            ));
        }
    }
    for (shape, span, material, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &LINES_EMISSIVE_BLACK,
                span,
                format!("this {type_name} is drawn black: it has no Color and its Material's emissiveColor is black"),
            )
            .node(shape)
            .related(material, "the Material")
            .help("lines and points are unlit: set the Material's emissiveColor, or give the geometry a Color"),
        );
    }
}
