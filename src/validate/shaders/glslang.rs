//! The GLSL compiler (the `glsl` feature): Khronos glslang (the reference compiler, through
//! `glslang-sys`, the raw bindings of the `glslang` crate), compiling each shader part for
//! its stage and linking the parts of one program, as an OpenGL driver does.
//!
//! Why the raw bindings and not the `glslang` crate: its safe `Shader` compiles a source without
//! `#version` as GLSL ES 1.00 (its default version is 100) and links with Vulkan rules,
//! and its `smartstring` dependency adds `Add` impls to `String` that break `s + &t`
//! elsewhere; X3D content is desktop OpenGL GLSL, where no `#version` means 1.10 (GLSL 1.10
//! §3.3). Here the client is "none" (glslang's plain OpenGL GLSL validation, as
//! `glslangValidator` without `-V`/`-G`), the default version 110 with no profile (so
//! the compatibility built-ins of 1.10–1.50, `gl_ModelViewMatrix`, `gl_Vertex`,
//! `ftransform()`, compile), and the link uses glslang's default (OpenGL) rules.
//! Includes are refused (glslang would otherwise read `#include`d files from disk).

use std::ffi::{c_char, c_int, c_void, CStr, CString};
use std::ptr::{null_mut, NonNull};
use std::sync::OnceLock;

use glslang_sys as sys;

use super::glsl::{Compiled, Message, Program, Stage, Unversioned};
use super::limits::RESOURCES;

impl Stage {
    fn sys(self) -> sys::glslang_stage_t {
        match self {
            Stage::Vertex => sys::glslang_stage_t::Vertex,
            Stage::Fragment => sys::glslang_stage_t::Fragment,
            Stage::Geometry => sys::glslang_stage_t::Geometry,
            Stage::TessControl => sys::glslang_stage_t::TesselationControl,
            Stage::TessEvaluation => sys::glslang_stage_t::TesselationEvaluation,
        }
    }
}

/// The process-wide glslang initialisation, done on the first shader.
fn initialised() -> bool {
    static READY: OnceLock<bool> = OnceLock::new();
    // SAFETY: glslang_initialize_process has no preconditions; OnceLock runs it once.
    *READY.get_or_init(|| unsafe { sys::glslang_initialize_process() != 0 })
}

unsafe extern "C" fn refuse_include(
    _context: *mut c_void,
    _header: *const c_char,
    _includer: *const c_char,
    _depth: usize,
) -> *mut sys::glsl_include_result_t {
    null_mut()
}

unsafe extern "C" fn free_nothing(
    _context: *mut c_void,
    _result: *mut sys::glsl_include_result_t,
) -> c_int {
    0
}

struct Shader(NonNull<sys::glslang_shader_t>);

impl Drop for Shader {
    fn drop(&mut self) {
        // SAFETY: created by glslang_shader_create, deleted once, after its program.
        unsafe { sys::glslang_shader_delete(self.0.as_ptr()) }
    }
}

struct Linker(NonNull<sys::glslang_program_t>);

impl Drop for Linker {
    fn drop(&mut self) {
        // SAFETY: created by glslang_program_create, deleted once.
        unsafe { sys::glslang_program_delete(self.0.as_ptr()) }
    }
}

/// Compiles each part for its stage and, when `link` and all compile, links them into one
/// program. Sources must not contain NUL (the caller reports those). None when glslang
/// could not be initialised.
pub fn compile(parts: &[(Stage, &str)], link: bool, unversioned: Unversioned) -> Option<Program> {
    if !initialised() {
        return None;
    }
    let mut shaders = Vec::new();
    let mut results = Vec::new();
    for &(stage, source) in parts {
        let code = CString::new(source).ok()?;
        let input = sys::glslang_input_t {
            language: sys::glslang_source_t::GLSL,
            stage: stage.sys(),
            client: sys::glslang_client_t::None,
            client_version: sys::glslang_target_client_version_t::OpenGL450,
            target_language: sys::glslang_target_language_t::None,
            target_language_version: sys::glslang_target_language_version_t::SPIRV1_0,
            code: code.as_ptr(),
            default_version: match unversioned {
                Unversioned::Desktop110 => 110,
                Unversioned::Es100 => 100,
            },
            default_profile: sys::glslang_profile_t::None,
            force_default_version_and_profile: 0,
            forward_compatible: 0,
            messages: sys::glslang_messages_t::DEFAULT,
            resource: &RESOURCES,
            callbacks: sys::glsl_include_callbacks_t {
                include_system: Some(refuse_include),
                include_local: Some(refuse_include),
                free_include_result: Some(free_nothing),
            },
            callbacks_ctx: null_mut(),
        };
        // SAFETY: `input` and the strings it points to outlive every call below; glslang
        // copies the source in preprocess.
        let shader = Shader(NonNull::new(unsafe { sys::glslang_shader_create(&input) })?);
        let ok = unsafe {
            sys::glslang_shader_preprocess(shader.0.as_ptr(), &input) != 0
                && sys::glslang_shader_parse(shader.0.as_ptr(), &input) != 0
        };
        if ok {
            let preprocessed =
                unsafe { text(sys::glslang_shader_get_preprocessed_code(shader.0.as_ptr())) };
            results.push(Compiled::Ok { preprocessed });
            shaders.push(shader);
        } else {
            let log = unsafe { text(sys::glslang_shader_get_info_log(shader.0.as_ptr())) };
            results.push(Compiled::Failed(errors(&log)));
        }
    }
    let mut link_errors = Vec::new();
    if link && shaders.len() == parts.len() && !shaders.is_empty() {
        // SAFETY: the shaders outlive the program (dropped after it, declared before).
        let linker = Linker(NonNull::new(unsafe { sys::glslang_program_create() })?);
        for shader in &shaders {
            unsafe { sys::glslang_program_add_shader(linker.0.as_ptr(), shader.0.as_ptr()) };
        }
        let linked = unsafe {
            sys::glslang_program_link(linker.0.as_ptr(), sys::glslang_messages_t::DEFAULT.0)
        };
        if linked == 0 {
            let log = unsafe { text(sys::glslang_program_get_info_log(linker.0.as_ptr())) };
            link_errors = errors(&log);
        }
        drop(linker);
    }
    drop(shaders);
    Some(Program {
        parts: results,
        link_errors,
    })
}

