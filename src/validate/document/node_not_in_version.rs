//! NODE_NOT_IN_VERSION: a node type of another X3D version (or one X3D added to VRML97).

use std::collections::HashSet;

use crate::diagnostic::{Applicability, Diagnostic, Fix, Span};
use crate::model::{Encoding, LibraryPlace, NodeId, NodeKind};
use crate::schema::{self, versions, Version};
use crate::validate::{edits, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a node type that does not exist in the document's version but does in
    /// another, such as PhysicalMaterial or UnlitMaterial in a 3.3 scene, or an X3D node
    /// (TriangleSet, Switch's X3D siblings such as StaticGroup, any node X3D added) in a
    /// VRML97 file (`#VRML V2.0 utf8`), whose 54 nodes are those of 14772-1 clause 6; and a
    /// `unit` statement in a version before 3.3, which introduced it (7.2.5.5). A node of
    /// an external prototype's body read from another file is judged against that file's
    /// version, once per node of the body (not at every instance), with no fix: a VRML97
    /// scene may use a prototype an X3D file declares, and its KeySensor is no fault of
    /// the VRML97 scene's.
    ///
    /// ## Why it matters
    /// A browser of the declared version does not know the node and skips it.
    /// Raising the document's version (and checking what else that changes) fixes it;
    /// a VRML97 file becomes an X3D one with a `#X3D V3.x utf8` header and a profile.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='3.3' profile='Immersive'>
    ///   <Scene><Shape><Appearance><PhysicalMaterial/></Appearance><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Fix safety
    /// In an X3D document (not VRML97), where every node so reported exists in a later
    /// version, the fix raises the `version` (XML attribute, JSON `@version`, ClassicVRML
    /// header) to the first version that has them all; each finding carries that same
    /// fix, which also raises the number in the DTD and schema files the header names
    /// (the DOCTYPE's `DTD X3D 3.3//EN` and `x3d-3.3.dtd`, `xsd:noNamespaceSchemaLocation`'s
    /// `x3d-3.3.xsd`, JSON's `x3d-3.3-JSONSchema.json`). It is unsafe: browsers of the old
    /// version no longer load the scene, and other rules of the new version apply
    /// (deprecations, profile and component levels).
    /// A node that a later version removed (a VRML97 one) has no fix.
    ///
    /// ## Clause
    /// 19775-1 the node's clause in the version that defines it; 7.2.5.2 (version);
    /// for VRML97 files, 14772-1 clause 6 (the node reference lists every VRML97 node).
    /// A node type the version does not have is in none of the version's components, so the
    /// document cannot declare it (VRML97: 14772-1 clause 6 lists every node a VRML97 file
    /// may use). The sentence was added to 7.2.5.4 by 19775-1 V3.1 (Amendment 1), read on
    /// the web3d.org V3.1 `core.html` page.
    /// > "A user shall declare all components and levels for the nodes and/or functionality being used either explicitly through the use of the COMPONENT statement or implicitly through the PROFILE statement" (19775-1 V3.1 7.2.5.4)
    pub static NODE_NOT_IN_VERSION = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    units_before_3_3(ctx);
    let mut found = Vec::new();
    let mut found_in_library = Vec::new();
    // The version every node reported has, when there is one: what the fix raises to.
    let mut target = Some(ctx.version);
    // The library bodies' nodes already reported, by body, line and type: a body is
    // copied at every instance, and its defect is one.
    let mut library_seen = HashSet::new();
    for (id, node) in ctx.doc.iter() {
        if let Some(place) = node.copy_of.and_then(|c| c.library) {
            if let NodeKind::Known { def, .. } = node.kind {
                if schema::schema(place.version).node(def.name).is_none()
                    && library_seen.insert((place.body, place.line, def.name))
                {
                    found_in_library.push(library_finding(id, node.name_span, def.name, place));
                }
            }
            continue;
        }
        if let NodeKind::Known { def, version } = node.kind {
            if version != ctx.version {
                let message = if ctx.version == Version::Vrml97 {
                    format!(
                        "VRML97 has no node {}; {} added it",
                        def.name,
                        first_with(|v| schema::schema(v).node(def.name).is_some()).name()
                    )
                } else {
                    format!(
                        "{} is not in {}; it is in {}",
                        def.name,
                        ctx.version.name(),
                        versions::describe(&versions::with_node(def.name))
                    )
                };
                let later = Version::X3D
                    .into_iter()
                    .find(|&v| v > ctx.version && schema::schema(v).node(def.name).is_some());
                target = target.zip(later).map(|(t, l)| t.max(l));
                found.push(Diagnostic::new(&NODE_NOT_IN_VERSION, node.name_span, message).node(id));
            }
        }
    }
    let fix = target.and_then(|target| raise_version(ctx, target));
    for mut diagnostic in found {
        if let Some(fix) = &fix {
            diagnostic = diagnostic.fix(fix.clone());
        }
        ctx.report(diagnostic);
    }
    // Raising this document's version does not change the library file's.
    for diagnostic in found_in_library {
        ctx.report(diagnostic);
    }
}

