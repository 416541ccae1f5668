//! VALIDATION_INCOMPLETE: a part of the scene x3dcheck does not check.

use crate::model::Span;
use crate::report::Diagnostic;
use crate::validate::prototypes::externs::Resolved;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Says which parts of a scene were not checked, so that a partial check never reads
    /// as "valid": Script code; shader source; prototypes (ProtoDeclare bodies are
    /// checked as written, without substituting the values passed through `IS`;
    /// ExternProtoDeclare bodies live in other files: at the deep level, one whose url
    /// resolves to a ProtoDeclare in a local file of the tree has its interface compared
    /// with it and is not listed); IMPORT/EXPORT; Inline scenes.
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
    for (id, node) in ctx.doc.iter() {
        let what = if node.is_a("Script") {
            "Script code is not checked"
        } else if node.is_a("X3DShaderNode")
            || node.is_a("ShaderPart")
            || node.is_a("ShaderProgram")
        {
            "shader source is not checked"
        } else if node.is_a("Inline") {
            "the inlined scene is not checked"
        } else {
            continue;
        };
        found.push((
            node.name_span,
            Some(id),
            format!("{}: {what}", node.type_name()),
        ));
    }
    for (index, proto) in ctx.doc.protos.iter().enumerate() {
        // At the deep level an external prototype resolved to a local ProtoDeclare has its
        // interface compared with it (EXTERNPROTO_INTERFACE_MISMATCH, PROTO_CYCLE).
        let resolved = matches!(ctx.externs.get(index), Some(Resolved::Found { .. }));
        let what = if proto.external && resolved {
            continue;
        } else if proto.external {
            format!(
                "ExternProtoDeclare {}: its body is in another file and is not checked",
                proto.name.text
            )
        } else {
            format!(
                "ProtoDeclare {}: the body is checked as written, without the values its instances pass through IS",
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
