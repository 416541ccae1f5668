//! HANIM_SKIN_WEIGHT_COUNT_MISMATCH: an HAnimJoint whose skinCoordWeight is not one weight
//! per skinCoordIndex entry.

use crate::diagnostic::Diagnostic;
use crate::validate::events::wiring::{any_set_elsewhere, routed_fields};
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an HAnimJoint whose `skinCoordIndex` and `skinCoordWeight` do not hold the
    /// same number of values, when at least one of them is written and neither is set by
    /// a ROUTE or `IS`.
    ///
    /// ## Why it matters
    /// The two fields are read as pairs: weight i says how strongly the joint moves the
    /// skin vertex that index i names. A weight without an index moves nothing, and an
    /// index without a weight leaves the vertex's share of the joint undefined, so
    /// browsers skin it differently (or not at all). It usually means an index or weight
    /// was lost when the skin was exported or edited.
    ///
    /// ## Example
    /// ```xml
    /// <HAnimJoint name='l_elbow' skinCoordIndex='0 1 2' skinCoordWeight='1 0.5'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <HAnimJoint name='l_elbow' skinCoordIndex='0 1 2' skinCoordWeight='1 0.5 0.5'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 26.3.3 HAnimJoint, whose semantics are those of the Joint object of ISO/IEC
    /// 19774 (HAnim 1.0, 6.3) and 19774-1 (HAnim 2.0): "The skinCoordWeight field contains
    /// a list of floating point values between 0.0 and 1.0 that describe an amount of
    /// weighting that should be used to affect a particular vertex from the skinCoord field
    /// of the Humanoid object. Each item in this list has a corresponding index value in
    /// the skinCoordIndex field of the Joint object indicating exactly which coordinate is
    /// to be influenced." Reading: the pairing defines the lists' meaning, so lists of
    /// different lengths have none for their unpaired values. The text states no "shall"
    /// on the file (the weights "should be used"), so the finding is a warning (issue 32:
    /// an error needs a sentence the file breaks; the audit of 2026-11-29 read one real
    /// case, 12 indices and 15 weights, as a warning).
    pub static HANIM_SKIN_WEIGHT_COUNT_MISMATCH = {
        severity: Warning,
        level: Standard,
        clause: "26.3.3",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let doc = ctx.doc;
    let routed = routed_fields(doc);
    let mut found = Vec::new();
    for id in doc.nodes_of_type("HAnimJoint") {
        if any_set_elsewhere(doc, &routed, id, &["skinCoordIndex", "skinCoordWeight"]) {
            continue;
        }
        let node = doc.node(id);
        let index = node.entry("skinCoordIndex");
        let weight = node.entry("skinCoordWeight");
        if index.is_some_and(|e| node.value(e.name()).is_none())
            || weight.is_some_and(|e| node.value(e.name()).is_none())
        {
            continue; // a value that did not parse: reported already
        }
        let indices = index.map_or(0, |e| e.value.len());
        let weights = weight.map_or(0, |e| e.value.len());
        if indices == weights {
            continue;
        }
        let Some(span) = weight.or(index).map(|e| e.span) else {
            continue;
        };
        let effect = if weights > indices {
            "the extra weights name no skin vertex"
        } else {
            "the vertices without a weight have no defined share of this joint"
        };
        let message = format!(
            "HAnimJoint{} has {} skinCoordIndex {} and {} skinCoordWeight {}: {effect}",
            super::name_suffix(doc, id),
            indices,
            if indices == 1 { "value" } else { "values" },
            weights,
            if weights == 1 { "value" } else { "values" },
        );
        let mut diagnostic = Diagnostic::new(&HANIM_SKIN_WEIGHT_COUNT_MISMATCH, span, message)
            .node(id)
            .help("give one weight per index, in the same order: weight i applies to the skin vertex index i names");
        if let (Some(index), Some(_)) = (index, weight) {
            diagnostic = diagnostic.related(index.span, format!("{indices} indices here"));
        }
        found.push(diagnostic);
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
