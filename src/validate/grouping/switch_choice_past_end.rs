//! SWITCH_CHOICE_PAST_END: a Switch whose whichChoice names no child.

use crate::diagnostic::Diagnostic;
use crate::model::{Document, NodeId};
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::numbers::plural;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a Switch whose `whichChoice` is zero or more but not less than the number
    /// of its children (VRML97: of its `choice` nodes), so that it names no child. A
    /// negative `whichChoice` (choose nothing, the default -1) is left alone, as is a
    /// Switch whose `whichChoice` or children a ROUTE changes (`set_whichChoice`,
    /// `addChildren`, …) or that takes them through `IS`; that `whichChoice` is at least
    /// -1 is FIELD_OUT_OF_RANGE's.
    ///
    /// ## Why it matters
    /// A Switch past its last child draws nothing, exactly as -1 does. Written as an
    /// index, it usually means a child was removed or the index counts from 1; the author
    /// expected something to show.
    ///
    /// ## Example
    /// ```xml
    /// <Switch whichChoice='2'>
    ///   <Shape><Box/></Shape>
    ///   <Shape><Sphere/></Shape>
    /// </Switch>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Switch whichChoice='1'>
    ///   <Shape><Box/></Shape>
    ///   <Shape><Sphere/></Shape>
    /// </Switch>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 10.4.4 Switch: "The whichChoice field specifies the index of the child to
    /// traverse, with the first child having index 0. If whichChoice is less than zero or
    /// greater than the number of nodes in the children field, nothing is chosen."
    /// ISO/IEC 14772-1 6.46 Switch for VRML97, with `choice` for `children`. A warning:
    /// the outcome is defined (nothing is chosen), only unlikely to be what was meant.
    pub static SWITCH_CHOICE_PAST_END = {
        severity: Warning,
        level: Standard,
        clause: "10.4.4",
        versions: "all",
        check: Some(check),
    }
}

/// The fields a ROUTE or IS can change a Switch's choices through.
const CHOICE_FIELDS: [&str; 5] = [
    "whichChoice",
    "children",
    "choice",
    "addChildren",
    "removeChildren",
];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Switch") {
        if any_set_elsewhere(doc, &routed, id, &CHOICE_FIELDS) {
            continue;
        }
        let node = doc.node(id);
        let Some(entry) = node.entry("whichChoice") else {
            continue;
        };
        let Some(&which) = entry.value.as_int32s().and_then(|v| v.first()) else {
            continue;
        };
        let (field, count) = choices(doc, id);
        if usize::try_from(which).is_ok_and(|which| which >= count) {
            found.push((id, entry.span, which, field, count));
        }
    }
    for (id, span, which, field, count) in found {
        let last = match count {
            0 => "it has none".to_string(),
            _ => format!("the last is {}", count - 1),
        };
        ctx.report(
            Diagnostic::new(
                &SWITCH_CHOICE_PAST_END,
                span,
                format!(
                    "Switch.whichChoice is {which} but the Switch has {}: nothing is chosen",
                    counted(field, count)
                ),
            )
            .node(id)
            .help(format!(
                "whichChoice counts the children from 0 ({last}); use -1 to choose nothing"
            )),
        );
    }
}

/// "3 children", "1 child", "2 choice nodes".
fn counted(field: &str, count: usize) -> String {
    match (field, count) {
        ("children", 1) => "1 child".to_string(),
        ("children", _) => format!("{count} children"),
        _ => plural(count, &format!("{field} node")),
    }
}

/// The field holding a Switch's choices (`choice` in VRML97, else `children`) and how
/// many nodes it holds.
fn choices(doc: &Document, id: NodeId) -> (&'static str, usize) {
    let node = doc.node(id);
    let field = if node.entry("choice").is_some() {
        "choice"
    } else {
        "children"
    };
    (field, node.children(field).len())
}
