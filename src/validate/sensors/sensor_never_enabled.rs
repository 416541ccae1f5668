//! SENSOR_NEVER_ENABLED: a sensor with `enabled FALSE` that nothing can enable.

use super::{is_sensor, written_disabled, written_in_scene};
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::Wiring;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a sensor node (every X3DSensorNode but Collision and the DIS nodes) that
    /// writes `enabled='false'` while nothing can set it to TRUE later: no ROUTE writes
    /// its `enabled` (or `set_enabled`), `enabled` is not passed in through `IS`, no
    /// Script field or ProtoInstance fieldValue holds the node, no EXPORT names it, and
    /// no Script code of the file names its DEF (a Script whose running code was not
    /// read may, so nothing is reported then).
    ///
    /// ## Why it matters
    /// A disabled sensor generates no events (X3DSensorNode 7.3.7; 22.4.1 says of a
    /// ProximitySensor that "cannot generate events" that "this is equivalent to
    /// setting the enabled field to FALSE"). Left disabled for good, the sensor
    /// and every ROUTE from it do nothing; usually a ROUTE meant to switch it on is
    /// missing, or `false` was left from testing.
    ///
    /// ## Example
    /// ```xml
    /// <TouchSensor DEF='Button' enabled='false'/>
    /// <ROUTE fromNode='Button' fromField='touchTime' toNode='Clock' toField='set_startTime'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <TouchSensor DEF='Button'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.3.7 X3DSensorNode (`enabled`), 22.4.1 ProximitySensor. Reading: a
    /// sensor that stays disabled for the life of the scene never sends an event;
    /// information, since it may be kept on purpose for later editing.
    pub static SENSOR_NEVER_ENABLED = {
        severity: Info,
        level: Standard,
        clause: "7.3.7",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let candidates: Vec<_> = written_in_scene(doc)
        .filter(|(_, node)| is_sensor(node))
        .filter_map(|(id, node)| Some((id, written_disabled(node)?)))
        .collect();
    if candidates.is_empty() {
        return;
    }
    let wiring = Wiring::new(ctx);
    let found = wiring.keep_unset(doc, candidates, "enabled");
    for (id, span) in found {
        let node = doc.node(id);
        let routes_out = wiring.is_routed_from(id);
        let consequence = if routes_out {
            "it never sends an event, so its ROUTEs carry nothing"
        } else {
            "it never sends an event"
        };
        ctx.report(
            Diagnostic::new(
                &SENSOR_NEVER_ENABLED,
                span,
                format!(
                    "{} is disabled and nothing enables it: {consequence}",
                    node.type_name()
                ),
            )
            .node(id)
            .help("remove `enabled='false'`, or ROUTE a TRUE event to its `enabled` field"),
        );
    }
}
