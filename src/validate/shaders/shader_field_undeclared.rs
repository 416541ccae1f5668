//! SHADER_FIELD_UNDECLARED: a shader field no uniform of its program takes.

use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a field declared on a GLSL ComposedShader (or a ShaderProgram of a
    /// ProgramShader) whose name no part of the program declares as a uniform. Checked
    /// only when every part's source was found and compiled.
    ///
    /// - Declarations are read from each part's preprocessed source (macros expanded,
    ///   inactive `#if` branches gone), not from the linker's active uniforms: a uniform
    ///   the compiler optimises away because no path reads it is still declared, and a
    ///   field naming it is not reported. Members of uniform blocks count as declared.
    /// - Only fields whose values reach a shader are checked: outputOnly fields send
    ///   events out, and SFString/MFString fields and SFNode/MFNode fields not holding a
    ///   texture are ignored by the binding (Annex I), so they are not reported.
    ///
    /// ## Why it matters
    /// Annex I maps each field to the uniform of the same name; a field with none (a
    /// typo, a uniform renamed in the source) sends its value nowhere, silently.
    ///
    /// ## Example
    /// ```xml
    /// <ComposedShader language='GLSL'>
    ///   <field name='tint' type='SFColor' accessType='inputOutput' value='1 0 0'/>
    ///   <ShaderPart type='FRAGMENT'><![CDATA[
    ///   uniform vec3 tnt;
    ///   void main() { gl_FragColor = vec4(tnt, 1.0); }
    ///   ]]></ShaderPart>
    /// </ComposedShader>
    /// ```
    ///
    /// ## Use instead
    /// Name the uniform as the field: `uniform vec3 tint;`.
    ///
    /// ## Clause
    /// 19775-1 31.2.2 Shader languages, Annex I (OpenGL shading
    /// language binding: "the name of the field maps to the uniform variable of the same
    /// name").
    pub static SHADER_FIELD_UNDECLARED = {
        severity: Warning,
        level: Standard,
        clause: "I",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    super::report(ctx, SHADER_FIELD_UNDECLARED.code);
}
