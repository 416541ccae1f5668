//! The bundled fonts (Liberation 2.1.5, SIL Open Font License 1.1: `assets/fonts/`), one
//! face for each family and style of 15.2.2.2: SERIF (Liberation Serif), SANS (Liberation
//! Sans), TYPEWRITER (Liberation Mono), each PLAIN, BOLD, ITALIC and BOLDITALIC. Liberation
//! is metric-compatible with Times New Roman, Arial and Courier New, so those names (and
//! their usual relatives) are known too.

use std::sync::OnceLock;

use ttf_parser::Face;

/// A family of 15.2.2.2.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    Serif,
    Sans,
    Typewriter,
}

/// A style of 15.2.2.2.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Style {
    Plain,
    Bold,
    Italic,
    BoldItalic,
}

/// One of the twelve bundled faces.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct FaceId {
    pub family: Family,
    pub style: Style,
}

const FILES: [[&[u8]; 4]; 3] = [
    [
        include_bytes!("../../../assets/fonts/LiberationSerif-Regular.ttf"),
        include_bytes!("../../../assets/fonts/LiberationSerif-Bold.ttf"),
        include_bytes!("../../../assets/fonts/LiberationSerif-Italic.ttf"),
        include_bytes!("../../../assets/fonts/LiberationSerif-BoldItalic.ttf"),
    ],
    [
        include_bytes!("../../../assets/fonts/LiberationSans-Regular.ttf"),
        include_bytes!("../../../assets/fonts/LiberationSans-Bold.ttf"),
        include_bytes!("../../../assets/fonts/LiberationSans-Italic.ttf"),
        include_bytes!("../../../assets/fonts/LiberationSans-BoldItalic.ttf"),
    ],
    [
        include_bytes!("../../../assets/fonts/LiberationMono-Regular.ttf"),
        include_bytes!("../../../assets/fonts/LiberationMono-Bold.ttf"),
        include_bytes!("../../../assets/fonts/LiberationMono-Italic.ttf"),
        include_bytes!("../../../assets/fonts/LiberationMono-BoldItalic.ttf"),
    ],
];

impl FaceId {
    fn index(self) -> (usize, usize) {
        let family = match self.family {
            Family::Serif => 0,
            Family::Sans => 1,
            Family::Typewriter => 2,
        };
        let style = match self.style {
            Style::Plain => 0,
            Style::Bold => 1,
            Style::Italic => 2,
            Style::BoldItalic => 3,
        };
        (family, style)
    }

    /// The parsed face (parsed once per process; the files are part of the build, so a
    /// parse failure is a broken build).
    pub fn face(self) -> &'static Face<'static> {
        static FACES: OnceLock<Vec<Vec<Face<'static>>>> = OnceLock::new();
        let faces = FACES.get_or_init(|| {
            FILES
                .iter()
                .map(|styles| {
                    styles
                        .iter()
                        .map(|bytes| Face::parse(bytes, 0).expect("a bundled font parses"))
                        .collect()
                })
                .collect()
        });
        let (family, style) = self.index();
        &faces[family][style]
    }

    /// The face's name, for notes.
    pub fn name(self) -> String {
        let family = match self.family {
            Family::Serif => "Liberation Serif",
            Family::Sans => "Liberation Sans",
            Family::Typewriter => "Liberation Mono",
        };
        let style = match self.style {
            Style::Plain => "",
            Style::Bold => " Bold",
            Style::Italic => " Italic",
            Style::BoldItalic => " Bold Italic",
        };
        format!("{family}{style}")
    }
}

/// The family a FontStyle's `family` list selects: the first name the renderer knows
/// (15.2.2.2: "the browser uses the first supported family"), else SERIF, as for an empty
/// list or "". The second value: the list named families and none was known.
pub fn family_of(names: &[String]) -> (Family, bool) {
    let known = names.iter().find_map(|name| known_family(name));
    let unknown = known.is_none() && names.iter().any(|n| !n.is_empty());
    (known.unwrap_or(Family::Serif), unknown)
}

fn known_family(name: &str) -> Option<Family> {
    // The three generic families are case-sensitive (15.4.1); the font names are not.
    match name {
        "SERIF" => return Some(Family::Serif),
        "SANS" => return Some(Family::Sans),
        "TYPEWRITER" => return Some(Family::Typewriter),
        _ => {}
    }
    let lower = name.trim().to_ascii_lowercase();
    match lower.as_str() {
        "liberation serif" | "tinos" | "times" | "times new roman" | "times roman" => {
            Some(Family::Serif)
        }
        "liberation sans" | "arimo" | "arial" | "helvetica" => Some(Family::Sans),
        "liberation mono" | "cousine" | "courier" | "courier new" => Some(Family::Typewriter),
        _ => None,
    }
}

/// The style a FontStyle's `style` names; "" and unknown values are PLAIN (15.4.1).
pub fn style_of(name: &str) -> Style {
    match name {
        "BOLD" => Style::Bold,
        "ITALIC" => Style::Italic,
        "BOLDITALIC" => Style::BoldItalic,
        _ => Style::Plain,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_bundled_face_parses_and_has_latin_glyphs() {
        for family in [Family::Serif, Family::Sans, Family::Typewriter] {
            for style in [Style::Plain, Style::Bold, Style::Italic, Style::BoldItalic] {
                let face = FaceId { family, style }.face();
                assert!(face.glyph_index('A').is_some());
                assert!(face.glyph_index('é').is_some());
            }
        }
    }

    #[test]
    fn the_first_known_family_wins_else_serif() {
        let names = |list: &[&str]| list.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            family_of(&names(&["Fancy", "SANS", "TYPEWRITER"])),
            (Family::Sans, false)
        );
        assert_eq!(
            family_of(&names(&["Courier New", "SANS"])),
            (Family::Typewriter, false)
        );
        assert_eq!(family_of(&names(&["Fancy"])), (Family::Serif, true));
        assert_eq!(family_of(&names(&[""])), (Family::Serif, false));
        assert_eq!(family_of(&[]), (Family::Serif, false));
        // Case-sensitive generic names: "sans" is not SANS.
        assert_eq!(family_of(&names(&["sans"])), (Family::Serif, true));
    }
}
