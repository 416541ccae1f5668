//! Comments addressed to x3dcheck (`x3dcheck: ignore CODE`): each reader finds them and
//! places them on what they apply to ([`Directive`]); what they say is read where the
//! findings of a file are gathered (`crate::suppress`).
//!
//! - XML: a comment applies to the element that follows it, subtree included ([`Following`]);
//!   one before the root element, to the whole file.
//! - ClassicVRML and VRML97: a `#` comment applies to the node, statement or field that
//!   starts next in the same parent ([`place_following`]); one before the first token after
//!   the header line, to the whole file.
//! - JSON: see [`place_json`].

use super::behind::{self, Progress};
use super::json::tree::{Kind, Tree};
use crate::model::{Directive, Document, Span};

const MARK: &[u8] = b"x3dcheck:";

/// The place of the text after `x3dcheck:` when the comment text at `inner` (without its
/// delimiters) starts with it, after whitespace.
pub fn addressed(source: &[u8], inner: Span) -> Option<Span> {
    let text = source.get(inner.range())?;
    let lead = text.iter().take_while(|b| b.is_ascii_whitespace()).count();
    text[lead..]
        .starts_with(MARK)
        .then(|| Span::new(inner.start as usize + lead + MARK.len(), inner.end as usize))
}

/// An empty scope at the end of a comment: the directive applies to nothing.
fn nothing_after(comment: Span) -> Option<Span> {
    Some(Span::new(comment.end as usize, comment.end as usize))
}

/// Places directives on the elements that follow them, as the XML reader meets comments,
/// element starts and element ends in document order.
#[derive(Default)]
pub struct Following {
    found: Vec<Directive>,
    /// Directives waiting for the next element to start.
    waiting: Vec<usize>,
    /// Open elements that directives apply to: depth, start and the directives.
    open: Vec<(usize, usize, Vec<usize>)>,
}

impl Following {
    /// A comment at `span` whose text after `x3dcheck:` is at `text`; `whole_file` when no
    /// element has started yet.
    pub fn comment(&mut self, span: Span, text: Span, whole_file: bool) {
        self.found.push(Directive {
            span,
            text,
            scope: None,
        });
        if !whole_file {
            self.waiting.push(self.found.len() - 1);
        }
    }

    /// An element starts at `start`, `depth` elements deep (0: the root).
    pub fn start(&mut self, depth: usize, start: usize) {
        if !self.waiting.is_empty() {
            let waiting = std::mem::take(&mut self.waiting);
            self.open.push((depth, start, waiting));
        }
    }

    /// The element `depth` deep ends at `end`. Directives still waiting were the last
    /// content of that element: nothing follows them.
    pub fn end(&mut self, depth: usize, end: usize) {
        self.nothing_follows();
        if self.open.last().is_some_and(|(d, _, _)| *d == depth) {
            let (_, start, placed) = self.open.pop().unwrap_or_default();
            for k in placed {
                self.found[k].scope = Some(Span::new(start, end));
            }
        }
    }

    fn nothing_follows(&mut self) {
        for k in std::mem::take(&mut self.waiting) {
            self.found[k].scope = nothing_after(self.found[k].span);
        }
    }

    /// The directives placed; an element left open runs to `len`, the end of the input.
    pub fn finish(mut self, len: usize) -> Vec<Directive> {
        self.nothing_follows();
        for (_, start, placed) in std::mem::take(&mut self.open) {
            for k in placed {
                self.found[k].scope = Some(Span::new(start, len));
            }
        }
        self.found
    }
}

/// Places the directive comments of a ClassicVRML or VRML97 document, given as (comment,
/// text after `x3dcheck:`) in document order. Those ending at or before `first_token`
/// apply to the whole file; each other applies to the node, statement or field that
/// starts first after it, unless a `}` or `]` comes between (its parent ends first, and it
/// applies to nothing).
pub fn place_following(
    source: &[u8],
    doc: &Document,
    comments: &[(Span, Span)],
    first_token: usize,
) -> Vec<Directive> {
    if comments.is_empty() {
        return Vec::new();
    }
    let mut starts = constructs(doc);
    starts.sort_unstable_by_key(|s| (s.start, std::cmp::Reverse(s.end)));
    comments
        .iter()
        .map(|&(span, text)| {
            let scope = if span.end as usize <= first_token {
                None
            } else {
                let next = starts.partition_point(|s| s.start < span.end);
                match starts.get(next) {
                    Some(target) if !closes(source, span.end as usize, target.start as usize) => {
                        Some(*target)
                    }
                    _ => nothing_after(span),
                }
            };
            Directive { span, text, scope }
        })
        .collect()
}

