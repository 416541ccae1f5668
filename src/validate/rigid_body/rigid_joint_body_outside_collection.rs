//! RIGID_JOINT_BODY_OUTSIDE_COLLECTION: a joint of a RigidBodyCollection connected to a
//! body that the collection does not hold.

use std::collections::HashSet;

use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, NodeKind};
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a joint in a RigidBodyCollection's `joints` whose `body1` or `body2` is a
    /// RigidBody that is not in the same collection's `bodies` (the same node, shared with
    /// DEF/USE). A NULL body is left alone, as are collections whose `bodies` or `joints`
    /// and joints whose `body1` or `body2` a ROUTE sends values to or take their value
    /// through `IS`, and lists that hold prototype instances (whose type x3dcheck does not
    /// resolve here).
    ///
    /// ## Why it matters
    /// A collection evaluates its bodies and the joints between them as one system. A
    /// joint to a body of another collection gives a result that depends on the browser,
    /// and a body in no collection is not simulated at all, so the joint constrains
    /// nothing that moves. The usual cause is a body written inline in the joint (a copy)
    /// instead of a `USE` of the body in `bodies`.
    ///
    /// ## Example
    /// ```xml
    /// <RigidBodyCollection>
    ///   <RigidBody DEF='Arm' containerField='bodies'/>
    ///   <BallJoint containerField='joints'>
    ///     <RigidBody USE='Arm' containerField='body1'/>
    ///     <RigidBody containerField='body2'/>
    ///   </BallJoint>
    /// </RigidBodyCollection>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <RigidBodyCollection>
    ///   <RigidBody DEF='Arm' containerField='bodies'/>
    ///   <RigidBody DEF='Hand' containerField='bodies'/>
    ///   <BallJoint containerField='joints'>
    ///     <RigidBody USE='Arm' containerField='body1'/>
    ///     <RigidBody USE='Hand' containerField='body2'/>
    ///   </BallJoint>
    /// </RigidBodyCollection>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 37.4.11 RigidBodyCollection: "The joints field is used to register all the
    /// joints between the bodies contained in this collection. If a joint is connected
    /// between bodies in two different collections, the result is
    /// implementation-dependent." The clause makes it no "shall", so a warning: the joint
    /// does not work as written in every browser.
    pub static RIGID_JOINT_BODY_OUTSIDE_COLLECTION = {
        severity: Warning,
        level: Standard,
        clause: "37.4.11",
        versions: "all",
        check: Some(check),
    }
}

const BODY_FIELDS: [&str; 2] = ["body1", "body2"];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let is_known = |id: NodeId| matches!(doc.node(id).kind, NodeKind::Known { .. });
    let mut found = Vec::new();
    for collection in doc.nodes_of_type("RigidBodyCollection") {
        let node = doc.node(collection);
        if set_elsewhere(doc, &routed, collection, "bodies")
            || set_elsewhere(doc, &routed, collection, "joints")
        {
            continue;
        }
        let bodies = node.children("bodies");
        if !bodies.iter().all(|c| is_known(c.node)) {
            continue;
        }
        let held: HashSet<NodeId> = bodies.iter().map(|c| c.node).collect();
        for joint in node.children("joints") {
            let joint_node = doc.node(joint.node);
            if !is_known(joint.node) {
                continue;
            }
            for field in BODY_FIELDS {
                if set_elsewhere(doc, &routed, joint.node, field) {
                    continue;
                }
                let Some(body) = joint_node.children(field).first() else {
                    continue;
                };
                if !is_known(body.node) || held.contains(&body.node) {
                    continue;
                }
                let name = doc
                    .node(body.node)
                    .def_name
                    .as_ref()
                    .map_or(String::from("a RigidBody"), |n| {
                        format!("RigidBody '{}'", n.text)
                    });
                let message = format!(
                    "{}.{field} is {name}, which is not in the `bodies` of its RigidBodyCollection",
                    joint_node.type_name()
                );
                found.push((joint.node, body.span, message));
            }
        }
    }
    for (joint, span, message) in found {
        ctx.report(
            Diagnostic::new(&RIGID_JOINT_BODY_OUTSIDE_COLLECTION, span, message)
                .node(joint)
                .help("list the body in the collection's `bodies` and refer to it from the joint with USE"),
        );
    }
}
