//! HANIM_NAME_NOT_STANDARD: joint or segment names of an HAnim 2.0 humanoid that are not
//! HAnim 2.0 names.

use super::names::{JOINT_ALIASES, JOINT_NAMES, SEGMENT_ALIASES, SEGMENT_NAMES};
use super::{humanoids, name_suffix, written_name, Humanoid};
use crate::diagnostic::Diagnostic;
use crate::model::{Document, NodeId};
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports, once per humanoid and kind, the HAnimJoint and HAnimSegment nodes of an
    /// HAnim 2.0 humanoid's skeleton whose `name` is not one of the HAnim 2.0 standard
    /// joint or segment names, naming the standard name where the name is an older one the
    /// X3D object model lists as its alias (`l_ankle` for `l_talocrural`). A humanoid is
    /// HAnim 2.0 when its `version` is `2.0`, or when it writes no `version` in an X3D 4
    /// scene (where 2.0 is the default). HAnim 1.0 humanoids are not checked: the
    /// oracle holds no faithful HAnim 1.0 table. Sites are not checked.
    ///
    /// ## Why it matters
    /// Animations, motion data and tools find a humanoid's joints by their standard names.
    /// A joint under another name is allowed (an extra joint of a figure that is not
    /// human-like), but nothing written for the standard skeleton moves it. Most often the
    /// names are HAnim 1.0 names (`l_wrist`, `l_index1`) left in a humanoid marked
    /// version 2.0, whose joints were renamed (`l_radiocarpal`,
    /// `l_metacarpophalangeal_2`).
    ///
    /// ## Example
    /// ```xml
    /// <HAnimHumanoid name='Jo' version='2.0'>
    ///   <HAnimJoint containerField='skeleton' name='humanoid_root'>
    ///     <HAnimJoint name='l_ankle'/>
    ///   </HAnimJoint>
    /// </HAnimHumanoid>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <HAnimHumanoid name='Jo' version='2.0'>
    ///   <HAnimJoint containerField='skeleton' name='humanoid_root'>
    ///     <HAnimJoint name='l_talocrural'/>
    ///   </HAnimJoint>
    /// </HAnimHumanoid>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 26.3.3 HAnimJoint and 26.3.5 HAnimSegment, whose names are those of
    /// ISO/IEC 19774-1:2019 (HAnim 2.0), as the X3D object model lists them
    /// (`hanimJointNameValues`, `hanimSegmentNameValues`: "This list is unbounded,
    /// additional enumeration values are allowed"). Reading: other names are allowed, so
    /// this is information, not a violation; the tables are generated from
    /// X3dUnifiedObjectModel-4.1.xml into `src/validate/hanim/names.rs`.
    pub static HANIM_NAME_NOT_STANDARD = {
        severity: Info,
        level: Standard,
        clause: "26.3.3",
        versions: "all",
        check: Some(check),
    }
}

/// How many names a finding quotes.
const QUOTED: usize = 5;

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for humanoid in humanoids(doc).iter().filter(|h| is_hanim_2(doc, h.id)) {
        found.extend(check_kind(
            doc,
            humanoid,
            "joint",
            JOINT_NAMES,
            JOINT_ALIASES,
        ));
        found.extend(check_kind(
            doc,
            humanoid,
            "segment",
            SEGMENT_NAMES,
            SEGMENT_ALIASES,
        ));
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// Whether a humanoid is HAnim 2.0: `version` 2.0 written, or not written in X3D 4.
fn is_hanim_2(doc: &Document, id: NodeId) -> bool {
    let node = doc.node(id);
    if node.is_connected("version") {
        return false;
    }
    match node.entry("version") {
        Some(entry) => entry
            .value
            .as_strings()
            .and_then(|v| v.first())
            .is_some_and(|v| v.trim() == "2.0"),
        None => doc.schema_version() >= Version::V4_0,
    }
}

fn check_kind(
    doc: &Document,
    humanoid: &Humanoid,
    kind: &str,
    names: &[&str],
    aliases: &[(&str, &str)],
) -> Option<Diagnostic> {
    let type_name = if kind == "joint" {
        "HAnimJoint"
    } else {
        "HAnimSegment"
    };
    let odd: Vec<(NodeId, &str)> = humanoid
        .of_type(type_name)
        .iter()
        .filter_map(|&id| Some((id, written_name(doc, id)?)))
        .filter(|(_, name)| names.binary_search(name).is_err())
        .collect();
    let &(first, _) = odd.first()?;
    let quoted: Vec<String> = odd
        .iter()
        .take(QUOTED)
        .map(
            |(_, name)| match aliases.binary_search_by(|(a, _)| a.cmp(name)) {
                Ok(at) => format!("`{name}` (HAnim 2.0: `{}`)", aliases[at].1),
                Err(_) => format!("`{name}`"),
            },
        )
        .collect();
    let more = if odd.len() > QUOTED { ", …" } else { "" };
    let humanoid_name = name_suffix(doc, humanoid.id);
    let message = format!(
        "HAnimHumanoid{humanoid_name} (HAnim 2.0) has {} {type_name} {} not among the HAnim 2.0 {kind} names: {}{more}",
        odd.len(),
        if odd.len() == 1 { "name" } else { "names" },
        quoted.join(", ")
    );
    let span = doc.node(first).entry("name")?.span;
    let mut diagnostic = Diagnostic::new(&HANIM_NAME_NOT_STANDARD, span, message)
        .node(humanoid.id)
        .help(format!(
            "use the HAnim 2.0 {kind} name of each part the standard skeleton has; keep a name of your own only for an extra {kind}"
        ));
    for &(id, _) in odd.iter().skip(1).take(QUOTED - 1) {
        if let Some(entry) = doc.node(id).entry("name") {
            diagnostic = diagnostic.related(entry.span, format!("{type_name} name not standard"));
        }
    }
    Some(diagnostic)
}
