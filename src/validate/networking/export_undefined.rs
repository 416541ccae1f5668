//! EXPORT_UNDEFINED: an EXPORT statement names no DEF of the file's top-level scene.

use crate::diagnostic::Diagnostic;
use crate::model::Scope;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports an EXPORT statement whose `localDEF` is missing or names no node DEF'd in the
    /// file's top-level scene: a misspelt name, a name DEF'd only inside a ProtoBody (each
    /// body is a name scope of its own, 4.4.7, which an EXPORT cannot reach), or none at all.
    /// The DEF may come before or after the EXPORT. Checked in every file as written,
    /// whether or not a scene inlines it.
    ///
    /// ## Why it matters
    /// An EXPORT makes a node of an inlined file reachable from the scene that inlines it
    /// (19775-1 4.9.3): ROUTEs of that scene reach the node through an IMPORT of the
    /// exported name. An EXPORT of no node exports nothing, so every IMPORT of the name
    /// fails and the ROUTEs to and from it do nothing.
    ///
    /// ## Example
    /// ```xml
    /// <TimeSensor DEF='Clock' loop='true'/>
    /// <EXPORT localDEF='Clok' AS='Timer'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <EXPORT localDEF='Clock' AS='Timer'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.9.3 EXPORT semantics (the localDEF names a node of the file's scene);
    /// the statement as encoded: 19776-1 (XML) `EXPORT` element with `localDEF` and `AS`,
    /// 19776-2 4.3.2.15 (ClassicVRML) `EXPORT localDEF AS name`, 19776-5 (JSON)
    /// `{"EXPORT": {"@localDEF", "@AS"}}`.
    /// In XML the schema makes `localDEF` an `xs:IDREF` (x3d-4.0.xsd, EXPORT), so a name
    /// that no DEF (an `xs:ID`) of the document carries breaks the XML validity constraint
    /// below; ClassicVRML and JSON carry the same statement, with the same meaning.
    /// > "each Name MUST match the value of an ID attribute on some element in the XML document" (XML 1.0 3.3.1, Validity constraint: IDREF)
    pub static EXPORT_UNDEFINED = {
        severity: Error,
        level: Standard,
        clause: "4.9.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for export in &doc.exports {
        let name = &export.local_def;
        if name.text.is_empty() {
            found.push(Diagnostic::new(
                &EXPORT_UNDEFINED,
                name.span,
                "EXPORT has no `localDEF`",
            ));
            continue;
        }
        if doc.defs.contains_key(&(Scope::Scene, name.text.clone())) {
            continue;
        }
        let in_body = doc
            .defs
            .keys()
            .any(|(scope, n)| *scope != Scope::Scene && *n == name.text);
        let help = if in_body {
            Some("a node of that name is DEF'd inside a ProtoBody, a name scope of its own: only nodes of the top-level scene can be exported".to_string())
        } else {
            let mut names: Vec<&str> = doc
                .defs
                .keys()
                .filter(|(scope, _)| *scope == Scope::Scene)
                .map(|(_, n)| n.as_str())
                .collect();
            names.sort_unstable();
            suggest::did_you_mean(&name.text, names).map(|c| format!("did you mean `{c}`?"))
        };
        found.push(
            Diagnostic::new(
                &EXPORT_UNDEFINED,
                name.span,
                format!(
                    "EXPORT localDEF `{}` names no DEF of this file's scene",
                    name.text
                ),
            )
            .value(name.text.clone())
            .help_opt(help),
        );
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
