//! NORMAL_ZERO: a zero-length normal vector (deep level).

use super::geometry::each_normal;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a vector of a Normal node, or a key value of a NormalInterpolator, whose
    /// three components are all zero (`-0` included). Every vector is checked; the repeats
    /// in one node fold into one diagnostic with a count. Non-finite vectors are
    /// FIELD_VALUE_NONFINITE and are not judged here.
    ///
    /// ## Why it matters
    /// "When specified as part of the content, normals shall have unit length" (11.2.1);
    /// a zero vector has no direction at all, so lighting at that vertex or face is
    /// undefined (black, or NaN in the shader).
    ///
    /// ## Example
    /// ```xml
    /// <Normal vector='0 0 1 0 0 0 0 0 1'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 11.2.1 (normals shall have unit length), 11.4.10 Normal; 19.4
    /// NormalInterpolator: "Values in the keyValue field shall be of unit length." (the
    /// 3.x text as H3D API's `NormalInterpolator.h` copies it; docs/traceability.md).
    /// > "When specified as part of the content, normals shall have unit length" (19775-1 11.2.1)
    pub static NORMAL_ZERO = {
        severity: Error,
        level: Deep,
        clause: "11.4.10",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    each_normal(ctx, &NORMAL_ZERO, |length| {
        (length == 0.0).then(|| "has zero length".to_string())
    });
}
