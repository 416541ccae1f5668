//! VALIDATION_INCOMPLETE: a part of the scene x3dcheck does not check.

use crate::model::Span;
use crate::report::Diagnostic;
use crate::validate::prototypes::externs::Resolved;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Says which parts of a scene were not checked, so that a partial check never reads
    /// as "valid": Script code below the standard level, and from it the Script code that
    /// is not ECMAScript, is on the network, or is in a `.js` file below the deep level
    /// (see SCRIPT_SYNTAX_ERROR); shader source; prototypes the document declares but never
    /// instantiates (their bodies are checked as written, with no values passed through
    /// `IS`); ExternProtoDeclare bodies, which live in other files (at the deep level, one
    /// whose url resolves to a ProtoDeclare in a local file of the tree has its interface
    /// compared with it and is not listed); IMPORT/EXPORT; Inline scenes.
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
            match crate::validate::scripting::unchecked(ctx, id) {
                Some(why) => why,
                None => continue,
            }
        } else if node.is_a("X3DShaderNode")
            || node.is_a("ShaderPart")
            || node.is_a("ShaderProgram")
        {
            "shader source is not checked".to_string()
        } else if node.is_a("Inline") {
            "the inlined scene is not checked".to_string()
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
    for &span in &ctx.doc.imports_exports {
        found.push((span, None, "IMPORT/EXPORT is not checked".to_string()));
    }
    for (span, node, message) in found {
        let mut diagnostic = Diagnostic::new(&VALIDATION_INCOMPLETE, span, message);
        diagnostic.node = node;
        ctx.report(diagnostic);
    }
}
