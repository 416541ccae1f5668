//! PROTO_BODY_EMPTY: a ProtoDeclare whose body holds no node.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a ProtoDeclare (ClassicVRML `PROTO`) whose body has no node: an empty
    /// `<ProtoBody/>`, a ProtoBody holding only comments, ROUTEs or nested ProtoDeclares
    /// (they are statements, not nodes), a JSON `ProtoBody` whose `-children` hold no
    /// node, a ClassicVRML `PROTO P [ ] { }`. A ProtoDeclare with no ProtoBody at all is
    /// reported the same way: the XML encoding makes ProtoBody a required child of
    /// ProtoDeclare (x3d-4.0.xsd: `ProtoInterface?, ProtoBody`), so a missing body is a
    /// body with no node. An ExternProtoDeclare has no body and is not concerned.
    ///
    /// ## Why it matters
    /// The first node of the body gives the prototype its type; without one, an instance
    /// has no type and nothing to show, and no field it is given takes effect. Browsers
    /// reject such a prototype or its instances.
    ///
    /// ## Example
    /// ```xml
    /// <ProtoDeclare name='Empty'>
    ///   <ProtoBody><!-- nothing yet --></ProtoBody>
    /// </ProtoDeclare>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <ProtoDeclare name='Empty'>
    ///   <ProtoBody><Group/></ProtoBody>
    /// </ProtoDeclare>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.4.4.2 PROTO statement (the body is one or more nodes; the first
    /// determines the prototype's type); 19776-1 4.3.7 (ProtoBody), 19776-2 the PROTO
    /// statement.
    /// > "A prototype definition consists of one or more nodes, nested PROTO statements, and ROUTE statements" (14772-1 4.8.3)
    ///
    /// A body with no node has none of the "one or more nodes", and no first node to give
    /// the prototype its type; the grammar says the same, `protoBody ::= protoStatements
    /// rootNodeStatement statements` (14772-1 A.2; 19776-2 Annex A likewise), where the root node
    /// statement is not optional.
    pub static PROTO_BODY_EMPTY = {
        severity: Error,
        level: Fast,
        clause: "4.4.4.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for decl in &ctx.doc.protos {
        if decl.external || !decl.body.is_empty() {
            continue;
        }
        let diagnostic = Diagnostic::new(
            &PROTO_BODY_EMPTY,
            decl.name.span,
            format!(
                "prototype `{}` has no node in its body: its first node gives its type",
                decl.name.text
            ),
        )
        .value(decl.name.text.clone())
        .help("put the node the prototype stands for in its ProtoBody");
        ctx.report(diagnostic);
    }
}
