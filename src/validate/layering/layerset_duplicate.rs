//! LAYERSET_DUPLICATE: a second LayerSet in the scene.

use crate::diagnostic::Diagnostic;
use crate::model::Scope;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports every LayerSet of the scene after the first one written, wherever it
    /// stands (LAYERSET_NOT_ROOT says when it is also not a root node). A `USE` of the
    /// first is the same node and is not counted; neither are LayerSets inside prototype
    /// bodies, whose instances decide how many the scene gets.
    ///
    /// ## Why it matters
    /// The scene is one sequence of layers with one rendering order and one active layer
    /// for navigation; with two LayerSets a browser renders one of them (the first, the
    /// last, or whichever it finds) and drops the other's layers without a word.
    ///
    /// ## Example
    /// ```xml
    /// <Scene>
    ///   <LayerSet order='1'><Layer><Shape><Box/></Shape></Layer></LayerSet>
    ///   <LayerSet order='1'><Layer><Shape><Sphere/></Shape></Layer></LayerSet>
    /// </Scene>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Scene>
    ///   <LayerSet order='1 2'>
    ///     <Layer><Shape><Box/></Shape></Layer>
    ///     <Layer><Shape><Sphere/></Shape></Layer>
    ///   </LayerSet>
    /// </Scene>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 35.2 Concepts (35.2.2 Layer sets in 3.3), read in the 4.0 IS page
    /// (web3d.org `…/ISO-IEC19775-1v4-IS/Part01/components/layering.html`) and the same
    /// sentence in the 3.3 page.
    /// > "Only one LayerSet node is allowed and shall be a root node." (19775-1 35.2)
    pub static LAYERSET_DUPLICATE = {
        severity: Error,
        level: Standard,
        clause: "35.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let mut layer_sets = doc
        .nodes_of_type("LayerSet")
        .filter(|id| id.index() < doc.written_nodes().len())
        .filter(|id| doc.node(*id).scope == Scope::Scene);
    let Some(first) = layer_sets.next() else {
        return;
    };
    let others: Vec<_> = layer_sets.collect();
    let first_span = doc.node(first).name_span;
    for id in others {
        ctx.report(
            Diagnostic::new(
                &LAYERSET_DUPLICATE,
                doc.node(id).name_span,
                "a second LayerSet: only one LayerSet node is allowed in a scene",
            )
            .node(id)
            .related(first_span, "the first LayerSet")
            .help("put the layers of both into one LayerSet, and list them all in its order field"),
        );
    }
}
