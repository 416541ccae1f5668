//! One pass over a document's shaders, shared by the three shader rules and
//! VALIDATION_INCOMPLETE: find each part's source, compile the parts of each GLSL program
//! together, read their uniform declarations and compare the shader's fields with them.

use std::collections::{HashMap, HashSet};

use super::glsl::{self, Compiled, Stage, Unversioned};
use super::macros;
use super::source::{self, Found, Origin, Source};
use super::uniforms::{self, Uniform};
use super::{SHADER_COMPILE_ERROR, SHADER_FIELD_TYPE_MISMATCH, SHADER_FIELD_UNDECLARED};
use crate::diagnostic::{Diagnostic, Level};
use crate::model::{Document, FieldDecl, NodeId, Span};
use crate::schema::AccessType;
use crate::validate::texturing::files::Resolver;
use crate::validate::Ctx;

/// What the shader rules report, and the notes for VALIDATION_INCOMPLETE.
#[derive(Default)]
pub struct Analysis {
    pub findings: Vec<Diagnostic>,
    pub notes: Vec<(Span, NodeId, String)>,
}

/// A program to compile: the shader node whose fields feed it and its parts.
struct Program {
    owner: NodeId,
    parts: Vec<NodeId>,
}

/// Whether the document has a node the shader rules look at (so that documents without
/// shaders cost one scan of the node types and nothing else).
pub fn has_shaders(doc: &Document) -> bool {
    doc.iter()
        .take(doc.written_nodes().len())
        .any(|(_, node)| node.is_a("X3DShaderNode"))
}

pub fn analyse(ctx: &Ctx) -> Analysis {
    let mut analysis = Analysis::default();
    if !has_shaders(ctx.doc) {
        return analysis;
    }
    let resolver = (ctx.config.level >= Level::Deep)
        .then(|| Resolver::new(ctx.base, ctx.config.root.as_deref()));
    let mut programs = Vec::new();
    for (id, node) in ctx.doc.iter().take(ctx.doc.written_nodes().len()) {
        let name = node.type_name();
        if !node.is_a("X3DShaderNode") {
            continue;
        }
        if !matches!(name, "ComposedShader" | "ProgramShader") {
            analysis.notes.push((
                node.name_span,
                id,
                format!("{name}: shader source is not checked (only ComposedShader and ProgramShader GLSL is compiled)"),
            ));
            continue;
        }
        let language = node
            .value("language")
            .and_then(|v| v.as_strings())
            .and_then(|s| s.first())
            .map(String::as_str)
            .unwrap_or("");
        if language != "GLSL" {
            analysis.notes.push((
                node.name_span,
                id,
                format!("{name}: language \"{language}\" is not checked (only GLSL is compiled)"),
            ));
            continue;
        }
        if name == "ComposedShader" {
            let parts = node
                .children("parts")
                .iter()
                .map(|c| c.node)
                .filter(|&p| ctx.doc.node(p).is_a("ShaderPart"))
                .collect();
            programs.push(Program { owner: id, parts });
        } else {
            for program in node.children("programs") {
                if ctx.doc.node(program.node).is_a("ShaderProgram") {
                    programs.push(Program {
                        owner: program.node,
                        parts: vec![program.node],
                    });
                }
            }
        }
    }
    let mut seen_notes = HashSet::new();
    let mut seen_findings = HashSet::new();
    for program in programs {
        check_program(ctx, &program, resolver.as_ref(), &mut analysis);
    }
    analysis
        .notes
        .retain(|(span, _, message)| seen_notes.insert((*span, message.clone())));
    analysis
        .findings
        .retain(|d| seen_findings.insert((d.code(), d.span, d.message.clone())));
    analysis
}

