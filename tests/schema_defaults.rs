//! Every default the X3D Unified Object Model prints as a shortened decimal of a multiple
//! of π (`0.7854`, `1.570796`, `0.26179167`) is, in the checker's tables, the float nearest
//! to the multiple itself at the field's precision: the value the interface tables print
//! (π/4, π/2, π/12). Derived from the UOM's text, so a default a later UOM adds is checked
//! too.

use std::f64::consts::PI;
use std::fs;
use std::path::Path;

use x3dcheck::schema::{schema, Scalar, Version};

/// Fields whose table prints a multiple of π other than the one the UOM's decimal is
/// close to, or a decimal: (version prefix, node, field, what the table prints).
const PRINTED: &[(&str, &str, &str, Option<f64>)] = &[
    // 17.4.4: π/4; the 4.x UOMs say 0.589049 (3π/16).
    ("4.", "SpotLight", "beamWidth", Some(PI / 4.0)),
    // 16.4 SpatialSound prints the decimal 6.2832 itself (its range is [0,2π]).
    ("4.", "SpatialSound", "coneInnerAngle", None),
    ("4.", "SpatialSound", "coneOuterAngle", None),
];

/// `name="…"` of one element's attribute text (preceded by white space, so that
/// `simpleType` does not match `type`).
fn attribute<'a>(element: &'a str, name: &str) -> Option<&'a str> {
    let key = format!("{name}=\"");
    let mut from = 0;
    while let Some(k) = element[from..].find(&key) {
        let at = from + k;
        if at > 0 && element.as_bytes()[at - 1].is_ascii_whitespace() {
            let rest = &element[at + key.len()..];
            return rest.find('"').map(|end| &rest[..end]);
        }
        from = at + key.len();
    }
    None
}

/// The multiple of π (k·π/n, k ≤ 12, n ≤ 16) a printed decimal shortens, if any: within
/// 5e-4 relative but not the multiple itself.
fn shortened_multiple_of_pi(value: f64) -> Option<f64> {
    for n in [1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0] {
        for k in 1..=12 {
            let exact = f64::from(k) * PI / n;
            if value != exact && ((value - exact) / exact).abs() < 5e-4 {
                return Some(exact);
            }
        }
    }
    None
}

#[test]
fn defaults_printed_as_multiples_of_pi_are_exact() {
    let oracle = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/oracle");
    let mut checked = 0;
    let mut wrong = Vec::new();
    for version in Version::X3D {
        let path = oracle.join(format!("X3dUnifiedObjectModel-{version}.xml"));
        let text = fs::read_to_string(&path).unwrap();
        for node_chunk in text.split("<ConcreteNode ").skip(1) {
            let node_name = attribute(&format!(" {node_chunk}"), "name")
                .unwrap()
                .to_string();
            let node_chunk = &node_chunk[..node_chunk.find("</ConcreteNode>").unwrap()];
            for field_chunk in node_chunk.split("<field").skip(1) {
                let element = &field_chunk[..field_chunk.find('>').unwrap()];
                let (Some(name), Some(ty), Some(default)) = (
                    attribute(element, "name"),
                    attribute(element, "type"),
                    attribute(element, "default"),
                ) else {
                    continue;
                };
                if !matches!(ty, "SFFloat" | "SFDouble" | "SFTime") {
                    continue;
                }
                let Ok(printed) = default.trim().parse::<f64>() else {
                    continue;
                };
                let Some(mut exact) = shortened_multiple_of_pi(printed) else {
                    continue;
                };
                if let Some(&(_, _, _, table)) = PRINTED.iter().find(|(v, n, f, _)| {
                    version.as_str().starts_with(v) && *n == node_name && *f == name
                }) {
                    match table {
                        Some(value) => exact = value,
                        None => continue,
                    }
                }
                let def = schema(version)
                    .node(&node_name)
                    .and_then(|n| n.field(name))
                    .unwrap_or_else(|| panic!("{version} {node_name}.{name} not in the tables"));
                let ok = match def.ty.scalar() {
                    Scalar::Float => def.default.parse::<f32>() == Ok(exact as f32),
                    _ => def.default.parse::<f64>() == Ok(exact),
                };
                checked += 1;
                if !ok {
                    wrong.push(format!(
                        "{version} {node_name}.{name}: the UOM prints {default}, the table the multiple of π {exact}; the tables have {}",
                        def.default
                    ));
                }
            }
        }
    }
    assert!(
        checked >= 50,
        "only {checked} defaults found: is the UOM read?"
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
