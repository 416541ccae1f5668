//! General entities declared in a DOCTYPE's internal subset (XML 1.0 4.2), which attribute
//! values may reference: `<!DOCTYPE X3D [<!ENTITY v "0 1 0">]>` … `point="&v; &v;"`.
//!
//! Only internal entities are read. External ones (`SYSTEM`/`PUBLIC`), parameter entities
//! (`%name;`) and the external DTD that X3D's DOCTYPE names by its public id are never
//! fetched: XML forbids references to external entities in attribute values anyway (WFC:
//! No External Entity References), so such a reference is reported as unknown.
//!
//! Expansion is bounded: references nested deeper than [`MAX_ENTITY_NESTING`] (a recursive
//! entity among them) and more than [`MAX_ENTITY_EXPANSION`] bytes of replacement text in
//! one document are refused, so "billion laughs" (entities of ten references to the one
//! before) costs a megabyte, not gigabytes.

use std::borrow::Cow;
use std::cell::Cell;
use std::collections::HashMap;

use quick_xml::escape::{resolve_predefined_entity, EscapeError};
use quick_xml::events::attributes::Attribute;
use quick_xml::XmlVersion;

use crate::limits::{MAX_ENTITY_EXPANSION, MAX_ENTITY_NESTING};

/// The entities of one document and what is left of its expansion budget.
pub struct Entities {
    declared: HashMap<String, String>,
    budget: Cell<usize>,
}

/// Why an attribute value could not be expanded.
pub enum ExpandError {
    /// Malformed or unknown reference (quick-xml's message, offset into the value).
    Malformed { at: usize, message: String },
    /// A limit of [`crate::limits`] was reached.
    Limit(String),
}

impl Default for Entities {
    fn default() -> Entities {
        Entities {
            declared: HashMap::new(),
            budget: Cell::new(MAX_ENTITY_EXPANSION),
        }
    }
}

impl Entities {
    /// Reads the declarations of a DOCTYPE (the text between `<!DOCTYPE` and its `>`).
    /// The first declaration of a name binds (XML 1.0 4.2).
    pub fn declare(&mut self, doctype: &str) {
        let Some(open) = doctype.find('[') else {
            return;
        };
        let subset = &doctype[open + 1..];
        let subset = &subset[..subset.rfind(']').unwrap_or(subset.len())];
        for (name, value) in declarations(subset) {
            self.declared
                .entry(name.to_string())
                .or_insert_with(|| value.to_string());
        }
    }

    /// An attribute's value with references replaced and whitespace normalized (XML 1.0
    /// 3.3.3), within the document's budget.
    pub fn expand<'a>(&self, attribute: &Attribute<'a>) -> Result<Cow<'a, str>, ExpandError> {
        let over_budget = Cell::new(false);
        let holds_lt = Cell::new(false);
        let resolve = |name: &str| {
            if let Some(text) = resolve_predefined_entity(name) {
                return Some(text);
            }
            let text = self.declared.get(name)?;
            if stands_for_lt(text) {
                holds_lt.set(true);
                return None;
            }
            match self.budget.get().checked_sub(text.len()) {
                Some(left) => {
                    self.budget.set(left);
                    Some(text.as_str())
                }
                None => {
                    over_budget.set(true);
                    None
                }
            }
        };
        let expanded =
            attribute.normalized_value_with(XmlVersion::Implicit1_0, MAX_ENTITY_NESTING, resolve);
        expanded.map_err(|error| match error {
            _ if over_budget.get() => ExpandError::Limit(format!(
                "entity references expand to more than {MAX_ENTITY_EXPANSION} bytes in this document; the rest are not read"
            )),
            quick_xml::Error::Escape(EscapeError::TooManyNestedEntities) => {
                ExpandError::Limit(format!(
                    "entity references nested more than {MAX_ENTITY_NESTING} deep (or a recursive entity); the value is not read"
                ))
            }
            quick_xml::Error::Escape(EscapeError::UnrecognizedEntity(range, name))
                if holds_lt.get() =>
            {
                ExpandError::Malformed {
                    at: range.start.saturating_sub(1),
                    message: format!(
                        "entity `&{name};` stands for text holding `<`, which an attribute value must not contain (XML 1.0 3.1, WFC: No < in Attribute Values)"
                    ),
                }
            }
            quick_xml::Error::Escape(EscapeError::UnrecognizedEntity(range, name)) => {
                ExpandError::Malformed {
                    at: range.start.saturating_sub(1),
                    message: format!("unknown entity `&{name};`"),
                }
            }
            other => ExpandError::Malformed {
                at: 0,
                message: other.to_string(),
            },
        })
    }
}

