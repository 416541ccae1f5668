//! EXTERNPROTO_NOT_FOUND: the local file an ExternProtoDeclare names has no such prototype.

use super::externs::{display_path, Resolved};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// At the deep level, reports an ExternProtoDeclare whose url names local files of the
    /// tree being checked, none of which declares the prototype: no top-level ProtoDeclare
    /// of the `#Name` the url gives, or none at all when it gives no name, or a file that is
    /// no X3D or VRML scene. A url that is only `#Name` names a ProtoDeclare of the same
    /// file.
    ///
    /// The url's entries are tried in order and the first local file that declares the
    /// prototype is used; this is reported only when none does (about the first local file
    /// tried). Local paths resolve as texture urls do (URL_UNRESOLVED: relative to the
    /// document, never outside the tree being checked); network URLs are not fetched and
    /// leave the prototype VALIDATION_INCOMPLETE. Prototypes nested in another's body are
    /// not visible from outside it (4.4.4.3), so they do not count.
    ///
    /// ## Why it matters
    /// A browser that loads the file finds no prototype to instantiate: every instance of
    /// the external prototype is missing from the scene.
    ///
    /// ## Example
    /// ```xml
    /// <ExternProtoDeclare name='Lamp' url='"library.x3d#Lamp"'>
    ///   <field name='on' type='SFBool' accessType='inputOutput'/>
    /// </ExternProtoDeclare>
    /// ```
    /// where `library.x3d` declares no ProtoDeclare `Lamp`.
    ///
    /// ## Use instead
    /// Name a prototype the file declares (`#Name` is case-sensitive), or the file that
    /// declares it.
    ///
    /// ## Clause
    /// 19775-1 4.4.5 External prototype semantics (4.4.5.3: the `#name` of the url names
    /// the prototype in the file; without it, the first prototype).
    /// A warning, not an error (issue 32): the declaration is right as written; whether the
    /// file its url names declares the prototype depends on that file, loaded at run time
    /// like any url (9.2.x; URL_UNRESOLVED, a warning, when the file is missing), and no
    /// sentence makes it an error of the declaring file.
    pub static EXTERNPROTO_NOT_FOUND = {
        severity: Warning,
        level: Deep,
        clause: "4.4.5",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let mut found = Vec::new();
    for (index, proto) in ctx.doc.protos.iter().enumerate() {
        let Some(Resolved::NotFound { url, path, why }) = ctx.externs.get(index) else {
            continue;
        };
        let message = format!(
            "ExternProtoDeclare `{}`: \"{url}\" names {}, but {why}",
            proto.name.text,
            display_path(ctx.base, path)
        );
        found.push(Diagnostic::new(
            &EXTERNPROTO_NOT_FOUND,
            proto.name.span,
            message,
        ));
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
