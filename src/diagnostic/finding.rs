//! One finding: which rule, where (a byte span and, when known, the node it concerns),
//! what, and the details a tool needs (MF element index, offending value, a suggestion).

use super::{Fix, NodeId, Rule, Severity, Span};

#[derive(Clone, Debug)]
pub struct Diagnostic {
    pub rule: &'static Rule,
    pub severity: Severity,
    pub message: String,
    pub span: Span,
    /// The node the finding concerns, for the structural path.
    pub node: Option<NodeId>,
    /// The MF element index, where one element is at fault.
    pub index: Option<usize>,
    /// For a folded diagnostic: the first indices of the repeats it stands for.
    pub indices: Vec<usize>,
    /// The offending value as text.
    pub value: Option<String>,
    /// A suggestion ("did you mean `diffuseColor`?").
    pub help: Option<String>,
    /// Other places that explain this one ("first defined here").
    pub related: Vec<(Span, String)>,
    /// How many findings this one stands for (repeats folded into one).
    pub count: usize,
    /// The clause this finding cites when it is not the rule's: a rule whose statement
    /// one clause makes of some node types and another clause of others.
    pub clause: Option<&'static str>,
    /// The edits that resolve the finding, where the rule knows them (boxed: most
    /// findings have none, and diagnostics are many).
    pub fix: Option<Box<Fix>>,
}

impl Diagnostic {
    pub fn new(rule: &'static Rule, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            rule,
            severity: rule.severity,
            message: message.into(),
            span,
            node: None,
            index: None,
            indices: Vec::new(),
            value: None,
            help: None,
            related: Vec::new(),
            count: 1,
            clause: None,
            fix: None,
        }
    }

    pub fn node(mut self, node: NodeId) -> Diagnostic {
        self.node = Some(node);
        self
    }

    pub fn index(mut self, index: usize) -> Diagnostic {
        self.index = Some(index);
        self
    }

    pub fn value(mut self, value: impl Into<String>) -> Diagnostic {
        self.value = Some(value.into());
        self
    }

    pub fn help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    pub fn help_opt(mut self, help: Option<String>) -> Diagnostic {
        self.help = help;
        self
    }

    pub fn related(mut self, span: Span, label: impl Into<String>) -> Diagnostic {
        self.related.push((span, label.into()));
        self
    }

    pub fn fix(mut self, fix: Fix) -> Diagnostic {
        self.fix = Some(Box::new(fix));
        self
    }

    /// Cite `clause` rather than the rule's.
    pub fn clause(mut self, clause: &'static str) -> Diagnostic {
        self.clause = Some(clause);
        self
    }

    pub fn severity(mut self, severity: Severity) -> Diagnostic {
        self.severity = severity;
        self
    }

    pub fn code(&self) -> &'static str {
        self.rule.code
    }
}
