//! HEIGHT_COUNT_MISMATCH: an ElevationGrid (or GeoElevationGrid) whose height count is not
//! xDimension × zDimension.

use crate::diagnostic::Diagnostic;
use crate::model::Value;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an ElevationGrid or GeoElevationGrid whose `height` field does not hold
    /// exactly xDimension × zDimension values, one per grid point. The product is
    /// computed in 64 bits, so dimensions up to 2147483647 each are compared exactly.
    /// Negative dimensions are FIELD_OUT_OF_RANGE's, a height that does not parse
    /// FIELD_VALUE_SYNTAX's, and fields connected by IS are left alone.
    ///
    /// ## Why it matters
    /// The grid point (i, j) takes height[i + j × xDimension]: with fewer heights the
    /// points past the end have none, and browsers differ (zero, the whole grid
    /// dropped); with more, the extra heights are not drawn, which usually means the
    /// dimensions are wrong.
    ///
    /// ## Example
    /// ```xml
    /// <ElevationGrid xDimension='3' zDimension='3' height='0 1 0 1 2 1'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ElevationGrid xDimension='3' zDimension='2' height='0 1 0 1 2 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 13.3.4 ElevationGrid ("The height field is an xDimension by zDimension
    /// array of scalar values"); GeoElevationGrid of the Geospatial component (clause 25),
    /// whose height array is laid out the same way. The clause fixes the count, so more
    /// heights than grid points are reported as well as fewer. The sentence defines the
    /// array's shape but puts no "shall" on the file, and what a browser draws from a
    /// short or long list is not said: a warning (issue 32: an error needs a sentence the
    /// file breaks). A grid with no `height`
    /// written is reported as having none (its default is empty; GeoElevationGrid's two
    /// zeros are not counted as if written), unless the default fits the grid.
    pub static HEIGHT_COUNT_MISMATCH = {
        severity: Warning,
        level: Standard,
        clause: "13.3.4",
        versions: "all",
        check: Some(check),
    }
}

const FIELDS: [&str; 3] = ["xDimension", "zDimension", "height"];

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for type_name in ["ElevationGrid", "GeoElevationGrid"] {
        for id in doc.nodes_of_type(type_name) {
            let node = doc.node(id);
            if FIELDS.iter().any(|f| node.is_connected(f)) {
                continue;
            }
            let dimension = |f| doc.i32_of(id, f).and_then(|d| u64::try_from(d).ok());
            let (Some(x), Some(z)) = (dimension("xDimension"), dimension("zDimension")) else {
                continue;
            };
            let Some(height) = doc.value_of(id, "height") else {
                continue;
            };
            if matches!(*height, Value::Unparsed(_)) {
                continue;
            }
            // Both below 2^31: the product fits in 64 bits.
            let points = x * z;
            let given = height.len() as u64;
            if given == points {
                continue;
            }
            let span = FIELDS
                .iter()
                .rev()
                .find_map(|f| node.entry(f))
                .map_or(node.name_span, |e| e.span);
            // A dimension the author left out is 0 by the tables (the 3.x UOMs say 2, so
            // files written with them may leave a 2 out): say so.
            let unwritten: Vec<&str> = FIELDS[..2]
                .iter()
                .copied()
                .filter(|f| node.entry(f).is_none())
                .collect();
            let defaults = match unwritten.as_slice() {
                [] => String::new(),
                [one] => format!(" ({one} is not written: its default is 0)"),
                _ => {
                    " (xDimension and zDimension are not written: their defaults are 0)".to_string()
                }
            };
            // An unwritten height is the table's default (none for ElevationGrid, two zeros
            // for GeoElevationGrid): the author gave no heights, so none are counted.
            let message = if node.entry("height").is_none() {
                format!("{type_name} has no height field for its {x} × {z} = {points} grid points{defaults}: it needs one height per point")
            } else {
                let only = if given < points { "only " } else { "" };
                let values = if given == 1 { "value" } else { "values" };
                format!("{type_name} has {only}{given} height {values} for its {x} × {z} = {points} grid points{defaults}: it needs one per point")
            };
            found.push((id, span, message));
        }
    }
    for (id, span, message) in found {
        ctx.report(Diagnostic::new(&HEIGHT_COUNT_MISMATCH, span, message).node(id));
    }
}