fn check_program(ctx: &Ctx, program: &Program, resolver: Option<&Resolver>, out: &mut Analysis) {
    let doc = ctx.doc;
    let mut sources: Vec<(NodeId, Stage, Source)> = Vec::new();
    let mut complete = true;
    for &part in &program.parts {
        let node = doc.node(part);
        let ty = node
            .value("type")
            .and_then(|v| v.as_strings())
            .and_then(|s| s.first())
            .map_or("VERTEX", String::as_str);
        let Some(stage) = Stage::parse(ty) else {
            // FIELD_ENUM_INVALID reports the value.
            complete = false;
            out.notes.push((
                node.name_span,
                part,
                format!(
                    "{}: type \"{ty}\" names no shader stage; not compiled",
                    node.type_name()
                ),
            ));
            continue;
        };
        match source::find(doc, ctx.source, part, resolver) {
            Found::Source(found) => {
                if found.text.contains('\0') {
                    complete = false;
                    out.findings.push(
                        Diagnostic::new(
                            &SHADER_COMPILE_ERROR,
                            source::line_span(ctx.source, &found.origin, None),
                            format!(
                                "{} shader contains a NUL character, which GLSL does not allow",
                                ty
                            ),
                        )
                        .node(part),
                    );
                } else if !macros::nesting_within_bound(&found.text) {
                    complete = false;
                    out.notes.push((
                        node.name_span,
                        part,
                        format!(
                            "{}: not compiled: its brackets nest more than {} deep",
                            node.type_name(),
                            macros::MAX_NESTING
                        ),
                    ));
                } else if !macros::within_bound(&found.text) {
                    complete = false;
                    out.notes.push((
                        node.name_span,
                        part,
                        format!(
                            "{}: not compiled: its macros could expand to more than {} tokens",
                            node.type_name(),
                            macros::MAX_EXPANDED_TOKENS
                        ),
                    ));
                } else {
                    sources.push((part, stage, found));
                }
            }
            Found::Unavailable(note) => {
                complete = false;
                if let Some(note) = note {
                    out.notes.push((node.name_span, part, note));
                }
            }
        }
    }
    if sources.is_empty() {
        return;
    }
    let inputs: Vec<(Stage, &str)> = sources
        .iter()
        .map(|(_, stage, s)| (*stage, s.text.as_str()))
        .collect();
    // Without `#version` a source is GLSL 1.10 to a desktop browser and GLSL ES 1.00 to a
    // WebGL one (precision qualifiers compile only there): it is an error only when it
    // compiles as neither.
    let mut compiled = glsl::compile(&inputs, complete, Unversioned::Desktop110);
    let unversioned_failed = compiled.as_ref().is_some_and(|program| {
        program
            .parts
            .iter()
            .zip(&inputs)
            .any(|(result, (_, text))| {
                matches!(result, Compiled::Failed(_)) && !text.contains("#version")
            })
            || !program.link_errors.is_empty()
    });
    if unversioned_failed {
        if let Some(es) = glsl::compile(&inputs, complete, Unversioned::Es100) {
            let failures = |p: &glsl::Program| {
                p.parts
                    .iter()
                    .filter(|r| matches!(r, Compiled::Failed(_)))
                    .count()
                    + usize::from(!p.link_errors.is_empty())
            };
            if compiled
                .as_ref()
                .is_none_or(|desktop| failures(&es) < failures(desktop))
            {
                compiled = Some(es);
            }
        }
    }
    let Some(compiled) = compiled else {
        out.notes.push((
            doc.node(program.owner).name_span,
            program.owner,
            format!("shader source is not checked: {}", glsl::UNAVAILABLE),
        ));
        return;
    };
    let mut declared: HashMap<String, Uniform> = HashMap::new();
    let mut all_compiled = true;
    for ((part, stage, found), result) in sources.iter().zip(&compiled.parts) {
        match result {
            Compiled::Ok { preprocessed } => uniforms::declared(preprocessed, &mut declared),
            Compiled::Failed(messages) => {
                all_compiled = false;
                if let Some(name) = browser_defined(&found.text, messages.first()) {
                    let node = doc.node(*part);
                    out.notes.push((
                        node.name_span,
                        *part,
                        format!(
                            "{}: not checked: the source uses `{name}`, which it does not declare (a browser defines it for its own shaders)",
                            node.type_name()
                        ),
                    ));
                } else {
                    out.findings
                        .push(compile_error(ctx.source, *part, *stage, found, messages));
                }
            }
        }
    }
    if !compiled.link_errors.is_empty() {
        let owner = doc.node(program.owner);
        let first = &compiled.link_errors[0];
        let more = more(compiled.link_errors.len());
        out.findings.push(
            Diagnostic::new(
                &SHADER_COMPILE_ERROR,
                owner.name_span,
                format!(
                    "the parts of this {} do not link: {}{more}",
                    owner.type_name(),
                    first.text
                ),
            )
            .node(program.owner),
        );
        return;
    }
    if complete && all_compiled {
        compare_fields(ctx, program.owner, &declared, out);
    }
}

/// The `x3d_…` (X_ITE) or `castle_…` (Castle Game Engine) name the first error stands
/// on, when the source uses it there without having named it before: those browsers give
/// their shaders structures, constants and functions of such names
/// (`x3d_MaterialParameters`, `x3d_MaxLights`) that sources written for them use
/// undeclared. glslang's syntax errors do not quote the token, so the error's line is
/// read.
fn browser_defined(source: &str, first: Option<&glsl::Message>) -> Option<String> {
    let first = first?;
    let line = first.line? as usize;
    let lines: Vec<&str> = source.lines().collect();
    let text = lines.get(line.checked_sub(1)?)?;
    let before = lines[..line - 1].join("\n");
    let mut rest = *text;
    while let Some(at) = rest.find("x3d_").or_else(|| rest.find("castle_")) {
        let name = &rest[at..];
        let end = name
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(name.len());
        let name = &name[..end];
        let boundary = rest[..at]
            .chars()
            .last()
            .is_none_or(|c| !(c.is_ascii_alphanumeric() || c == '_'));
        if boundary && !before.contains(name) {
            return Some(name.to_string());
        }
        rest = &rest[at + end.max(1)..];
    }
    None
}

