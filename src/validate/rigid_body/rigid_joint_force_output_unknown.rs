//! RIGID_JOINT_FORCE_OUTPUT_UNKNOWN: a joint's `forceOutput` value that names no output
//! field of the joint, or that is ignored because "NONE" is listed too.

use crate::diagnostic::Diagnostic;
use crate::model::Value;
use crate::schema::AccessType;
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a value of a rigid body joint's `forceOutput` (every X3DRigidJointNode:
    /// BallJoint, SliderJoint, the hinge joints, MotorJoint, UniversalJoint) that is
    /// neither "ALL" nor "NONE" and is not, exactly, the name of one of the joint type's
    /// output-only fields (`body1AnchorPoint`, `hinge1Angle`, …); and, in a list that
    /// holds "NONE", every other value. A `forceOutput` a ROUTE sends values to or that
    /// takes its value through `IS` is left alone.
    ///
    /// ## Why it matters
    /// A joint generates only the outputs its `forceOutput` names; the rest stay silent to
    /// save the physics engine work. A name with a case slip, a `_changed` suffix or a
    /// field of another joint type names nothing, so the ROUTE that waits for that output
    /// never fires. Next to "NONE" every name is ignored.
    ///
    /// ## Example
    /// ```xml
    /// <SingleAxisHingeJoint forceOutput='"Angle"'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <SingleAxisHingeJoint forceOutput='"angle"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 37.3.3 X3DRigidJointNode: "The values of the array are to describe the
    /// names, exactly, of the output field(s) that are to be updated at the start of the
    /// next frame. Two special values are defined: "ALL" and "NONE". … If the list of
    /// values is empty, it shall be treated as if "NONE" were specified. Other values
    /// provided in addition to "NONE" shall be ignored." The clause sets no "shall" on the
    /// author, so a warning: such a value does not do what it says.
    pub static RIGID_JOINT_FORCE_OUTPUT_UNKNOWN = {
        severity: Warning,
        level: Standard,
        clause: "37.3.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !node.is_a("X3DRigidJointNode") || set_elsewhere(doc, &routed, id, "forceOutput") {
            continue;
        }
        let (Some(def), Some(entry)) = (node.def(), node.entry("forceOutput")) else {
            continue;
        };
        let Value::Strings(values) = &entry.value else {
            continue;
        };
        let has_none = values.iter().any(|v| v == "NONE");
        let outputs: Vec<&'static str> = def
            .fields
            .iter()
            .filter(|f| f.access == AccessType::OutputOnly)
            .map(|f| f.name)
            .collect();
        for value in values {
            if value == "ALL" || value == "NONE" {
                continue;
            }
            let (message, help) = if has_none {
                (
                    format!(
                        "{}.forceOutput \"{value}\" is ignored: the list also holds \"NONE\"",
                        node.type_name()
                    ),
                    String::from("remove \"NONE\" to have the named outputs generated"),
                )
            } else if outputs.contains(&value.as_str()) {
                continue;
            } else {
                (
                    format!(
                        "{}.forceOutput \"{value}\" names no output field of this joint type",
                        node.type_name()
                    ),
                    suggest::help(value, outputs.iter().copied()).unwrap_or_else(|| {
                        format!(
                            "use \"ALL\", \"NONE\" or the exact names of the outputs wanted: {}",
                            outputs.join(", ")
                        )
                    }),
                )
            };
            found.push((id, entry.span, message, help));
        }
    }
    for (id, span, message, help) in found {
        ctx.report(
            Diagnostic::new(&RIGID_JOINT_FORCE_OUTPUT_UNKNOWN, span, message)
                .node(id)
                .help(help),
        );
    }
}
