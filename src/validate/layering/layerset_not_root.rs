//! LAYERSET_NOT_ROOT: a LayerSet held in a field of another node.

use super::is_layer_set;
use crate::diagnostic::Diagnostic;
use crate::model::{FieldEntry, FieldRef, NodeId};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a LayerSet that stands in a field of another node (a Group's `children`, a
    /// LayoutLayer's, a Switch's, a prototype instance's field value, …), written there or
    /// placed there by `USE`; a prototype instance that builds a LayerSet counts as one.
    /// A LayerSet among the Scene's top-level nodes is a root node and is left alone, as
    /// is one at the top of a prototype body (the instance decides where it stands). A
    /// field whose type does not take a LayerSet (a group's `children`, which takes
    /// X3DChildNode) is NODE_TYPE_NOT_ALLOWED's, so this rule reports the fields that
    /// take any node: Script and shader fields, prototype field values.
    /// Each file is checked on its own: a LayerSet at the top of a file that an Inline
    /// loads is the root of that file's scene.
    ///
    /// ## Why it matters
    /// The LayerSet is what makes the scene a set of layers: browsers look for it among
    /// the root nodes. One buried in a group is ignored or, by some browsers, rendered as
    /// a plain group of all its layers on top of each other, with one navigation for all.
    ///
    /// ## Example
    /// ```xml
    /// <Scene>
    ///   <Script>
    ///     <field name='layers' type='SFNode' accessType='initializeOnly'>
    ///       <LayerSet order='1'>
    ///         <Layer><Shape><Box/></Shape></Layer>
    ///       </LayerSet>
    ///     </field>
    ///   </Script>
    /// </Scene>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Scene>
    ///   <LayerSet DEF='Layers' order='1'>
    ///     <Layer><Shape><Box/></Shape></Layer>
    ///   </LayerSet>
    ///   <Script>
    ///     <field name='layers' type='SFNode' accessType='initializeOnly'/>
    ///   </Script>
    /// </Scene>
    /// ```
    /// and give the Script the LayerSet at run time, or hold only the Layer it needs.
    ///
    /// ## Clause
    /// 19775-1 35.2 Concepts (35.2.2 Layer sets in 3.3), read in the 4.0 IS page
    /// (web3d.org `…/ISO-IEC19775-1v4-IS/Part01/components/layering.html`) and the same
    /// sentence in the 3.3 page. A root node is a top-level node of the scene (4.4.2.1);
    /// a node inside a prototype body becomes one only where its instance is one.
    /// > "Only one LayerSet node is allowed and shall be a root node." (19775-1 35.2)
    pub static LAYERSET_NOT_ROOT = {
        severity: Error,
        level: Standard,
        clause: "35.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut found = Vec::new();
    for (index, node) in doc.written_nodes().iter().enumerate() {
        for entry in &node.fields {
            let Some(children) = entry.value.as_nodes() else {
                continue;
            };
            if typed_against_layer_set(ctx, entry) {
                continue;
            }
            for child in children.iter().filter(|c| is_layer_set(doc, c.node)) {
                let holder = format!("{}.{}", node.type_name(), entry.name());
                found.push((child.node, child.span, holder, NodeId(index as u32)));
            }
        }
    }
    for (id, span, holder, parent) in found {
        ctx.report(
            Diagnostic::new(
                &LAYERSET_NOT_ROOT,
                span,
                format!("LayerSet is in {holder}: a LayerSet shall be a root node of the scene"),
            )
            .node(id)
            .related(doc.node(parent).name_span, "held here")
            .help("move the LayerSet to the top level of the Scene and put the other nodes inside its layers"),
        );
    }
}

/// Whether `entry` is a field of the schema, in the document's version, whose type takes
/// no LayerSet: NODE_TYPE_NOT_ALLOWED reports what stands there.
fn typed_against_layer_set(ctx: &Ctx, entry: &FieldEntry) -> bool {
    let FieldRef::Schema { def, version } = entry.field else {
        return false;
    };
    version == ctx.version
        && !def.acceptable.is_empty()
        && !def.acceptable.iter().any(|a| LAYER_SET_TYPES.contains(a))
}

/// The types a LayerSet is: a field that takes one of them takes a LayerSet.
const LAYER_SET_TYPES: [&str; 2] = ["LayerSet", "X3DNode"];
