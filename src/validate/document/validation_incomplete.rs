//! VALIDATION_INCOMPLETE: a part of the scene x3dcheck does not check.

use crate::model::Span;
use crate::report::Diagnostic;
use crate::validate::networking::inlines::InlineTarget;
use crate::validate::prototypes::externs::Resolved;
use crate::validate::{Ctx, Level};

crate::declare_rule! {
    /// ## What it does
    /// Says which parts of a scene were not checked, so that a partial check never reads
    /// as "valid": Script code; shader source; prototypes the document declares but never
    /// instantiates (their bodies are checked as written, with no values passed through
    /// `IS`); ExternProtoDeclare bodies, which live in other files (at the deep level, one
    /// whose url resolves to a ProtoDeclare in a local file of the tree has its interface
    /// compared with it and is not listed); Inline scenes and IMPORT statements below the
    /// deep level, which reads the inlined files; at the deep level, an Inline whose local
    /// file is no X3D or VRML scene (glTF, which X3D 4 Inlines may load), and an IMPORT
    /// whose Inline's file is out of reach (network URLs, files outside the tree or missing,
    /// standard input: the Inline itself is noted by URL_UNRESOLVED). A local Inline's file
    /// is checked as a scene of its own at the deep level and gets no note.
    ///
    /// Each ProtoInstance of a ProtoDeclare is instantiated (19775-1 4.4.4) and every rule
    /// checks the nodes it builds with the values it passes, so a prototype with an
    /// instance is checked whole and gets no note here. A prototype with no instance in
    /// the document builds nothing in this scene (4.4.4: the body is not part of the
    /// transformation hierarchy; only instances are); but such a document is most often
    /// a prototype library that other scenes instantiate through ExternProtoDeclare with
    /// values x3dcheck does not see here, so the note stays: what its IS fields hold is
    /// not checked.
    ///
    /// ## Why it matters
    /// A clean report should mean the whole scene is right. Where x3dcheck cannot look,
    /// it says so.
    ///
    /// ## Example
    /// ```xml
    /// <Script DEF='S'><![CDATA[ecmascript: function initialize() {}]]></Script>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 29 Scripting, 31 Programmable shaders, 4.4.4 Prototype semantics,
    /// 9.4.2 Inline.
    pub static VALIDATION_INCOMPLETE = {
        severity: Info,
        level: Fast,
        clause: "4.4.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let mut found: Vec<(Span, Option<crate::model::NodeId>, String)> = Vec::new();
    // The nodes as written: a copy made for a prototype instance is the same Script.
    for (id, node) in ctx.doc.iter().take(ctx.doc.written_nodes().len()) {
        let what = if node.is_a("Script") {
            "Script code is not checked"
        } else if node.is_a("X3DShaderNode")
            || node.is_a("ShaderPart")
            || node.is_a("ShaderProgram")
        {
            "shader source is not checked"
        } else if node.is_a("Inline") {
            match inline_note(ctx, id) {
                Some(what) => what,
                None => continue,
            }
        } else {
            continue;
        };
        found.push((
            node.name_span,
            Some(id),
            format!("{}: {what}", node.type_name()),
        ));
    }
    let mut instantiated = vec![false; ctx.doc.protos.len()];
    for instantiation in &ctx.doc.instantiations {
        instantiated[instantiation.proto] = true;
    }
    for (index, proto) in ctx.doc.protos.iter().enumerate() {
        // At the deep level an external prototype resolved to a local ProtoDeclare has its
        // interface compared with it (EXTERNPROTO_INTERFACE_MISMATCH, PROTO_CYCLE).
        let resolved = matches!(ctx.externs.get(index), Some(Resolved::Found { .. }));
        let what = if instantiated[index] || (proto.external && resolved) {
            continue;
        } else if proto.external {
            format!(
                "ExternProtoDeclare {}: its body is in another file and is not checked",
                proto.name.text
            )
        } else {
            format!(
                "ProtoDeclare {}: no instance in this document, so the body is checked as written, without values passed through IS",
                proto.name.text
            )
        };
        found.push((proto.name.span, None, what));
    }
    // At the deep level IMPORT_UNRESOLVED resolves each IMPORT, and notes those whose
    // Inline's file is out of reach.
    if ctx.config.level < Level::Deep {
        for import in &ctx.doc.imports {
            found.push((
                import.span,
                None,
                format!(
                    "IMPORT {}.{}: the inlined file is read, and the import resolved, at the deep level only",
                    import.inline_def.text, import.imported_def.text
                ),
            ));
        }
    }
    for (span, node, message) in found {
        let mut diagnostic = Diagnostic::new(&VALIDATION_INCOMPLETE, span, message);
        diagnostic.node = node;
        ctx.report(diagnostic);
    }
}

/// What is not checked of an Inline's scene: below the deep level, all of it; at the deep
/// level, a local file that is no scene x3dcheck reads (glTF, say). Files out of reach
/// (network URLs, outside the tree, standard input) are URL_UNRESOLVED's notes; a file
/// read is checked as a scene of its own.
fn inline_note(ctx: &Ctx, id: crate::model::NodeId) -> Option<&'static str> {
    if ctx.config.level < Level::Deep {
        return Some("the inlined scene is read and checked at the deep level only");
    }
    match ctx.inlines.get(id)? {
        InlineTarget::Loaded { library, .. } if library.document.is_none() => {
            Some("its file is no X3D or VRML scene x3dcheck reads, and is not checked")
        }
        _ => None,
    }
}
