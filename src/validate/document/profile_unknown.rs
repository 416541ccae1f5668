//! PROFILE_UNKNOWN: the root's `profile` names no X3D profile.

use crate::diagnostic::Diagnostic;
use crate::validate::{suggest, Ctx};

/// The profiles of 19775-1 (clause 7.2.5.3 and Annexes A–F, H, I).
pub const PROFILES: [&str; 8] = [
    "Core",
    "Interchange",
    "CADInterchange",
    "Interactive",
    "Immersive",
    "MedicalInterchange",
    "MPEG4Interactive",
    "Full",
];

crate::declare_rule! {
    /// ## What it does
    /// Reports a `profile` that is not one of Core, Interchange, CADInterchange,
    /// Interactive, Immersive, MedicalInterchange, MPEG4Interactive, Full (names are
    /// case-sensitive).
    ///
    /// ## Why it matters
    /// A browser that does not know the profile may refuse to load the scene.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0' profile='interchange'><Scene/></X3D>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 7.2.5.3 (PROFILE statement).
    /// The profile is of type `profileNameChoices` in x3d-4.0.xsd, a closed list.
    /// > "This list is bounded, no additional values are allowed." (x3d-4.0.xsd, profileNameChoices)
    pub static PROFILE_UNKNOWN = {
        severity: Error,
        level: Fast,
        clause: "7.2.5.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let Some(profile) = &ctx.doc.profile else {
        return;
    };
    if PROFILES.contains(&profile.text.as_str()) {
        return;
    }
    ctx.report(
        Diagnostic::new(
            &PROFILE_UNKNOWN,
            profile.span,
            format!("`{}` is not an X3D profile", profile.text),
        )
        .value(profile.text.clone())
        .help_opt(suggest::help(&profile.text, PROFILES)),
    );
}
