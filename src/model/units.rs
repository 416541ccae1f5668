//! UNIT statements (19775-1 7.2.5.5; 4.3.6 in X3D 4): a file may write its lengths and
//! angles in other units than metres and radians, each statement giving the factor that
//! converts one of its values into the base unit (base = value × conversionFactor; a
//! file in degrees states `conversionFactor='0.017453292519943295'`). The statements apply
//! to the file's own scene; an Inline file's content is in the units that file states.
//!
//! For drawing, the two categories are applied differently:
//! - every length of a scene is a coordinate, a size or a distance along the same axes, so
//!   converting all of them is the uniform scale [`Units::length`] applied at the root of
//!   the file's scene (a scale commutes with the transforms, which have no length of their
//!   own but their translations and centres, converted along with everything else); only
//!   the lengths that are no coordinates of the scene (`LENGTH_VALUES`) are converted as
//!   values;
//! - angles are converted as values ([`in_base_units`]): the angle of every SFRotation and
//!   MFRotation value, and the angle fields of `ANGLE_FIELDS`.

use super::{Document, Value};
use crate::schema::FieldType;

/// The factors of a file's UNIT statements (1 where it states none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Units {
    /// Metres per length unit of the file.
    pub length: f64,
    /// Radians per angle unit of the file.
    pub angle: f64,
}

/// SFFloat and MFFloat fields that are angles (every rotation's angle is one too):
/// creaseAngle (11.2.2), Background sky and ground angles (24.4.1), SpotLight beam
/// (17.4.5), Arc2D and ArcClose2D (14.4), sensors' and HAnimJoint's limits, TextureTransform's
/// rotation (18.4.10), and the fieldOfView of a perspective viewpoint (OrthoViewpoint's is
/// a length).
const ANGLE_FIELDS: &[&str] = &[
    "creaseAngle",
    "skyAngle",
    "groundAngle",
    "beamWidth",
    "cutOffAngle",
    "startAngle",
    "endAngle",
    "minAngle",
    "maxAngle",
    "diskAngle",
    "llimit",
    "ulimit",
    "fieldOfView",
    "rotation",
];

/// (node type, field): lengths the renderer reads that are no coordinates of the scene, so
/// the root scale does not reach them.
const LENGTH_VALUES: &[(&str, &str)] = &[
    ("Fog", "visibilityRange"),
    ("LocalFog", "visibilityRange"),
    ("NavigationInfo", "avatarSize"),
    ("NavigationInfo", "visibilityLimit"),
    ("PointLight", "radius"),
    ("SpotLight", "radius"),
    ("OrthoViewpoint", "fieldOfView"),
];

impl Document {
    /// The length and angle factors of the file's UNIT statements: the first statement of a
    /// category with a positive finite factor (a repeated category is an error the checker
    /// reports), else 1.
    pub fn units(&self) -> Units {
        let factor = |category: &str| {
            self.head
                .units
                .iter()
                .filter(|u| u.category.as_ref().is_some_and(|c| c.text == category))
                .find_map(|u| u.conversion_factor.as_ref().and_then(|(f, _)| *f))
                .filter(|f| f.is_finite() && *f > 0.0)
                .unwrap_or(1.0)
        };
        Units {
            length: factor("length"),
            angle: factor("angle"),
        }
    }
}

/// The document with its angles and `LENGTH_VALUES` in base units; None when its units
/// are the base units (nothing to convert). Values the document leaves at their defaults
/// are already in base units.
pub fn in_base_units(doc: &Document) -> Option<Document> {
    let units = doc.units();
    if units.length == 1.0 && units.angle == 1.0 {
        return None;
    }
    let mut converted = doc.clone();
    for node in &mut converted.nodes {
        let type_name = node.def().map_or("", |d| d.name);
        for entry in &mut node.fields {
            let Some(def) = entry.schema_def() else {
                continue;
            };
            let (ty, name) = (def.ty, def.name);
            let Value::Floats(values) = &mut entry.value else {
                continue;
            };
            let scale = |values: &mut [f32], factor: f64| {
                for v in values {
                    *v = (f64::from(*v) * factor) as f32;
                }
            };
            match ty {
                FieldType::SFRotation | FieldType::MFRotation => {
                    for rotation in values.chunks_exact_mut(4) {
                        scale(&mut rotation[3..], units.angle);
                    }
                }
                FieldType::SFFloat | FieldType::MFFloat => {
                    if LENGTH_VALUES.contains(&(type_name, name)) {
                        scale(values.as_mut_slice(), units.length);
                    } else if ANGLE_FIELDS.contains(&name) {
                        scale(values.as_mut_slice(), units.angle);
                    }
                }
                _ => {}
            }
        }
    }
    Some(converted)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Document {
        crate::parse::read(text.as_bytes()).document.unwrap()
    }

    #[test]
    fn angles_and_non_coordinate_lengths_convert_and_coordinates_do_not() {
        let doc = read(
            "<X3D profile='Immersive' version='4.0'><head>\
             <unit category='angle' name='degree' conversionFactor='0.0174532925199433'/>\
             <unit category='length' name='mm' conversionFactor='0.001'/></head><Scene>\
             <Transform rotation='0 1 0 90' translation='1000 0 0'/>\
             <Viewpoint fieldOfView='45'/><OrthoViewpoint fieldOfView='-500 -500 500 500'/>\
             <NavigationInfo avatarSize='250 1600 750'/></Scene></X3D>",
        );
        assert_eq!(
            doc.units(),
            Units {
                length: 0.001,
                angle: 0.0174532925199433
            }
        );
        let base = in_base_units(&doc).unwrap();
        let floats = |ty: &str, field: &str| {
            let id = base.nodes_of_type(ty).next().unwrap();
            base.value_of(id, field)
                .unwrap()
                .as_floats()
                .unwrap()
                .to_vec()
        };
        let rotation = floats("Transform", "rotation");
        assert!((rotation[3] - std::f32::consts::FRAC_PI_2).abs() < 1e-6);
        assert_eq!(floats("Transform", "translation"), [1000.0, 0.0, 0.0]);
        assert!((floats("Viewpoint", "fieldOfView")[0] - std::f32::consts::FRAC_PI_4).abs() < 1e-6);
        assert_eq!(
            floats("OrthoViewpoint", "fieldOfView"),
            [-0.5, -0.5, 0.5, 0.5]
        );
        assert_eq!(floats("NavigationInfo", "avatarSize"), [0.25, 1.6, 0.75]);
    }

    #[test]
    fn a_file_without_units_is_not_copied() {
        let doc = read("<X3D profile='Immersive' version='4.0'><Scene/></X3D>");
        assert!(in_base_units(&doc).is_none());
    }
}
