//! VIEWPOINT_ORIENTATION_AXIS_ZERO: a viewpoint whose orientation has no rotation axis.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Viewpoint, OrthoViewpoint or GeoViewpoint (every X3DViewpointNode) whose
    /// `orientation` has the axis `0 0 0` (either zero counts, -0 included), whatever
    /// its angle. An orientation passed in through `IS` is left alone.
    ///
    /// ## Why it matters
    /// An SFRotation's first three values are the normalized axis the rotation turns
    /// about (5.3, SFRotation); a zero vector has no direction and cannot be
    /// normalized. Browsers then look along the default direction, produce NaN view
    /// matrices (a blank view), or reject the value, and the author's intended view is
    /// lost. It is usually a typo for `0 1 0` or `0 0 1`.
    ///
    /// ## Example
    /// ```xml
    /// <Viewpoint orientation='0 0 0 1.57'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Viewpoint orientation='0 1 0 1.57'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 23.3.1 X3DViewpointNode (`orientation`, a rotation relative to the default
    /// orientation), 5.3 SFRotation ("The first three values specify a normalized
    /// rotation axis vector"). Reading: an axis that cannot be normalized is no
    /// SFRotation value even with angle 0, so `0 0 0 0` is reported too (write
    /// `0 0 1 0`, the default, or leave the field out).
    /// A warning, not an error (issue 32): "normalized rotation axis vector" describes the
    /// value without a "shall", and the interface table gives `orientation` the range
    /// `[-1,1],(-∞,∞)`, which `0 0 0` is inside; browsers normalize any other axis, and
    /// what they do with a zero one is left undefined.
    pub static VIEWPOINT_ORIENTATION_AXIS_ZERO = {
        severity: Warning,
        level: Standard,
        clause: "23.3.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let mut found = Vec::new();
    for (id, node) in ctx.doc.iter() {
        if !is_viewpoint(node) || node.is_connected("orientation") {
            continue;
        }
        let Some(entry) = node.entry("orientation") else {
            continue;
        };
        let Some(rotation) = entry.value.as_floats() else {
            continue;
        };
        if rotation.len() == 4 && rotation[..3].iter().all(|c| *c == 0.0) {
            found.push((id, entry.span, node.type_name()));
        }
    }
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &VIEWPOINT_ORIENTATION_AXIS_ZERO,
                span,
                format!("{type_name}.orientation has the axis 0 0 0: a rotation needs an axis to turn about"),
            )
            .node(id)
            .help("give the axis the view turns about, e.g. `0 1 0` to turn left or right; `0 0 1 0` (the default) for no rotation"),
        );
    }
}

/// An X3DViewpointNode. The 3.0 and 3.1 object models list no such type among
/// Viewpoint's ancestors, so the node types are named as well.
fn is_viewpoint(node: &crate::model::Node) -> bool {
    node.is_a("X3DViewpointNode")
        || matches!(
            node.type_name(),
            "Viewpoint" | "OrthoViewpoint" | "GeoViewpoint"
        )
}
