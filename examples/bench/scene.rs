//! The generated benchmark scene: six Shapes, each an IndexedTriangleSet on a square grid
//! (a smooth random height field) with Coordinate, Normal (unit vectors computed from the
//! heights), TextureCoordinate and a triangle `index`, a Material and a PixelTexture,
//! inside Transforms. The same scene is written as X3D XML, X3D JSON and ClassicVRML.
//!
//! Deterministic: a fixed-seed splitmix64 drives everything, so the same generator version
//! and scale give byte-identical files. Numbers are written as exporters write them, with
//! trailing zeros dropped: coordinates with six significant digits (C's `%g`), normals
//! with three decimals, texture coordinates with four.

use std::fmt::Write as _;
use std::fs::{self, File};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// Bump when the output changes: the version is part of the file names, so an old file is
/// never mistaken for the current scene.
pub const GENERATOR_VERSION: u32 = 2;

pub const SHAPES: usize = 6;
/// Vertices per shape at scale 1.
const VERTICES: f64 = 160_000.0;
const SEED: u64 = 0x5833_4443_4845_434b; // "X3DCHECK"
/// Grid spacing in scene units (a tile is 19.95 units wide at scale 1).
const STEP: f64 = 0.05;

pub struct Scene {
    pub xml: PathBuf,
    pub json: PathBuf,
    pub classic: PathBuf,
    /// Vertices per shape (a square grid).
    pub vertices: usize,
    pub triangles: usize,
    pub generated: bool,
}

/// The scene files for `scale` in `dir`, generated when missing (or when `regenerate`).
pub fn ensure(dir: &Path, scale: f64, regenerate: bool) -> io::Result<Scene> {
    let side = grid_side(scale);
    let stem = format!("scene-g{GENERATOR_VERSION}-{side}x{side}x{SHAPES}");
    let xml = dir.join(format!("{stem}.x3d"));
    let json = dir.join(format!("{stem}.x3dj"));
    let classic = dir.join(format!("{stem}.x3dv"));
    let vertices = side * side;
    let triangles = 2 * (side - 1) * (side - 1);
    let exists = xml.is_file() && json.is_file() && classic.is_file();
    if exists && !regenerate {
        return Ok(Scene {
            xml,
            json,
            classic,
            vertices,
            triangles,
            generated: false,
        });
    }
    fs::create_dir_all(dir)?;
    // Written under temporary names and renamed, so an interrupted run leaves no file
    // that looks complete.
    let xml_tmp = dir.join(format!("{stem}.x3d.partial"));
    let json_tmp = dir.join(format!("{stem}.x3dj.partial"));
    let classic_tmp = dir.join(format!("{stem}.x3dv.partial"));
    write(side, &xml_tmp, &json_tmp, &classic_tmp)?;
    fs::rename(&xml_tmp, &xml)?;
    fs::rename(&json_tmp, &json)?;
    fs::rename(&classic_tmp, &classic)?;
    remove_old_versions(dir);
    Ok(Scene {
        xml,
        json,
        classic,
        vertices,
        triangles,
        generated: true,
    })
}

