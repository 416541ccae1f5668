//! BACKGROUND_COLOR_COUNT_MISMATCH: a background whose sky or ground has not one colour
//! more than it has angles.

use super::{is_background, Gradient, GRADIENTS};
use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, Span};
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Background or TextureBackground whose `skyColor` does not hold exactly one
    /// colour more than `skyAngle` holds angles, or whose `groundColor` does not hold one
    /// more than `groundAngle`, counting the defaults of fields not written (`skyColor`
    /// `0 0 0`, the others empty). A gradient with no colours and no angles is left alone:
    /// it is the default ground, which is not drawn. Fields a ROUTE sends values to or
    /// that take their value through `IS` are left alone too.
    ///
    /// ## Why it matters
    /// The first colour is the one at the zenith (nadir) and each angle gives the circle
    /// where the next colour is reached. With too few colours the last angles have none,
    /// with too many the extra colours have no angle: browsers drop the extra values,
    /// reuse the last colour, or draw no gradient at all.
    ///
    /// ## Example
    /// ```xml
    /// <Background skyAngle='0.8 1.2' skyColor='0 0 1 1 1 1'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Background skyAngle='0.8 1.2' skyColor='0 0 1 0.5 0.5 1 1 1 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 24.2.1 Backgrounds (X3D 3.x; 24.3.1 X3DBackgroundNode in 4.0): "There shall
    /// be one more skyColor value than there are skyAngle values" and "There shall be one
    /// more groundColor value than there are groundAngle values"; ISO/IEC 14772-1 6.5
    /// Background for VRML97, in the same words. Reading: no colours and no angles is the
    /// default of the ground (groundColor `[]`), a gradient not drawn, not a mismatch.
    /// > "There shall be one more skyColor value than there are skyAngle values" (19775-1 24.2.1)
    pub static BACKGROUND_COLOR_COUNT_MISMATCH = {
        severity: Error,
        level: Standard,
        clause: "24.2.1",
        versions: "all",
        check: Some(check),
    }
}

struct Mismatch {
    id: NodeId,
    span: Span,
    related: Option<Span>,
    message: String,
    angles_field: &'static str,
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter().filter(|(_, node)| is_background(node)) {
        for gradient in &GRADIENTS {
            let Gradient {
                part,
                colors: colors_field,
                angles: angles_field,
            } = *gradient;
            if set_elsewhere(doc, &routed, id, colors_field)
                || set_elsewhere(doc, &routed, id, angles_field)
            {
                continue;
            }
            let (Some(colors), Some(angles)) = (
                doc.value_of(id, colors_field).map(|v| v.len() / 3),
                doc.value_of(id, angles_field).map(|v| v.len()),
            ) else {
                continue;
            };
            if colors == angles + 1 || (colors == 0 && angles == 0) {
                continue;
            }
            let (colors_entry, angles_entry) = (node.entry(colors_field), node.entry(angles_field));
            let Some(span) = colors_entry.or(angles_entry).map(|e| e.span) else {
                continue;
            };
            let related = angles_entry
                .filter(|_| colors_entry.is_some())
                .map(|e| e.span);
            found.push(Mismatch {
                id,
                span,
                related,
                message: format!(
                    "{}.{colors_field} has {} for {}: the {part} needs {}",
                    node.type_name(),
                    plural(colors, "colour"),
                    plural(angles, &format!("{angles_field} value")),
                    plural(angles + 1, "colour"),
                ),
                angles_field,
            });
        }
    }
    for m in found {
        let mut diagnostic = Diagnostic::new(&BACKGROUND_COLOR_COUNT_MISMATCH, m.span, m.message)
            .node(m.id)
            .help("give one colour for the pole and one for each angle");
        if let Some(related) = m.related {
            diagnostic = diagnostic.related(related, m.angles_field);
        }
        ctx.report(diagnostic);
    }
}
