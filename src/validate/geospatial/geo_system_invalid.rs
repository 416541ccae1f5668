//! GEO_SYSTEM_INVALID: a `geoSystem` value that names no spatial reference frame, two of
//! them, a UTM frame without a valid zone, or two different zones or ellipsoids.

use super::{frames, geo_systems, quoted, Argument, Frame};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a `geoSystem` value written on a Geospatial node (GeoCoordinate,
    /// GeoLocation, GeoOrigin, GeoViewpoint, GeoElevationGrid, …) that does not designate
    /// one spatial reference frame as 25.2.3 defines them:
    /// - no string is a frame code (`"GD"`/`"GDC"`, `"UTM"`, `"GC"`/`"GCC"`; matching is
    ///   case sensitive, so `"gd"` is none);
    /// - two different frames are named (`"UTM" … "GD"`);
    /// - a `"UTM"` frame has no zone argument `"Z<n>"`, a zone whose number is not 1 to
    ///   60, or two different zones;
    /// - two different ellipsoid codes of Table 25.3 are named.
    ///
    /// An empty value and one passed in through `IS` are left alone; arguments that are
    /// merely not listed for the frame are GEO_SYSTEM_ARGUMENT_UNSUPPORTED's.
    ///
    /// ## Why it matters
    /// The frame says how every geospatial coordinate of the node is read: the same
    /// numbers are degrees under `"GD"`, metres of easting and northing under `"UTM"` and
    /// earth-centred metres under `"GC"`. A value the browser cannot resolve to one frame
    /// (and, for UTM, one zone) puts the geometry somewhere else on the globe, or nowhere:
    /// browsers fall back to their own default (X_ITE uses `"GD" "WE"`), which the author
    /// did not choose.
    ///
    /// ## Example
    /// ```xml
    /// <GeoLocation geoSystem='"UTM" "S"' geoCoords='4145173 572227 0'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <GeoLocation geoSystem='"UTM" "Z10" "S"' geoCoords='4145173 572227 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 25.2.3 Specifying a spatial reference frame: the supported values are
    /// `"GD"` (synonym `"GDC"`) with an optional ellipsoid code of Table 25.3, `"UTM"`,
    /// for which "one further required argument must be supplied … to specify the zone
    /// number (1..60)" in the form `"Z<n>"`, and `"GC"` (synonym `"GCC"`); "argument
    /// matching is case sensitive". Reading: a value that designates no frame, or two,
    /// has no defined meaning, so it is reported as an error like the missing zone the
    /// clause requires.
    /// > "one further required argument must be supplied" (19775-1 25.2.3)
    pub static GEO_SYSTEM_INVALID = {
        severity: Error,
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
        let problems = problems(strings);
        if !problems.is_empty() {
            found.push((id, span, quoted(strings), problems.join("; ")));
        }
    }
    for (id, span, value, problems) in found {
        let node = doc.node(id);
        ctx.report(
            Diagnostic::new(
                &GEO_SYSTEM_INVALID,
                span,
                format!("{}.geoSystem [{value}]: {problems}", node.type_name()),
            )
            .node(id)
            .help("name one frame first: `\"GD\" \"WE\"` (latitude/longitude), `\"UTM\" \"Z<1..60>\"` with `\"S\"` south of the equator, or `\"GC\"`"),
        );
    }
}

/// What keeps the value from naming one frame, in words.
fn problems(strings: &[String]) -> Vec<String> {
    let mut problems = Vec::new();
    let frames = frames(strings);
    match frames.as_slice() {
        [] => problems.push(
            "no spatial reference frame is named (\"GD\", \"UTM\" or \"GC\"; matching is case sensitive)"
                .to_string(),
        ),
        [_] => {}
        several => {
            let codes: Vec<_> = several.iter().map(|f| format!("\"{}\"", f.code())).collect();
            problems.push(format!("it names {} frames: {}", several.len(), codes.join(" and ")));
        }
    }
    let arguments: Vec<(&str, Argument)> = strings
        .iter()
        .map(|s| (s.as_str(), Argument::of(s)))
        .collect();
    if frames == [Frame::Utm] {
        let zones: Vec<_> = arguments
            .iter()
            .filter_map(|(text, a)| match a {
                Argument::Zone(number) => Some((*text, *number)),
                _ => None,
            })
            .collect();
        if zones.is_empty() {
            problems.push("a UTM frame needs its zone, \"Z1\" to \"Z60\"".to_string());
        }
        for (text, number) in &zones {
            if !number.is_some_and(|n| (1..=60).contains(&n)) {
                problems.push(format!("\"{text}\" is no UTM zone (\"Z1\" to \"Z60\")"));
            }
        }
        let mut distinct: Vec<&str> = zones.iter().map(|(text, _)| *text).collect();
        distinct.dedup();
        if distinct.len() > 1 {
            problems.push(format!("it names {} zones", distinct.len()));
        }
    }
    if frames.len() == 1 && frames[0] != Frame::Geocentric {
        let mut ellipsoids: Vec<&str> = arguments
            .iter()
            .filter(|(_, a)| *a == Argument::Ellipsoid)
            .map(|(text, _)| *text)
            .collect();
        ellipsoids.sort_unstable();
        ellipsoids.dedup();
        if ellipsoids.len() > 1 {
            let codes: Vec<_> = ellipsoids.iter().map(|e| format!("\"{e}\"")).collect();
            problems.push(format!(
                "it names {} ellipsoids: {}",
                codes.len(),
                codes.join(" and ")
            ));
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::problems;

    fn of(value: &[&str]) -> Vec<String> {
        problems(&value.iter().map(|s| s.to_string()).collect::<Vec<_>>())
    }

    #[test]
    fn standard_values_pass() {
        for value in [
            &["GD", "WE"][..],
            &["GDC"],
            &["GD", "WE", "longitude_first"],
            &["UTM", "Z10"],
            &["UTM", "WE", "Z60", "S"],
            &["UTM", "Z10", "S", "easting_first", "WGS84"],
            &["UTM", "Z10", "N"],
            &["GC"],
            &["GCC"],
            &["GD", "GDC", "WE", "WE"],
        ] {
            assert!(of(value).is_empty(), "{value:?}: {:?}", of(value));
        }
    }

    #[test]
    fn broken_values_fail() {
        for value in [
            &["gd"][..],
            &["WE"],
            &["UTM", "Z10", "S", "GD"],
            &["UTM"],
            &["UTM", "S"],
            &["UTM", "Z0"],
            &["UTM", "Z61"],
            &["UTM", "Z10N"],
            &["UTM", "Z10", "Z11"],
            &["GD", "WE", "WD"],
        ] {
            assert!(!of(value).is_empty(), "{value:?} passes");
        }
    }
}
