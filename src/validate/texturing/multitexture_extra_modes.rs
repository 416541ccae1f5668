//! MULTITEXTURE_EXTRA_MODES: more mode/source/function entries than textures.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a MultiTexture whose `mode`, `source` or `function` field has more entries
    /// than its `texture` field has textures, one diagnostic per field.
    ///
    /// ## Why it matters
    /// 18.4.3: "The number of used texture stages is determined by the length of the
    /// texture field." The extra entries are ignored; usually a texture was removed and its
    /// mode left behind, or the modes were written for another texture order.
    ///
    /// ## Example
    /// ```xml
    /// <MultiTexture mode='"MODULATE" "ADD"'><ImageTexture url='"a.png"'/></MultiTexture>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.3 MultiTexture.
    pub static MULTITEXTURE_EXTRA_MODES = {
        severity: Info,
        level: Standard,
        clause: "18.4.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("MultiTexture") {
        let node = doc.node(id);
        if node.is_connected("texture") {
            continue;
        }
        let textures = node.children("texture").len();
        for field in ["mode", "source", "function"] {
            let Some(entry) = node.entry(field) else {
                continue;
            };
            let given = entry.value.as_strings().map_or(0, <[String]>::len);
            if given > textures && !node.is_connected(field) {
                found.push((id, entry.span, field, given, textures));
            }
        }
    }
    for (id, span, field, given, textures) in found {
        let extra = given - textures;
        ctx.report(
            Diagnostic::new(
                &MULTITEXTURE_EXTRA_MODES,
                span,
                format!(
                    "MultiTexture.{field} has {given} entries for {textures} texture{}: the last {extra} {} ignored",
                    if textures == 1 { "" } else { "s" },
                    if extra == 1 { "is" } else { "are" }
                ),
            )
            .node(id),
        );
    }
}
