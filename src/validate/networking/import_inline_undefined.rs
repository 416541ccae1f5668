//! IMPORT_INLINE_UNDEFINED: an IMPORT whose inlineDEF names no Inline of its scope.

use super::imports::named_inline;
use crate::diagnostic::Diagnostic;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports an IMPORT statement whose `inlineDEF` is empty, names no node DEF'd in the
    /// statement's name scope, or names a node that is not an Inline. This is decided
    /// within the file, at every level, without reading the inlined file; whether the
    /// Inline's file exports `importedDEF` is IMPORT_UNRESOLVED's (deep level).
    ///
    /// ## Why it matters
    /// An IMPORT takes a node from the scene an Inline loads; with no such Inline a
    /// browser imports nothing, the ROUTEs naming the imported node are dropped, and the
    /// interaction they wire does nothing. Usually the Inline's DEF name is misspelt.
    ///
    /// ## Example
    /// ```xml
    /// <Inline DEF='Lamp' url='"lamp.x3d"'/>
    /// <IMPORT inlineDEF='Lmap' importedDEF='Switch' AS='LampSwitch'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Inline DEF='Lamp' url='"lamp.x3d"'/>
    /// <IMPORT inlineDEF='Lamp' importedDEF='Switch' AS='LampSwitch'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.9.2 IMPORT semantics: the statement names "the DEF name of the Inline
    /// node" whose scene exports the node, in the importing scene's name scope (4.4.7);
    /// 9.4.2 Inline. The statements as encoded: 19776-1 (XML) `IMPORT` with `inlineDEF`,
    /// 19776-2 4.3.2.14 (ClassicVRML) `IMPORT inlineDEF.importedDEF AS name`, 19776-5
    /// (JSON) `@inlineDEF`. Until this code, IMPORT_UNRESOLVED reported these statements
    /// at the deep level only.
    /// In XML the schema makes `inlineDEF` an `xs:IDREF` (x3d-4.0.xsd, IMPORT), so a name
    /// that no DEF of the document carries breaks the XML validity constraint below; a DEF
    /// that names no Inline breaks 4.9.2's reading of the name ("the DEF name of the Inline
    /// node"). ClassicVRML and JSON carry the same statement, with the same meaning.
    /// > "each Name MUST match the value of an ID attribute on some element in the XML document" (XML 1.0 3.3.1, Validity constraint: IDREF)
    pub static IMPORT_INLINE_UNDEFINED = {
        severity: Error,
        level: Standard,
        clause: "4.9.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for import in &doc.imports {
        let Err(named) = named_inline(doc, import) else {
            continue;
        };
        let inline = &import.inline_def;
        let diagnostic = match named {
            _ if inline.text.is_empty() => Diagnostic::new(
                &IMPORT_INLINE_UNDEFINED,
                inline.span,
                "IMPORT has no `inlineDEF`",
            ),
            Some(type_name) => Diagnostic::new(
                &IMPORT_INLINE_UNDEFINED,
                inline.span,
                format!(
                    "IMPORT inlineDEF `{}` names a {type_name}, not an Inline",
                    inline.text
                ),
            )
            .value(inline.text.clone()),
            None => {
                let mut names: Vec<&str> = doc
                    .defs
                    .iter()
                    .filter(|((scope, _), id)| {
                        *scope == import.scope && doc.node(**id).is_a("Inline")
                    })
                    .map(|((_, n), _)| n.as_str())
                    .collect();
                names.sort_unstable();
                Diagnostic::new(
                    &IMPORT_INLINE_UNDEFINED,
                    inline.span,
                    format!(
                        "IMPORT inlineDEF `{}` names no Inline DEF'd in its scope",
                        inline.text
                    ),
                )
                .value(inline.text.clone())
                .help_opt(
                    suggest::did_you_mean(&inline.text, names)
                        .map(|c| format!("did you mean `{c}`?")),
                )
            }
        };
        found.push(diagnostic);
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
