//! Text (15.4.2) as triangles: each string a line of glyphs in the local XY plane (z = 0),
//! laid out as its FontStyle (15.4.1) says, the glyph outlines of the bundled fonts
//! ([`fonts`]) filled once per render ([`Glyphs`]).
//!
//! How the clause's words are read:
//! - **Size** is the font's em: a glyph outline in ems is scaled by `size`; lines are
//!   `spacing × size` apart (15.2.2.3).
//! - **Edges of a line** (Tables 15.2–15.5, justify BEGIN and END): along the direction
//!   characters advance, a line runs from its first character's pen position to its last
//!   character's advance (horizontal), or over one `size` per character (vertical: the
//!   bundled fonts have no vertical metrics). Across it, a horizontal line spans the font's
//!   descender to its ascender around its baseline, a vertical line `size` centred on its
//!   axis. So justify MIDDLE centres each line's advance on x = 0, minor FIRST puts the
//!   first baseline on y = 0, minor BEGIN the first line's ascender.
//! - **length and maxExtent** (15.4.2) scale the glyphs and their spacing along the
//!   direction of advance (browsers may also change the space between characters).
//! - **Texture coordinates** (15.4.2): the origin at the first string's origin (where its
//!   first character starts, on its baseline or axis), one unit per `size`, s to the right
//!   and t up.
//! - **leftToRight FALSE** lays characters out from right to left as given; there is no
//!   bidirectional reordering, shaping or ligatures (one glyph per character, with the
//!   font's pair kerning).

pub mod fonts;
mod glyphs;

use ttf_parser::{Face, GlyphId};

use self::fonts::{family_of, style_of, FaceId};
use super::draw_list::Primitive;
use super::fields::{boolean, child, float, floats, type_is};
use super::geometry::Needs;
use super::mesh::LocalMesh;
use crate::model::{Document, NodeId};
pub use glyphs::Glyphs;

/// Justification along one axis (15.4.1 `justify`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Justify {
    First,
    Begin,
    Middle,
    End,
}

impl Justify {
    /// A `justify` value; "" and unknown values (reported by the checker) are `default`.
    fn of(value: Option<&String>, default: Justify) -> Justify {
        match value.map(String::as_str) {
            Some("FIRST") => Justify::First,
            Some("BEGIN") => Justify::Begin,
            Some("MIDDLE") => Justify::Middle,
            Some("END") => Justify::End,
            _ => default,
        }
    }
}

/// A FontStyle's values (or its defaults, for a Text without one).
struct Style {
    face: FaceId,
    size: f64,
    spacing: f64,
    horizontal: bool,
    left_to_right: bool,
    top_to_bottom: bool,
    major: Justify,
    minor: Justify,
}

/// A Text built: its mesh (None: nothing to draw) and what the report should say.
pub struct BuiltText {
    pub mesh: Option<LocalMesh>,
    pub notes: Vec<String>,
}

/// The characters of a Text's strings (the renderer's budget counts them before layout).
pub fn characters(doc: &Document, text: NodeId) -> usize {
    strings(doc, text).iter().map(|s| s.chars().count()).sum()
}

fn strings(doc: &Document, text: NodeId) -> Vec<String> {
    doc.value_of(text, "string")
        .and_then(|v| v.as_strings().map(<[String]>::to_vec))
        .unwrap_or_default()
}

