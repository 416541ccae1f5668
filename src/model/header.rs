//! What the header of a document holds beyond its statements' values: content X3D gives
//! no meaning there, and attributes its statements do not have. Readers record them here
//! (ROOT_CONTENT_IGNORED and FIELD_UNKNOWN report them) and skip what they hold.

use super::Named;
use crate::limits::MAX_DIAGNOSTICS;

/// Where ignored content was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HeaderPart {
    /// Under the X3D root, which holds a head and a Scene (19776-1 4.2.2; 19776-5).
    Root,
    /// Under head, which holds component, unit and meta statements.
    Head,
}

/// An element (XML) or member (JSON) that is no part of the document where it stands.
#[derive(Clone, Debug)]
pub struct IgnoredContent {
    pub name: Named,
    pub part: HeaderPart,
}

/// An attribute (XML) or `@` member (JSON) that a head statement does not have.
#[derive(Clone, Debug)]
pub struct UnknownAttribute {
    /// `head`, `component`, `unit` or `meta`.
    pub statement: &'static str,
    /// Without JSON's `@`.
    pub name: Named,
}

/// The attributes of the head statements (x3d-4.0.xsd, the JSON schema): their own, then
/// the `class`, `id` and `style` every X3D 4 statement takes. None for another name.
pub fn statement_attributes(statement: &str) -> Option<&'static [&'static str]> {
    Some(match statement {
        "head" => &["class", "id", "style"],
        "component" => &["name", "level", "class", "id", "style"],
        "unit" => &[
            "category",
            "name",
            "conversionFactor",
            "class",
            "id",
            "style",
        ],
        "meta" => &[
            "name",
            "content",
            "dir",
            "http-equiv",
            "lang",
            "scheme",
            "class",
            "id",
            "style",
        ],
        _ => return None,
    })
}

/// The statement name as a static string (`statement` is one of the head statements).
pub fn statement_name(statement: &str) -> Option<&'static str> {
    ["head", "component", "unit", "meta"]
        .into_iter()
        .find(|&s| s == statement)
}

/// Records kept of each kind: no more can be reported (a file of a million stray `meta`
/// attributes costs no more than this).
pub const MAX_RECORDS: usize = MAX_DIAGNOSTICS;

/// Pushes `item` unless `list` holds `MAX_RECORDS` already.
pub fn record<T>(list: &mut Vec<T>, item: T) {
    if list.len() < MAX_RECORDS {
        list.push(item);
    }
}

/// Whether an XML attribute is a namespace declaration (`xmlns`, `xmlns:ds`), which any
/// element may carry.
pub fn is_namespace_declaration(name: &str) -> bool {
    name == "xmlns" || name.starts_with("xmlns:")
}
