//! UNIT_CATEGORY_DUPLICATE: two `unit` statements of one category in one document.

use std::collections::HashMap;

use crate::diagnostic::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a `unit` statement whose `category` an earlier `unit` statement of the same
    /// document already set, at the later statement's category, with a note at the first.
    /// Categories are compared as written (they are case-sensitive enumeration values); a
    /// category outside angle, force, length and mass is FIELD_ENUM_INVALID and is still
    /// compared here. Before X3D 3.3 the statements themselves are NODE_NOT_IN_VERSION
    /// and this rule stays silent.
    ///
    /// ## Why it matters
    /// A unit statement redefines the base unit of its category for the whole scene;
    /// the clause lets each category have one such definition. With two, the scene's
    /// lengths (or angles, forces, masses) mean one thing to one browser and another to
    /// the next, depending on which statement it keeps.
    ///
    /// ## Example
    /// ```xml
    /// <head>
    ///   <unit category='length' name='centimeters' conversionFactor='0.01'/>
    ///   <unit category='length' name='millimeters' conversionFactor='0.001'/>
    /// </head>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <head>
    ///   <unit category='length' name='millimeters' conversionFactor='0.001'/>
    /// </head>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.2.5.5 UNIT statement (one conversion per base unit category, the
    /// categories of 4.3.6 Table 4.2); 19776-1 4.2.3.4, 19776-2 the UNIT statement.
    ///
    /// A warning (issue 33): no "shall" found in 19775-1 itself. The sentence below is the
    /// X3D 3.3 Units proposal's wording for 7.2.5.5, as D. Brutzman quoted it on
    /// x3d-public, 2011-06-19 ("important questions regarding Units proposal"); neither the
    /// 3.3 nor the 4.0 text of 7.2.5.5, nor a copy of it in a browser's source, was found
    /// to confirm that the standard kept it, and the XML schema does not constrain it
    /// (no uniqueness constraint on `unit/@category`).
    ///
    /// "At most one UNIT statement shall be provided for each base unit type." (the 3.3
    /// Units proposal, for 19775-1 7.2.5.5)
    pub static UNIT_CATEGORY_DUPLICATE = {
        severity: Warning,
        level: Fast,
        clause: "7.2.5.5",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if ctx.version < Version::V3_3 {
        return;
    }
    let mut first = HashMap::new();
    for unit in &ctx.doc.head.units {
        let Some(category) = &unit.category else {
            continue;
        };
        let Some(earlier) = first.get(category.text.as_str()) else {
            first.insert(category.text.as_str(), unit.span);
            continue;
        };
        let diagnostic = Diagnostic::new(
            &UNIT_CATEGORY_DUPLICATE,
            category.span,
            format!(
                "a second unit statement for category `{}`: each category takes one",
                category.text
            ),
        )
        .value(category.text.clone())
        .related(*earlier, format!("`{}` first set here", category.text))
        .help("keep one unit statement per category");
        ctx.report(diagnostic);
    }
}
