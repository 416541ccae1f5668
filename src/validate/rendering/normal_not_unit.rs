//! NORMAL_NOT_UNIT: a normal vector whose length is not 1 (deep level).

use super::geometry::each_normal;
use crate::validate::numbers::readable;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a vector of a Normal node, or a key value of a NormalInterpolator, whose
    /// length differs from 1 by more than the tolerance (`normal_tolerance` in the
    /// configuration, default 0.01). The length is computed in f64 on the vector scaled by
    /// its largest component, so (1e-30, 0, 0) has length 1e-30 and (3e38, 0, 0) has
    /// length 3e38: neither underflows to zero nor overflows to infinity. Zero vectors are NORMAL_ZERO; non-finite ones
    /// FIELD_VALUE_NONFINITE. The repeats in one node fold into one diagnostic.
    ///
    /// ## Why it matters
    /// "When specified as part of the content, normals shall have unit length" (11.2.1).
    /// Browsers pass supplied normals to the lighting equations as they are; many do not
    /// renormalize, so a long normal over-lights and a short one darkens the surface.
    ///
    /// ## Example
    /// ```xml
    /// <Normal vector='0 0 1 0 0 2 0 0.5 0'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.2.1 (normals shall have unit length), 11.4.10 Normal; 19.4
    /// NormalInterpolator: "Values in the keyValue field shall be of unit length." (the
    /// 3.x text as H3D API's `NormalInterpolator.h` copies it; docs/traceability.md).
    pub static NORMAL_NOT_UNIT = {
        severity: Warning,
        level: Deep,
        clause: "11.2.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let tolerance = ctx.config.normal_tolerance;
    each_normal(ctx, &NORMAL_NOT_UNIT, |length| {
        (length > 0.0 && (length - 1.0).abs() > tolerance).then(|| {
            format!(
                "has length {}, not 1 (tolerance {tolerance})",
                readable(length)
            )
        })
    });
}
