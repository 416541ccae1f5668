//! FIELD_DEPRECATED: TextureProperties.borderColor and borderWidth in X3D 4.

use crate::diagnostic::{Applicability, Diagnostic};
use crate::model::Origin;
use crate::validate::{edits, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports TextureProperties `borderColor` or `borderWidth` set in an X3D 4.x scene.
    ///
    /// ## Why it matters
    /// Texture borders are deprecated in X3D 4 (modern graphics APIs have no texture
    /// borders); browsers ignore them.
    ///
    /// ## Example
    /// ```xml
    /// <TextureProperties borderWidth='1'/>
    /// ```
    ///
    /// ## Fix safety
    /// The fix removes the field (the XML attribute, the JSON member with its comma, the
    /// ClassicVRML name and value). It is unsafe: an X3D 4 browser ignores the field, but a
    /// 3.x browser loading the file would lose the border it drew.
    ///
    /// ## Clause
    /// 19775-1 (4.x) 18.4.9 TextureProperties.
    pub static FIELD_DEPRECATED = {
        severity: Warning,
        level: Fast,
        clause: "18.4.9",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if !ctx.version.is_4x() {
        return;
    }
    for id in ctx.doc.nodes_of_type("TextureProperties") {
        let node = ctx.doc.node(id);
        for entry in node
            .fields
            .iter()
            .filter(|e| matches!(e.name(), "borderColor" | "borderWidth"))
        {
            let mut diagnostic = Diagnostic::new(
                &FIELD_DEPRECATED,
                entry.name_span,
                format!(
                    "TextureProperties.{} is deprecated in X3D 4 and ignored",
                    entry.name()
                ),
            )
            .node(id);
            let removal = (matches!(entry.origin, Origin::Attribute | Origin::Member)
                && edits::written(ctx.doc, id))
            .then(|| edits::remove_field(ctx.source, ctx.doc.encoding, entry.name_span, entry.span))
            .flatten();
            if let Some(removal) = removal {
                diagnostic = diagnostic.fix(edits::fix(
                    format!("Remove `{}`", entry.name()),
                    Applicability::Unsafe,
                    vec![removal],
                ));
            }
            ctx.report(diagnostic);
        }
    }
}
