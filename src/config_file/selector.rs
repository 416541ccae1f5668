//! Rule selectors, as `--select`, `--ignore`, `--severity`, `x3dcheck.toml` and
//! `x3dcheck rules` take them: a code, a prefix of whole words of codes (`BACK_MATERIAL_`
//! or `BACK_MATERIAL` selects every backMaterial rule; `BACK_MAT` is a typo, not a prefix),
//! or `ALL`, in any case. A selector that is a whole code selects that code alone, even if
//! it also begins longer codes (add `_` to mean the family). A selector that matches no code
//! is an error naming the nearest code.

use crate::diagnostic::Rule;
use crate::validate::{find_rule, RULES};

/// The rules `selector` selects, in catalogue order; never empty.
pub fn select(selector: &str) -> Result<Vec<&'static Rule>, String> {
    let wanted = selector.trim().to_ascii_uppercase();
    if wanted == "ALL" {
        return Ok(RULES.to_vec());
    }
    if let Some(rule) = find_rule(&wanted) {
        return Ok(vec![rule]);
    }
    let family: Vec<&'static Rule> = RULES
        .iter()
        .copied()
        .filter(|r| {
            r.code.strip_prefix(&wanted).is_some_and(|rest| {
                (wanted.ends_with('_') && wanted.len() > 1) || rest.starts_with('_')
            })
        })
        .collect();
    if !family.is_empty() {
        return Ok(family);
    }
    let nearest = RULES
        .iter()
        .map(|r| (strsim::jaro_winkler(&wanted, r.code), r.code))
        .filter(|(score, _)| *score > 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, code)| code);
    let hint = nearest.map_or(String::new(), |c| format!(" (did you mean `{c}`?)"));
    Err(format!(
        "`{selector}` is no rule code, code prefix or ALL{hint}; `x3dcheck rules` lists the codes"
    ))
}

/// The codes of [`select`].
pub fn select_codes(selector: &str) -> Result<Vec<String>, String> {
    Ok(select(selector)?
        .into_iter()
        .map(|r| r.code.to_string())
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn codes(selector: &str) -> Vec<&'static str> {
        select(selector).unwrap().iter().map(|r| r.code).collect()
    }

    #[test]
    fn codes_prefixes_and_all_in_any_case() {
        assert_eq!(codes("DEF_DUPLICATE"), ["DEF_DUPLICATE"]);
        assert_eq!(codes("def_duplicate"), ["DEF_DUPLICATE"]);
        let family = codes("back_material_");
        assert!(family.len() > 1, "{family:?}");
        assert!(family.iter().all(|c| c.starts_with("BACK_MATERIAL_")));
        assert_eq!(codes("BACK_MATERIAL"), family);
        assert_eq!(codes("All").len(), RULES.len());
    }

    #[test]
    fn a_selector_matching_nothing_is_an_error_with_the_nearest_code() {
        let e = select("DEF_DUPLICAT").unwrap_err();
        assert!(e.contains("did you mean `DEF_DUPLICATE`?"), "{e}");
        assert!(select("NOTHING_LIKE_THIS").is_err());
        assert!(select("BACK_MAT").is_err(), "a prefix of whole words only");
        assert!(select("").is_err());
        assert!(select("_").is_err());
    }
}
