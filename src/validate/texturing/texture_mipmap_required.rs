//! TEXTURE_MIPMAP_REQUIRED: a MIPMAP minification filter without mipmaps.

use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a TextureProperties whose `minificationFilter` names a MIPMAP mode while
    /// `generateMipMaps` is FALSE (its default).
    ///
    /// ## Why it matters
    /// 18.4.9: "Modes with MIPMAP in the name require mipmaps. If mipmaps are not provided,
    /// the mode shall pick the corresponding non-mipmapped mode (e.g.,
    /// AVG_PIXEL_NEAREST_MIPMAP becomes AVG_PIXEL)." The filtering asked for is not the one
    /// drawn; `generateMipMaps='true'` gives it.
    ///
    /// ## Example
    /// ```xml
    /// <TextureProperties minificationFilter='AVG_PIXEL_AVG_MIPMAP'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 18.4.9 TextureProperties.
    pub static TEXTURE_MIPMAP_REQUIRED = {
        severity: Warning,
        level: Standard,
        clause: "18.4.9",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for id in doc.nodes_of_type("TextureProperties") {
        let node = doc.node(id);
        if node.is_connected("minificationFilter") || node.is_connected("generateMipMaps") {
            continue;
        }
        let Some(entry) = node.entry("minificationFilter") else {
            continue;
        };
        let Some(filter) = entry.value.as_strings().and_then(|v| v.first()) else {
            continue;
        };
        if filter.contains("MIPMAP") && doc.bool_of(id, "generateMipMaps") == Some(false) {
            found.push((id, entry.span, filter.clone()));
        }
    }
    for (id, span, filter) in found {
        let fallback = filter
            .trim_end_matches("_MIPMAP")
            .trim_end_matches("_AVG")
            .trim_end_matches("_NEAREST");
        ctx.report(
            Diagnostic::new(
                &TEXTURE_MIPMAP_REQUIRED,
                span,
                format!(
                    "minificationFilter \"{filter}\" needs mipmaps but generateMipMaps is FALSE: {fallback} is used instead"
                ),
            )
            .node(id)
            .help("set generateMipMaps='true'"),
        );
    }
}
