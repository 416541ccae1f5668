//! The Layout component (19775-1 clause 36): a LayoutLayer draws its children in 2D
//! regions of its rectangle of the image, not moved by any viewpoint (36.2.1). Each
//! Layout (36.4.1) sizes and aligns a rectangle within its parent's (the layer's, or an
//! enclosing LayoutGroup's, 36.4.2) and sets the scale its children are drawn at.
//!
//! Readings where the text leaves a choice (they agree with X_ITE):
//! - The layer is seen through an orthographic camera at +Z whose smaller side spans 2
//!   "layer units" (the default OrthoViewpoint's −1 … 1); a layout's translation and
//!   scale are in layer units, depth (z) is left unscaled.
//! - The children's origin is the centre of their rectangle.
//! - WORLD sizes and offsets are in the parent's child units (its scale); the layer itself
//!   has no parent layout, so there WORLD is FRACTION of the layer and scaleMode NONE (the
//!   parent's scale) is FRACTION too (36.4.1).
//! - STRETCH on one axis takes the other axis's scale; on both, the larger side's.
//! - A LayoutLayer or LayoutGroup without a Layout adds no transformation.

use glam::{DMat4, DVec2, DVec3};

use crate::model::{Document, NodeId};
use crate::render::fields::floats;

/// The rectangle a layout sets up, in layer units, and the scale of its children.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Region {
    /// Width and height.
    pub size: DVec2,
    /// Layer units per child unit, horizontally and vertically.
    pub scale: DVec2,
}

/// The layer a layout lies in: its size in layer units, and the units of a pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Surface {
    pub size: DVec2,
    pub unit_per_pixel: f64,
}

impl Surface {
    /// A layer drawn over `width` × `height` pixels: its smaller side spans 2 units.
    pub fn of_pixels(width: f64, height: f64) -> Surface {
        let unit_per_pixel = 2.0 / width.min(height).max(1.0);
        Surface {
            size: DVec2::new(width, height) * unit_per_pixel,
            unit_per_pixel,
        }
    }

