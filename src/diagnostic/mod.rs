//! The diagnostics core below the readers, the model and the rules: where a finding is
//! ([`Span`], [`NodeId`]), which rule it is ([`Rule`], declared with
//! [`declare_rule!`](crate::declare_rule)) and the finding itself ([`Diagnostic`]).
//! It depends on nothing else of the crate, so that readers and the model can report
//! without importing `validate` or `check`.

mod finding;
mod fix;
mod rule;

pub use finding::Diagnostic;
pub use fix::{Applicability, Edit, Fix};
pub use rule::{find_rule_in, Level, Rule, Severity};

/// A byte range in the input. Line and column are computed only for reported diagnostics.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Span {
    pub start: u32,
    pub end: u32,
}

impl Span {
    pub fn new(start: usize, end: usize) -> Span {
        Span {
            start: start as u32,
            end: end as u32,
        }
    }

    pub fn range(self) -> std::ops::Range<usize> {
        self.start as usize..self.end as usize
    }
}

/// A node's place in the arena.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct NodeId(pub u32);

impl NodeId {
    pub fn index(self) -> usize {
        self.0 as usize
    }
}
