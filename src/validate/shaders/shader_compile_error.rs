//! SHADER_COMPILE_ERROR: GLSL that does not compile for its stage, or parts that do not link.

use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Compiles the GLSL of each ShaderPart of a ComposedShader and of each ShaderProgram
    /// of a ProgramShader whose `language` is `"GLSL"`, for the stage its `type` names
    /// (VERTEX, FRAGMENT, GEOMETRY, TESS_CONTROL, TESS_EVALUATION), with glslang, the
    /// Khronos reference compiler, and reports the first error of each part at its line
    /// in the X3D file (in a CDATA section, a ClassicVRML string, a url entry with line
    /// breaks) or, for a local file read at the deep level, as `file:line`. When every
    /// part of a ComposedShader compiles, the parts are linked as one program and a link
    /// error is reported at the ComposedShader.
    ///
    /// - Sources: the CDATA section (JSON `#sourceCode`), then the url entries in order
    ///   (9.2.1): `data:` URLs (base64 or percent-encoded, line breaks and `#` kept, as
    ///   X_ITE and Castle Game Engine read them), source text written in the entry
    ///   (31.2.2.1; an entry with no scheme holding a line break, `;` or `{`), and at the
    ///   deep level the first local file of the checked tree. Network URLs are not
    ///   fetched; parts with no source stay VALIDATION_INCOMPLETE.
    /// - Versions: what the source's `#version` says, 1.10 to 4.60 and ES 1.00 to 3.20;
    ///   without `#version`, GLSL 1.10 (GLSL 1.10 §3.3), whose built-ins
    ///   (`gl_ModelViewMatrix`, `gl_Vertex`, `ftransform()`) compile, as 1.20–1.50
    ///   compatibility ones do. Nothing is prepended: Annex I leaves the source to the
    ///   author. X_ITE and Castle Game Engine give their shaders structures, constants and
    ///   functions of their own (`x3d_MaterialParameters`, `x3d_MaxLights`) that a source
    ///   written for them uses undeclared; a part whose first error names an `x3d_…` or
    ///   `castle_…` identifier is therefore not reported but gets VALIDATION_INCOMPLETE.
    /// - Linking: a browser links the parts of a ComposedShader into one program object
    ///   (Annex I.3.3: LoadSensor reports a valid program only once it links) and a
    ///   program that fails to link draws nothing, as one that fails to compile does.
    ///   glslang's OpenGL link checks what a driver's does between parts: one `main` per
    ///   stage, functions called but defined in no part, and varyings and uniforms of one
    ///   name declared with different types in two stages. It does not require each
    ///   fragment input to be written by the vertex stage (neither does
    ///   GL_ARB_separate_shader_objects), so that is not reported.
    /// - Macros are bounded before glslang sees them (its preprocessor has no limit): a
    ///   source whose macros could expand past 4,000,000 tokens, or whose brackets nest
    ///   more than 256 deep, is not compiled and gets VALIDATION_INCOMPLETE. `#include`
    ///   is refused.
    ///
    /// Reported at the standard level for sources in the X3D file, at the deep level for
    /// local files.
    ///
    /// ## Why it matters
    /// A shader that does not compile or link is not used: the browser falls back to
    /// the next shader or to the Appearance's material, so the scene looks
    /// nothing like what the author wrote, and browsers report it only on their console.
    ///
    /// ## Example
    /// ```xml
    /// <ShaderPart type='FRAGMENT'><![CDATA[
    /// void main() { gl_FragColor = colour; }
    /// ]]></ShaderPart>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ShaderPart type='FRAGMENT'><![CDATA[
    /// uniform vec4 colour;
    /// void main() { gl_FragColor = colour; }
    /// ]]></ShaderPart>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 31.2.2 Shader language support, 31.4.7 ShaderPart, 31.4.8 ShaderProgram,
    /// Annex I (OpenGL shading language binding); the OpenGL Shading Language 1.10–4.60
    /// and OpenGL ES Shading Language 1.00–3.20 specifications.
    /// > "Compile-time errors must be returned for lexically or grammatically incorrect shaders." (The OpenGL Shading Language 4.60, 1 Introduction, Error Handling)
    /// > "Where the specification uses the terms required, must/must not, does/does not, disallowed, or not supported, the compiler or linker is required to detect and report any violations." (The OpenGL ES Shading Language 3.20, 1 Introduction, Error Handling)
    ///
    /// A part that glslang rejects breaks the language its `#version` names, which is
    /// the language 31.2.2 and Annex I bind the ShaderPart to. (Read in the
    /// KhronosGroup/GLSL sources, chapters/introduction.adoc.)
    pub static SHADER_COMPILE_ERROR = {
        severity: Error,
        level: Standard,
        clause: "31.4.7",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    super::report(ctx, SHADER_COMPILE_ERROR.code);
}