    /// The layer as a parent: one child unit is its whole width or height.
    pub fn region(&self) -> Region {
        Region {
            size: self.size,
            scale: self.size,
        }
    }
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Align {
    Low,
    Centre,
    High,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Unit {
    World,
    Fraction,
    Pixel,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum ScaleMode {
    None,
    Fraction,
    Stretch,
    Pixel,
}

/// A Layout node's values (36.4.1), per axis (horizontal, vertical). One value given for
/// a pair applies to both.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    align: [Align; 2],
    offset: [f64; 2],
    offset_units: [Unit; 2],
    size: [f64; 2],
    size_units: [Unit; 2],
    scale_mode: [ScaleMode; 2],
}

impl Default for Layout {
    fn default() -> Self {
        Layout {
            align: [Align::Centre; 2],
            offset: [0.0; 2],
            offset_units: [Unit::World; 2],
            size: [1.0; 2],
            size_units: [Unit::World; 2],
            scale_mode: [ScaleMode::None; 2],
        }
    }
}

impl Layout {
    /// The Layout `id`; values out of their enumerations (reported by the checker) are
    /// the defaults.
    pub fn of(doc: &Document, id: NodeId) -> Layout {
        let strings = |name: &str| -> Vec<String> {
            doc.value_of(id, name)
                .and_then(|v| v.as_strings().map(<[String]>::to_vec))
                .unwrap_or_default()
        };
        let pair = |values: Vec<String>, read: &dyn Fn(&str, usize) -> Option<u8>| {
            let first = values.first().and_then(|v| read(v, 0));
            let second = values.get(1).and_then(|v| read(v, 1)).or(first);
            [first, second]
        };
        let align = pair(strings("align"), &|v, axis| match (v, axis) {
            ("LEFT", 0) | ("BOTTOM", 1) => Some(0),
            ("CENTER", _) => Some(1),
            ("RIGHT", 0) | ("TOP", 1) => Some(2),
            _ => None,
        })
        .map(|a| match a {
            Some(0) => Align::Low,
            Some(2) => Align::High,
            _ => Align::Centre,
        });
        let unit = |name: &str| {
            pair(strings(name), &|v, _| match v {
                "WORLD" => Some(0),
                "FRACTION" => Some(1),
                "PIXEL" => Some(2),
                _ => None,
            })
            .map(|u| match u {
                Some(1) => Unit::Fraction,
                Some(2) => Unit::Pixel,
                _ => Unit::World,
            })
        };
        let scale_mode = pair(strings("scaleMode"), &|v, _| match v {
            "NONE" => Some(0),
            "FRACTION" => Some(1),
            "STRETCH" => Some(2),
            "PIXEL" => Some(3),
            _ => None,
        })
        .map(|m| match m {
            Some(1) => ScaleMode::Fraction,
            Some(2) => ScaleMode::Stretch,
            Some(3) => ScaleMode::Pixel,
            _ => ScaleMode::None,
        });
        let numbers = |name: &str, fallback: f64| {
            let values = floats(doc, id, name);
            let read = |i: usize| {
                values
                    .get(i)
                    .map(|v| f64::from(*v))
                    .filter(|v| v.is_finite())
            };
            let first = read(0).unwrap_or(fallback);
            [first, read(1).unwrap_or(first)]
        };
        Layout {
            align,
            offset: numbers("offset", 0.0),
            offset_units: unit("offsetUnits"),
            size: numbers("size", 1.0).map(|s| s.max(0.0)),
            size_units: unit("sizeUnits"),
            scale_mode,
        }
    }

    /// Places the rectangle within `parent` (the layer's region for a LayoutLayer): the
    /// translation of its centre from the parent's origin, and its region.
    pub fn place(&self, parent: Region, frame: &Surface) -> (DVec2, Region) {
        let convert = |unit: Unit, value: f64, axis: usize| match unit {
            Unit::Fraction => value * parent.size[axis],
            Unit::Pixel => value * frame.unit_per_pixel,
            Unit::World => value * parent.scale[axis],
        };
        let size = DVec2::new(
            convert(self.size_units[0], self.size[0], 0),
            convert(self.size_units[1], self.size[1], 1),
        );
        let mut translation = DVec2::ZERO;
        for axis in 0..2 {
            let room = (parent.size[axis] - size[axis]) / 2.0;
            translation[axis] = match self.align[axis] {
                Align::Low => -room,
                Align::Centre => 0.0,
                Align::High => room,
            } + convert(self.offset_units[axis], self.offset[axis], axis);
        }
        let mut scale = DVec2::ZERO;
        for axis in 0..2 {
            scale[axis] = match self.scale_mode[axis] {
                ScaleMode::None => parent.scale[axis],
                ScaleMode::Fraction | ScaleMode::Stretch => size[axis],
                ScaleMode::Pixel => frame.unit_per_pixel,
            };
        }
        match self.scale_mode {
            [ScaleMode::Stretch, ScaleMode::Stretch] => scale = DVec2::splat(size.max_element()),
            [ScaleMode::Stretch, _] => scale.x = scale.y,
            [_, ScaleMode::Stretch] => scale.y = scale.x,
            _ => {}
        }
        (translation, Region { size, scale })
    }
}

/// The transformation of a laid-out group: the enclosing transformation's rotation and
/// translation (its scale gives way to the layout's), then the rectangle's translation
/// and the children's scale.
pub fn group_transform(world: DMat4, translation: DVec2, region: &Region) -> DMat4 {
    let (_, rotation, origin) = world.to_scale_rotation_translation();
    let rotation = if rotation.is_finite() {
        rotation.normalize()
    } else {
        glam::DQuat::IDENTITY
    };
    DMat4::from_rotation_translation(rotation, origin)
        * DMat4::from_translation(translation.extend(0.0))
        * DMat4::from_scale(DVec3::new(region.scale.x, region.scale.y, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layout(xml: &str) -> Layout {
        let source =
            format!("<X3D profile='Full' version='4.0'><Scene><LayoutLayer>{xml}</LayoutLayer></Scene></X3D>");
        let doc = crate::parse::read(source.as_bytes()).document.unwrap();
        let id = doc
            .iter()
            .find(|(_, n)| n.type_name() == "Layout")
            .map(|(id, _)| id)
            .unwrap();
        Layout::of(&doc, id)
    }

    /// A 400 × 200 pixel layer: 4 × 2 units, 0.01 unit per pixel.
    fn frame() -> Surface {
        Surface::of_pixels(400.0, 200.0)
    }

    #[test]
    fn the_default_layout_fills_the_layer_and_scales_by_its_size() {
        let (t, r) = layout("<Layout/>").place(frame().region(), &frame());
        assert_eq!(t, DVec2::ZERO);
        assert_eq!(r.size, DVec2::new(4.0, 2.0));
        assert_eq!(r.scale, DVec2::new(4.0, 2.0));
    }

    #[test]
    fn a_pixel_box_at_the_top_left() {
        // 100 × 50 pixels, 10 pixels in from the left and down from the top.
        let l = layout(
            "<Layout align='\"LEFT\" \"TOP\"' size='100 50' sizeUnits='\"PIXEL\" \"PIXEL\"' \
             offset='10 -10' offsetUnits='\"PIXEL\" \"PIXEL\"' scaleMode='\"PIXEL\" \"PIXEL\"'/>",
        );
        let (t, r) = l.place(frame().region(), &frame());
        assert!((r.size - DVec2::new(1.0, 0.5)).length() < 1e-12);
        // Centre: left edge −2 + 0.5 + 0.1, top edge 1 − 0.25 − 0.1.
        assert!((t - DVec2::new(-1.4, 0.65)).length() < 1e-12, "{t}");
        assert_eq!(r.scale, DVec2::splat(0.01));
    }

    #[test]
    fn fractions_of_the_parent_and_stretch() {
        let l = layout(
            "<Layout align='\"RIGHT\" \"BOTTOM\"' size='0.5 0.25' \
             sizeUnits='\"FRACTION\" \"FRACTION\"' scaleMode='\"FRACTION\" \"STRETCH\"'/>",
        );
        let (t, r) = l.place(frame().region(), &frame());
        assert_eq!(r.size, DVec2::new(2.0, 0.5));
        assert_eq!(t, DVec2::new(1.0, -0.75));
        assert_eq!(r.scale, DVec2::new(2.0, 2.0));
        // One value for a pair applies to both axes.
        let one = layout("<Layout size='0.5' sizeUnits='\"FRACTION\"' scaleMode='\"STRETCH\"'/>");
        let (_, r) = one.place(frame().region(), &frame());
        assert_eq!(r.size, DVec2::new(2.0, 1.0));
        assert_eq!(r.scale, DVec2::splat(2.0));
    }

    #[test]
    fn world_units_and_none_follow_the_parent_scale() {
        let parent = Region {
            size: DVec2::new(2.0, 1.0),
            scale: DVec2::splat(0.01),
        };
        let (t, r) = layout("<Layout size='50 20' offset='5 0'/>").place(parent, &frame());
        assert_eq!(r.size, DVec2::new(0.5, 0.2));
        assert_eq!(t, DVec2::new(0.05, 0.0));
        assert_eq!(r.scale, DVec2::splat(0.01));
    }
}
