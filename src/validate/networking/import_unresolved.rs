//! IMPORT_UNRESOLVED: an IMPORT names a name its Inline's file does not export.

use super::imports::ImportTarget;
use crate::diagnostic::Diagnostic;
use crate::validate::document::validation_incomplete::VALIDATION_INCOMPLETE;
use crate::validate::prototypes::externs::display_path;
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// At the deep level, reports an IMPORT statement whose `importedDEF` is not a name
    /// the inlined file EXPORTs (an EXPORT's `AS`, else its `localDEF`). An `inlineDEF`
    /// that names no Inline DEF'd in the statement's name scope is decided without the
    /// inlined file and reported at every level as IMPORT_INLINE_UNDEFINED (this code
    /// reported it before that code existed). The inlined file is
    /// the one the Inline loads: the first entry of its url naming a readable local file of
    /// the tree being checked, read as Inline files are (once per batch, checked as a
    /// scene of its own). An Inline whose file cannot be read (network URLs, files outside
    /// the tree, a document read from standard input) leaves the IMPORT
    /// VALIDATION_INCOMPLETE, saying why; one whose local file is missing is
    /// URL_UNRESOLVED's finding. A VRML97 file has no EXPORT statement (14772-1 has none;
    /// x3dcheck reports one there as VRML_MALFORMED), so nothing can be imported from it.
    ///
    /// The imported node takes the name `AS`, else `importedDEF`, in the importing scope:
    /// ROUTEs to and from it are checked against the exported node's type and fields like
    /// any other ROUTE (ROUTE_FIELD_UNKNOWN, ROUTE_TYPE_MISMATCH). Below the deep level the
    /// name is taken on trust (ROUTE_NODE_UNDEFINED does not report it).
    ///
    /// ## Why it matters
    /// A browser that cannot find the Inline or the exported node imports nothing: the
    /// ROUTEs naming the imported node are dropped, and the interaction they wire between
    /// the scene and its inlined part does nothing.
    ///
    /// ## Example
    /// ```xml
    /// <Inline DEF='Lamp' url='"lamp.x3d"'/>
    /// <IMPORT inlineDEF='Lamp' importedDEF='Switch' AS='LampSwitch'/>
    /// ```
    /// where `lamp.x3d` has no `<EXPORT localDEF='…' AS='Switch'/>` (nor an EXPORT of a
    /// node DEF'd `Switch` without `AS`).
    ///
    /// ## Use instead
    /// Import a name the file exports, or EXPORT the node in the inlined file.
    ///
    /// ## Clause
    /// 19775-1 4.9.2 IMPORT semantics and 4.9.3 EXPORT semantics, 9.4.2 Inline; the
    /// statements as encoded: 19776-1 (XML) `IMPORT` element with `inlineDEF`, `importedDEF`
    /// and `AS`, 19776-2 4.3.2.14 (ClassicVRML) `IMPORT inlineDEF.importedDEF AS name`,
    /// 19776-5 (JSON) `{"IMPORT": {"@inlineDEF", "@importedDEF", "@AS"}}`.
    /// A warning, not an error (issue 32): the IMPORT is right as written; what it finds
    /// depends on another file, which the browser loads at run time like any url (9.2.x, as
    /// URL_UNRESOLVED, a warning) and which may change independently, and no sentence
    /// makes a name the loaded file does not export an error of the importing file. An
    /// inlined VRML97 file with `EXPORT` lines (castle-demo-models-classic sound.wrl) is the
    /// case the message names: VRML97 has no EXPORT, so the lines are VRML_MALFORMED in that
    /// file, and the importing scene gets this warning saying why nothing is imported.
    pub static IMPORT_UNRESOLVED = {
        severity: Warning,
        level: Deep,
        clause: "4.9.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (index, import) in doc.imports.iter().enumerate() {
        let Some(target) = ctx.imports.get(index) else {
            continue;
        };
        let inline = &import.inline_def;
        let imported = &import.imported_def;
        let diagnostic = match target {
            // A missing local file is URL_UNRESOLVED's finding at the Inline; a name exported
            // but undefined is EXPORT_UNDEFINED's in the inlined file; no Inline at all,
            // IMPORT_INLINE_UNDEFINED's at every level.
            ImportTarget::Node { .. }
            | ImportTarget::ExportUndefined
            | ImportTarget::NoInline(_)
            | ImportTarget::Unread(None) => continue,
            ImportTarget::NotExported { library, exported } => {
                let file = display_path(ctx.base, &library.path);
                let vrml97 = library
                    .document
                    .as_ref()
                    .is_some_and(|d| d.version == Some(crate::schema::Version::Vrml97));
                let vrml97_export = vrml97 && names_export(&library.text, &imported.text);
                let help = if vrml97_export {
                    Some(format!("EXPORT is an X3D statement (19775-1 4.9.3) that VRML97 (14772-1) does not have: a VRML97 browser exports nothing; write {file} as X3D (`#X3D V3.3 utf8`) to export `{}`", imported.text))
                } else if vrml97 {
                    Some(format!("{file} is VRML97, which has no EXPORT statement (14772-1): a browser imports nothing from it; write it as X3D (`#X3D V3.3 utf8`) to export nodes"))
                } else if exported.is_empty() {
                    Some(format!("{file} has no EXPORT statement"))
                } else {
                    let names = exported.iter().map(String::as_str);
                    suggest::did_you_mean(&imported.text, names)
                        .map(|c| format!("did you mean `{c}`?"))
                        .or_else(|| {
                            Some(format!(
                                "{file} exports {}",
                                exported
                                    .iter()
                                    .map(|n| format!("`{n}`"))
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ))
                        })
                };
                let message = if vrml97_export {
                    format!(
                        "IMPORT {}.{}: {file}, which Inline `{}` loads, is VRML97: its `EXPORT {}` is not a VRML97 statement, so it exports nothing",
                        inline.text, imported.text, inline.text, imported.text
                    )
                } else {
                    format!(
                        "IMPORT {}.{}: {file}, which Inline `{}` loads, exports no `{}`",
                        inline.text, imported.text, inline.text, imported.text
                    )
                };
                Diagnostic::new(&IMPORT_UNRESOLVED, imported.span, message)
                    .value(imported.text.clone())
                    .help_opt(help)
            }
            ImportTarget::Unread(Some(why)) => {
                let why = why.text();
                Diagnostic::new(
                    &VALIDATION_INCOMPLETE,
                    import.span,
                    format!(
                        "IMPORT {}.{} is not checked: the file of Inline `{}` is not read: {why}",
                        inline.text, imported.text, inline.text
                    ),
                )
            }
            ImportTarget::NotScene { library } => Diagnostic::new(
                &VALIDATION_INCOMPLETE,
                import.span,
                format!(
                    "IMPORT {}.{} is not checked: {} is no X3D or VRML scene x3dcheck reads",
                    inline.text,
                    imported.text,
                    display_path(ctx.base, &library.path)
                ),
            ),
        };
        found.push(diagnostic);
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// Whether a VRML97 text has a line `EXPORT name` (or `EXPORT x AS name`), which its reader
/// drops as no VRML97 statement.
fn names_export(text: &[u8], name: &str) -> bool {
    text.split(|byte| *byte == b'\n').any(|line| {
        let Ok(line) = std::str::from_utf8(line) else {
            return false;
        };
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["EXPORT", local, rest @ ..] => match rest {
                ["AS", exported, ..] => *exported == name,
                _ => *local == name,
            },
            _ => false,
        }
    })
}
