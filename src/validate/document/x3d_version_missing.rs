//! X3D_VERSION_MISSING: the root has no `version`.

use crate::report::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an `X3D` root without a `version` attribute (`@version` member in JSON).
    ///
    /// ## Why it matters
    /// The version decides which nodes, fields and value ranges apply. The encodings
    /// require it. x3dcheck then checks against the latest version, 4.1.
    ///
    /// ## Example
    /// ```xml
    /// <X3D profile='Interchange'><Scene/></X3D>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 4.2 (X3D element); 19775-1 7.2.5.2 (X3D header statement).
    pub static X3D_VERSION_MISSING = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    // A VRML97 file has its version from its header line, not from a `version`.
    if ctx.doc.version_text.is_none() && ctx.doc.version != Some(Version::Vrml97) {
        ctx.report(
            Diagnostic::new(&X3D_VERSION_MISSING, ctx.doc.root_span, "the X3D root has no `version`")
                .help("add version='4.1' (or the version the scene was written for); checking against 4.1"),
        );
    }
}
