//! HANIM_LIST_MISMATCH: an HAnimHumanoid's `joints`, `segments` or `sites` list that does
//! not hold the nodes of that type in its skeleton.

use std::collections::HashSet;

use super::{describe, humanoids, Humanoid};
use crate::diagnostic::Diagnostic;
use crate::model::{NodeId, NodeKind};
use crate::validate::events::wiring::{routed_fields, set_elsewhere};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an HAnimHumanoid whose `joints`, `segments` or `sites` field is written
    /// (not empty) but leaves out an HAnimJoint, HAnimSegment or HAnimSite of its
    /// `skeleton` (a site listed in `viewpoints` instead counts as listed), and each node
    /// such a list holds that is not in the skeleton (except a site the humanoid also
    /// holds in `viewpoints`: a viewpoint site outside the skeleton, which some
    /// exporters list in `sites` too), and a node such a list holds more than once. An empty list is left alone, as is
    /// a humanoid whose skeleton holds prototype instances or is set by a ROUTE or `IS`.
    ///
    /// ## Why it matters
    /// The lists are how a browser and an animation find the humanoid's parts: joints
    /// left out of `joints` cannot be driven by name from outside, and skin binding
    /// (`jointBindingPositions`, …) pairs its values with the `joints` list in order.
    /// A node listed but not in the skeleton is not part of the figure at all. A partial
    /// list usually means a joint was added to (or renamed in) the skeleton without
    /// updating the list.
    ///
    /// ## Example
    /// ```xml
    /// <HAnimHumanoid name='Jo' version='2.0'>
    ///   <HAnimJoint DEF='Jo_root' containerField='skeleton' name='humanoid_root'>
    ///     <HAnimJoint DEF='Jo_sacroiliac' name='sacroiliac'/>
    ///   </HAnimJoint>
    ///   <HAnimJoint USE='Jo_root' containerField='joints'/>
    /// </HAnimHumanoid>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <HAnimHumanoid name='Jo' version='2.0'>
    ///   <HAnimJoint DEF='Jo_root' containerField='skeleton' name='humanoid_root'>
    ///     <HAnimJoint DEF='Jo_sacroiliac' name='sacroiliac'/>
    ///   </HAnimJoint>
    ///   <HAnimJoint USE='Jo_root' containerField='joints'/>
    ///   <HAnimJoint USE='Jo_sacroiliac' containerField='joints'/>
    /// </HAnimHumanoid>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 26.3.2 HAnimHumanoid, with the Humanoid object of ISO/IEC 19774 and 19774-1:
    /// the joints field holds one reference for each Joint object of the skeleton
    /// hierarchy, and segments and sites likewise (the X3D object model: "The joints field contains a
    /// list of USE references for all HAnimJoint node instances found within the preceding
    /// skeleton hierarchy"). Reading: an empty list is common in files that never use the
    /// lists and is not reported; a warning, since the skeleton itself is whole.
    pub static HANIM_LIST_MISMATCH = {
        severity: Warning,
        level: Standard,
        clause: "26.3.2",
        versions: "all",
        check: Some(check),
    }
}

const LISTS: [(&str, &str); 3] = [
    ("joints", "HAnimJoint"),
    ("segments", "HAnimSegment"),
    ("sites", "HAnimSite"),
];

/// How many missing nodes a finding points at with notes.
const NOTES: usize = 5;

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for humanoid in humanoids(doc).iter().filter(|h| !h.opaque) {
        for (field, type_name) in LISTS {
            found.extend(check_list(ctx, &routed, humanoid, field, type_name));
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

fn check_list(
    ctx: &Ctx,
    routed: &HashSet<(NodeId, String)>,
    humanoid: &Humanoid,
    field: &str,
    type_name: &str,
) -> Vec<Diagnostic> {
    let doc = ctx.doc;
    let node = doc.node(humanoid.id);
    let Some(entry) = node.entry(field) else {
        return Vec::new();
    };
    let listed = node.children(field);
    if listed.is_empty()
        || set_elsewhere(doc, routed, humanoid.id, field)
        || listed
            .iter()
            .any(|c| !matches!(doc.node(c.node).kind, NodeKind::Known { .. }))
    {
        return Vec::new();
    }
    let skeleton = humanoid.of_type(type_name);
    let in_skeleton: HashSet<NodeId> = skeleton.iter().copied().collect();
    // A site with a Viewpoint that the humanoid holds in `viewpoints` may be listed in
    // `sites` as well, and a site of the skeleton listed in `viewpoints` counts as listed.
    let viewpoints: HashSet<NodeId> = if field == "sites" {
        node.children("viewpoints").iter().map(|c| c.node).collect()
    } else {
        HashSet::new()
    };
    let mut listed_set: HashSet<NodeId> = listed.iter().map(|c| c.node).collect();
    listed_set.extend(viewpoints.iter().copied());
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    for child in listed {
        let listed_node = doc.node(child.node);
        if !seen.insert(child.node) {
            let message = format!(
                "HAnimHumanoid `{field}` lists {} more than once",
                describe(doc, child.node)
            );
            out.push(
                Diagnostic::new(&HANIM_LIST_MISMATCH, child.span, message)
                    .node(humanoid.id)
                    .help(format!(
                        "list each {type_name} of the skeleton once in `{field}`"
                    )),
            );
            continue;
        }
        if listed_node.type_name() != type_name
            || in_skeleton.contains(&child.node)
            || viewpoints.contains(&child.node)
        {
            continue;
        }
        let message = format!(
            "HAnimHumanoid `{field}` lists {}, which is not in the humanoid's skeleton",
            describe(doc, child.node)
        );
        out.push(
            Diagnostic::new(&HANIM_LIST_MISMATCH, child.span, message)
                .node(humanoid.id)
                .related(listed_node.span, "defined here, outside the skeleton")
                .help(format!("list in `{field}` only the {type_name} nodes of the `skeleton` hierarchy, each once")),
        );
    }
    let missing: Vec<NodeId> = skeleton
        .iter()
        .copied()
        .filter(|id| !listed_set.contains(id))
        .collect();
    if !missing.is_empty() {
        let names: Vec<String> = missing
            .iter()
            .take(NOTES)
            .map(|&id| describe(doc, id))
            .collect();
        let more = if missing.len() > NOTES { ", …" } else { "" };
        let message = format!(
            "HAnimHumanoid `{field}` leaves out {} of the {} {type_name} nodes of its skeleton: {}{more}",
            missing.len(),
            skeleton.len(),
            names.join(", ")
        );
        let mut diagnostic = Diagnostic::new(&HANIM_LIST_MISMATCH, entry.span, message)
            .node(humanoid.id)
            .help(format!(
                "add a USE of each to `{field}` (containerField='{field}')"
            ));
        for &id in missing.iter().take(NOTES) {
            diagnostic = diagnostic.related(doc.node(id).span, "not listed");
        }
        out.push(diagnostic);
    }
    out
}
