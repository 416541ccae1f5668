//! The uniforms a program declares, and which GLSL types an X3D field's value can be given
//! to (19775-1 Annex I, OpenGL shading language binding).
//!
//! Declarations are read from glslang's preprocessed source (macros expanded, comments
//! and inactive `#if` branches gone), not from the uniforms a linker reports active: a
//! uniform the compiler optimises away is still declared, and a field naming it is not a
//! mistake of the author's (a browser's `glGetUniformLocation` returns -1 and the value
//! is dropped, as for a shader that reads it only on some paths). glslang's C interface
//! has no reflection anyway.

use std::collections::HashMap;

use crate::schema::FieldType;

/// A declared uniform: its type name (`vec3`, `sampler2D`, a struct's name) and whether it
/// is an array. `ty` is None for members of uniform blocks, which browsers cannot set one
/// by one and which are therefore only counted as declared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Uniform {
    pub ty: Option<String>,
    pub array: bool,
}

/// Qualifiers that may stand around `uniform` in a declaration.
const QUALIFIERS: &[&str] = &[
    "uniform",
    "const",
    "lowp",
    "mediump",
    "highp",
    "invariant",
    "precise",
    "coherent",
    "volatile",
    "restrict",
    "readonly",
    "writeonly",
    "flat",
    "smooth",
    "noperspective",
    "centroid",
];

/// The uniforms declared at the top level of a preprocessed source, by name.
pub fn declared(preprocessed: &str, into: &mut HashMap<String, Uniform>) {
    let tokens = tokens(preprocessed);
    let mut depth = 0usize;
    let mut statement: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < tokens.len() {
        let token = tokens[i];
        i += 1;
        if token.starts_with('#') {
            continue;
        }
        match token {
            "{" => {
                if depth == 0 && statement.contains(&"uniform") {
                    // A uniform block: its members are declared, but not settable one by one.
                    let end = closing(&tokens, i);
                    for member in members(&tokens[i..end]) {
                        into.entry(member.to_string()).or_insert(Uniform {
                            ty: None,
                            array: false,
                        });
                    }
                    i = end + 1;
                    // `} instance;`: the instance name is not a uniform of its own.
                    while i < tokens.len() && tokens[i] != ";" {
                        i += 1;
                    }
                    i += 1;
                    statement.clear();
                    continue;
                }
                depth += 1;
                statement.clear();
            }
            "}" => {
                depth = depth.saturating_sub(1);
                statement.clear();
            }
            ";" => {
                if depth == 0 && statement.contains(&"uniform") {
                    declarators(&statement, into);
                }
                statement.clear();
            }
            _ => statement.push(token),
        }
    }
}

/// The index of the `}` closing the block whose content starts at `from`.
fn closing(tokens: &[&str], from: usize) -> usize {
    let mut depth = 1;
    for (i, token) in tokens.iter().enumerate().skip(from) {
        match *token {
            "{" => depth += 1,
            "}" => {
                depth -= 1;
                if depth == 0 {
                    return i;
                }
            }
            _ => {}
        }
    }
    tokens.len()
}

/// The member names of a block's declarations (`float a, b[2]; vec3 c;`).
fn members<'a>(tokens: &[&'a str]) -> Vec<&'a str> {
    let mut names = Vec::new();
    for statement in tokens.split(|t| *t == ";") {
        let mut previous = None;
        let mut brackets = 0;
        for token in statement {
            match *token {
                "[" => brackets += 1,
                "]" => brackets -= 1,
                "," if brackets == 0 => names.extend(previous.take()),
                t if brackets == 0 && is_identifier(t) => previous = Some(t),
                _ => {}
            }
        }
        names.extend(previous);
    }
    names
}

