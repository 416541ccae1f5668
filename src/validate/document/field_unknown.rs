//! FIELD_UNKNOWN: a field no version of the node's type has.

use crate::diagnostic::{Applicability, Fix};
use crate::model::{statement_attributes, FieldRef, NodeKind, Origin};
use crate::report::Diagnostic;
use crate::validate::{edits, suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports a field (XML attribute, JSON `@` member) that the node's type does not
    /// have in any X3D version, and suggests the nearest field name (`diffusecolor` →
    /// `diffuseColor`). Fields of unknown node types are not reported again, and node
    /// children placed by `containerField` are CONTAINER_FIELD_INVALID's business.
    ///
    /// The statements of the header are checked the same way: an attribute that `head`,
    /// `component`, `unit` or `meta` does not have (x3d-4.0.xsd and the JSON schema:
    /// component `name` `level`; unit `category` `name` `conversionFactor`; meta `name`
    /// `content` `dir` `http-equiv` `lang` `scheme`; and `class` `id` `style` on each,
    /// which X3D 4 gives every statement; XML namespace declarations are not attributes).
    ///
    /// ## Why it matters
    /// Browsers ignore unknown fields, so a misspelt field silently keeps its default
    /// (and a misspelt `meta` attribute loses its metadata).
    ///
    /// ## Example
    /// ```xml
    /// <Material diffusecolor='1 0 0'/>
    /// ```
    ///
    /// ## Fix safety
    /// Where the one suggestion is a case slip (`diffusecolor` → `diffuseColor`), renaming
    /// the field is a safe fix (no two fields of a node differ only in case), unless the node
    /// already sets the field so named: then the value to keep is the author's choice and
    /// there is no fix. The statements of the header get the same fix.
    ///
    /// ## Clause
    /// 19775-1 4.4.2 (field semantics) and the node's interface table.
    /// 19776-1 4.2.3 (the header statements).
    pub static FIELD_UNKNOWN = {
        severity: Error,
        level: Fast,
        clause: "4.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for unknown in &ctx.doc.head.unknown_attributes {
        if ctx.is_full() {
            return;
        }
        let (statement, name) = (unknown.statement, &unknown.name.text);
        let names = statement_attributes(statement).unwrap_or(&[]);
        let suggestion = suggest::did_you_mean(name, names.iter().copied());
        let mut diagnostic = Diagnostic::new(
            &FIELD_UNKNOWN,
            unknown.name.span,
            format!("the {statement} statement has no attribute `{name}`"),
        )
        .value(name.clone())
        .help_opt(suggestion.map(|c| format!("did you mean `{c}`?")));
        if let Some(to) = suggestion.filter(|to| to.eq_ignore_ascii_case(name)) {
            if let Some(fix) = rename(ctx, unknown.name.span, name, to) {
                diagnostic = diagnostic.fix(fix);
            }
        }
        ctx.report(diagnostic);
    }
    for (id, node) in ctx.doc.iter() {
        let NodeKind::Known { def, .. } = node.kind else {
            continue;
        };
        for entry in &node.fields {
            let FieldRef::Unknown { name } = &entry.field else {
                continue;
            };
            if entry.origin == Origin::Children {
                continue;
            }
            if ctx.is_full() {
                return;
            }
            let names = def.fields.iter().map(|f| f.name);
            let suggestion = suggest::did_you_mean(name, names);
            let mut diagnostic = Diagnostic::new(
                &FIELD_UNKNOWN,
                entry.name_span,
                format!("{} has no field `{name}`", def.name),
            )
            .node(id)
            .value(name.clone())
            .help_opt(suggestion.map(|c| format!("did you mean `{c}`?")));
            let already_set = |to: &str| node.fields.iter().any(|e| e.name() == to);
            if let Some(to) = suggestion
                .filter(|to| to.eq_ignore_ascii_case(name) && !already_set(to))
                .filter(|_| edits::written(ctx.doc, id))
            {
                if let Some(fix) = rename(ctx, entry.name_span, name, to) {
                    diagnostic = diagnostic.fix(fix);
                }
            }
            ctx.report(diagnostic);
        }
    }
}

/// Renames the field written at `span` (an attribute, `@name` key or ClassicVRML name).
fn rename(ctx: &Ctx, span: crate::model::Span, from: &str, to: &str) -> Option<Fix> {
    let at = edits::name_at_end(ctx.source, span, from)?;
    Some(edits::fix(
        format!("Rename to `{to}`"),
        Applicability::Safe,
        vec![edits::edit(at, to)],
    ))
}
