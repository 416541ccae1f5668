//! COMPONENT_UNKNOWN: a `component` statement names no component, or a level it lacks.

use crate::report::Diagnostic;
use crate::schema;
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
    /// ## Clause
    /// 19775-1 7.2.5.4 (COMPONENT statement); the support-level tables of each component.
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
