//! MULTITEXTURE_COORDS_SHORT: fewer MultiTextureCoordinate entries than textures.

use std::collections::HashSet;

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports, per Shape, a MultiTexture in `Appearance.texture` with more textures than
    /// the geometry's MultiTextureCoordinate has entries (at least one). Each pair of
    /// MultiTexture and MultiTextureCoordinate is reported once, however many shapes share
    /// it. A geometry without a MultiTextureCoordinate is not checked: it has one set of
    /// coordinates, or generates them.
    ///
    /// ## Why it matters
    /// 18.4.4: "When the MultiTexture node is used in Appearance.texture field, and there is
    /// not enough texture coordinates in the MultiTextureCoordinate, texture coordinates for
    /// the last channel are replicated along the other channels." The later textures are
    /// mapped with coordinates meant for another one.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance><MultiTexture><ImageTexture url='"a.png"'/><ImageTexture url='"b.png"'/></MultiTexture></Appearance>
    /// <IndexedFaceSet coordIndex='0 1 2'><MultiTextureCoordinate><TextureCoordinate point='0 0 1 0 0 1'/></MultiTextureCoordinate>…
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.4 MultiTextureCoordinate.
    pub static MULTITEXTURE_COORDS_SHORT = {
        severity: Info,
        level: Standard,
        clause: "18.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut seen = HashSet::new();
    let mut found = Vec::new();
    for (shape, node) in doc.iter() {
        if !node.is_a("X3DShapeNode") {
            continue;
        }
        let Some(texture) = node
            .child("appearance")
            .and_then(|a| doc.child_of(a, "texture"))
            .filter(|t| doc.node(*t).type_name() == "MultiTexture")
        else {
            continue;
        };
        let Some(coords) = node
            .child("geometry")
            .and_then(|g| doc.child_of(g, "texCoord"))
            .filter(|c| doc.node(*c).type_name() == "MultiTextureCoordinate")
        else {
            continue;
        };
        let textures = doc.node(texture).children("texture").len();
        let given = doc.node(coords).children("texCoord").len();
        if given >= 1 && given < textures && seen.insert((texture, coords)) {
            found.push((shape, coords, textures, given));
        }
    }
    for (shape, coords, textures, given) in found {
        let node = doc.node(coords);
        let span = node.entry("texCoord").map_or(node.name_span, |e| e.span);
        ctx.report(
            Diagnostic::new(
                &MULTITEXTURE_COORDS_SHORT,
                span,
                format!(
                    "MultiTextureCoordinate has {given} texture coordinate node{} for {textures} textures: the last is replicated for the remaining {}",
                    if given == 1 { "" } else { "s" },
                    textures - given
                ),
            )
            .node(coords)
            .related(doc.node(shape).name_span, "in this Shape"),
        );
    }
}