fn more(count: usize) -> String {
    match count {
        0 | 1 => String::new(),
        2 => " (and 1 more error)".to_string(),
        n => format!(" (and {} more errors)", n - 1),
    }
}

/// SHADER_COMPILE_ERROR at the first error's line.
fn compile_error(
    file: &[u8],
    part: NodeId,
    stage: Stage,
    found: &Source,
    messages: &[glsl::Message],
) -> Diagnostic {
    let stage = stage_name(stage);
    let Some(first) = messages.first() else {
        return Diagnostic::new(
            &SHADER_COMPILE_ERROR,
            source::line_span(file, &found.origin, None),
            format!("{stage} shader does not compile"),
        )
        .node(part);
    };
    let more = more(messages.len());
    let span = source::line_span(file, &found.origin, first.line);
    let message = match (&found.origin, first.line) {
        (Origin::File { url, .. }, Some(line)) => {
            format!(
                "{stage} shader \"{url}\" does not compile: {url}:{line}: {}{more}",
                first.text
            )
        }
        (Origin::File { url, .. }, None) => {
            format!(
                "{stage} shader \"{url}\" does not compile: {}{more}",
                first.text
            )
        }
        (
            Origin::Inline {
                first_line: Some(_),
                ..
            },
            _,
        )
        | (Origin::Inline { .. }, None) => {
            format!("{stage} shader does not compile: {}{more}", first.text)
        }
        (
            Origin::Inline {
                first_line: None, ..
            },
            Some(line),
        ) => format!(
            "{stage} shader does not compile: line {line} of its source: {}{more}",
            first.text
        ),
    };
    Diagnostic::new(&SHADER_COMPILE_ERROR, span, message).node(part)
}

fn stage_name(stage: Stage) -> &'static str {
    match stage {
        Stage::Vertex => "VERTEX",
        Stage::Fragment => "FRAGMENT",
        Stage::Geometry => "GEOMETRY",
        Stage::TessControl => "TESS_CONTROL",
        Stage::TessEvaluation => "TESS_EVALUATION",
    }
}

/// SHADER_FIELD_UNDECLARED and SHADER_FIELD_TYPE_MISMATCH for the fields of `owner`.
fn compare_fields(
    ctx: &Ctx,
    owner: NodeId,
    declared: &HashMap<String, Uniform>,
    out: &mut Analysis,
) {
    let node = ctx.doc.node(owner);
    let kind = node.type_name();
    for field in &node.declared {
        let Some(ty) = field.ty else { continue };
        // An outputOnly field sends events out of the shader node; nothing goes in.
        if field.access == Some(AccessType::OutputOnly) {
            continue;
        }
        let name = field.name.text.as_str();
        let texture = field_texture(ctx.doc, field);
        let Some(uniform) = declared.get(name) else {
            // Strings and nodes other than textures never reach a shader (Annex I).
            let passed = uniforms::accepted(ty).is_some() || texture.is_some();
            if passed {
                out.findings.push(
                    Diagnostic::new(
                        &SHADER_FIELD_UNDECLARED,
                        field.name.span,
                        format!("{kind} field `{name}` ({}) has no uniform of that name in its shader source: its value never reaches the shader", ty.as_str()),
                    )
                    .node(owner),
                );
            }
            continue;
        };
        let Some(glsl_type) = uniform.ty.as_deref() else {
            continue;
        };
        if !uniforms::is_builtin(glsl_type) {
            continue;
        }
        let fits: Option<&[&str]> = match texture {
            Some(texture) => uniforms::samplers_for(ctx.doc.node(texture)),
            None => uniforms::accepted(ty),
        };
        let Some(fits) = fits else { continue };
        if !fits.contains(&glsl_type) {
            let what = match texture {
                Some(texture) => format!("{} ({})", ty.as_str(), ctx.doc.node(texture).type_name()),
                None => ty.as_str().to_string(),
            };
            out.findings.push(
                Diagnostic::new(
                    &SHADER_FIELD_TYPE_MISMATCH,
                    field.name.span,
                    format!(
                        "{kind} field `{name}` is {what}, but its uniform is declared `{glsl_type}`; Annex I gives {what} to {}",
                        fits[0]
                    ),
                )
                .node(owner),
            );
        }
    }
}

/// The texture an SFNode/MFNode field holds first, if it holds one.
fn field_texture(doc: &Document, field: &FieldDecl) -> Option<NodeId> {
    let (value, _) = field.value.as_ref()?;
    let first = value.as_nodes()?.first()?;
    doc.node(first.node)
        .is_a("X3DTextureNode")
        .then_some(first.node)
}
