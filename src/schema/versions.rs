//! Which X3D versions define a node type or a field, said the way a reader wants it: the
//! first version that has it and, where it is missing from a version in between, every
//! run of versions it is in.

use super::{schema, Version};

/// The X3D versions whose schema has node type `name`.
pub fn with_node(name: &str) -> Vec<Version> {
    Version::X3D
        .into_iter()
        .filter(|&v| schema(v).node(name).is_some())
        .collect()
}

/// The X3D versions whose schema has `field` on node type `node`.
pub fn with_field(node: &str, field: &str) -> Vec<Version> {
    Version::X3D
        .into_iter()
        .filter(|&v| schema(v).node(node).and_then(|d| d.field(field)).is_some())
        .collect()
}

/// "X3D 3.1 and later", "X3D 3.3 only", "X3D 3.0–3.3 and 4.1": the runs of consecutive
/// versions in `versions` (a subset of [`Version::X3D`] in its order); "VRML97 only" for
/// none, since every node and field of the schema is in some version.
pub fn describe(versions: &[Version]) -> String {
    let mut runs: Vec<(Version, Version)> = Vec::new();
    for &v in versions {
        let position = |v: Version| Version::X3D.iter().position(|&w| w == v);
        match runs.last_mut() {
            Some((_, last)) if position(*last).map(|p| p + 1) == position(v) => *last = v,
            _ => runs.push((v, v)),
        }
    }
    let text = |&(first, last): &(Version, Version)| {
        if first == last {
            first.to_string()
        } else {
            format!("{first}–{last}")
        }
    };
    match runs.as_slice() {
        [] => "VRML97 only".to_string(),
        [(first, last)] if *last == Version::LATEST && first != last => {
            format!("X3D {first} and later")
        }
        [(first, last)] if first == last => format!("X3D {first} only"),
        _ => {
            let texts: Vec<String> = runs.iter().map(text).collect();
            match texts.split_last() {
                Some((last, [])) => format!("X3D {last}"),
                Some((last, rest)) => format!("X3D {} and {last}", rest.join(", ")),
                None => unreachable!("runs is not empty"),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_the_first_version_and_the_gaps() {
        assert_eq!(
            describe(&with_field("PointLight", "global")),
            "X3D 3.1 and later"
        );
        assert_eq!(describe(&with_node("MetadataBoolean")), "X3D 3.3 and later");
        assert_eq!(describe(&[Version::V3_3]), "X3D 3.3 only");
        assert_eq!(
            describe(&[Version::V3_0, Version::V3_1, Version::V4_1]),
            "X3D 3.0–3.1 and 4.1"
        );
        assert_eq!(
            describe(&[Version::V3_0, Version::V3_2, Version::V4_0, Version::V4_1]),
            "X3D 3.0, 3.2 and 4.0–4.1"
        );
    }
}
