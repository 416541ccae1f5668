//! Geospatial component (clause 25): the `geoSystem` strings that name a node's spatial
//! reference frame (25.2.3).

pub mod geo_system_argument_unsupported;
pub mod geo_system_invalid;

use super::Check;
use crate::model::{Document, NodeId, Span};

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[
    &geo_system_invalid::CHECK,
    &geo_system_argument_unsupported::CHECK,
];

/// A spatial reference frame of 25.2.3.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum Frame {
    /// `GD` (or its synonym `GDC`): geodetic, latitude and longitude.
    Geodetic,
    /// `UTM`: Universal Transverse Mercator.
    Utm,
    /// `GC` (or its synonym `GCC`): earth-fixed geocentric.
    Geocentric,
}

impl Frame {
    fn of(argument: &str) -> Option<Frame> {
        match argument {
            "GD" | "GDC" => Some(Frame::Geodetic),
            "UTM" => Some(Frame::Utm),
            "GC" | "GCC" => Some(Frame::Geocentric),
            _ => None,
        }
    }

    pub fn code(self) -> &'static str {
        match self {
            Frame::Geodetic => "GD",
            Frame::Utm => "UTM",
            Frame::Geocentric => "GC",
        }
    }
}

/// The earth ellipsoid codes of Table 25.3. The XSD's list leaves out `AA` (Airy 1830),
/// which the table has.
pub(crate) const ELLIPSOIDS: [&str; 23] = [
    "AA", "AM", "AN", "BN", "BR", "CC", "CD", "EA", "EB", "EC", "ED", "EE", "EF", "FA", "HE", "HO",
    "ID", "IN", "KA", "RF", "SA", "WD", "WE",
];

/// What one argument of a `geoSystem` value is.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum Argument {
    Frame(Frame),
    Ellipsoid,
    /// `WGS84`: elevations relative to the WGS84 geoid (GD and UTM).
    Geoid,
    /// `latitude_first`, `longitude_first` (GD).
    LatitudeOrder,
    /// `northing_first`, `easting_first` (UTM).
    NorthingOrder,
    /// `S`: southern hemisphere (UTM).
    South,
    /// `Z` and a zone number; the number when it is digits alone.
    Zone(Option<u32>),
    /// A string 25.2.3 does not list.
    Unknown,
}

impl Argument {
    pub fn of(text: &str) -> Argument {
        if let Some(frame) = Frame::of(text) {
            return Argument::Frame(frame);
        }
        match text {
            "WGS84" => Argument::Geoid,
            "latitude_first" | "longitude_first" => Argument::LatitudeOrder,
            "northing_first" | "easting_first" => Argument::NorthingOrder,
            "S" => Argument::South,
            _ if ELLIPSOIDS.contains(&text) => Argument::Ellipsoid,
            _ => match text.strip_prefix('Z') {
                Some(digits) if !digits.is_empty() => {
                    let number = digits
                        .bytes()
                        .all(|b| b.is_ascii_digit())
                        .then(|| digits.parse().ok())
                        .flatten();
                    Argument::Zone(number)
                }
                _ => Argument::Unknown,
            },
        }
    }

    /// Whether 25.2.3 lists this argument for `frame`.
    pub fn belongs_to(self, frame: Frame) -> bool {
        match self {
            Argument::Frame(other) => other == frame,
            Argument::Ellipsoid | Argument::Geoid => frame != Frame::Geocentric,
            Argument::LatitudeOrder => frame == Frame::Geodetic,
            Argument::NorthingOrder | Argument::South | Argument::Zone(_) => frame == Frame::Utm,
            Argument::Unknown => false,
        }
    }
}

/// A written `geoSystem` value: the node, where the value is, and its strings. Only what
/// this file writes itself counts: values passed in through `IS` and prototype copies
/// are left out, and so is an empty list (25.2.3 gives it no meaning to check).
pub(crate) fn geo_systems(doc: &Document) -> Vec<(NodeId, Span, &[String])> {
    doc.iter()
        .take(doc.written_nodes().len())
        .filter(|(_, node)| !node.is_connected("geoSystem"))
        .filter_map(|(id, node)| {
            let entry = node.entry("geoSystem")?;
            entry.schema_def()?;
            let strings = entry.value.as_strings()?;
            (!strings.is_empty()).then_some((id, entry.span, strings))
        })
        .collect()
}

/// The frames a value names, each once, in the order written.
pub(crate) fn frames(strings: &[String]) -> Vec<Frame> {
    let mut frames = Vec::new();
    for text in strings {
        if let Some(frame) = Frame::of(text) {
            if !frames.contains(&frame) {
                frames.push(frame);
            }
        }
    }
    frames
}

/// `"UTM" "Z10"`: the strings as the ClassicVRML and XML encodings write them.
pub(crate) fn quoted(strings: &[String]) -> String {
    strings
        .iter()
        .map(|s| format!("\"{s}\""))
        .collect::<Vec<_>>()
        .join(" ")
}
