//! NODE_DEPRECATED: TwoSidedMaterial in X3D 4, GeoOrigin in X3D 3.3.

use crate::diagnostic::{Applicability, Diagnostic, Fix, Span};
use crate::model::{Encoding, NodeId, Origin, Place, Value};
use crate::schema::Version;
use crate::validate::{edits, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports TwoSidedMaterial in an X3D 4.x scene, with the upgrade path of 12.4.9 for
    /// this node: with `separateBackColor` FALSE, a Material with the same front values
    /// does the same; with TRUE, put a Material in Appearance.material and another in
    /// Appearance.backMaterial. Also reports GeoOrigin in an X3D 3.3 scene (and only
    /// there: it is restored in 4.0).
    ///
    /// ## Why it matters
    /// TwoSidedMaterial is deprecated in X3D 4 and cannot be used with the physical or
    /// unlit material models or with Appearance.backMaterial. GeoOrigin is deprecated
    /// and discouraged in 3.3: browsers of 3.3 may ignore it, so the geospatial nodes
    /// that name it may be placed without the origin the author meant; 4.0 restores it
    /// for devices with limited floating-point resolution.
    ///
    /// ## Example
    /// ```xml
    /// <X3D version='4.0' profile='Immersive'>
    ///   <Scene><Shape><Appearance><TwoSidedMaterial/></Appearance><Box/></Shape></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Fix safety
    /// The fix follows that upgrade path: the node becomes a Material keeping its front
    /// fields as written, its `back…` fields and `separateBackColor` are removed, and with
    /// `separateBackColor` TRUE a second Material with the back values (`backDiffuseColor`
    /// as `diffuseColor`, …) is added as Appearance.backMaterial (XML: a sibling element
    /// with `containerField='backMaterial'`; JSON: a `-backMaterial` member after
    /// `-material`; ClassicVRML: a `backMaterial` field after `material`). The defaults of
    /// the two nodes are equal, so the Phong colours stay; it is unsafe because a browser
    /// of X3D 3.x cannot load the result, and because the back faces are now lit with the
    /// back Material's normal (12.2.4) rather than as TwoSidedMaterial's back side.
    /// There is no fix for a node with a DEF name (ROUTEs or USEs may name its back fields
    /// or share it), for a field set through IS, or when the Appearance already has a
    /// backMaterial (BACK_MATERIAL_WITH_TWO_SIDED).
    ///
    /// ## Clause
    /// 19775-1 (4.x) 12.4.9 TwoSidedMaterial. For GeoOrigin, 19775-1 (3.3) 25.4.5, as
    /// the X3D 3.3 XML Schema and Unified Object Model annotate the node (the 19775-1
    /// text itself was not read): "GeoOrigin is deprecated and discouraged (but
    /// nevertheless allowed) in X3D version 3.3. GeoOrigin is restored in X3D version 4.0
    /// for special use on devices with limited floating-point resolution."
    pub static NODE_DEPRECATED = {
        severity: Warning,
        level: Fast,
        clause: "12.4.9",
        versions: "3.3, 4.x",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    if ctx.version == Version::V3_3 {
        geo_origins(ctx);
    }
    if !ctx.version.is_4x() {
        return;
    }
    for id in ctx.doc.nodes_of_type("TwoSidedMaterial") {
        let node = ctx.doc.node(id);
        let separate = matches!(node.value("separateBackColor"), Some(Value::Bools(b)) if b.first() == Some(&true));
        let help = if separate {
            "separateBackColor is TRUE: use a Material in Appearance.material and a second Material in Appearance.backMaterial"
        } else {
            "separateBackColor is FALSE: a Material with the same front values does the same"
        };
        let mut diagnostic = Diagnostic::new(
            &NODE_DEPRECATED,
            node.name_span,
            "TwoSidedMaterial is deprecated in X3D 4",
        )
        .node(id)
        .help(help);
        if let Some(fix) = upgrade(ctx, id, separate) {
            diagnostic = diagnostic.fix(fix);
        }
        ctx.report(diagnostic);
    }
}

/// GeoOrigin in a 3.3 scene: deprecated there, restored in 4.0 (the schema annotation).
fn geo_origins(ctx: &mut Ctx) {
    for id in ctx.doc.nodes_of_type("GeoOrigin") {
        let diagnostic = Diagnostic::new(
            &NODE_DEPRECATED,
            ctx.doc.node(id).name_span,
            "GeoOrigin is deprecated and discouraged in X3D 3.3 (it is restored in 4.0)",
        )
        .node(id)
        .help("leave the geoOrigin fields empty, or declare version='4.0' if the scene needs a GeoOrigin for floating-point precision");
        ctx.report(diagnostic);
    }
}

/// TwoSidedMaterial's back fields and the Material fields they become.
const BACK_FIELDS: [(&str, &str); 6] = [
    ("backAmbientIntensity", "ambientIntensity"),
    ("backDiffuseColor", "diffuseColor"),
    ("backEmissiveColor", "emissiveColor"),
    ("backShininess", "shininess"),
    ("backSpecularColor", "specularColor"),
    ("backTransparency", "transparency"),
];

/// The upgrade of 12.4.9 as edits (see the rule's Fix safety).
fn upgrade(ctx: &Ctx, id: NodeId, separate: bool) -> Option<Fix> {
    let (doc, source) = (ctx.doc, ctx.source);
    let node = doc.node(id);
    let Place::Field { parent, .. } = node.place else {
        return None;
    };
    let appearance = doc.node(parent);
    if node.def_name.is_some()
        || !edits::written(doc, id)
        || appearance.entry("backMaterial").is_some()
    {
        return None;
    }
    let mut fix_edits =
        edits::rename_node(source, doc.encoding, node, "TwoSidedMaterial", "Material")?;
    let mut back = Vec::new();
    for field in &node.fields {
        let name = field.name();
        let material_name = BACK_FIELDS
            .iter()
            .find(|(b, _)| *b == name)
            .map(|(_, m)| *m);
        if material_name.is_none() && name != "separateBackColor" {
            continue;
        }
        if !matches!(field.origin, Origin::Attribute | Origin::Member) {
            return None;
        }
        fix_edits.push(edits::remove_field(
            source,
            doc.encoding,
            field.name_span,
            field.span,
        )?);
        if let Some(material_name) = material_name {
            let value = std::str::from_utf8(source.get(field.span.range())?).ok()?;
            back.push((material_name, value));
        }
    }
    if separate {
        let (at, text) = match doc.encoding {
            Encoding::Xml => {
                let attributes: String = back.iter().map(|(n, v)| format!(" {n}='{v}'")).collect();
                (
                    node.span.end,
                    format!("<Material containerField='backMaterial'{attributes}/>"),
                )
            }
            Encoding::Json => {
                let members: Vec<String> =
                    back.iter().map(|(n, v)| format!("\"@{n}\": {v}")).collect();
                // The node's span is its member `"TwoSidedMaterial": {…}`; the `-material`
                // value is the object around it, closed by the next `}`.
                let close = edits::skip_space(source, node.span.end as usize);
                if source.get(close) != Some(&b'}') {
                    return None;
                }
                (
                    close as u32 + 1,
                    format!(
                        ", \"-backMaterial\": {{\"Material\": {{{}}}}}",
                        members.join(", ")
                    ),
                )
            }
            Encoding::ClassicVrml | Encoding::Vrml97 => {
                let fields: String = back.iter().map(|(n, v)| format!(" {n} {v}")).collect();
                (
                    node.span.end,
                    format!(" backMaterial Material {{{fields} }}"),
                )
            }
        };
        fix_edits.push(edits::edit(Span { start: at, end: at }, text));
    }
    fix_edits.sort_by_key(|e| e.span);
    let title = if separate {
        "Replace with a Material and a backMaterial (12.4.9)"
    } else {
        "Replace with a Material (12.4.9)"
    };
    Some(edits::fix(title, Applicability::Unsafe, fix_edits))
}