/// The places of what a ClassicVRML directive can apply to: the nodes the document
/// writes, their fields (name to value), ROUTEs, PROTOs, IMPORTs, EXPORTs, COMPONENT and
/// UNIT statements.
fn constructs(doc: &Document) -> Vec<Span> {
    let mut spans = Vec::new();
    for node in doc.written_nodes() {
        spans.push(node.span);
        spans.extend(node.fields.iter().map(|f| {
            Span::new(
                f.name_span.start as usize,
                f.span.end.max(f.name_span.end) as usize,
            )
        }));
    }
    spans.extend(doc.routes.iter().map(|r| r.span));
    spans.extend(doc.protos.iter().map(|p| p.span));
    spans.extend(doc.imports.iter().map(|i| i.span));
    spans.extend(doc.exports.iter().map(|e| e.span));
    spans.extend(doc.head.components.iter().map(|c| c.span));
    spans.extend(doc.head.units.iter().map(|u| u.span));
    spans
}

/// Whether a `}` or `]` (outside strings and comments) lies in `source[from..to]`.
fn closes(source: &[u8], from: usize, to: usize) -> bool {
    let gap = source.get(from..to).unwrap_or_default();
    let mut at = 0;
    while at < gap.len() {
        match gap[at] {
            b'}' | b']' => return true,
            b'#' if gap[at..].starts_with(b"#/*") => {
                at = memchr::memmem::find(&gap[at + 3..], b"*/#")
                    .map_or(gap.len(), |k| at + 3 + k + 3);
            }
            b'#' => at = memchr::memchr2(b'\n', b'\r', &gap[at..]).map_or(gap.len(), |k| at + k),
            b'"' => {
                at += 1;
                while at < gap.len() && gap[at] != b'"' {
                    at += if gap[at] == b'\\' { 2 } else { 1 };
                }
                at += 1;
            }
            _ => at += 1,
        }
    }
    false
}

/// Places the `#comment` members of an X3D JSON document that start with `x3dcheck:`:
/// - a comment statement (an object of only `#comment` members, an element of a node
///   array, as the XML-to-JSON stylesheet writes XML comments) applies to the next element
///   of its array, or to nothing when it is the last;
/// - a `#comment` member of a node's object applies to that node (the whole
///   `{ "Type": { … } }` object);
/// - one in the top-level object, the `X3D` object or anywhere in `head` applies to the
///   whole file.
pub fn place_json(t: &Tree, progress: &dyn Progress) -> Vec<Directive> {
    let mut found = Vec::new();
    if !behind::contains(t.src.as_bytes(), MARK, progress) {
        return found;
    }
    // The open objects, arrays and members around the item being looked at.
    let mut around: Vec<usize> = Vec::new();
    for i in 0..t.items.len() {
        while around.last().is_some_and(|&open| t.next(open) <= i) {
            around.pop();
        }
        let kind = t.items[i].kind;
        if !matches!(kind, Kind::Object | Kind::Array | Kind::Key) {
            continue;
        }
        if kind == Kind::Key && t.raw(i).starts_with("#comment") {
            if let Some(directive) = json_directive(t, i, &around) {
                found.push(directive);
            }
        }
        around.push(i);
    }
    found
}

/// The directive of the `#comment` member whose key is `key`, `around` being the open
/// containers (the innermost last: the object holding it).
fn json_directive(t: &Tree, key: usize, around: &[usize]) -> Option<Directive> {
    let value = key + 1;
    if t.kind(value) != Kind::String {
        return None;
    }
    let (start, end) = t.span(value);
    let text = addressed(t.src.as_bytes(), Span::new(start, end))?;
    let (full_start, full_end) = t.full_span(value);
    let span = Span::new(full_start, full_end);
    let object = *around.last()?;
    // around: [top, "X3D", X3D object, "head", …] for what lies in head.
    let whole_file = around.len() <= 3 || t.raw(around[3]) == "head";
    let scope = if whole_file {
        None
    } else if let [.., array, _] = around {
        if t.kind(*array) != Kind::Array {
            holder(t, around)
        } else if t
            .members(object)
            .all(|(k, _)| t.raw(k).starts_with("#comment"))
        {
            let next = t.next(object);
            if next < t.next(*array) {
                let (s, e) = t.full_span(next);
                Some(Span::new(s, e))
            } else {
                nothing_after(span)
            }
        } else {
            let (s, e) = t.full_span(object);
            Some(Span::new(s, e))
        }
    } else {
        None
    };
    Some(Directive { span, text, scope })
}

/// The scope of a `#comment` member of an object that is not an element of an array: the
/// node it belongs to, `{ "Type": { … } }`, or else the object itself.
fn holder(t: &Tree, around: &[usize]) -> Option<Span> {
    let object = around[around.len() - 1];
    let outer = match around {
        [.., wrapper, key, _] if t.kind(*key) == Kind::Key && t.kind(*wrapper) == Kind::Object => {
            *wrapper
        }
        _ => object,
    };
    let (s, e) = t.full_span(outer);
    Some(Span::new(s, e))
}
