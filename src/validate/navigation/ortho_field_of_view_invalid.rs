//! ORTHO_FIELD_OF_VIEW_INVALID: an OrthoViewpoint whose fieldOfView is not four values
//! with each minimum below its maximum.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, written_entries};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an OrthoViewpoint whose `fieldOfView` does not hold four values (minimum
    /// x, minimum y, maximum x, maximum y, as the default `-1 -1 1 1`), or holds four
    /// where a minimum is not below its maximum (`minimum x < maximum x`, `minimum y <
    /// maximum y`). A `fieldOfView` a ROUTE sends values to or that takes its value
    /// through `IS` is left alone, as are NaN and infinities (FIELD_VALUE_NONFINITE's).
    ///
    /// ## Why it matters
    /// The four values are the edges of the orthographic view volume. With another count
    /// browsers read whatever numbers are there (or none) as edges; with a minimum at or
    /// beyond its maximum the view has no width or height, or is mirrored: a blank or
    /// flipped picture.
    ///
    /// ## Example
    /// ```xml
    /// <OrthoViewpoint fieldOfView='-2 2 2 -2'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <OrthoViewpoint fieldOfView='-2 -2 2 2'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 23.4.5 OrthoViewpoint: "The fieldOfView field specifies minimum and maximum
    /// extents of the view in units of the local coordinate system." and "The minimum and
    /// maximum values in each direction of the field of view shall have the relationship
    /// minimum < maximum." Reading: the four values and their order (minimum x, minimum
    /// y, maximum x, maximum y) are those of the interface's default `-1 -1 1 1`; the
    /// clause names no other layout, so a count other than four leaves the relationship
    /// it requires unreadable and is reported under the same code.
    /// > "The minimum and maximum values in each direction of the field of view shall have the relationship minimum < maximum" (19775-1 23.4.5)
    pub static ORTHO_FIELD_OF_VIEW_INVALID = {
        severity: Error,
        level: Standard,
        clause: "23.4.5",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, entry) in written_entries(doc, &routed, "OrthoViewpoint", "fieldOfView") {
        let Some(values) = entry.value.as_floats() else {
            continue;
        };
        let problem = match values {
            [min_x, min_y, max_x, max_y] => {
                let inverted: Vec<&str> = [("x", min_x, max_x), ("y", min_y, max_y)]
                    .into_iter()
                    .filter(|(_, min, max)| min.is_finite() && max.is_finite() && min >= max)
                    .map(|(axis, _, _)| axis)
                    .collect();
                if inverted.is_empty() {
                    continue;
                }
                format!(
                    "OrthoViewpoint.fieldOfView has its minimum {} not below its maximum: the values are minimum x, minimum y, maximum x, maximum y",
                    inverted.join(" and ")
                )
            }
            _ => format!(
                "OrthoViewpoint.fieldOfView has {} values, not four (minimum x, minimum y, maximum x, maximum y)",
                values.len()
            ),
        };
        found.push((id, entry.span, problem));
    }
    for (id, span, message) in found {
        ctx.report(
            Diagnostic::new(&ORTHO_FIELD_OF_VIEW_INVALID, span, message)
                .node(id)
                .help("give the view's edges as `minX minY maxX maxY`, each minimum below its maximum, e.g. `-1 -1 1 1` (the default)"),
        );
    }
}