/// Builds `text` with only what `needs` asks for (normals +z; every texture coordinate
/// set is the default mapping: Text has no texCoord field). Glyphs stop being added once
/// the mesh has more than `max_triangles` triangles, so that the caller's budget check
/// stops there without building the rest.
pub fn build(
    doc: &Document,
    text: NodeId,
    needs: &Needs,
    glyphs: &mut Glyphs,
    max_triangles: usize,
) -> BuiltText {
    let mut notes = Vec::new();
    let Some(style) = style(doc, text, &mut notes) else {
        return BuiltText { mesh: None, notes };
    };
    let font = style.face.face();
    let units_per_em = em(style.face);
    // A character the face lacks is drawn as a missing-glyph box: the face's own glyph 0,
    // or Liberation Sans's where the face's is empty (Liberation Serif's).
    let missing_box = if font.glyph_bounding_box(GlyphId(0)).is_some() {
        style.face
    } else {
        FaceId {
            family: fonts::Family::Sans,
            ..style.face
        }
    };
    let lines: Vec<Vec<(FaceId, GlyphId)>> = {
        let mut missing = 0usize;
        let lines = strings(doc, text)
            .iter()
            .map(|s| {
                s.chars()
                    .filter(|c| !c.is_control())
                    .map(|c| match font.glyph_index(c) {
                        Some(glyph) => (style.face, glyph),
                        None => {
                            missing += 1;
                            (missing_box, GlyphId(0))
                        }
                    })
                    .collect()
            })
            .collect();
        if missing > 0 {
            let characters = if missing == 1 {
                "character"
            } else {
                "characters"
            };
            notes.push(format!(
                "Text: {missing} {characters} that {} lacks drawn as a missing-glyph box",
                style.face.name()
            ));
        }
        lines
    };
    if lines.is_empty() {
        return BuiltText { mesh: None, notes };
    }

    // Each line's pen positions along its direction of advance, in ems.
    let pens: Vec<Pens> = lines.iter().map(|line| Pens::of(line, &style)).collect();
    let scales = major_scales(doc, text, &pens, style.size);
    let layout = Layout::new(&style, font, units_per_em, lines.len());

    let mut mesh = LocalMesh {
        primitive: Primitive::Triangles,
        ..LocalMesh::default()
    };
    let mut tex = Vec::new();
    let texture_origin = layout.point(0, pens[0].start(&style, scales[0]), 0.0);
    'lines: for (l, (line, pens)) in lines.iter().zip(&pens).enumerate() {
        let k = scales[l];
        let start = pens.start(&style, k);
        for (&(face, glyph), &pen) in line.iter().zip(&pens.at) {
            let shape = glyphs.get(face, glyph);
            if shape.indices.is_empty() {
                continue;
            }
            let advance = advance(face, glyph);
            let base = mesh.positions.len() as u32;
            for &[px, py] in &shape.points {
                let [x, y] =
                    layout.glyph_point(l, start, pen, advance, k, [f64::from(px), f64::from(py)]);
                mesh.positions.push([x as f32, y as f32, 0.0]);
                if !needs.tex_coords.is_empty() {
                    tex.push([
                        ((x - texture_origin[0]) / style.size) as f32,
                        ((y - texture_origin[1]) / style.size) as f32,
                    ]);
                }
            }
            mesh.indices.extend(shape.indices.iter().map(|&i| base + i));
            if mesh.indices.len() / 3 > max_triangles {
                break 'lines;
            }
        }
    }
    if needs.normals {
        mesh.normals = Some(vec![[0.0, 0.0, 1.0]; mesh.positions.len()]);
    }
    mesh.tex_coords = vec![tex; needs.tex_coords.len()];
    BuiltText {
        mesh: Some(mesh),
        notes,
    }
}

