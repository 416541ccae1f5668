//! SHADER_FIELD_TYPE_MISMATCH: a shader field whose uniform has a type its value cannot take.

use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Compares the type of each field of a GLSL ComposedShader (or ShaderProgram) with
    /// the type its uniform is declared with, by the mapping of 19775-1 Annex I.
    ///
    /// The mapping:
    ///
    /// | X3D field | GLSL uniform |
    /// |---|---|
    /// | SFBool | bool |
    /// | SFInt32 | int |
    /// | SFFloat, SFDouble, SFTime | float |
    /// | SFVec2f, SFVec2d | vec2 |
    /// | SFVec3f, SFVec3d, SFColor | vec3 |
    /// | SFVec4f, SFVec4d, SFColorRGBA, SFRotation | vec4 |
    /// | SFMatrix3f, SFMatrix3d | mat3 |
    /// | SFMatrix4f, SFMatrix4d | mat4 |
    /// | MF… of these | arrays of the same |
    /// | SFNode holding an X3DTexture2DNode / X3DTexture3DNode / X3DEnvironmentTextureNode | sampler2D / sampler3D / samplerCube (Table I.2) |
    ///
    /// Only values that cannot reach the uniform are reported, so the check also takes
    /// what the OpenGL calls browsers use accept (OpenGL 4.6 7.6.1): an int field for
    /// `bool` and sampler uniforms, bool vectors for float ones, `double` types for double
    /// fields, a `mat3` for an SFRotation (X_ITE passes rotations so), shadow and
    /// rectangle samplers for 2D textures. Arrays are not compared (a one-element MF value
    /// sets a plain uniform), nor uniforms of a structure type, nor fields of types the
    /// annex does not map (SFString, SFImage, nodes other than textures).
    ///
    /// ## Why it matters
    /// A browser sets the uniform with the call for the field's type; for another type
    /// OpenGL refuses it (GL_INVALID_OPERATION) and the uniform keeps its default, so the
    /// shader runs with a value the author never gave.
    ///
    /// ## Example
    /// ```xml
    /// <field name='tint' type='SFColor' accessType='inputOutput' value='1 0 0'/>
    /// <!-- in the source: uniform vec4 tint; -->
    /// ```
    ///
    /// ## Use instead
    /// `uniform vec3 tint;` for an SFColor, or an SFColorRGBA field for a `vec4`.
    ///
    /// ## Clause
    /// 19775-1 Annex I (OpenGL shading language binding), Tables I.2 and I.3.
    ///
    /// A warning (issue 32): the annex gives a mapping ("The texture types are mapped as
    /// defined in Table I.2", 19775-1 V4.0 Annex I), not a "shall" on the file; that OpenGL
    /// then refuses to set the uniform is a run-time matter of the browser's calls.
    pub static SHADER_FIELD_TYPE_MISMATCH = {
        severity: Warning,
        level: Standard,
        clause: "I",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    super::report(ctx, SHADER_FIELD_TYPE_MISMATCH.code);
}
