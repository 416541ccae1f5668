//! COMPONENT_LEVEL_INSUFFICIENT: a node needs more of a component than the profile and
//! `component` statements provide.

use std::collections::BTreeMap;

use crate::model::{NodeId, NodeKind};
use crate::report::Diagnostic;
use crate::schema::profiles;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a node type whose component level (from the support-level tables: 11.2,
    /// 12.4, 17.6, 18.11, …) is more than the document's profile provides, raised by its
    /// `component` statements. For example PhysicalMaterial needs Shape 2, TwoSidedMaterial
    /// Shape 4 in 4.0 and Shape 3 in 4.1. One diagnostic per node type, at its first use,
    /// with the count.
    ///
    /// Statements are checked too, at the levels the X3D Unified Object Model gives them:
    /// ProtoDeclare and ExternProtoDeclare need Core 2, IMPORT and EXPORT Networking 3
    /// (Interchange provides Core 1 and Networking 1).
    ///
    /// Only node types and statements are checked, not fields: the per-field levels of the X3D Unified
    /// Object Model describe what a browser must support at a level, not what a scene
    /// must declare. A document without a profile is checked as Full (PROFILE_MISSING
    /// says so); an unknown profile is not checked (PROFILE_UNKNOWN).
    ///
    /// ## Why it matters
    /// A browser that supports exactly the declared profile may refuse the scene or skip
    /// the node. Declaring the component makes the requirement explicit.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0' profile='Interchange'>
    ///   <Scene><Shape><Appearance><TwoSidedMaterial/></Appearance><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.2.5.3 (PROFILE), 7.2.5.4 (COMPONENT) and each component's support levels.
    pub static COMPONENT_LEVEL_INSUFFICIENT = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let Some(profile_name) = &ctx.doc.profile else {
        return;
    };
    let Some(profile) = profiles::profile(ctx.version, &profile_name.text) else {
        return;
    };
    let declared = |component: &str| {
        ctx.doc
            .head
            .components
            .iter()
            .filter(|c| c.name.text == component)
            .filter_map(|c| c.level.map(|(level, _)| level))
            .max()
            .unwrap_or(0)
    };
    // Node type → (first node, count), in name order for a stable report.
    let mut short: BTreeMap<&'static str, (NodeId, usize)> = BTreeMap::new();
    // The nodes as written: a prototype instance's copies are the same statements.
    for (id, node) in ctx.doc.iter().take(ctx.doc.written_nodes().len()) {
        let NodeKind::Known { def, version } = node.kind else {
            continue;
        };
        if version != ctx.version {
            continue;
        }
        let needed = def.component;
        let provided =
            i32::from(profile.level(ctx.version, needed.component)).max(declared(needed.component));
        if provided < i32::from(needed.level) {
            short.entry(def.name).or_insert((id, 0)).1 += 1;
        }
    }
    statements(ctx, profile);
    let mut found: Vec<_> = short.into_iter().collect();
    found.sort_by_key(|(_, (id, _))| *id);
    for (name, (id, count)) in found {
        let node = ctx.doc.node(id);
        let Some(def) = node.def() else { continue };
        let needed = def.component;
        let has = provided_text(
            ctx,
            profile.name,
            profile.level(ctx.version, needed.component),
            needed.component,
        );
        let times = if count > 1 {
            format!(" ({count} nodes)")
        } else {
            String::new()
        };
        let mut diagnostic = Diagnostic::new(
            &COMPONENT_LEVEL_INSUFFICIENT,
            node.name_span,
            format!(
                "{name} needs {} level {}, but {has}{times}",
                needed.component, needed.level
            ),
        )
        .node(id)
        .help(if declared(needed.component) > 0 {
            format!(
                "raise the component statement to <component name='{}' level='{}'/>, or use a larger profile",
                needed.component, needed.level
            )
        } else {
            format!(
                "add <component name='{}' level='{}'/> to the head, or use a larger profile",
                needed.component, needed.level
            )
        });
        diagnostic.count = count;
        ctx.report(diagnostic);
    }
}

/// What the document provides of `component`: the profile's level and every `component`
/// statement that names it, each with its level ("profile Immersive has no HAnim and
/// `<component name='HAnim' level='1'/>` provides level 1").
fn provided_text(ctx: &Ctx, profile: &str, from_profile: u8, component: &str) -> String {
    let mut parts = vec![if from_profile == 0 {
        format!("profile {profile} has no {component}")
    } else {
        format!("profile {profile} provides {component} level {from_profile}")
    }];
    for statement in ctx
        .doc
        .head
        .components
        .iter()
        .filter(|c| c.name.text == component)
    {
        parts.push(match statement.level {
            Some((level, _)) => {
                format!("<component name='{component}' level='{level}'/> provides level {level}")
            }
            None => format!("<component name='{component}'/> gives no level"),
        });
    }
    parts.join(" and ")
}

/// Statements that need more than Core 1, with the component level the UOM gives them
/// (`componentInfo` of each `Statement`; the Core support levels of 7.7 put prototypes at
/// level 2, the Networking ones of 9.5 IMPORT/EXPORT at level 3).
const STATEMENT_LEVELS: [(&str, &str, u8); 4] = [
    ("ProtoDeclare", "Core", 2),
    ("ExternProtoDeclare", "Core", 2),
    ("IMPORT", "Networking", 3),
    ("EXPORT", "Networking", 3),
];

/// One diagnostic per statement kind that needs more than the document provides, at its
/// first use, with the count.
fn statements(ctx: &mut Ctx, profile: &profiles::Profile) {
    let doc = ctx.doc;
    let declared = |component: &str| {
        doc.head
            .components
            .iter()
            .filter(|c| c.name.text == component)
            .filter_map(|c| c.level.map(|(level, _)| level))
            .max()
            .unwrap_or(0)
    };
    let mut uses: Vec<(&str, crate::model::Span)> = doc
        .protos
        .iter()
        .map(|p| {
            let kind = if p.external {
                "ExternProtoDeclare"
            } else {
                "ProtoDeclare"
            };
            (kind, p.span)
        })
        .collect();
    uses.extend(doc.imports.iter().map(|i| ("IMPORT", i.span)));
    uses.extend(doc.exports.iter().map(|e| ("EXPORT", e.span)));
    uses.sort_by_key(|(_, span)| *span);
    for (kind, component, level) in STATEMENT_LEVELS {
        let mut found = uses.iter().filter(|(k, _)| *k == kind);
        let Some(&(_, span)) = found.next() else {
            continue;
        };
        let profile_level = profile.level(ctx.version, component);
        if i32::from(profile_level).max(declared(component)) >= i32::from(level) {
            continue;
        }
        let count = 1 + found.count();
        let has = provided_text(ctx, profile.name, profile_level, component);
        let times = if count > 1 {
            format!(" ({count} statements)")
        } else {
            String::new()
        };
        let mut diagnostic = Diagnostic::new(
            &COMPONENT_LEVEL_INSUFFICIENT,
            span,
            format!("the {kind} statement needs {component} level {level}, but {has}{times}"),
        )
        .help(format!(
            "add <component name='{component}' level='{level}'/> to the head, or use a larger profile"
        ));
        diagnostic.count = count;
        ctx.report(diagnostic);
    }
}