/// Removes scene files of other generator versions (about 170 MB each pair).
fn remove_old_versions(dir: &Path) {
    let current = format!("scene-g{GENERATOR_VERSION}-");
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        let ours = name.starts_with("scene-g")
            && (name.ends_with(".x3d") || name.ends_with(".x3dj") || name.ends_with(".x3dv"))
            && !name.starts_with(&current);
        if ours {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Grid points per side: 400 at scale 1 (160,000 vertices), at least 2.
fn grid_side(scale: f64) -> usize {
    let n = (VERTICES * scale.max(0.0)).sqrt().round() as usize;
    n.max(2)
}

/// splitmix64 (Steele, Lea, Flood 2014).
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// One shape's arrays, as text with single spaces between numbers.
struct ShapeText {
    index: String,
    point: String,
    vector: String,
    tex: String,
    diffuse: String,
    translation: String,
}

fn shape(side: usize, number: usize, rng: &mut Rng) -> ShapeText {
    // A height field: a sum of random waves plus a little noise.
    let waves: Vec<[f64; 5]> = (0..6)
        .map(|_| {
            [
                rng.range(0.2, 1.6),
                rng.range(0.1, 0.9),
                rng.range(0.1, 0.9),
                rng.range(0.0, std::f64::consts::TAU),
                rng.range(0.0, std::f64::consts::TAU),
            ]
        })
        .collect();
    let step = STEP;
    let extent = STEP * (side - 1) as f64;
    let coord = |i: usize| -10.0 + step * i as f64;
    let mut heights = vec![0.0f64; side * side];
    for j in 0..side {
        for i in 0..side {
            let (x, z) = (coord(i), coord(j));
            let smooth: f64 = waves
                .iter()
                .map(|w| w[0] * (w[1] * x + w[3]).sin() * (w[2] * z + w[4]).cos())
                .sum();
            heights[j * side + i] = smooth + rng.range(-0.005, 0.005);
        }
    }

    let mut g = Fmt::default();
    let mut point = String::with_capacity(side * side * 24);
    let mut vector = String::with_capacity(side * side * 28);
    let mut tex = String::with_capacity(side * side * 14);
    for j in 0..side {
        for i in 0..side {
            let h = |i: usize, j: usize| heights[j * side + i];
            g.push(&mut point, coord(i), 6);
            g.push(&mut point, h(i, j), 6);
            g.push(&mut point, coord(j), 6);
            // Central differences (one-sided at the border) of the written heights.
            let (i0, i1) = (i.saturating_sub(1), (i + 1).min(side - 1));
            let (j0, j1) = (j.saturating_sub(1), (j + 1).min(side - 1));
            let dx = (h(i1, j) - h(i0, j)) / (step * (i1 - i0) as f64);
            let dz = (h(i, j1) - h(i, j0)) / (step * (j1 - j0) as f64);
            let len = (dx * dx + 1.0 + dz * dz).sqrt();
            g.push_fixed(&mut vector, -dx / len, 3);
            g.push_fixed(&mut vector, 1.0 / len, 3);
            g.push_fixed(&mut vector, -dz / len, 3);
            g.push_fixed(&mut tex, i as f64 / (side - 1) as f64, 4);
            g.push_fixed(&mut tex, j as f64 / (side - 1) as f64, 4);
        }
    }
    // Two triangles per grid cell, counter-clockwise seen from +y (where the normals point).
    let mut index = String::with_capacity((side - 1) * (side - 1) * 6 * 7);
    for j in 0..side - 1 {
        for i in 0..side - 1 {
            let v00 = j * side + i;
            let (v10, v01, v11) = (v00 + 1, v00 + side, v00 + side + 1);
            for v in [v00, v01, v10, v10, v01, v11] {
                if !index.is_empty() {
                    index.push(' ');
                }
                let _ = write!(index, "{v}");
            }
        }
    }
    let mut diffuse = String::new();
    for _ in 0..3 {
        g.push(&mut diffuse, rng.range(0.2, 0.9), 3);
    }
    let mut translation = String::new();
    let gap = extent * 1.1;
    g.push(&mut translation, ((number % 3) as f64 - 1.0) * gap, 6);
    g.push(&mut translation, 0.0, 6);
    g.push(&mut translation, ((number / 3) as f64 - 0.5) * gap, 6);
    ShapeText {
        index,
        point,
        vector,
        tex,
        diffuse,
        translation,
    }
}

/// Writes numbers as C's `%g` does, separated by single spaces.
#[derive(Default)]
struct Fmt {
    scratch: String,
}

impl Fmt {
    /// `%.{sig}g`: `sig` significant digits, trailing zeros dropped, exponent form only for
    /// very small or large magnitudes.
    fn push(&mut self, out: &mut String, v: f64, sig: usize) {
        if !out.is_empty() {
            out.push(' ');
        }
        if v == 0.0 || !v.is_finite() {
            out.push('0');
            return;
        }
        self.scratch.clear();
        let _ = write!(self.scratch, "{:.*e}", sig - 1, v);
        let (mantissa, exp) = self.scratch.split_once('e').unwrap_or((&self.scratch, "0"));
        let exp: i32 = exp.parse().unwrap_or(0);
        if exp < -4 || exp >= sig as i32 {
            out.push_str(trim_zeros(mantissa));
            let _ = write!(out, "e{}{:02}", if exp < 0 { '-' } else { '+' }, exp.abs());
        } else {
            let start = out.len();
            let _ = write!(out, "{:.*}", (sig as i32 - 1 - exp) as usize, v);
            let kept = trim_zeros(&out[start..]).len();
            out.truncate(start + kept);
        }
    }

    /// `%.{decimals}f` with trailing zeros dropped.
    fn push_fixed(&mut self, out: &mut String, v: f64, decimals: usize) {
        if !out.is_empty() {
            out.push(' ');
        }
        let start = out.len();
        let _ = write!(out, "{v:.decimals$}");
        let kept = trim_zeros(&out[start..]).len();
        out.truncate(start + kept);
        if &out[start..] == "-0" {
            out.truncate(start);
            out.push('0');
        }
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

fn write(side: usize, xml_path: &Path, json_path: &Path, classic_path: &Path) -> io::Result<()> {
    let mut xml = BufWriter::with_capacity(1 << 20, File::create(xml_path)?);
    let mut json = BufWriter::with_capacity(1 << 20, File::create(json_path)?);
    let mut classic = BufWriter::with_capacity(1 << 20, File::create(classic_path)?);
    let schema = "https://www.web3d.org/specifications/x3d-4.0.xsd";
    let title = format!("x3dcheck benchmark scene (generator v{GENERATOR_VERSION})");
    let generator =
        format!("x3dcheck-bench, seed {SEED:#x}, {SHAPES} shapes of {side}x{side} vertices");

    write!(
        xml,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <X3D profile='Interchange' version='4.0' \
         xmlns:xsd='http://www.w3.org/2001/XMLSchema-instance' \
         xsd:noNamespaceSchemaLocation='{schema}'>\n\
         <head>\n\
         <meta name='title' content='{title}'/>\n\
         <meta name='generator' content='{generator}'/>\n\
         </head>\n\
         <Scene>\n\
         <Viewpoint description='Overview' position='0 45 55' orientation='1 0 0 -0.7'/>\n"
    )?;
    write!(
        json,
        "{{\"X3D\": {{\n\
         \"encoding\":\"UTF-8\",\n\
         \"@profile\":\"Interchange\",\n\
         \"@version\":\"4.0\",\n\
         \"@xsd:noNamespaceSchemaLocation\":\"{schema}\",\n\
         \"head\": {{\"meta\": [\n\
         {{\"@name\":\"title\",\"@content\":\"{title}\"}},\n\
         {{\"@name\":\"generator\",\"@content\":\"{generator}\"}}\n\
         ]}},\n\
         \"Scene\": {{\"-children\": [\n\
         {{\"Viewpoint\": {{\"@description\":\"Overview\",\"@position\":[0,45,55],\"@orientation\":[1,0,0,-0.7]}}}}"
    )?;

    write!(
        classic,
        "#X3D V4.0 utf8\n\
         PROFILE Interchange\n\
         META \"title\" \"{title}\"\n\
         META \"generator\" \"{generator}\"\n\
         Viewpoint {{ description \"Overview\" position 0 45 55 orientation 1 0 0 -0.7 }}\n"
    )?;

    let mut rng = Rng(SEED);
    for number in 0..SHAPES {
        let s = shape(side, number, &mut rng);
        let j = |text: &str| text.replace(' ', ",");
        writeln!(
            xml,
            "<Transform DEF='Tile{number}' translation='{}'>",
            s.translation
        )?;
        writeln!(xml, "<Shape>")?;
        writeln!(xml, "<Appearance>")?;
        writeln!(xml, "<Material diffuseColor='{}'/>", s.diffuse)?;
        writeln!(
            xml,
            "<PixelTexture image='2 2 3 0xFF0000 0x00FF00 0x0000FF 0xFFFFFF'/>"
        )?;
        writeln!(xml, "</Appearance>")?;
        writeln!(xml, "<IndexedTriangleSet index='{}'>", s.index)?;
        writeln!(xml, "<Coordinate point='{}'/>", s.point)?;
        writeln!(xml, "<Normal vector='{}'/>", s.vector)?;
        writeln!(xml, "<TextureCoordinate point='{}'/>", s.tex)?;
        writeln!(xml, "</IndexedTriangleSet>")?;
        writeln!(xml, "</Shape>")?;
        writeln!(xml, "</Transform>")?;

        write!(
            classic,
            "DEF Tile{number} Transform {{\n\
             translation {}\n\
             children Shape {{\n\
             appearance Appearance {{\n\
             material Material {{ diffuseColor {} }}\n\
             texture PixelTexture {{ image 2 2 3 0xFF0000 0x00FF00 0x0000FF 0xFFFFFF }}\n\
             }}\n\
             geometry IndexedTriangleSet {{\n\
             index [ {} ]\n\
             coord Coordinate {{ point [ {} ] }}\n\
             normal Normal {{ vector [ {} ] }}\n\
             texCoord TextureCoordinate {{ point [ {} ] }}\n\
             }}\n\
             }}\n\
             }}\n",
            s.translation, s.diffuse, s.index, s.point, s.vector, s.tex
        )?;

        write!(
            json,
            ",\n{{\"Transform\": {{\"@DEF\":\"Tile{number}\",\"@translation\":[{}],\"-children\": [\n\
             {{\"Shape\": {{\n\
             \"-appearance\": {{\"Appearance\": {{\n\
             \"-material\": {{\"Material\": {{\"@diffuseColor\":[{}]}}}},\n\
             \"-texture\": {{\"PixelTexture\": {{\"@image\":[2,2,3,16711680,65280,255,16777215]}}}}\n\
             }}}},\n\
             \"-geometry\": {{\"IndexedTriangleSet\": {{\n\
             \"@index\":[{}],\n\
             \"-coord\": {{\"Coordinate\": {{\"@point\":[{}]}}}},\n\
             \"-normal\": {{\"Normal\": {{\"@vector\":[{}]}}}},\n\
             \"-texCoord\": {{\"TextureCoordinate\": {{\"@point\":[{}]}}}}\n\
             }}}}\n\
             }}}}\n\
             ]}}}}",
            j(&s.translation),
            j(&s.diffuse),
            j(&s.index),
            j(&s.point),
            j(&s.vector),
            j(&s.tex)
        )?;
    }
    writeln!(xml, "</Scene>\n</X3D>")?;
    writeln!(json, "\n]}}\n}}}}")?;
    xml.flush()?;
    json.flush()?;
    classic.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_like_c_g() {
        let mut f = Fmt::default();
        let cases = [
            (1.0, "1"),
            (-0.5, "-0.5"),
            (123456.7, "123457"),
            (1234567.0, "1.23457e+06"),
            (0.000123456789, "0.000123457"),
            (0.0000123456789, "1.23457e-05"),
            (9.9999996, "10"),
            (-10.0, "-10"),
            (0.1, "0.1"),
        ];
        for (v, want) in cases {
            let mut s = String::new();
            f.push(&mut s, v, 6);
            assert_eq!(s, want, "{v}");
        }
    }
}
