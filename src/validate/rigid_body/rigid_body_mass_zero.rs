//! RIGID_BODY_MASS_ZERO: a RigidBody whose mass is zero.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a RigidBody whose `mass` is written as 0. The default (1 kilogram) is fine;
    /// a `mass` a ROUTE sends values to or that takes its value through `IS` is left alone.
    ///
    /// ## Why it matters
    /// A physics engine divides by the mass to turn forces into accelerations: a body of
    /// zero mass either makes the simulation blow up or is rejected by the engine, and
    /// what happens differs between browsers. A body meant not to move is written with
    /// `fixed TRUE` instead.
    ///
    /// ## Example
    /// ```xml
    /// <RigidBody mass='0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <RigidBody fixed='true'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 37.4.10 RigidBody: "The mass field indicates the mass of the body in
    /// kilograms. All bodies shall have a non-zero mass, with the default value of 1
    /// kilogram." The interface table gives `mass` no range, so FIELD_OUT_OF_RANGE does
    /// not report it.
    /// > "All bodies shall have a non-zero mass" (19775-1 37.4.10)
    pub static RIGID_BODY_MASS_ZERO = {
        severity: Error,
        level: Standard,
        clause: "37.4.10",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let found: Vec<_> = doc
        .nodes_of_type("RigidBody")
        .filter(|&id| !set_elsewhere(doc, &routed, id, "mass"))
        .filter_map(|id| {
            let entry = doc.node(id).entry("mass")?;
            (doc.f32_of(id, "mass")? == 0.0).then_some((id, entry.span))
        })
        .collect();
    for (id, span) in found {
        ctx.report(
            Diagnostic::new(&RIGID_BODY_MASS_ZERO, span, "RigidBody.mass is 0")
                .node(id)
                .help("give the body its mass in kilograms; for a body that does not move, set fixed TRUE"),
        );
    }
}
