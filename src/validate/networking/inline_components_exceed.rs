//! INLINE_COMPONENTS_EXCEED: an Inline loads a scene that declares components or levels
//! the containing scene does not.

use std::collections::BTreeMap;

use crate::diagnostic::Diagnostic;
use crate::model::Document;
use crate::schema::profiles;
use crate::validate::networking::inlines::InlineTarget;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// For every Inline whose url loads a local scene (see INLINE_CYCLE for how the url
    /// resolves), compares the components and levels the inlined scene declares (its
    /// profile's, raised by its `component` statements) with those of the containing
    /// scene, and reports each component the inlined scene declares that the containing
    /// scene lacks or declares at a lower level. Scenes without a profile or with an
    /// unknown one (VRML97 files included) are not compared. The containing scene is the
    /// file that holds the Inline; an inlined file that inlines others is checked the same
    /// way against its own Inlines, so the chain stays within the top scene.
    ///
    /// ## Why it matters
    /// A browser shall refuse the url (it is "not interpretable") and try the next one:
    /// with a single url the inlined scene is not shown at all.
    ///
    /// ## Example
    /// ```xml
    /// <X3D profile='Interchange' version='4.0'>
    ///   <Scene><Inline url='"immersive-world.x3d"'/></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Use instead
    /// Declare in the containing scene a profile (or `component` statements) that
    /// provides everything the inlined scene declares.
    ///
    /// ## Clause
    /// 19775-1 9.4.2 Inline, read in the 3.3 text as quoted (the 3.3 networking page)
    /// on the web3d.org x3d-public list, 2019-03-12.
    /// > "It shall be an error to specify a file in the URL field that has a set of component definitions that is not a subset of the components of the containing world. In addition, the components shall not be of a higher support level than those used by the containing world." (19775-1 9.4.2)
    pub static INLINE_COMPONENTS_EXCEED = {
        severity: Error,
        level: Deep,
        clause: "9.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let Some(containing) = declared_components(ctx.doc) else {
        return;
    };
    let mut found = Vec::new();
    for (inline, target) in ctx.inlines.iter() {
        let InlineTarget::Loaded { library, url } = target else {
            continue;
        };
        let Some(inlined) = library.document.as_ref().and_then(declared_components) else {
            continue;
        };
        let exceeding: Vec<String> = inlined
            .iter()
            .filter_map(|(component, &level)| {
                let has = containing.get(component).copied().unwrap_or(0);
                (level > has).then(|| match has {
                    0 => format!("{component} {level} (none here)"),
                    _ => format!("{component} {level} (level {has} here)"),
                })
            })
            .collect();
        if exceeding.is_empty() {
            continue;
        }
        let node = ctx.doc.node(inline);
        let span = node.entry("url").map_or(node.name_span, |entry| entry.span);
        found.push(
            Diagnostic::new(
                &INLINE_COMPONENTS_EXCEED,
                span,
                format!(
                    "Inline loads \"{url}\", which declares components this scene does not provide: {}",
                    exceeding.join(", ")
                ),
            )
            .node(inline)
            .value(url.clone()),
        );
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// The level of each component a document declares: its profile's, raised by its
/// `component` statements. None without a known profile (or version).
fn declared_components(doc: &Document) -> Option<BTreeMap<String, u8>> {
    let version = doc.version?;
    let profile = profiles::profile(version, &doc.profile.as_ref()?.text)?;
    let mut levels: BTreeMap<String, u8> = profile
        .component_levels(version)
        .into_iter()
        .map(|c| (canonical(c.component).to_string(), c.level))
        .collect();
    for statement in &doc.head.components {
        let name = canonical(&statement.name.text);
        let level = statement
            .level
            .and_then(|(level, _)| u8::try_from(level).ok())
            .unwrap_or(1);
        let entry = levels.entry(name.to_string()).or_insert(0);
        *entry = (*entry).max(level);
    }
    Some(levels)
}

/// One name per component: X3D 4 renamed H-Anim to HAnim, and a 3.3 scene may inline a
/// 4.0 one.
fn canonical(component: &str) -> &str {
    match component {
        "H-Anim" => "HAnim",
        other => other,
    }
}
