//! VALIDATION_INCOMPLETE: a part of the scene x3dcheck does not check.

use crate::diagnostic::{Diagnostic, Level};
use crate::model::Span;
use crate::validate::networking::inlines::InlineTarget;
use crate::validate::prototypes::externs::Resolved;
use crate::validate::texturing::files::{not_fetched, Resolution, Resolver};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Says which parts of a scene were not checked, so that a partial check never reads
    /// as "valid": Script code below the standard level, and from it the Script code that
    /// is not ECMAScript, is on the network, or is in a `.js` file below the deep level
    /// (see SCRIPT_SYNTAX_ERROR); shader source (below the standard level; from it on,
    /// what the GLSL compiler could not check: other languages, PackagedShader, sources
    /// in network or, below deep, local files); the bodies of external prototypes that
    /// x3dcheck cannot read; Inline scenes and IMPORT statements below the deep level,
    /// which reads the inlined files; at the deep level, an Inline whose local file is no
    /// X3D or VRML scene (glTF, which X3D 4 Inlines may load), and an IMPORT whose Inline's
    /// file is out of reach (network URLs, files outside the tree or missing, standard
    /// input: the Inline itself is noted by URL_UNRESOLVED). A local Inline's file is
    /// checked as a scene of its own at the deep level and gets no note. In a web page
    /// that is a server's template, the attribute values that are placeholders
    /// (`url="{{ model.inline }}"`) are left out, and one note says how many.
    ///
    /// Prototypes: each ProtoInstance of a ProtoDeclare is instantiated (19775-1 4.4.4)
    /// and every rule checks the nodes it builds with the values it passes. A ProtoDeclare
    /// with no instance in the document gets no note: it builds nothing in this scene
    /// (4.4.4: a body is not part of the transformation hierarchy; only instances are), and
    /// its body is checked as written (each node, each IS statement's names and types);
    /// the values another scene passes to it are checked in that scene, where its
    /// instances are. Below the deep level an ExternProtoDeclare's body is not looked for
    /// ("its body is in another file"); at the deep level one whose url resolves to a
    /// local file is instantiated from it, one whose local files exist without the
    /// prototype is EXTERNPROTO_NOT_FOUND, and one whose url names only local files that do
    /// not exist is URL_UNRESOLVED; what remains here is a url x3dcheck does not read: a
    /// network URL (never fetched; a browser falls back to it when the local entries
    /// before it are missing), a file outside the tree being checked, or a relative URL of
    /// a document read from standard input.
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
    /// 19775-1 29 Scripting, 31 Programmable shaders, 4.4.4 Prototype semantics, 4.4.5
    /// External prototype semantics, 9.2.1 URLs, 9.4.2 Inline.
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
            match crate::validate::scripting::unchecked(ctx, id) {
                Some(why) => why,
                None => continue,
            }
        } else if node.is_a("X3DShaderNode")
            || node.is_a("ShaderPart")
            || node.is_a("ShaderProgram")
        {
            // From the standard level on, GLSL is compiled and the shader rules say what
            // was not (validate/shaders).
            if ctx.config.level >= crate::diagnostic::Level::Standard {
                continue;
            }
            "shader source is not checked".to_string()
        } else if node.is_a("Inline") {
            match inline_note(ctx, id) {
                Some(what) => what.to_string(),
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
    let deep = ctx.config.level >= Level::Deep;
    for (index, proto) in ctx.doc.protos.iter().enumerate() {
        if !proto.external {
            continue;
        }
        let what = if !deep {
            format!(
                "ExternProtoDeclare {}: its body is in another file and is not checked",
                proto.name.text
            )
        } else if let Some(Resolved::Unresolved) = ctx.externs.get(index) {
            let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
            let unread = proto
                .url
                .iter()
                .find_map(|url| match resolver.resolve(url) {
                    Resolution::Network(_) => Some(not_fetched(url)),
                    Resolution::Outside(_) => Some(format!(
                        "\"{url}\" is outside the directory tree being checked and is not read"
                    )),
                    Resolution::NoBase => Some(
                        "relative URLs of a document read from standard input are not resolved"
                            .to_string(),
                    ),
                    _ => None,
                });
            // Only missing local files: URL_UNRESOLVED.
            let Some(unread) = unread else {
                continue;
            };
            format!(
                "ExternProtoDeclare {}: its body is not checked: {unread}",
                proto.name.text
            )
        } else {
            continue;
        };
        found.push((proto.name.span, None, what));
    }
    if ctx.config.level >= crate::diagnostic::Level::Standard {
        let shaders = crate::validate::shaders::analysis(ctx);
        for (span, node, message) in &shaders.notes {
            found.push((*span, Some(*node), message.clone()));
        }
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
    // The attribute values of a page template (`url="{{ model.inline }}"`), left out by
    // the HTML reader: the page is checked without them.
    if let Some(&first) = ctx.doc.template_values.first() {
        let count = ctx.doc.template_values.len();
        let values = if count == 1 {
            "an attribute value is a template placeholder".to_string()
        } else {
            format!("{count} attribute values are template placeholders")
        };
        found.push((
            first,
            None,
            format!("{values} (`{{{{ … }}}}`, `{{% … %}}`) that a server fills in: not checked"),
        ));
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
