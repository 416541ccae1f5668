//! HANIM_NAME_DUPLICATE: two joints (or segments, or sites) of one humanoid with the same
//! name.

use std::collections::HashMap;

use super::{humanoids, written_name};
use crate::diagnostic::Diagnostic;
use crate::model::NodeId;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an HAnimJoint, HAnimSegment or HAnimSite whose `name` is the name of
    /// another node of the same type in the same humanoid's skeleton. A node reached
    /// twice through USE is one node and is not reported; empty names are left alone.
    ///
    /// ## Why it matters
    /// HAnim identifies a humanoid's parts by name: animations, motion data
    /// (HAnimMotion's `joints`) and applications look joints up by name. With two joints
    /// named `l_hip` only one of them is found, so the other never moves; a copied limb
    /// whose names were not changed to the other side is the usual cause.
    ///
    /// ## Example
    /// ```xml
    /// <HAnimJoint name='l_hip'>
    ///   <HAnimJoint name='l_knee'/>
    /// </HAnimJoint>
    /// <HAnimJoint name='l_hip'>
    ///   <HAnimJoint name='l_knee'/>
    /// </HAnimJoint>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <HAnimJoint name='l_hip'>
    ///   <HAnimJoint name='l_knee'/>
    /// </HAnimJoint>
    /// <HAnimJoint name='r_hip'>
    ///   <HAnimJoint name='r_knee'/>
    /// </HAnimJoint>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 26.3.3 HAnimJoint, 26.3.5 HAnimSegment, 26.3.6 HAnimSite, with the objects
    /// of ISO/IEC 19774 and 19774-1, whose name field is what identifies the joint,
    /// segment or site at run time. Reading: the text does not say "shall be unique" in
    /// so many words, but a name shared by two parts identifies neither; a warning.
    pub static HANIM_NAME_DUPLICATE = {
        severity: Warning,
        level: Standard,
        clause: "26.3.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for humanoid in humanoids(doc) {
        for nodes in [&humanoid.joints, &humanoid.segments, &humanoid.sites] {
            let mut first: HashMap<&str, NodeId> = HashMap::new();
            for &id in nodes {
                let Some(name) = written_name(doc, id) else {
                    continue;
                };
                let Some(&earlier) = first.get(name) else {
                    first.insert(name, id);
                    continue;
                };
                let node = doc.node(id);
                let Some(entry) = node.entry("name") else {
                    continue;
                };
                let message = format!(
                    "{} name `{name}` is already the name of another {} of this humanoid",
                    node.type_name(),
                    node.type_name()
                );
                found.push(
                    Diagnostic::new(&HANIM_NAME_DUPLICATE, entry.span, message)
                        .node(id)
                        .related(doc.node(earlier).span, "first named so here")
                        .help("give each part its own name: the standard names of its side and place (l_…, r_…), or a name of your own for an extra part"),
                );
            }
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
