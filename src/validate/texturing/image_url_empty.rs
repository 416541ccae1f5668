//! IMAGE_URL_EMPTY: an ImageTexture or MovieTexture without a url.

use crate::diagnostic::Diagnostic;
use crate::model::{Document, NodeId, NodeKind};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an ImageTexture or MovieTexture whose `url` is empty (`url []`, or not
    /// given). Not reported when the url arrives at run time: a ROUTE to the node's `url`,
    /// or an `IS` connection inside a ProtoBody. A prototype instance that passes an
    /// empty url in through `IS` is reported, naming the prototype field that does.
    ///
    /// ## Why it matters
    /// 18.4.1: "When the url field contains no values ([]), texturing is disabled." The
    /// shape is drawn untextured; usually the url was lost in an export.
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.1 ImageTexture, 18.4.2 MovieTexture.
    pub static IMAGE_URL_EMPTY = {
        severity: Info,
        level: Standard,
        clause: "18.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (id, node) in doc.iter() {
        if !matches!(node.type_name(), "ImageTexture" | "MovieTexture") {
            continue;
        }
        if node.connects.iter().any(|c| c.node_field.text == "url") || routed_to_url(ctx, id) {
            continue;
        }
        if doc.value_of(id, "url").is_some_and(|v| v.is_empty()) {
            let span = node.entry("url").map_or(node.name_span, |e| e.span);
            found.push((id, span, node.type_name().to_string(), passed_in(doc, id)));
        }
    }
    for (id, span, type_name, passed_in) in found {
        let message = match passed_in {
            Some((proto, field)) => format!(
                "{type_name} has no url: texturing is disabled (its url is field `{field}` of prototype `{proto}`, empty in this instance)"
            ),
            None => format!("{type_name} has no url: texturing is disabled"),
        };
        ctx.report(Diagnostic::new(&IMAGE_URL_EMPTY, span, message).node(id));
    }
}

/// For a prototype body's node copied for an instance whose url comes through `IS`: the
/// prototype's name and the field of its interface that passes the url in.
fn passed_in(doc: &Document, id: NodeId) -> Option<(String, String)> {
    let copied = doc.node(id).copy_of.filter(|c| c.library.is_none())?;
    let connect = doc
        .node(copied.original)
        .connects
        .iter()
        .find(|c| c.node_field.text == "url")?;
    let NodeKind::ProtoInstance { name, .. } = &doc.node(copied.instance).kind else {
        return None;
    };
    Some((name.clone(), connect.proto_field.text.clone()))
}

/// Whether a ROUTE sends a url to the node (by its DEF name).
fn routed_to_url(ctx: &Ctx, id: NodeId) -> bool {
    let Some(name) = &ctx.doc.node(id).def_name else {
        return false;
    };
    ctx.doc.routes.iter().any(|r| {
        r.to_node.text == name.text && matches!(r.to_field.text.as_str(), "url" | "set_url")
    })
}
