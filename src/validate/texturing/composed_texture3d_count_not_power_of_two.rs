//! COMPOSED_TEXTURE3D_COUNT_NOT_POWER_OF_TWO: a ComposedTexture3D whose slices are not
//! 2^n textures.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ComposedTexture3D whose `texture` field holds a number of textures that
    /// is not a power of two (3, 5, 6, 7, 9, …). An empty `texture` (the default) is left
    /// alone, and so is one that takes its value through `IS` or that a ROUTE changes.
    ///
    /// ## Why it matters
    /// Each texture is one depth slice of the volume, the first at depth 0, and the
    /// slices are stacked along R into one 3D texture. The clause asks for 2^n of them,
    /// the depth a 3D texture of commodity hardware takes; with another count a browser
    /// may resample the stack, drop slices or refuse the texture, so the depth the author
    /// built is not what is shown.
    ///
    /// ## Example
    /// ```xml
    /// <ComposedTexture3D>
    ///   <ImageTexture url='"slice0.png"'/>
    ///   <ImageTexture url='"slice1.png"'/>
    ///   <ImageTexture url='"slice2.png"'/>
    /// </ComposedTexture3D>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ComposedTexture3D>
    ///   <ImageTexture url='"slice0.png"'/>
    ///   <ImageTexture url='"slice1.png"'/>
    ///   <ImageTexture url='"slice2.png"'/>
    ///   <ImageTexture url='"slice3.png"'/>
    /// </ComposedTexture3D>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 33.4.1 ComposedTexture3D: "The texture values are interpreted with the
    /// first image being at depth 0 and each following image representing an increasing
    /// depth value in the R direction. A user shall provide 2^n source textures in this
    /// array." Read in the 3.x text as H3D API's `Composed3DTexture.h` and x3dom's
    /// ComposedTexture3D source copy it, and on the web3d.org wiki's Composed3DTexture
    /// page; the 4.0 page itself was not read (docs/traceability.md). An error: the
    /// sentence says "shall". Reading: 2^0 = 1 is a power of two, so one texture is
    /// allowed; no texture is the field's default, not a count the user provided.
    /// > "A user shall provide 2^n source textures in this array." (19775-1 33.4.1)
    pub static COMPOSED_TEXTURE3D_COUNT_NOT_POWER_OF_TWO = {
        severity: Error,
        level: Standard,
        clause: "33.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("ComposedTexture3D") {
        if any_set_elsewhere(doc, &routed, id, &["texture"]) {
            continue;
        }
        let Some(entry) = doc.node(id).entry("texture") else {
            continue;
        };
        let count = doc.node(id).children("texture").len();
        if count == 0 || count.is_power_of_two() {
            continue;
        }
        found.push((id, entry.span, count));
    }
    for (id, span, count) in found {
        let fewer = 1usize << (usize::BITS - 1 - count.leading_zeros());
        let more = fewer * 2;
        ctx.report(
            Diagnostic::new(
                &COMPOSED_TEXTURE3D_COUNT_NOT_POWER_OF_TWO,
                span,
                format!(
                    "ComposedTexture3D has {}: the slices of a 3D texture shall be 2^n ({fewer} or {more} here)",
                    plural(count, "texture")
                ),
            )
            .node(id)
            .help(format!(
                "give {fewer} or {more} slices, e.g. repeat the last slice up to {more}"
            )),
        );
    }
}
