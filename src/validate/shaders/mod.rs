//! Programmable shaders (clause 31), RULES.md §8: the GLSL of ComposedShader and
//! ProgramShader compiled by glslang (`glsl`), from CDATA, `data:` URLs, source text in
//! url entries and, at the deep level, local files (`source`); their fields compared
//! with the uniforms the source declares (`uniforms`, Annex I). Nothing runs for a
//! document without shader nodes, and glslang is initialised on the first shader. Also
//! FloatVertexAttribute's value count (31.4.1).

use std::rc::Rc;

use super::{Check, Ctx};
use crate::diagnostic::Level;

pub mod analysis;
pub(crate) mod glsl;
#[cfg(feature = "glsl")]
mod glslang;
#[cfg(feature = "glsl")]
mod limits;
mod macros;
pub mod shader_compile_error;
pub mod shader_field_type_mismatch;
pub mod shader_field_undeclared;
pub(crate) mod source;
mod uniforms;
pub mod vertex_attribute_count_not_multiple;

pub use shader_compile_error::SHADER_COMPILE_ERROR;
pub use shader_field_type_mismatch::SHADER_FIELD_TYPE_MISMATCH;
pub use shader_field_undeclared::SHADER_FIELD_UNDECLARED;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &shader_compile_error::CHECK,
    &shader_field_undeclared::CHECK,
    &shader_field_type_mismatch::CHECK,
    &vertex_attribute_count_not_multiple::CHECK,
];

/// The document's shader analysis, made on first use (standard level and above: below it
/// nothing is compiled and VALIDATION_INCOMPLETE says so).
pub fn analysis(ctx: &mut Ctx) -> Rc<analysis::Analysis> {
    if let Some(done) = &ctx.shaders {
        return done.clone();
    }
    let done = Rc::new(if ctx.config.level >= Level::Standard {
        analysis::analyse(ctx)
    } else {
        analysis::Analysis::default()
    });
    ctx.shaders = Some(done.clone());
    done
}

/// Reports the analysis's findings of one rule.
fn report(ctx: &mut Ctx, code: &str) {
    let analysis = analysis(ctx);
    for finding in analysis.findings.iter().filter(|d| d.code() == code) {
        ctx.report(finding.clone());
    }
}
