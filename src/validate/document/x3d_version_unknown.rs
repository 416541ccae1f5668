//! X3D_VERSION_UNKNOWN: the root's `version` is not a known X3D version.

use crate::diagnostic::Diagnostic;
use crate::schema::Version;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a `version` that is not one of 3.0, 3.1, 3.2, 3.3, 4.0, 4.1.
    ///
    /// ## Why it matters
    /// Browsers pick their rules by version; an unknown one is treated differently by
    /// each. x3dcheck then checks against the latest version, 4.1.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4' profile='Interchange'><Scene/></X3D>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.2.5.2 (X3D header statement).
    /// The version is of type `x3dVersionChoices` in x3d-4.0.xsd (3.0 to 4.0; 4.1 in
    /// x3d-4.1.xsd), a closed list.
    /// > "x3dVersionChoices enumeration string constants are used to identify the allowed versions for an X3D scene graph. This list is bounded, no additional values are allowed." (x3d-4.0.xsd)
    pub static X3D_VERSION_UNKNOWN = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let Some(text) = &ctx.doc.version_text else {
        return;
    };
    if ctx.doc.version.is_some() {
        return;
    }
    let known = Version::X3D.map(Version::as_str);
    let help = suggest::help(text.text.trim(), known)
        .unwrap_or_else(|| format!("known versions: {}; checking against 4.1", known.join(", ")));
    ctx.report(
        Diagnostic::new(
            &X3D_VERSION_UNKNOWN,
            text.span,
            format!("`{}` is not a known X3D version", text.text),
        )
        .value(text.text.clone())
        .help(help),
    );
}
