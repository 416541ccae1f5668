//! BACK_MATERIAL_NO_EFFECT: backMaterial on a Shape whose back faces are never drawn.

use super::analysis::{back_material, shape_pairs};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports, per Shape, an Appearance with a `backMaterial` whose geometry never shows
    /// back faces:
    /// - a geometry with `solid TRUE` (the default): "when the solid is TRUE, the value of
    ///   backMaterial has no effect on rendering";
    /// - a geometry with no `solid` field (LineSet, IndexedLineSet, PointSet, Arc2D,
    ///   Circle2D, Polyline2D, Polypoint2D, NurbsCurve): these are lines and points, which
    ///   have no faces, so there is no back side for the backMaterial to apply to.
    ///
    /// One Appearance may serve several geometries, so each Appearance × geometry pair is
    /// judged on its own and reported at the first Shape forming it; a `solid` connected
    /// by `IS` is not judged.
    ///
    /// ## Why it matters
    /// The back material is dead weight for that Shape, and usually a sign that the author
    /// forgot `solid='false'`.
    ///
    /// ## Example
    /// ```xml
    /// <Shape>
    ///   <Appearance><Material/><Material containerField='backMaterial'/></Appearance>
    ///   <Box/>
    /// </Shape>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.2.3 Two-sided materials; 11.2.3 Common geometry fields (solid).
    pub static BACK_MATERIAL_NO_EFFECT = {
        severity: Info,
        level: Standard,
        clause: "12.2.3",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    let doc = ctx.doc;
    for pair in shape_pairs(doc) {
        let Some(back) = pair
            .appearance
            .and_then(|a| back_material(doc, doc.node(a)))
        else {
            continue;
        };
        let geometry = doc.node(pair.geometry);
        let Some(def) = geometry.def() else {
            continue;
        };
        let (span, message) = if def.field("solid").is_some() {
            if geometry.is_connected("solid") || doc.bool_of(pair.geometry, "solid") != Some(true) {
                continue;
            }
            let explicit = geometry.entry("solid");
            (
                explicit.map_or(pair.geometry_ref.span, |e| e.span),
                format!(
                    "backMaterial has no effect on this Shape: its {} is solid{}, so back faces are never drawn",
                    def.name,
                    if explicit.is_some() { "" } else { " (the default)" }
                ),
            )
        } else {
            (
                pair.geometry_ref.span,
                format!(
                    "backMaterial has no effect on this Shape: a {} is lines or points, with no faces",
                    def.name
                ),
            )
        };
        ctx.report(
            Diagnostic::new(&BACK_MATERIAL_NO_EFFECT, span, message)
                .node(pair.shape)
                .related(back.span, "the backMaterial"),
        );
    }
}
