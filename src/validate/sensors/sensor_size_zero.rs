//! SENSOR_SIZE_ZERO: a ProximitySensor or TransformSensor whose box has no volume.

use super::written_in_scene;
use crate::diagnostic::Diagnostic;
use crate::model::{Node, Span};
use crate::validate::events::wiring::Wiring;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ProximitySensor or TransformSensor whose `size` has a component of 0
    /// (-0 included), whether written or left at the default `0 0 0`, unless the scene
    /// can change it: a ROUTE to `size`, an `IS`, a Script or prototype instance holding
    /// the node, an EXPORT, or Script code naming its DEF. VisibilitySensor is left out:
    /// its clause says nothing of an empty box, and a flat or point box can still be in
    /// view (X_ITE senses it).
    ///
    /// ## Why it matters
    /// 22.4.1: "A ProximitySensor node with a box containing zero volume (i.e., any size
    /// field element of 0.0) cannot generate events. This is equivalent to setting the
    /// enabled field to FALSE." TransformSensor (22.4.2) senses its target in the same
    /// kind of box, and the X3D tooltips say the same of it. `size` defaults to `0 0 0`,
    /// so a sensor written without it senses nothing, and neither does one given a flat
    /// box such as `10 10 0` for a floor area.
    ///
    /// ## Example
    /// ```xml
    /// <ProximitySensor DEF='Room' center='0 1 0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ProximitySensor DEF='Room' center='0 1 0' size='10 3 10'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 22.4.1 ProximitySensor, 22.4.2 TransformSensor. Reading: the sensor can
    /// never fire, which the spec states as a fact, not a requirement; information.
    pub static SENSOR_SIZE_ZERO = {
        severity: Info,
        level: Standard,
        clause: "22.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let candidates: Vec<_> = written_in_scene(doc)
        .filter(|(_, node)| {
            matches!(node.type_name(), "ProximitySensor" | "TransformSensor")
                && !node.is_connected("size")
        })
        .filter_map(|(id, node)| Some((id, flat_box(node)?)))
        .collect();
    if candidates.is_empty() {
        return;
    }
    let wiring = Wiring::new(ctx);
    let found = wiring.keep_unset(doc, candidates, "size");
    for (id, (span, size)) in found {
        let node = doc.node(id);
        let written = if node.entry("size").is_some() {
            format!("size `{size}`")
        } else {
            format!("size left at its default `{size}`")
        };
        ctx.report(
            Diagnostic::new(
                &SENSOR_SIZE_ZERO,
                span,
                format!(
                    "{} has {written}: a box without volume cannot generate events",
                    node.type_name()
                ),
            )
            .node(id)
            .help("give every component of `size` a positive extent, in the sensor's local units"),
        );
    }
}

/// Where the box is given (the `size` value, or the node when left at the default) and
/// its size as text, when a component is 0.
fn flat_box(node: &Node) -> Option<(Span, String)> {
    let (span, size): (Span, Vec<f32>) = match node.entry("size") {
        Some(entry) => (entry.span, entry.value.as_floats()?.to_vec()),
        None => {
            let default = node.def()?.field("size")?.default;
            let parsed = default.split_whitespace().map(str::parse);
            (node.name_span, parsed.collect::<Result<_, _>>().ok()?)
        }
    };
    if size.len() != 3 || !size.contains(&0.0) {
        return None;
    }
    let text = size.iter().map(f32::to_string).collect::<Vec<_>>();
    Some((span, text.join(" ")))
}
