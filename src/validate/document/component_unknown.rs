//! COMPONENT_UNKNOWN: a `component` statement names no component, or a level it lacks.

use crate::diagnostic::{Diagnostic, Severity};
use crate::schema::{self, Version};
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a `component` statement whose name is no component of the document's
    /// version, or whose level is below 1 or above the highest level that component has.
    ///
    /// ## Why it matters
    /// Browsers refuse scenes that ask for a component or level they do not know; a
    /// typo here makes a valid scene fail to load.
    ///
    /// ## Example
    /// ```xml
    /// <head><component name='Shape' level='9'/></head>
    /// ```
    ///
    /// `H-Anim`, the X3D 3 name of the HAnim component, is a warning in an X3D 4 document:
    /// 4.0 renamed the component HAnim, but x3d-4.0.xsd and x3d-4.1.xsd keep `H-Anim` in
    /// their `componentNameChoices` ("Legacy enumeration H-Anim for X3D versions 3.0-3.3
    /// provides backwards compatibility with Humanoid Animation (HAnim) version 1,
    /// preferred form of enumeration value is HAnim"), so the document is schema-valid and
    /// browsers take the old name; the help says to write the new one.
    ///
    /// ## Clause
    /// 19775-1 7.2.5.4 (COMPONENT statement); the support-level tables of each component.
    /// Each component's clause opens by naming it, e.g. 12.1 "The name of this component
    /// is "Shape"". A name no component of the version has breaks that sentence; a level
    /// outside the component's support-level table asks for support the version does not
    /// define.
    /// > "This name shall be used when referring to this component in the COMPONENT statement" (19775-1 12.1, and the first subclause of every component's clause)
    pub static COMPONENT_UNKNOWN = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.4",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let version_schema = schema::schema(ctx.version);
    for statement in &ctx.doc.head.components {
        let name = &statement.name;
        if name.text == "H-Anim" && matches!(ctx.version, Version::V4_0 | Version::V4_1) {
            ctx.report(
                Diagnostic::new(
                    &COMPONENT_UNKNOWN,
                    name.span,
                    format!(
                        "`H-Anim` is the X3D 3 name of the HAnim component; {} names it HAnim (its schema keeps `H-Anim` as a legacy name)",
                        ctx.version.name()
                    ),
                )
                .severity(Severity::Warning)
                .value(name.text.clone())
                .help("name the component HAnim"),
            );
            continue;
        }
        let Some(component) = version_schema.component(&name.text) else {
            let names = version_schema.components.iter().map(|c| c.name);
            ctx.report(
                Diagnostic::new(
                    &COMPONENT_UNKNOWN,
                    name.span,
                    format!(
                        "`{}` is not a component of {}",
                        name.text,
                        ctx.version.name()
                    ),
                )
                .value(name.text.clone())
                .help_opt(suggest::help(&name.text, names)),
            );
            continue;
        };
        if let Some((level, span)) = statement.level {
            if level < 1 || level > i32::from(component.max_level) {
                ctx.report(
                    Diagnostic::new(
                        &COMPONENT_UNKNOWN,
                        span,
                        format!(
                            "component {} has levels 1 to {} in {}, not {level}",
                            component.name,
                            component.max_level,
                            ctx.version.name()
                        ),
                    )
                    .value(level.to_string()),
                );
            }
        }
    }
}