/// A node of an external prototype's body that its own file's version lacks.
fn library_finding(id: NodeId, span: Span, name: &str, place: LibraryPlace) -> Diagnostic {
    let message = if place.version == Version::Vrml97 {
        format!(
            "VRML97 (the version of the prototype's file) has no node {name}; {} added it",
            first_with(|v| schema::schema(v).node(name).is_some()).name()
        )
    } else {
        format!(
            "{name} is not in {} (the version of the prototype's file); it is in {}",
            place.version.name(),
            versions::describe(&versions::with_node(name))
        )
    };
    Diagnostic::new(&NODE_NOT_IN_VERSION, span, message).node(id)
}

/// Replaces the version as written with `target`'s number, and the number in the names of
/// the DTD and schema files an XML or JSON document's header names.
fn raise_version(ctx: &Ctx, target: Version) -> Option<Fix> {
    if ctx.version == Version::Vrml97 || target <= ctx.version {
        return None;
    }
    let written = ctx.doc.version_text.as_ref()?;
    let number = target.name().strip_prefix("X3D ")?;
    let text = ctx.source.get(written.span.range())?;
    let at = memchr::memmem::find(text, written.text.as_bytes())? + written.span.start as usize;
    let mut edits = vec![edits::edit(Span::new(at, at + written.text.len()), number)];
    let header_end = match ctx.doc.encoding {
        Encoding::Xml => edits::xml_header_end(ctx.source, written.span.end as usize),
        Encoding::Json => edits::json_header_end(ctx.source, written.span.end as usize),
        Encoding::ClassicVrml | Encoding::Vrml97 => None,
    };
    if let Some(end) = header_end {
        edits.extend(
            edits::schema_file_versions(ctx.source, end, &written.text)
                .into_iter()
                .map(|span| edits::edit(span, number)),
        );
    }
    Some(edits::fix(
        format!("Raise the version to {number}"),
        Applicability::Unsafe,
        edits,
    ))
}

/// The first X3D version where `has` holds: the one that added a node or field VRML97
/// lacks. The caller found it in some version, so one exists.
pub(crate) fn first_with(has: impl Fn(Version) -> bool) -> Version {
    Version::X3D
        .into_iter()
        .find(|&v| has(v))
        .unwrap_or(Version::LATEST)
}

/// The `unit` statement came with X3D 3.3 (19775-1 7.2.5.5: "UNIT statements may only be
/// contained in X3D worlds created for X3D version 3.3 or later"; a browser shall fail on
/// one in an earlier version). A statement is judged like a node here: NODE_UNKNOWN
/// covers unknown statements too.
fn units_before_3_3(ctx: &mut Ctx) {
    if ctx.version >= Version::V3_3 {
        return;
    }
    for unit in &ctx.doc.head.units {
        ctx.report(
            Diagnostic::new(
                &NODE_NOT_IN_VERSION,
                unit.span,
                format!(
                    "the unit statement is not in {}; X3D 3.3 introduced it",
                    ctx.version.name()
                ),
            )
            .help("declare version='3.3' or later, or remove the unit statement"),
        );
    }
}
