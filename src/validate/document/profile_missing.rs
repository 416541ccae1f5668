//! PROFILE_MISSING: the root has no `profile`.

use crate::diagnostic::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an `X3D` root without a `profile` attribute, or a ClassicVRML file without
    /// a PROFILE statement. VRML97 files have no profiles (14772-1 has no such statement)
    /// and are not reported.
    ///
    /// ## Why it matters
    /// The profile tells a browser which components the scene needs; without one the
    /// Full profile is assumed, so a browser that supports less may refuse the scene, and
    /// component-level checks have nothing to measure against.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0'><Scene/></X3D>
    /// ```
    ///
    /// Not reported for VRML97 files: VRML97 has no profiles and no PROFILE statement
    /// (14772-1 4.2.2: the header ends at `utf8` and an optional comment), so its files are checked against the
    /// VRML97 node set instead and the component-level rules have nothing to measure.
    ///
    /// ## Clause
    /// 19775-1 7.2.5.3 (PROFILE statement).
    ///
    /// Not reported for an X3D island of an HTML page, which X3DOM and X_ITE read without
    /// `profile`.
    pub static PROFILE_MISSING = {
        severity: Warning,
        level: Fast,
        clause: "7.2.5.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    // An island of an HTML page is read by X3DOM and X_ITE without one.
    if ctx.doc.profile.is_none() && ctx.version != Version::Vrml97 && !ctx.doc.in_page {
        ctx.report(
            Diagnostic::new(
                &PROFILE_MISSING,
                ctx.doc.root_span,
                "the X3D root has no `profile`; Full is assumed",
            )
            .help("add profile='Interchange' (or the smallest profile the scene fits)"),
        );
    }
}
