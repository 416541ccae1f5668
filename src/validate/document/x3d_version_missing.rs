//! X3D_VERSION_MISSING: the root has no `version`.

use crate::diagnostic::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an `X3D` root without a `version` attribute (`@version` member in JSON).
    ///
    /// ## Why it matters
    /// The version decides which nodes, fields and value ranges apply. The encodings
    /// require it. x3dcheck then checks against the version the DOCTYPE
    /// (`<!DOCTYPE X3D PUBLIC "ISO//Web3D//DTD X3D 3.0//EN" …>`) or the schema location
    /// (`x3d-3.0.xsd`) names, if one does, and otherwise against the latest version, 4.1;
    /// the message says which.
    ///
    /// ## Example
    /// ```xml
    /// <X3D profile='Interchange'><Scene/></X3D>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 4.2 (X3D element); 19775-1 7.2.5.2 (X3D header statement).
    /// x3d-4.0.xsd declares the attribute `use="required"` on the X3D element, with the
    /// appinfo quoted below (the same in 3.x and 4.1); the JSON schema's X3D object requires
    /// `@version` likewise.
    /// > "Warning: version is required and must be specified in source document." (x3d-4.0.xsd, X3D element, version attribute)
    ///
    /// Not reported for an X3D island of an HTML page: that is no document of the XML
    /// encoding, and X3DOM and X_ITE read islands without `version` (their own examples
    /// have none); such an island is checked against 4.1.
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
    // An island of an HTML page is read by X3DOM and X_ITE without one.
    if ctx.doc.version_text.is_some() || ctx.doc.version == Some(Version::Vrml97) || ctx.doc.in_page
    {
        return;
    }
    let help = match ctx.doc.version_hint {
        Some(hint) => format!(
            "add version='{0}': the {1} names X3D {0}, so the scene is checked against {0}",
            hint.version.as_str(),
            hint.source
        ),
        None => "add version='4.1' (or the version the scene was written for); checking \
                 against 4.1"
            .to_string(),
    };
    ctx.report(
        Diagnostic::new(
            &X3D_VERSION_MISSING,
            ctx.doc.root_span,
            "the X3D root has no `version`",
        )
        .help(help),
    );
}
