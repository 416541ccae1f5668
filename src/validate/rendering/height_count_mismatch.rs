//! HEIGHT_COUNT_MISMATCH: an ElevationGrid (or GeoElevationGrid) whose height count is not
//! xDimension × zDimension.

use crate::model::Value;
use crate::report::Diagnostic;
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
    /// heights than grid points are reported as well as fewer.
    pub static HEIGHT_COUNT_MISMATCH = {
        severity: Error,
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
            if given != points {
                let span = FIELDS
                    .iter()
                    .rev()
                    .find_map(|f| node.entry(f))
                    .map_or(node.name_span, |e| e.span);
                found.push((id, span, type_name, x, z, points, given));
            }
        }
    }
    for (id, span, type_name, x, z, points, given) in found {
        let only = if given < points { "only " } else { "" };
        let values = if given == 1 { "value" } else { "values" };
        let message = format!(
            "{type_name} has {only}{given} height {values} for its {x} × {z} = {points} grid points: it needs one per point"
        );
        ctx.report(Diagnostic::new(&HEIGHT_COUNT_MISMATCH, span, message).node(id));
    }
}
