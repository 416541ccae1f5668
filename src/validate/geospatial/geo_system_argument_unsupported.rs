//! GEO_SYSTEM_ARGUMENT_UNSUPPORTED: a `geoSystem` string that 25.2.3 does not list for the
//! frame the value names.

use super::{frames, geo_systems, quoted, Argument, Frame, ELLIPSOIDS};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports each string of a `geoSystem` value that 25.2.3 does not list for the one
    /// frame the value names: a string listed nowhere (`"N"`, `"we"`, `"WGS-84"`), an
    /// argument of another frame (`"S"` or `"Z10"` after `"GD"`, `"longitude_first"`
    /// after `"UTM"`), or any argument after `"GC"`, which takes none. Values that name
    /// no frame or several are GEO_SYSTEM_INVALID's and are not looked at here; so are
    /// empty values and values passed in through `IS`.
    ///
    /// ## Why it matters
    /// The argument has no meaning in the frame, so the browser ignores it, and what the
    /// author meant by it does not happen: `"longitude-first"` misspelled leaves the
    /// coordinates read latitude first, a lower-case `"we"` is no ellipsoid, `"S"` on a
    /// geodetic frame does not move anything south. `"N"` (for the northern hemisphere,
    /// which UTM assumes without `"S"`) is harmless but is not a value of the clause.
    ///
    /// ## Example
    /// ```xml
    /// <GeoViewpoint geoSystem='"GD" "we" "longitude-first"' position='-121.9 36.6 500'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <GeoViewpoint geoSystem='"GD" "WE" "longitude_first"' position='-121.9 36.6 500'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 25.2.3 Specifying a spatial reference frame ("Argument matching is case
    /// sensitive … The following values are supported": `"GD"` with an ellipsoid code of
    /// Table 25.3, `"WGS84"` and `"longitude_first"`; `"UTM"` with `"Z<n>"`, `"S"`, an
    /// ellipsoid, `"WGS84"` and `"easting_first"`; `"GC"`, for which "no additional
    /// arguments are supported"), 25.2.4 for the coordinate orders (`latitude_first` and
    /// `northing_first`, the defaults, are accepted too). Reading: the clause lists what
    /// is supported without forbidding other strings, so an unlisted one is a warning,
    /// not an error.
    pub static GEO_SYSTEM_ARGUMENT_UNSUPPORTED = {
        severity: Warning,
        level: Standard,
        clause: "25.2.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, span, strings) in geo_systems(doc) {
        let [frame] = frames(strings)[..] else {
            continue;
        };
        let mut seen: Vec<&str> = Vec::new();
        for text in strings {
            let argument = Argument::of(text);
            if argument.belongs_to(frame) || seen.contains(&text.as_str()) {
                continue;
            }
            seen.push(text);
            found.push((id, span, quoted(strings), text.clone(), frame, argument));
        }
    }
    for (id, span, value, text, frame, argument) in found {
        let node = doc.node(id);
        let why = match argument {
            Argument::Unknown if text == "N" && frame == Frame::Utm => {
                "no such argument (the northern hemisphere needs none: it is UTM's default without \"S\")".to_string()
            }
            Argument::Unknown => match suggestion(&text) {
                Some(known) => format!("no such argument (did you mean \"{known}\"?)"),
                None => "no such argument".to_string(),
            },
            _ if frame == Frame::Geocentric => {
                "an argument, and \"GC\" takes none".to_string()
            }
            _ => format!("not an argument of the \"{}\" frame", frame.code()),
        };
        ctx.report(
            Diagnostic::new(
                &GEO_SYSTEM_ARGUMENT_UNSUPPORTED,
                span,
                format!(
                    "{}.geoSystem [{value}]: \"{text}\" is {why}; browsers ignore it",
                    node.type_name()
                ),
            )
            .node(id)
            .help(help(frame)),
        );
    }
}

/// The listed string a case-insensitive match of `text` finds.
fn suggestion(text: &str) -> Option<&'static str> {
    const OTHERS: [&str; 11] = [
        "GD",
        "GDC",
        "UTM",
        "GC",
        "GCC",
        "WGS84",
        "S",
        "latitude_first",
        "longitude_first",
        "northing_first",
        "easting_first",
    ];
    let normalized = text.replace('-', "_");
    OTHERS
        .iter()
        .chain(ELLIPSOIDS.iter())
        .copied()
        .find(|known| known.eq_ignore_ascii_case(&normalized))
}

fn help(frame: Frame) -> &'static str {
    match frame {
        Frame::Geodetic => "\"GD\" takes an ellipsoid code of Table 25.3 (default \"WE\"), \"WGS84\" and \"longitude_first\"; remove anything else",
        Frame::Utm => "\"UTM\" takes \"Z1\"..\"Z60\", \"S\" (southern hemisphere; north needs nothing), an ellipsoid code, \"WGS84\" and \"easting_first\"; remove anything else",
        Frame::Geocentric => "write `\"GC\"` alone",
    }
}