/// `layout(…) uniform highp vec3 a, b[2] = …;` → a: vec3, b: vec3[].
fn declarators(statement: &[&str], into: &mut HashMap<String, Uniform>) {
    let mut rest = statement;
    let mut ty: Option<&str> = None;
    let mut type_array = false;
    while let Some((&first, tail)) = rest.split_first() {
        if first == "layout" {
            rest = skip_parens(tail);
        } else if QUALIFIERS.contains(&first) {
            rest = tail;
        } else {
            ty = Some(first);
            rest = tail;
            if rest.first() == Some(&"[") {
                type_array = true;
                rest = skip_brackets(rest);
            }
            break;
        }
    }
    let Some(ty) = ty else { return };
    let mut expect_name = true;
    let mut depth = 0i32;
    let mut k = 0;
    while k < rest.len() {
        let token = rest[k];
        match token {
            "(" | "[" if depth > 0 || !expect_name => depth += 1,
            ")" | "]" if depth > 0 => depth -= 1,
            "," if depth == 0 => expect_name = true,
            _ if depth == 0 && expect_name && is_identifier(token) => {
                let array = type_array || rest.get(k + 1) == Some(&"[");
                into.insert(
                    token.to_string(),
                    Uniform {
                        ty: Some(ty.to_string()),
                        array,
                    },
                );
                expect_name = false;
            }
            _ => {}
        }
        k += 1;
    }
}

fn skip_parens<'a, 'b>(tokens: &'a [&'b str]) -> &'a [&'b str] {
    skip_group(tokens, "(", ")")
}

fn skip_brackets<'a, 'b>(tokens: &'a [&'b str]) -> &'a [&'b str] {
    skip_group(tokens, "[", "]")
}

fn skip_group<'a, 'b>(tokens: &'a [&'b str], open: &str, close: &str) -> &'a [&'b str] {
    if tokens.first() != Some(&open) {
        return tokens;
    }
    let mut depth = 0;
    for (i, token) in tokens.iter().enumerate() {
        if *token == open {
            depth += 1;
        } else if *token == close {
            depth -= 1;
            if depth == 0 {
                return &tokens[i + 1..];
            }
        }
    }
    &[]
}

fn is_identifier(token: &str) -> bool {
    token.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
}

/// Identifiers and numbers as single tokens, a preprocessor line as one token, every other
/// character on its own.
fn tokens(text: &str) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    let mut line_start = true;
    while i < bytes.len() {
        let b = bytes[i];
        if b == b'\n' {
            line_start = true;
            i += 1;
            continue;
        }
        if b.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        if b == b'#' && line_start {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
        } else if b.is_ascii_alphanumeric() || b == b'_' || b == b'.' {
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || matches!(bytes[i], b'_' | b'.'))
            {
                i += 1;
            }
        } else {
            i += text[i..].chars().next().map_or(1, char::len_utf8);
        }
        line_start = false;
        found.push(&text[start..i]);
    }
    found
}

/// The GLSL types a field of `ty` can be given to: Table I.3 of Annex I maps each X3D
/// type to one GLSL type (SFBool → bool, SFInt32 → int, SFFloat, SFDouble and SFTime →
/// float, SFVec2* → vec2, SFVec3* and SFColor → vec3, SFVec4*, SFColorRGBA and
/// SFRotation → vec4, SFMatrix3* → mat3, SFMatrix4* → mat4, MF* → arrays of the same).
/// Where browsers set a uniform through a call the GLSL type also accepts, the check
/// takes that too, so that only values that cannot reach the uniform are reported:
/// `glUniform*i` sets bool and int vectors and sampler units, `glUniform*f` bool vectors
/// (OpenGL 4.6 7.6.1), double fields may meet `double` uniforms, and an SFRotation may
/// be taken as a `mat3` (X_ITE passes rotations so). None: the type is not mapped
/// (SFString, SFImage, SFNode: see [`sampler_fits`]), nothing to compare.
pub fn accepted(ty: FieldType) -> Option<&'static [&'static str]> {
    use FieldType::*;
    Some(match ty.single() {
        SFBool => &["bool", "int", "float"],
        SFInt32 => &[
            "int",
            "bool",
            "uint",
            "sampler1D",
            "sampler2D",
            "sampler3D",
            "samplerCube",
            "sampler2DShadow",
            "sampler2DRect",
            "sampler2DArray",
        ],
        SFFloat => &["float", "bool"],
        SFDouble | SFTime => &["float", "double", "bool"],
        SFVec2f | SFVec2d => &["vec2", "dvec2", "bvec2"],
        SFVec3f | SFVec3d | SFColor => &["vec3", "dvec3", "bvec3"],
        SFVec4f | SFVec4d | SFColorRGBA => &["vec4", "dvec4", "bvec4"],
        SFRotation => &["vec4", "mat3", "dvec4"],
        SFMatrix3f | SFMatrix3d => &["mat3", "dmat3", "mat3x3"],
        SFMatrix4f | SFMatrix4d => &["mat4", "dmat4", "mat4x4"],
        _ => return None,
    })
}

