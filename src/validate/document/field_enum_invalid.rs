//! FIELD_ENUM_INVALID: a string not among a field's enumerated values.

use crate::model::Value;
use crate::report::Diagnostic;
use crate::schema::FieldDef;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a string value that is not among the values a field allows, for every
    /// field whose values are a closed list in the X3D Unified Object Model of the
    /// document's version (Appearance.alphaMode, TextureCoordinateGenerator.mode,
    /// TextureProperties boundary modes, filters and compression, MultiTexture
    /// mode/source/function, …), with the values a clause adds to the UOM's list (an
    /// empty FontStyle `style` or `justify`, 15.2.2.2–3). Each string of an MFString
    /// is checked on its own against every string the allowed values are made of (the
    /// UOM lists MFString values whole, as combinations such as `"MIDDLE" "BEGIN"`).
    /// Values are case-sensitive, and a case slip gets a suggestion. The `category` of a
    /// `unit` statement is checked the same way: angle, force, length or mass (7.2.5.5,
    /// Table 4.2; the UOM's `unitCategoryChoices`).
    ///
    /// ## Why it matters
    /// Browsers fall back to the default for an unknown value, silently.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance alphaMode='blend'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 the node's clause (the field's list of values).
    pub static FIELD_ENUM_INVALID = {
        severity: Error,
        level: Fast,
        clause: "4.4.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    unit_categories(ctx);
    for (id, node) in ctx.doc.iter() {
        for entry in &node.fields {
            let Some(def) = entry.schema_def() else {
                continue;
            };
            let (true, Value::Strings(strings)) = (def.enumeration_strict, &entry.value) else {
                continue;
            };
            let allowed = allowed_values(def);
            for (i, string) in strings.iter().enumerate() {
                if allowed.contains(&string.as_str()) {
                    continue;
                }
                let mut diagnostic = Diagnostic::new(
                    &FIELD_ENUM_INVALID,
                    entry.span,
                    format!(
                        "{}.{}: `{string}` is not one of its values",
                        node.type_name(),
                        def.name
                    ),
                )
                .node(id)
                .value(string.clone())
                .help(
                    suggest::help(string, allowed.iter().copied())
                        .unwrap_or_else(|| format!("allowed: {}", allowed.join(", "))),
                );
                if def.ty.is_mf() {
                    diagnostic = diagnostic.index(i);
                }
                ctx.report(diagnostic);
            }
        }
    }
}

/// The values one string may take. The UOM writes MFString enumerations as whole values
/// (`"MIDDLE" "BEGIN"` for FontStyle.justify); each string of such a value is checked
/// against every string those values are made of, in first-seen order.
fn allowed_values(def: &FieldDef) -> Vec<&'static str> {
    let mut allowed: Vec<&'static str> = Vec::new();
    for entry in def.enumeration {
        let strings: Vec<&'static str> = if def.ty.is_mf() && entry.contains('"') {
            entry.split('"').skip(1).step_by(2).collect()
        } else {
            vec![*entry]
        };
        for s in strings {
            if !allowed.contains(&s) {
                allowed.push(s);
            }
        }
    }
    allowed
}

/// The base unit categories a `unit` statement may rescale (19775-1 7.2.5.5 and 4.3.6,
/// Table 4.2; `unitCategoryChoices` in the UOM, a closed list).
const UNIT_CATEGORIES: [&str; 4] = ["angle", "force", "length", "mass"];

fn unit_categories(ctx: &mut Ctx) {
    for unit in &ctx.doc.head.units {
        let Some(category) = &unit.category else {
            continue;
        };
        if UNIT_CATEGORIES.contains(&category.text.as_str()) {
            continue;
        }
        let diagnostic = Diagnostic::new(
            &FIELD_ENUM_INVALID,
            category.span,
            format!(
                "unit.category: `{}` is not one of its values",
                category.text
            ),
        )
        .value(category.text.clone())
        .help(
            suggest::help(&category.text, UNIT_CATEGORIES)
                .unwrap_or_else(|| format!("allowed: {}", UNIT_CATEGORIES.join(", "))),
        );
        ctx.report(diagnostic);
    }
}
