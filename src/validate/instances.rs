//! Findings in prototype instances. The rules see the nodes each instantiation copies
//! (see `model::instantiate`) besides the body as written, and a copy keeps the places of
//! the body node it copies, so one cause can be found many times: in the body as written
//! and in each copy, or in the copies of instances with different values. Here the same
//! finding (code, place, message, element) is kept once:
//! - found in the body as written too, it is the as-written finding (the instances add
//!   nothing to it);
//! - found only in copies, it gets a related note at the instance (for a nested
//!   instance, at each instance from the inside out) and, when it comes from more than one
//!   instance, says how many.

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, Span};
use crate::model::{Document, NodeId, NodeKind};

/// Folds the repeats of findings in prototype instances (see the module doc).
pub fn fold(doc: &Document, diagnostics: Vec<Diagnostic>) -> Vec<Diagnostic> {
    if doc.instantiations.is_empty() {
        return diagnostics;
    }
    /// Per kept diagnostic: the instance it was found in (None: as written) and how
    /// many instances it stands for.
    struct Kept {
        diagnostic: Diagnostic,
        instance: Option<NodeId>,
        instances: u64,
    }
    let mut kept: Vec<Kept> = Vec::with_capacity(diagnostics.len());
    let mut seen: HashMap<(&'static str, Span, String, Option<usize>), usize> = HashMap::new();
    for diagnostic in diagnostics {
        let instance = diagnostic
            .node
            .and_then(|n| doc.nodes.get(n.index()))
            .and_then(|n| n.copy_of)
            .map(|c| c.instance);
        let key = (
            diagnostic.rule.code,
            diagnostic.span,
            diagnostic.message.clone(),
            diagnostic.index,
        );
        match seen.get(&key) {
            Some(&at) if instance.is_some() || kept[at].instance.is_some() => {
                let first = &mut kept[at];
                match (first.instance, instance) {
                    (Some(_), Some(also)) => {
                        first.instances = first.instances.saturating_add(instances(doc, also))
                    }
                    (Some(_), None) => {
                        first.instance = None;
                        first.diagnostic = diagnostic;
                    }
                    _ => {}
                }
            }
            _ => {
                seen.insert(key, kept.len());
                let instances = instance.map_or(0, |i| instances(doc, i));
                kept.push(Kept {
                    diagnostic,
                    instance,
                    instances,
                });
            }
        }
    }
    kept.into_iter()
        .map(|k| {
            let mut d = k.diagnostic;
            if let Some(instance) = k.instance {
                if k.instances > 1 {
                    d.message = format!("{} (in {} prototype instances)", d.message, k.instances);
                    d.count = d
                        .count
                        .max(1)
                        .saturating_mul(k.instances.min(usize::MAX as u64) as usize);
                }
                note_library(doc, &mut d);
                note_instances(doc, &mut d, instance);
            }
            d
        })
        .collect()
}

/// How many ProtoInstance nodes an instantiation's copy stands for: those sharing it,
/// times those sharing each instantiation it is nested in.
fn instances(doc: &Document, instance: NodeId) -> u64 {
    let mut count = 1u64;
    let mut current = Some(instance);
    while let Some(id) = current {
        count = count.saturating_mul(doc.instantiation_of(id).map_or(1, |i| i.count));
        current = doc.node(id).copy_of.map(|c| c.instance);
    }
    count
}

/// For a finding in a copy of a library file's body: where in that file, as a note at the
/// finding's place (spans of another file are never shown against this one).
fn note_library(doc: &Document, d: &mut Diagnostic) {
    let place = d
        .node
        .and_then(|n| doc.nodes.get(n.index()))
        .and_then(|n| n.copy_of)
        .and_then(|c| c.library);
    if let Some(place) = place {
        let body = doc
            .library_bodies
            .get(place.body as usize)
            .map_or("", |body| body.label.as_str());
        d.related
            .push((d.span, format!("in the body of {body} line {}", place.line)));
    }
}

/// A related note at the instance, and at each instance it is nested in.
fn note_instances(doc: &Document, d: &mut Diagnostic, instance: NodeId) {
    let mut current = Some(instance);
    while let Some(id) = current {
        let node = doc.node(id);
        let name = match &node.kind {
            NodeKind::ProtoInstance { name, .. } => name.as_str(),
            _ => "",
        };
        let nested = if node.copy_of.is_some() {
            ", in the body"
        } else {
            ""
        };
        d.related.push((
            node.name_span,
            format!("in this instance of `{name}`{nested}"),
        ));
        current = node.copy_of.map(|c| c.instance);
    }
}
