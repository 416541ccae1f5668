//! COMPONENT_LEVEL_INSUFFICIENT: a node needs more of a component than the profile and
//! `component` statements provide.

use std::collections::BTreeMap;

use crate::diagnostic::{Applicability, Diagnostic, Fix, Span};
use crate::model::{Encoding, NodeId, NodeKind};
use crate::schema::{profiles, Version};
use crate::validate::{edits, Ctx};

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
    /// ## Fix safety
    /// The fix declares the component at the level needed (the highest any finding of the
    /// document needs of it, so that all findings on one component share one fix): it
    /// raises the level of the `component` statement that names it, or adds one after the
    /// last `component` statement — in XML `<component name='Shape' level='2'/>` in the
    /// head (making a head before the Scene when there is none), in ClassicVRML
    /// `COMPONENT Shape:2` after the PROFILE statement, in JSON a `component` member of
    /// `head`. It is safe: it states what the scene already uses, and a browser that has the
    /// component loads it as before. A statement without a level, or a self-closed
    /// `<head/>`, gets no fix.
    ///
    /// ## Clause
    /// 19775-1 7.2.5.3 (PROFILE), 7.2.5.4 (COMPONENT) and each component's support levels.
    /// A node whose component level neither the profile nor a `component` statement
    /// provides is functionality the document uses without declaring it. The sentence was
    /// added to 7.2.5.4 by 19775-1 V3.1 (Amendment 1) and read there, on the web3d.org
    /// V3.1 `core.html` page that lists the amendment's changes.
    /// > "A user shall declare all components and levels for the nodes and/or functionality being used either explicitly through the use of the COMPONENT statement or implicitly through the PROFILE statement" (19775-1 V3.1 7.2.5.4)
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
            .filter(|c| names(&c.name.text, component, ctx.version))
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
    let mut findings = statements(ctx, profile);
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
                "raise the component statement to {}, or use a larger profile",
                statement_text(ctx.doc.encoding, needed.component, needed.level)
            )
        } else {
            add_help(ctx.doc.encoding, needed.component, needed.level)
        });
        diagnostic.count = count;
        findings.push((diagnostic, needed.component, needed.level));
    }
    findings.sort_by_key(|(d, _, _)| d.span);
    let mut needed: BTreeMap<&str, u8> = BTreeMap::new();
    for &(_, component, level) in &findings {
        let most = needed.entry(component).or_default();
        *most = (*most).max(level);
    }
    for (mut diagnostic, component, _) in findings {
        if let Some(fix) = declare(ctx, component, needed[component]) {
            diagnostic = diagnostic.fix(fix);
        }
        ctx.report(diagnostic);
    }
}

/// Whether a `component` statement's `name` declares `component`: by its name, or in
/// X3D 4 by `H-Anim`, the X3D 3 name of HAnim that the 4.x schemas keep as a legacy name
/// (COMPONENT_UNKNOWN warns about it).
fn names(name: &str, component: &str, version: Version) -> bool {
    name == component
        || (component == "HAnim"
            && name == "H-Anim"
            && matches!(version, Version::V4_0 | Version::V4_1))
}

/// A fix declaring `component` at `level` (see the rule's Fix safety).
fn declare(ctx: &Ctx, component: &str, level: u8) -> Option<Fix> {
    let (doc, source) = (ctx.doc, ctx.source);
    let statements = &doc.head.components;
    let title = format!("Declare {}", statement_text(doc.encoding, component, level));
    let fix = |edit| Some(edits::fix(title.clone(), Applicability::Safe, vec![edit]));
    if let Some(existing) = statements.iter().rev().find(|c| c.name.text == component) {
        let (_, span) = existing.level?;
        let quoted = source.get(span.start as usize) == Some(&b'"');
        let number = if quoted {
            format!("\"{level}\"")
        } else {
            level.to_string()
        };
        return fix(edits::edit(span, number));
    }
    let insert = |at: usize, text: String| fix(edits::edit(Span::new(at, at), text));
    let last = statements.last().map(|c| c.span.end as usize);
    match doc.encoding {
        Encoding::Xml => {
            let statement = format!("<component name='{component}' level='{level}'/>");
            if let Some(end) = last {
                let indent = edits::indentation(source, end);
                return insert(end, format!("\n{indent}{statement}"));
            }
            let scene = doc.scene_span?.start as usize;
            match edits::xml_start_tag(source, doc.root_span.start as usize + 1, scene, "head") {
                Some(head) => {
                    let close = head + memchr::memchr(b'>', &source[head..scene])?;
                    if source[close - 1] == b'/' {
                        return None;
                    }
                    let indent = edits::indentation(source, head);
                    insert(close + 1, format!("\n{indent}  {statement}"))
                }
                None => {
                    let indent = edits::indentation(source, scene);
                    insert(
                        scene,
                        format!("<head>\n{indent}  {statement}\n{indent}</head>\n{indent}"),
                    )
                }
            }
        }
        Encoding::Json => {
            let object = format!("{{\"@name\": \"{component}\", \"@level\": {level}}}");
            if let Some(end) = last {
                return insert(end, format!(", {object}"));
            }
            let root = doc.root_span.start as usize;
            match edits::json_object_member(source, root, source.len(), "head") {
                Some(inside) => {
                    let empty =
                        source[inside..].iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'}');
                    let comma = if empty { "" } else { "," };
                    insert(inside, format!("\"component\": [{object}]{comma}"))
                }
                None => {
                    let scene = doc.scene_span?.start as usize;
                    insert(scene, format!("\"head\": {{\"component\": [{object}]}}, "))
                }
            }
        }
        Encoding::ClassicVrml | Encoding::Vrml97 => {
            let after = last.or(doc.profile.as_ref().map(|p| p.span.end as usize))?;
            insert(after, format!("\nCOMPONENT {component}:{level}"))
        }
    }
}

/// The component statement declaring `component` at `level`, written as the document's
/// encoding writes it (19776-1 `<component>`, 19776-2 `COMPONENT`, 19776-5 JSON).
fn statement_text(encoding: Encoding, component: &str, level: impl std::fmt::Display) -> String {
    match encoding {
        Encoding::Xml => format!("<component name='{component}' level='{level}'/>"),
        Encoding::Json => format!("{{\"@name\": \"{component}\", \"@level\": {level}}}"),
        Encoding::ClassicVrml | Encoding::Vrml97 => format!("COMPONENT {component}:{level}"),
    }
}

/// The help for a component the document does not declare: where its statement goes.
fn add_help(encoding: Encoding, component: &str, level: u8) -> String {
    let statement = statement_text(encoding, component, level);
    let place = match encoding {
        Encoding::Xml => "to the head",
        Encoding::Json => "to the head's \"component\" list",
        Encoding::ClassicVrml | Encoding::Vrml97 => "after the PROFILE statement",
    };
    format!("add {statement} {place}, or use a larger profile")
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
            Some((level, _)) => format!(
                "{} provides level {level}",
                statement_text(ctx.doc.encoding, component, level)
            ),
            None => format!("the {component} component statement gives no level"),
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
/// first use, with the count, and the component and level it needs.
fn statements(ctx: &Ctx, profile: &profiles::Profile) -> Vec<(Diagnostic, &'static str, u8)> {
    let mut findings = Vec::new();
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
        .help(add_help(doc.encoding, component, level));
        diagnostic.count = count;
        findings.push((diagnostic, component, level));
    }
    findings
}