/// The Text's FontStyle values; None (noted) when the Text is not drawn.
fn style(doc: &Document, text: NodeId, notes: &mut Vec<String>) -> Option<Style> {
    let node = child(doc, text, "fontStyle");
    if node.is_some_and(|n| type_is(doc, n, "ScreenFontStyle")) {
        notes.push("Text with a ScreenFontStyle (sized in points on screen) is not drawn".into());
        return None;
    }
    let font_style = node.filter(|&n| type_is(doc, n, "FontStyle"));
    let strings_of = |name: &str| -> Vec<String> {
        font_style
            .and_then(|n| doc.value_of(n, name))
            .and_then(|v| v.as_strings().map(<[String]>::to_vec))
            .unwrap_or_default()
    };
    let float_of =
        |name: &str, default: f32| font_style.map_or(default, |n| float(doc, n, name, default));
    let bool_of = |name: &str| font_style.is_none_or(|n| boolean(doc, n, name, true));
    let families = strings_of("family");
    let (family, unknown) = family_of(&families);
    let style_name = font_style
        .and_then(|n| doc.string_of(n, "style"))
        .unwrap_or_default();
    let face = FaceId {
        family,
        style: style_of(&style_name),
    };
    if unknown {
        let listed: Vec<String> = families.iter().map(|f| format!("\"{f}\"")).collect();
        notes.push(format!(
            "FontStyle family {} is not bundled: drawn with SERIF ({})",
            listed.join(" "),
            face.name()
        ));
    }
    let size = f64::from(float_of("size", 1.0));
    // NaN too is not positive.
    if size.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        notes.push("Text whose FontStyle size is not positive is not drawn".into());
        return None;
    }
    let justify = strings_of("justify");
    Some(Style {
        face,
        size,
        spacing: f64::from(float_of("spacing", 1.0)),
        horizontal: bool_of("horizontal"),
        left_to_right: bool_of("leftToRight"),
        top_to_bottom: bool_of("topToBottom"),
        major: Justify::of(justify.first(), Justify::Begin),
        minor: Justify::of(justify.get(1), Justify::First),
    })
}

/// The units per em of `face`.
fn em(face: FaceId) -> f64 {
    f64::from(face.face().units_per_em().max(1))
}

/// A glyph's horizontal advance in ems.
fn advance(face: FaceId, glyph: GlyphId) -> f64 {
    f64::from(face.face().glyph_hor_advance(glyph).unwrap_or(0)) / em(face)
}

/// The pair kerning of `left` followed by `right`, in ems (horizontal subtables of the
/// `kern` table); none between glyphs of two faces.
fn kerning(left: (FaceId, GlyphId), right: (FaceId, GlyphId)) -> f64 {
    let face = left.0;
    if right.0 != face {
        return 0.0;
    }
    let (left, right) = (left.1, right.1);
    let Some(kern) = face.face().tables().kern else {
        return 0.0;
    };
    let units: i32 = kern
        .subtables
        .into_iter()
        .filter(|s| s.horizontal && !s.variable && !s.has_cross_stream)
        .filter_map(|s| s.glyphs_kerning(left, right))
        .map(i32::from)
        .sum();
    f64::from(units) / em(face)
}

/// Where each character of a line starts along the direction of advance, and the
/// line's length, in ems.
struct Pens {
    at: Vec<f64>,
    length: f64,
}

impl Pens {
    fn of(line: &[(FaceId, GlyphId)], style: &Style) -> Pens {
        if !style.horizontal {
            // One em per character (the bundled fonts have no vertical metrics).
            return Pens {
                at: (0..line.len()).map(|i| i as f64).collect(),
                length: line.len() as f64,
            };
        }
        let mut at = Vec::with_capacity(line.len());
        let mut pen = 0.0;
        for (i, &glyph) in line.iter().enumerate() {
            at.push(pen);
            pen += advance(glyph.0, glyph.1);
            if let Some(&next) = line.get(i + 1) {
                // Kerning pairs are in visual order, left glyph first.
                pen += if style.left_to_right {
                    kerning(glyph, next)
                } else {
                    kerning(next, glyph)
                };
            }
        }
        Pens { at, length: pen }
    }

    /// Where the line starts along its axis, justified (15.2.2.3, major alignment), its
    /// length scaled by `k`: BEGIN (and FIRST) put the start on 0, END the end, MIDDLE the
    /// middle.
    fn start(&self, style: &Style, k: f64) -> f64 {
        let length = self.length * style.size * k;
        let direction = major_direction(style);
        match style.major {
            Justify::First | Justify::Begin => 0.0,
            Justify::Middle => -direction * length / 2.0,
            Justify::End => -direction * length,
        }
    }
}

/// +1 or −1: the direction characters advance along the major axis (x when horizontal,
/// else y).
fn major_direction(style: &Style) -> f64 {
    let forward = if style.horizontal {
        style.left_to_right
    } else {
        !style.top_to_bottom
    };
    if forward {
        1.0
    } else {
        -1.0
    }
}

