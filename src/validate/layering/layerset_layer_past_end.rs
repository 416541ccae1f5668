//! LAYERSET_LAYER_PAST_END: a LayerSet order or activeLayer value that names no layer.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a LayerSet whose `order` holds, or whose `activeLayer` is, a number
    /// greater than the number of nodes in its `layers`. Layers are numbered from 1 in the
    /// order `layers` lists them; 0 is the layer of the nodes outside the LayerSet, so 0
    /// and every number up to the count name a layer. A LayerSet whose `layers`, `order`
    /// or `activeLayer` a ROUTE changes (or that takes them through `IS`) is left alone;
    /// negative values are FIELD_OUT_OF_RANGE's.
    ///
    /// ## Why it matters
    /// A number past the last layer renders nothing: the layer meant is not drawn, or
    /// navigation happens in no layer. It usually means a layer was removed, or the
    /// numbers were counted from 0.
    ///
    /// ## Example
    /// ```xml
    /// <LayerSet order='1 2' activeLayer='2'>
    ///   <Layer><Shape><Box/></Shape></Layer>
    /// </LayerSet>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <LayerSet order='1' activeLayer='1'>
    ///   <Layer><Shape><Box/></Shape></Layer>
    /// </LayerSet>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 35.4.2 LayerSet, read in instantreality's copy of the node's text (the
    /// 4.0 IS page's interface table was not reached): "The layers are assigned ordinals
    /// according to their position in the list in the LayerSet node" (35.2); "Each layer is
    /// assigned an ordinal number depending on its position in the list. Ordinals start
    /// with the numeral 1 representing the first item in the list"; "If order contains
    /// numbers that are not ordinals assigned to layers, such numbers are ignored"; "The
    /// activeLayer field specifies the layer in which navigation takes place." A warning:
    /// the outcome is stated (the number is ignored), and no sentence forbids it.
    pub static LAYERSET_LAYER_PAST_END = {
        severity: Warning,
        level: Standard,
        clause: "35.4.2",
        versions: "all",
        check: Some(check),
    }
}

/// The fields a ROUTE or IS can change the layers or the numbers through.
const LAYER_FIELDS: [&str; 3] = ["layers", "order", "activeLayer"];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("LayerSet") {
        if any_set_elsewhere(doc, &routed, id, &LAYER_FIELDS) {
            continue;
        }
        let node = doc.node(id);
        let layers = node.children("layers").len();
        let past_end = |value: i32| usize::try_from(value).is_ok_and(|v| v > layers);
        for field in ["order", "activeLayer"] {
            let Some(entry) = node.entry(field) else {
                continue;
            };
            let Some(values) = entry.value.as_int32s() else {
                continue;
            };
            if let Some(position) = values.iter().position(|&v| past_end(v)) {
                found.push((id, entry.span, field, values[position], position, layers));
            }
        }
    }
    for (id, span, field, value, position, layers) in found {
        let what = match field {
            "order" => "the number is ignored",
            _ => "navigation has no layer",
        };
        let mut diagnostic = Diagnostic::new(
            &LAYERSET_LAYER_PAST_END,
            span,
            format!(
                "LayerSet.{field} names layer {value} but the LayerSet has {}: {what}",
                plural(layers, "layer")
            ),
        )
        .node(id)
        .help(match layers {
            0 => "add the layers to the layers field: they are numbered from 1 in its order (0 is the layer of the nodes outside the LayerSet)".to_string(),
            _ => format!("layers are numbered from 1 in the order of the layers field (0 is the layer of the nodes outside the LayerSet); the last is {layers}"),
        });
        if field == "order" {
            diagnostic = diagnostic.index(position);
        }
        ctx.report(diagnostic);
    }
}
