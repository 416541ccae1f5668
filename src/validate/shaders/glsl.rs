//! The GLSL front end's results, and the compiler behind it: Khronos glslang
//! (`glslang.rs`, the `glsl` feature) or, in a build without it (the WebAssembly one, where
//! the C++ compiler cannot come along), none, and the shaders are reported as
//! VALIDATION_INCOMPLETE.

/// A stage a part is compiled for (ShaderPart.type, ShaderProgram.type).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Stage {
    Vertex,
    Fragment,
    Geometry,
    TessControl,
    TessEvaluation,
}

impl Stage {
    /// The stage a `type` value names (19775-1 31.4.7 ShaderPart, 31.4.8 ShaderProgram).
    pub fn parse(text: &str) -> Option<Stage> {
        Some(match text {
            "VERTEX" => Stage::Vertex,
            "FRAGMENT" => Stage::Fragment,
            "GEOMETRY" => Stage::Geometry,
            "TESS_CONTROL" => Stage::TessControl,
            "TESS_EVALUATION" => Stage::TessEvaluation,
            _ => return None,
        })
    }
}

/// One error glslang reported: the line of the source it names (1-based), if any.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Message {
    pub line: Option<u32>,
    pub text: String,
}

/// What compiling one part gave.
// Only the compiler makes these, and a build without it has none.
#[cfg_attr(not(feature = "glsl"), allow(dead_code))]
pub enum Compiled {
    /// The preprocessed source (macros expanded, comments and inactive `#if` branches
    /// gone), where uniform declarations are looked for.
    Ok {
        preprocessed: String,
    },
    Failed(Vec<Message>),
}

/// What compiling and linking the parts of one program gave: one result per part, and
/// the link errors when every part compiled.
pub struct Program {
    pub parts: Vec<Compiled>,
    pub link_errors: Vec<Message>,
}

/// The version a source without `#version` is compiled as.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Unversioned {
    /// GLSL 1.10, desktop OpenGL (GLSL 1.10 §3.3): Castle Game Engine, FreeWRL, Instant
    /// Player.
    Desktop110,
    /// GLSL ES 1.00, WebGL (GLSL ES 1.00 §3.4): X_ITE, X3DOM.
    Es100,
}

/// Compiles each part for its stage and, when `link` and all compile, links them into one
/// program; None when there is no compiler ([`UNAVAILABLE`]).
#[cfg(feature = "glsl")]
pub use super::glslang::compile;

/// This build has no compiler: nothing is compiled.
#[cfg(not(feature = "glsl"))]
pub fn compile(_: &[(Stage, &str)], _link: bool, _: Unversioned) -> Option<Program> {
    None
}

/// Why [`compile`] gave None, for VALIDATION_INCOMPLETE.
#[cfg(feature = "glsl")]
pub const UNAVAILABLE: &str = "the GLSL compiler could not be started";
#[cfg(not(feature = "glsl"))]
pub const UNAVAILABLE: &str =
    "this build of x3dcheck has no GLSL compiler (built without the `glsl` feature, as the WebAssembly one is)";
