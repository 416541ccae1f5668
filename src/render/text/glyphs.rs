//! Glyph outlines filled into triangles, once per (face, glyph) and render: scenes
//! repeat characters, and a glyph's triangles are the same wherever it is placed. The
//! outlines come from ttf-parser, the triangles from lyon's fill tessellator with the
//! nonzero rule TrueType outlines are drawn with.

use std::collections::HashMap;

use lyon_tessellation::math::point;
use lyon_tessellation::path::Path;
use lyon_tessellation::{BuffersBuilder, FillOptions, FillTessellator, FillVertex, VertexBuffers};
use ttf_parser::{GlyphId, OutlineBuilder};

use super::fonts::FaceId;

/// How far the flattened curves may stray from the outline, in ems: a 1,000-pixel-tall
/// glyph (a text filling an 800 × 600 image) is off by at most a pixel.
const TOLERANCE_EM: f32 = 0.001;

/// A glyph's triangles in ems (the font's units divided by its units per em), counter-
/// clockwise seen from +z, with y up and the origin on the baseline.
#[derive(Debug, Default)]
pub struct GlyphMesh {
    pub points: Vec<[f32; 2]>,
    pub indices: Vec<u32>,
}

/// The glyphs tessellated during one render.
#[derive(Default)]
pub struct Glyphs {
    cache: HashMap<(FaceId, u16), GlyphMesh>,
}

impl Glyphs {
    /// The triangles of `glyph` of `face` (none for an empty glyph such as a space).
    pub fn get(&mut self, face: FaceId, glyph: GlyphId) -> &GlyphMesh {
        self.cache
            .entry((face, glyph.0))
            .or_insert_with(|| tessellate(face, glyph))
    }

    /// Distinct glyphs tessellated so far.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.cache.len()
    }
}

fn tessellate(face: FaceId, glyph: GlyphId) -> GlyphMesh {
    let font = face.face();
    let scale = 1.0 / f32::from(font.units_per_em().max(1));
    let mut outline = Outline {
        builder: Path::builder(),
        scale,
        open: false,
    };
    if font.outline_glyph(glyph, &mut outline).is_none() {
        return GlyphMesh::default();
    }
    if outline.open {
        outline.builder.end(true);
    }
    let path = outline.builder.build();
    let mut buffers: VertexBuffers<[f32; 2], u32> = VertexBuffers::new();
    let options = FillOptions::non_zero().with_tolerance(TOLERANCE_EM);
    let result = FillTessellator::new().tessellate_path(
        &path,
        &options,
        &mut BuffersBuilder::new(&mut buffers, |v: FillVertex| v.position().to_array()),
    );
    if result.is_err() {
        // The bundled fonts' outlines are well formed; a glyph lyon cannot fill is left out.
        return GlyphMesh::default();
    }
    let VertexBuffers {
        vertices: points,
        mut indices,
    } = buffers;
    // lyon does not promise a winding: make every triangle face +z.
    for t in indices.chunks_exact_mut(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| points[i as usize]);
        let twice_area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if twice_area < 0.0 {
            t.swap(1, 2);
        }
    }
    GlyphMesh { points, indices }
}

/// ttf-parser's outline calls as a lyon path, scaled to ems.
struct Outline {
    builder: lyon_tessellation::path::path::Builder,
    scale: f32,
    /// A contour is begun and not yet ended.
    open: bool,
}

impl Outline {
    fn at(&self, x: f32, y: f32) -> lyon_tessellation::math::Point {
        point(x * self.scale, y * self.scale)
    }
}

impl OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        if self.open {
            self.builder.end(true);
        }
        self.builder.begin(self.at(x, y));
        self.open = true;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        self.builder.line_to(self.at(x, y));
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        self.builder
            .quadratic_bezier_to(self.at(x1, y1), self.at(x, y));
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        self.builder
            .cubic_bezier_to(self.at(x1, y1), self.at(x2, y2), self.at(x, y));
    }

    fn close(&mut self) {
        if self.open {
            self.builder.end(true);
            self.open = false;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::fonts::{Family, Style};
    use super::*;

    const SANS: FaceId = FaceId {
        family: Family::Sans,
        style: Style::Plain,
    };

    fn area(mesh: &GlyphMesh) -> f32 {
        mesh.indices
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| mesh.points[i as usize]);
                ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])) / 2.0
            })
            .sum()
    }

    #[test]
    fn a_glyph_is_filled_counterclockwise_with_its_hole_left_open() {
        let mut glyphs = Glyphs::default();
        let face = SANS.face();
        let o = glyphs.get(SANS, face.glyph_index('O').unwrap());
        assert!(o.indices.chunks_exact(3).all(|t| {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| o.points[i as usize]);
            (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) >= 0.0
        }));
        let ring = area(o);
        // The O's ring is well under its bounding box (the hole is not filled).
        let bbox = face
            .glyph_bounding_box(face.glyph_index('O').unwrap())
            .unwrap();
        let em = f32::from(face.units_per_em());
        let box_area = f32::from(bbox.width()) * f32::from(bbox.height()) / em / em;
        assert!(
            ring > 0.2 * box_area && ring < 0.6 * box_area,
            "{ring} {box_area}"
        );
    }

    #[test]
    fn each_glyph_is_tessellated_once_and_a_space_is_empty() {
        let mut glyphs = Glyphs::default();
        let face = SANS.face();
        let a = face.glyph_index('a').unwrap();
        let first = glyphs.get(SANS, a).indices.len();
        assert!(first > 0);
        assert_eq!(glyphs.get(SANS, a).indices.len(), first);
        assert_eq!(glyphs.len(), 1);
        assert!(glyphs
            .get(SANS, face.glyph_index(' ').unwrap())
            .indices
            .is_empty());
    }
}
