//! TEXTURE_PROJECTOR_DIRECTION_ZERO: a texture projector pointing nowhere.

use crate::diagnostic::Diagnostic;
use crate::validate::lighting::{all_zero, lights_setting};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a TextureProjector or TextureProjectorParallel whose `direction` is
    /// `0 0 0` (either zero counts, -0 included). A `direction` that takes its value
    /// through `IS` is left alone.
    ///
    /// ## Why it matters
    /// The direction is the axis the texture is projected along, as a light's direction
    /// is the axis it shines along (17.4.1); a zero vector gives no axis, and browsers
    /// project nothing, project along an arbitrary axis, or produce NaN texture
    /// coordinates.
    ///
    /// ## Example
    /// ```xml
    /// <TextureProjector direction='0 0 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 42.3.1 X3DTextureProjectorNode (4.0), with 42.4.1 TextureProjector and
    /// 42.4.2 TextureProjectorParallel: `direction` specifies the direction of the
    /// projection. A warning, not an error, as LIGHT_DIRECTION_ZERO: the field's range is
    /// `(-∞,∞)` and no sentence forbids the zero vector; what it projects is left
    /// undefined.
    pub static TEXTURE_PROJECTOR_DIRECTION_ZERO = {
        severity: Warning,
        level: Standard,
        clause: "42.3.1",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let found = lights_setting(
        ctx.doc,
        |node| {
            matches!(
                node.type_name(),
                "TextureProjector" | "TextureProjectorParallel"
            )
        },
        "direction",
        all_zero,
    );
    for (id, span, type_name) in found {
        ctx.report(
            Diagnostic::new(
                &TEXTURE_PROJECTOR_DIRECTION_ZERO,
                span,
                format!("{type_name}.direction is 0 0 0: the projector has no direction"),
            )
            .node(id)
            .help("give the direction the texture is projected in, e.g. `0 0 1` (the default)"),
        );
    }
}
