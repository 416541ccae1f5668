//! EXTERNPROTO_INTERFACE_MISMATCH: an ExternProtoDeclare's field that the ProtoDeclare it
//! names lacks or declares otherwise.

use super::externs::display_path;
use crate::diagnostic::Diagnostic;
use crate::model::{FieldDecl, Span};
use crate::validate::events::endpoint::did_you_mean;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// At the deep level, compares each field an ExternProtoDeclare declares with the
    /// ProtoDeclare its url resolves to (in a local file of the tree being checked, see
    /// EXTERNPROTO_NOT_FOUND) and reports a field the ProtoDeclare does not declare, or
    /// declares with another type or access type. The ExternProtoDeclare may declare fewer
    /// fields than the ProtoDeclare (the others are then not reachable from this file), not
    /// more or other ones. Declarations without a valid type or accessType are not compared
    /// on that point.
    ///
    /// ## Why it matters
    /// 4.4.5.2: the interface of an external prototype shall match that of the prototype it
    /// names. Browsers refuse the mismatching field (or the whole prototype): fieldValues,
    /// ROUTEs and IS statements that use it connect to nothing.
    ///
    /// ## Example
    /// ```xml
    /// <ExternProtoDeclare name='Lamp' url='"library.x3d#Lamp"'>
    ///   <field name='on' type='SFFloat' accessType='inputOutput'/>
    /// </ExternProtoDeclare>
    /// ```
    /// where `library.x3d` declares `Lamp`'s `on` as an inputOutput SFBool.
    ///
    /// ## Use instead
    /// Copy the field declarations from the ProtoDeclare's interface (without their values).
    ///
    /// ## Clause
    /// 19775-1 4.4.5.2 EXTERNPROTO interface semantics.
    /// > "shall be a subset of those defined in the implementation" (14772-1 4.9.2, said of the names and types of the interface declaration)
    pub static EXTERNPROTO_INTERFACE_MISMATCH = {
        severity: Error,
        level: Deep,
        clause: "4.4.5.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (index, proto) in doc.protos.iter().enumerate() {
        let Some((_, target, library)) = ctx.externs.declaration(doc, index) else {
            continue;
        };
        // Where a declaration of the ProtoDeclare is, for messages: a place in the
        // library, or (in this file) a related note.
        let place = |span: Span| match library {
            Some(library) => {
                let (line, column) = library.line_column(span);
                let path = display_path(ctx.base, &library.path);
                format!(" ({path}:{line}:{column})")
            }
            None => String::new(),
        };
        let names: Vec<String> = target
            .interface
            .iter()
            .map(|f| f.name.text.clone())
            .collect();
        for field in &proto.interface {
            let name = &field.name.text;
            let Some(declared) = target.interface.iter().find(|f| &f.name.text == name) else {
                let location = place(target.name.span);
                let d = Diagnostic::new(
                    &EXTERNPROTO_INTERFACE_MISMATCH,
                    field.name.span,
                    format!(
                        "ExternProtoDeclare `{}` field `{name}`: ProtoDeclare `{}`{location} declares no such field",
                        proto.name.text, target.name.text
                    ),
                )
                .value(name.clone())
                .help_opt(did_you_mean(name, &names));
                found.push(related_here(
                    d,
                    library.is_none(),
                    target.name.span,
                    "declared here",
                ));
                continue;
            };
            let type_differs = field.ty.zip(declared.ty).is_some_and(|(a, b)| a != b);
            let access_differs = field
                .access
                .zip(declared.access)
                .is_some_and(|(a, b)| a != b);
            if !type_differs && !access_differs {
                continue;
            }
            let d = Diagnostic::new(
                &EXTERNPROTO_INTERFACE_MISMATCH,
                field.span,
                format!(
                    "ExternProtoDeclare `{}` field `{name}` is {} here but {} in ProtoDeclare `{}`{}",
                    proto.name.text,
                    declaration(field),
                    declaration(declared),
                    target.name.text,
                    place(declared.span),
                ),
            )
            .value(name.clone());
            found.push(related_here(
                d,
                library.is_none(),
                declared.span,
                "declared here",
            ));
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// `inputOutput SFBool`, as far as it is known.
fn declaration(field: &FieldDecl) -> String {
    let access = field.access.map_or("(no accessType)", |a| a.as_str());
    let ty = field.ty.map_or("(no type)".to_string(), |t| t.to_string());
    format!("{access} {ty}")
}

/// A related note at the ProtoDeclare's place when it is in this document (a place in a
/// library is in the message).
fn related_here(d: Diagnostic, in_this_file: bool, span: Span, what: &str) -> Diagnostic {
    if in_this_file {
        d.related(span, what)
    } else {
        d
    }
}
