//! Numbers at the extremes (DESIGN.md, Robustness): NaN, ±∞, subnormals, ±3.4e38, -0 and
//! values one ulp either side of a range bound are read exactly, judged exactly at the
//! field's precision, and never make a rule panic or a report print NaN.

mod normals;
mod parsing;
mod ranges;
mod reports;
mod support;
mod transforms;
mod triangles;
