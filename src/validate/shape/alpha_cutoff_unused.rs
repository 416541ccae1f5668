//! ALPHA_CUTOFF_UNUSED: alphaCutoff set while alphaMode never uses it.

use crate::diagnostic::Diagnostic;
use crate::schema::Version;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an Appearance (X3D 4.0 and later: the published 4.0 has `alphaMode`, the 4.0
    /// drafts do not) that sets `alphaCutoff` explicitly while its
    /// `alphaMode` is OPAQUE or BLEND. With AUTO (the default) the browser may choose MASK,
    /// so the cutoff may be used and is not reported.
    ///
    /// ## Why it matters
    /// 12.4.2: the cutoff is "used either when alphaMode has value MASK or else when
    /// alphaMode has value AUTO and the X3D browser determines that MASK mode is most
    /// appropriate". Under OPAQUE or BLEND it does nothing; usually MASK was meant.
    ///
    /// ## Example
    /// ```xml
    /// <Appearance alphaMode='BLEND' alphaCutoff='0.3'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 12.4.2 Appearance (X3D 4.0, 4.1).
    pub static ALPHA_CUTOFF_UNUSED = {
        severity: Hint,
        level: Standard,
        clause: "12.4.2",
        versions: "4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if ctx.version < Version::V4_0 {
        return;
    }
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("Appearance") {
        let node = doc.node(id);
        let Some(cutoff) = node.entry("alphaCutoff") else {
            continue;
        };
        if node.is_connected("alphaMode") {
            continue;
        }
        if let Some(mode) = doc
            .string_of(id, "alphaMode")
            .filter(|m| m == "OPAQUE" || m == "BLEND")
        {
            found.push((id, cutoff.span, mode));
        }
    }
    for (id, span, mode) in found {
        ctx.report(
            Diagnostic::new(
                &ALPHA_CUTOFF_UNUSED,
                span,
                format!("alphaCutoff has no effect with alphaMode {mode:?}"),
            )
            .node(id)
            .help("alphaCutoff is used by alphaMode \"MASK\" (or \"AUTO\")"),
        );
    }
}