/// Each line's scale along the direction of advance: `length` stretches or compresses a
/// line to its length (0 or missing: its own), then `maxExtent` compresses every line
/// when the longest is longer (15.4.2).
fn major_scales(doc: &Document, text: NodeId, pens: &[Pens], size: f64) -> Vec<f64> {
    let lengths = floats(doc, text, "length");
    let mut scales: Vec<f64> = pens
        .iter()
        .enumerate()
        .map(|(l, p)| {
            let natural = p.length * size;
            match lengths.get(l).map(|&v| f64::from(v)) {
                Some(wanted) if wanted > 0.0 && wanted.is_finite() && natural > 0.0 => {
                    wanted / natural
                }
                _ => 1.0,
            }
        })
        .collect();
    let max_extent = f64::from(float(doc, text, "maxExtent", 0.0));
    let longest = pens
        .iter()
        .zip(&scales)
        .map(|(p, k)| p.length * size * k)
        .fold(0.0, f64::max);
    if max_extent > 0.0 && longest > max_extent {
        let shrink = max_extent / longest;
        for k in &mut scales {
            *k *= shrink;
        }
    }
    scales
}

/// Where lines go across the direction of advance (15.2.2.3, minor alignment).
struct Layout {
    horizontal: bool,
    major_direction: f64,
    size: f64,
    /// Line l's baseline (horizontal) or axis (vertical) is at `first + l × step`.
    first: f64,
    step: f64,
    /// A vertical glyph's baseline below the middle of its cell, in ems.
    middle: f64,
}

impl Layout {
    fn new(style: &Style, font: &Face, em: f64, lines: usize) -> Layout {
        let size = style.size;
        // The direction successive lines go, and a line's extent across it around its
        // baseline or axis.
        let (direction, [low, high]) = if style.horizontal {
            let direction = if style.top_to_bottom { -1.0 } else { 1.0 };
            let extent = [
                f64::from(font.descender()) / em * size,
                f64::from(font.ascender()) / em * size,
            ];
            (direction, extent)
        } else {
            let direction = if style.left_to_right { 1.0 } else { -1.0 };
            (direction, [-size / 2.0, size / 2.0])
        };
        let step = direction * style.spacing * size;
        // The edge a line meets first and the one it meets last, going the line direction.
        let (start_edge, end_edge) = if direction < 0.0 {
            (high, low)
        } else {
            (low, high)
        };
        let last = (lines.saturating_sub(1)) as f64 * step;
        let first = match style.minor {
            Justify::First if style.horizontal => 0.0,
            Justify::First | Justify::Begin => -start_edge,
            Justify::End => -(last + end_edge),
            Justify::Middle => -(last + start_edge + end_edge) / 2.0,
        };
        let middle = (f64::from(font.ascender()) + f64::from(font.descender())) / 2.0 / em;
        Layout {
            horizontal: style.horizontal,
            major_direction: major_direction(style),
            size,
            first,
            step,
            middle,
        }
    }

    /// The local point at `along` on line `line`'s axis, `across` off it.
    fn point(&self, line: usize, along: f64, across: f64) -> [f64; 2] {
        let minor = self.first + line as f64 * self.step + across;
        if self.horizontal {
            [along, minor]
        } else {
            [minor, along]
        }
    }

    /// Outline point `p` (ems) of a glyph of `advance` ems whose character starts at
    /// `pen` ems along line `line`, which starts at `start` and is scaled by `k`.
    fn glyph_point(
        &self,
        line: usize,
        start: f64,
        pen: f64,
        advance: f64,
        k: f64,
        [px, py]: [f64; 2],
    ) -> [f64; 2] {
        let (size, d) = (self.size, self.major_direction);
        if self.horizontal {
            // Going left, a character's outline starts where its advance ends.
            let origin = if d > 0.0 { pen } else { -(pen + advance) };
            self.point(line, start + (origin + px) * size * k, py * size)
        } else {
            // Centred in its one-em cell, across and along.
            let centre = start + d * (pen + 0.5) * size * k;
            self.point(
                line,
                centre + (py - self.middle) * size * k,
                (px - advance / 2.0) * size,
            )
        }
    }
}
