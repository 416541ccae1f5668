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
    /// Only node types are checked, not fields: the per-field levels of the X3D Unified
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
    for (id, node) in ctx.doc.iter() {
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