/// Table I.2: the sampler type a texture node is given to. None when the node is no
/// texture of the three kinds (the field is then ignored, Annex I).
pub fn samplers_for(texture: &crate::model::Node) -> Option<&'static [&'static str]> {
    if texture.is_a("X3DEnvironmentTextureNode") {
        Some(&["samplerCube", "samplerCubeShadow"])
    } else if texture.is_a("X3DTexture3DNode") {
        Some(&["sampler3D"])
    } else if texture.is_a("X3DTexture2DNode") {
        Some(&["sampler2D", "sampler2DShadow", "sampler2DRect"])
    } else {
        None
    }
}

/// Whether a GLSL type names a built-in type the tables speak of (a struct's name does
/// not: such uniforms are not compared).
pub fn is_builtin(ty: &str) -> bool {
    const SCALARS: &[&str] = &["bool", "int", "uint", "float", "double"];
    SCALARS.contains(&ty)
        || ty.starts_with("sampler")
        || ty.starts_with("isampler")
        || ty.starts_with("usampler")
        || ["vec", "ivec", "uvec", "bvec", "dvec", "mat", "dmat"]
            .iter()
            .any(|p| {
                ty.strip_prefix(p)
                    .is_some_and(|n| n.starts_with(|c: char| c.is_ascii_digit()))
            })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(source: &str) -> HashMap<String, Uniform> {
        let mut found = HashMap::new();
        declared(source, &mut found);
        found
    }

    #[test]
    fn declarations_are_read() {
        let found = scan(
            "#version 300 es\nprecision highp float;\nuniform highp vec3 a, b[2];\nlayout(location = 3) uniform mat4 m;\nuniform float[4] f;\nuniform float g = 1.0, h;\nvoid main() { float uniform_x; }\nstruct S { float s; };\nuniform S st;\nuniform Block { float member; } inst;",
        );
        let ty = |n: &str| found.get(n).map(|u| (u.ty.clone(), u.array));
        assert_eq!(ty("a"), Some((Some("vec3".into()), false)));
        assert_eq!(ty("b"), Some((Some("vec3".into()), true)));
        assert_eq!(ty("m"), Some((Some("mat4".into()), false)));
        assert_eq!(ty("f"), Some((Some("float".into()), true)));
        assert_eq!(ty("g"), Some((Some("float".into()), false)));
        assert_eq!(ty("h"), Some((Some("float".into()), false)));
        assert_eq!(ty("st"), Some((Some("S".into()), false)));
        assert_eq!(ty("member"), Some((None, false)));
        assert_eq!(ty("uniform_x"), None);
        assert_eq!(ty("s"), None);
        assert_eq!(ty("inst"), None);
    }

    #[test]
    fn types_are_mapped_as_annex_i_says() {
        assert!(accepted(FieldType::SFVec3f).unwrap().contains(&"vec3"));
        assert!(!accepted(FieldType::SFVec3f).unwrap().contains(&"vec4"));
        assert!(accepted(FieldType::MFFloat).unwrap().contains(&"float"));
        assert!(accepted(FieldType::SFString).is_none());
        assert!(is_builtin("vec3") && is_builtin("sampler2D") && is_builtin("mat4"));
        assert!(!is_builtin("x3d_MaterialParameters") && !is_builtin("material"));
    }
}
