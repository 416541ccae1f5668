//! SENSOR_UNROUTED: a sensor with a DEF name that no ROUTE, IS, Script or EXPORT connects.

use super::{is_sensor, written_disabled, written_in_scene};
use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::Wiring;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a sensor node (TouchSensor, PlaneSensor, CylinderSensor, SphereSensor,
    /// KeySensor, StringSensor, TimeSensor, ProximitySensor, VisibilitySensor,
    /// TransformSensor, LoadSensor, the picking sensors, the Geo sensors: every
    /// X3DSensorNode but Collision and the DIS nodes) that has a DEF name, yet nothing
    /// connects: no ROUTE reads or writes any of its fields, no `IS` passes its fields
    /// to a prototype's interface, no Script field or ProtoInstance fieldValue holds it,
    /// no EXPORT names it, and no Script code of the file names its DEF (where a Script
    /// runs code that was not read, such as a `.js` file below the deep level, it may,
    /// so nothing is reported). A sensor whose `enabled` is FALSE is left to
    /// SENSOR_NEVER_ENABLED.
    ///
    /// ## Why it matters
    /// A sensor does nothing but generate events (7.3.7: "the base type for all
    /// sensors"); with no route from it those events reach no node, so the touch, the
    /// clock tick or the viewer's approach changes nothing in the scene. The DEF name
    /// says a ROUTE was meant: usually it was forgotten, or names another node by a
    /// typo. This is information, not an error: a pointing-device sensor still shows
    /// its description and hides the sensors above it (20.2.1), and a page around the
    /// scene may script it through the SAI, which a file cannot show.
    ///
    /// ## Example
    /// ```xml
    /// <TimeSensor DEF='Clock' cycleInterval='4' loop='true'/>
    /// <PositionInterpolator DEF='Mover' key='0 1' keyValue='0 0 0 0 2 0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ROUTE fromNode='Clock' fromField='fraction_changed' toNode='Mover' toField='set_fraction'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.3.7 X3DSensorNode ("the base type for all sensors", whose output is its
    /// events). Reading: events reach other nodes only along ROUTEs (or through Scripts and
    /// prototype interfaces), so a node kept only for its events, whose events nothing can
    /// receive, does nothing; information.
    pub static SENSOR_UNROUTED = {
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
        .filter(|(_, node)| {
            is_sensor(node)
                && node.def_name.is_some()
                && node.connects.is_empty()
                && written_disabled(node).is_none()
        })
        .map(|(id, _)| id)
        .collect();
    if candidates.is_empty() {
        return;
    }
    let wiring = Wiring::new(ctx);
    let found: Vec<_> = candidates
        .into_iter()
        .filter(|&id| {
            !wiring.is_routed_from(id)
                && !wiring.is_routed_into(id)
                && !wiring.is_reachable_by_code(doc, id)
        })
        .collect();
    for id in found {
        let node = doc.node(id);
        let name = node.def_name.as_ref().map_or("", |d| d.text.as_str());
        ctx.report(
            Diagnostic::new(
                &SENSOR_UNROUTED,
                node.name_span,
                format!(
                    "{} `{name}` is connected to nothing: no ROUTE reads its events, so they change nothing",
                    node.type_name()
                ),
            )
            .node(id)
            .help(format!(
                "add a ROUTE from `{name}` to the node it should drive, or remove the sensor"
            )),
        );
    }
}
