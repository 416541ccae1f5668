//! "Did you mean" for names: a case slip first (`material` → `Material`), then the
//! closest name within a small edit distance.

/// The candidate the user most likely meant by `name`, if any is close enough.
pub fn did_you_mean<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str> + Clone,
) -> Option<&'a str> {
    if let Some(exact) = candidates
        .clone()
        .into_iter()
        .find(|c| c.eq_ignore_ascii_case(name))
    {
        return Some(exact);
    }
    let lower = name.to_ascii_lowercase();
    let limit = (name.chars().count() / 3).clamp(1, 3);
    let length = name.chars().count();
    candidates
        .into_iter()
        // The edit distance is at least the difference in length: skip the hopeless ones.
        .filter(|c| c.chars().count().abs_diff(length) <= limit)
        .map(|c| (strsim::levenshtein(&lower, &c.to_ascii_lowercase()), c))
        .filter(|(distance, _)| *distance <= limit)
        .min_by_key(|(distance, c)| (*distance, *c))
        .map(|(_, c)| c)
}

/// `did you mean `x`?` as help text.
pub fn help(
    name: &str,
    candidates: impl IntoIterator<Item = &'static str> + Clone,
) -> Option<String> {
    did_you_mean(name, candidates).map(|c| format!("did you mean `{c}`?"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn case_slips_win_over_edits() {
        let names = ["Material", "MaterialX", "diffuseColor"];
        assert_eq!(did_you_mean("material", names), Some("Material"));
        assert_eq!(did_you_mean("diffusecolor", names), Some("diffuseColor"));
        assert_eq!(did_you_mean("difuseColor", names), Some("diffuseColor"));
        assert_eq!(did_you_mean("Transform", names), None);
    }
}