/// Whether an entity's text puts a `<` into the value: literally, or as a character
/// reference, which XML replaces when it reads the declaration (4.5), so that the
/// replacement text holds `<` (`&#38;#60;` stands for the text `&#60;`, which is fine).
fn stands_for_lt(text: &str) -> bool {
    text.contains('<')
        || text.split("&#").skip(1).any(|reference| {
            let digits = reference.split(';').next().unwrap_or("");
            let code = match digits.strip_prefix('x') {
                Some(hex) => u32::from_str_radix(hex, 16),
                None => digits.parse::<u32>(),
            };
            code == Ok(0x3C)
        })
}

/// `(name, replacement text)` of each internal general entity declared in an internal
/// subset, skipping comments, processing instructions, other declarations (quoted text
/// in them may hold `>`), parameter entities and external entities.
fn declarations(subset: &str) -> Vec<(&str, &str)> {
    let mut found = Vec::new();
    let mut rest = subset;
    while let Some(at) = rest.find('<') {
        rest = &rest[at..];
        if let Some(after) = rest.strip_prefix("<!--") {
            rest = after.find("-->").map_or("", |end| &after[end + 3..]);
        } else if let Some(after) = rest.strip_prefix("<?") {
            rest = after.find("?>").map_or("", |end| &after[end + 2..]);
        } else if let Some(after) = rest.strip_prefix("<!ENTITY") {
            if let Some(entity) = internal_entity(after) {
                found.push(entity);
            }
            rest = skip_declaration(after);
        } else {
            rest = skip_declaration(&rest[1..]);
        }
    }
    found
}

/// `name "value"` (or with single quotes) after `<!ENTITY`; None for `% name` and for
/// `name SYSTEM …` / `name PUBLIC …`.
fn internal_entity(decl: &str) -> Option<(&str, &str)> {
    let decl = decl.trim_start_matches(is_xml_space);
    let end = decl.find(is_xml_space)?;
    let (name, rest) = decl.split_at(end);
    if name.starts_with('%') {
        return None;
    }
    let rest = rest.trim_start_matches(is_xml_space);
    let quote = rest.chars().next().filter(|c| matches!(c, '"' | '\''))?;
    let value = &rest[1..];
    let close = value.find(quote)?;
    Some((name, &value[..close]))
}

/// The text after the `>` that ends a declaration, stepping over quoted strings.
fn skip_declaration(decl: &str) -> &str {
    let mut quote = None;
    for (i, c) in decl.char_indices() {
        match (quote, c) {
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), _) if c == q => quote = None,
            (None, '>') => return &decl[i + 1..],
            _ => {}
        }
    }
    ""
}

fn is_xml_space(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\r' | '\n')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn internal_general_entities_only() {
        let subset = r#"
            <!-- <!ENTITY commented "no"> -->
            <!ENTITY a "one">
            <!ENTITY a "second declaration: ignored">
            <!ENTITY b 'two "quoted" > still'>
            <!ENTITY % p "parameter">
            <!ENTITY ext SYSTEM "file:///etc/passwd">
            <!ATTLIST X3D note CDATA "<!ENTITY fake 'x'>">
            <?pi <!ENTITY pi "x"> ?>
            %p;
        "#;
        assert_eq!(
            declarations(subset),
            [
                ("a", "one"),
                ("a", "second declaration: ignored"),
                ("b", r#"two "quoted" > still"#)
            ]
        );
        let mut entities = Entities::default();
        entities.declare(&format!("X3D [{subset}]"));
        assert_eq!(entities.declared["a"], "one");
        assert_eq!(entities.declared.len(), 2);
    }

    #[test]
    fn truncated_declarations_end_the_scan() {
        for subset in [
            "<!ENTITY",
            "<!ENTITY a",
            "<!ENTITY a \"open",
            "<!--",
            "<?",
            "<!A '",
        ] {
            let _ = declarations(subset);
        }
    }
}
