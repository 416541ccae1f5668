//! SHADERS_REPLACE_LIGHTING: an Appearance with shaders.

use crate::diagnostic::Diagnostic;
use crate::model::NodeKind;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an Appearance whose `shaders` field holds a shader node: a node of an
    /// X3DShaderNode type (ComposedShader, PackagedShader, ProgramShader), or a prototype
    /// instance whose body's first node is one or whose body was not read (12.4.2: "The
    /// field shall contain one of the various types of shader nodes"). A node of an
    /// unknown type there (such as CommonSurfaceShader, an extension that NODE_UNKNOWN
    /// reports) is no shader a browser can select, so the fixed rendering still applies.
    ///
    /// ## Why it matters
    /// 12.4.2: "If the field is not empty, one shader node is selected and the fixed
    /// rendering requirements defined by this specification are ignored": material,
    /// texture and lighting rules no longer say what is drawn, and x3dcheck compiles GLSL
    /// (SHADER_COMPILE_ERROR) but does not run it, so the Shape's look is not verified.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance>
    ///   <ComposedShader language='GLSL'>…</ComposedShader>
    /// </Appearance>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.2 Appearance; 31 Programmable shaders component.
    pub static SHADERS_REPLACE_LIGHTING = {
        severity: Info,
        level: Standard,
        clause: "12.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Appearance") {
        let node = doc.node(id);
        let shaders: Vec<_> = node
            .children("shaders")
            .iter()
            .filter(|c| match doc.node(c.node).kind {
                // A body that was not read (an external prototype not found) is taken to
                // be the shader the field requires.
                NodeKind::ProtoInstance { .. } => doc
                    .built(c.node)
                    .is_none_or(|built| doc.node(built).is_a("X3DShaderNode")),
                _ => doc.node(c.node).is_a("X3DShaderNode"),
            })
            .collect();
        if let (Some(first), Some(entry)) = (shaders.first(), node.entry("shaders")) {
            let span = if entry.span.end > entry.span.start {
                entry.span
            } else {
                first.span
            };
            found.push((id, span, shaders.len()));
        }
    }
    for (id, span, count) in found {
        let nodes = if count == 1 {
            "a shader".to_string()
        } else {
            format!("{count} shaders")
        };
        ctx.report(
            Diagnostic::new(
                &SHADERS_REPLACE_LIGHTING,
                span,
                format!("Appearance has {nodes}: fixed lighting and texturing are replaced, and what it draws is not verified"),
            )
            .node(id),
        );
    }
}