/// A C string glslang owns, copied (lossily: logs quote the source, which may hold any
/// bytes).
unsafe fn text(pointer: *const c_char) -> String {
    if pointer.is_null() {
        return String::new();
    }
    CStr::from_ptr(pointer).to_string_lossy().into_owned()
}

/// The errors of a glslang log: `ERROR: 0:12: 'x' : undeclared identifier` gives line 12;
/// `ERROR: Linking fragment stage: …` none. The summary lines ("2 compilation errors. No
/// code generated.", "compilation terminated") repeat what the others say and are dropped.
fn errors(log: &str) -> Vec<Message> {
    let mut found: Vec<Message> = Vec::new();
    let mut in_error = false;
    for line in log.lines() {
        let Some(rest) = line.strip_prefix("ERROR: ") else {
            // A link error's details follow on indented lines ("    v: \"…\" versus \"…\"").
            let detail = line.trim();
            if in_error && line.starts_with(' ') && !detail.is_empty() {
                if let Some(last) = found.last_mut() {
                    last.text.push(' ');
                    last.text.push_str(detail);
                }
            } else {
                in_error = false;
            }
            continue;
        };
        in_error = true;
        let mut located = None;
        if let Some((string, after)) = rest.split_once(':') {
            if let Some((number, message)) = after.split_once(": ") {
                if string.bytes().all(|b| b.is_ascii_digit()) && !string.is_empty() {
                    if let Ok(number) = number.parse::<u32>() {
                        located = Some((number, message));
                    }
                }
            }
        }
        let (line, message) = match located {
            Some((number, message)) => (Some(number), message.trim()),
            None => (None, rest.trim()),
        };
        let summary = message.contains("compilation errors.")
            || message.ends_with("compilation terminated")
            || message.contains("No code generated");
        if !summary && !message.is_empty() {
            found.push(Message {
                line,
                text: tidy(message),
            });
        } else {
            in_error = false;
        }
    }
    found
}

/// `'' :  syntax error, …` → `syntax error, …`: glslang names no token there, and
/// pads its separators.
fn tidy(message: &str) -> String {
    let message = message.strip_prefix("'' :").unwrap_or(message);
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn first_error(stage: Stage, source: &str) -> Option<Message> {
        match compile(&[(stage, source)], true, Unversioned::Desktop110)
            .unwrap()
            .parts
            .remove(0)
        {
            Compiled::Ok { .. } => None,
            Compiled::Failed(messages) => Some(messages[0].clone()),
        }
    }

    #[test]
    fn the_versions_x3d_content_uses_compile() {
        let legacy = "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }";
        assert_eq!(first_error(Stage::Vertex, legacy), None);
        let v120 = "#version 120\nvarying vec2 t;\nvoid main() { gl_Position = ftransform(); t = gl_MultiTexCoord0.st; }";
        assert_eq!(first_error(Stage::Vertex, v120), None);
        let es100 =
            "#version 100\nprecision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }";
        assert_eq!(first_error(Stage::Fragment, es100), None);
        let es300 =
            "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }";
        assert_eq!(first_error(Stage::Fragment, es300), None);
        let v460 = "#version 460\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1.0); }";
        assert_eq!(first_error(Stage::Fragment, v460), None);
    }

    #[test]
    fn errors_name_their_line() {
        let error = first_error(
            Stage::Fragment,
            "void main()\n{\n  gl_FragColor = colour;\n}",
        )
        .expect("an undeclared identifier");
        assert_eq!(error.line, Some(3), "{error:?}");
        assert!(error.text.contains("colour"), "{error:?}");
    }

    #[test]
    fn includes_are_refused() {
        let source = "#version 460\n#extension GL_GOOGLE_include_directive : require\n#include \"/etc/passwd\"\nvoid main() {}";
        assert!(first_error(Stage::Vertex, source).is_some());
    }

    #[test]
    fn mismatched_varyings_fail_to_link() {
        let vertex = "varying vec3 v;\nvoid main() { v = vec3(1.0); gl_Position = ftransform(); }";
        let fragment = "varying vec4 v;\nvoid main() { gl_FragColor = v; }";
        let program = compile(
            &[(Stage::Vertex, vertex), (Stage::Fragment, fragment)],
            true,
            Unversioned::Desktop110,
        )
        .unwrap();
        assert!(program
            .parts
            .iter()
            .all(|p| matches!(p, Compiled::Ok { .. })));
        assert!(!program.link_errors.is_empty());
    }
}
