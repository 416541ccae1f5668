//! The tree of an HTML page as the HTML standard's tree construction (html5ever's) builds
//! it, each element with the tag it came from and the tag that closed it, found in the
//! page's text by [`Tags`], so that what is reported has the page's positions.

use std::borrow::Cow;
use std::cell::{Cell, RefCell};

use html5ever::buffer_queue::BufferQueue;
use html5ever::interface::tree_builder::{
    ElemName, ElementFlags, NodeOrText, QuirksMode, TreeSink,
};
use html5ever::tendril::StrTendril;
use html5ever::tokenizer::{
    Tag as TagToken, TagKind, Token, TokenSink, TokenSinkResult, Tokenizer, TokenizerOpts,
};
use html5ever::tree_builder::{TreeBuilder, TreeBuilderOpts};
use html5ever::{Attribute, LocalName, Namespace, QualName, TokenizerResult};

use super::tags::{Kind, Tags};

pub type NodeId = usize;

pub enum Data {
    Document,
    Element {
        name: QualName,
        attrs: Vec<Attribute>,
        /// The start tag in [`Tree::tags`] (none for an element the tree builder implied).
        tag: Option<usize>,
        /// The tag whose token closed it (an end tag, or its own start tag when void or
        /// when the tree builder closed it at once); none at the end of the page.
        closed_by: Option<usize>,
    },
    Text(String),
    /// A comment and its tag in [`Tree::tags`].
    Comment(Option<usize>),
    Other,
}

pub struct Node {
    pub data: Data,
    pub parent: Option<NodeId>,
    pub children: Vec<NodeId>,
}

/// A parsed page: its nodes (the document first) and its tags.
pub struct Tree {
    pub nodes: Vec<Node>,
    pub tags: Tags,
}

impl Tree {
    pub fn parse(text: &str) -> Tree {
        let sink = Sink {
            nodes: RefCell::new(vec![Node {
                data: Data::Document,
                parent: None,
                children: Vec::new(),
            }]),
            current: Cell::new(None),
        };
        let tap = Tap {
            builder: TreeBuilder::new(sink, TreeBuilderOpts::default()),
            tags: RefCell::new(Tags::scan(text.as_bytes())),
        };
        let tokenizer = Tokenizer::new(tap, TokenizerOpts::default());
        let input = BufferQueue::default();
        input.push_back(StrTendril::from_slice(text));
        while !matches!(tokenizer.feed(&input), TokenizerResult::Done) {}
        tokenizer.end();
        let Tap { builder, tags } = tokenizer.sink;
        let mut tree = Tree {
            nodes: builder.sink.nodes.into_inner(),
            tags: tags.into_inner(),
        };
        tree.close_by_end_tags();
        tree
    }

    /// Gives the elements the tree builder closed without telling its sink their closing
    /// tag. html5ever pops the elements an "any other end tag" closes (HTML 13.2.6.4.7:
    /// every X3D element, unknown to HTML, is closed so) by truncating its stack of open
    /// elements, without `TreeSink::pop`; that step is replayed here over the tags: an end
    /// tag closes the latest open element of its name and every element opened after it.
    fn close_by_end_tags(&mut self) {
        let mut opened_by = vec![None; self.tags.list.len()];
        for (id, node) in self.nodes.iter().enumerate() {
            if let Data::Element { tag: Some(t), .. } = node.data {
                opened_by[t] = Some(id);
            }
        }
        let mut open: Vec<NodeId> = Vec::new();
        for (t, tag) in self.tags.list.iter().enumerate() {
            match tag.kind {
                Kind::Start => open.extend(opened_by[t]),
                Kind::End => {
                    // An element of its name the sink was told this tag closes: done.
                    let told = open.iter().any(|&n| match &self.nodes[n].data {
                        Data::Element {
                            name, closed_by, ..
                        } => *closed_by == Some(t) && *name.local == *tag.name,
                        _ => false,
                    });
                    open.retain(|&n| unclosed(&self.nodes[n]).is_some());
                    let latest = open.iter().rposition(|&n| {
                        !told
                            && unclosed(&self.nodes[n]).is_some_and(|name| *name.local == *tag.name)
                    });
                    if let Some(at) = latest {
                        for n in open.drain(at..) {
                            if let Data::Element { closed_by, .. } = &mut self.nodes[n].data {
                                *closed_by = Some(t);
                            }
                        }
                    }
                }
                Kind::Comment => {}
            }
        }
    }

    pub fn element(&self, id: NodeId) -> Option<(&QualName, &[Attribute])> {
        match &self.nodes[id].data {
            Data::Element { name, attrs, .. } => Some((name, attrs)),
            _ => None,
        }
    }
}

/// The name of an element its sink has not been told the closing of.
fn unclosed(node: &Node) -> Option<&QualName> {
    match &node.data {
        Data::Element {
            name,
            closed_by: None,
            ..
        } => Some(name),
        _ => None,
    }
}

/// Passes the tokenizer's tokens to the tree builder, telling its sink first which tag of
/// the page each came from.
struct Tap {
    builder: TreeBuilder<NodeId, Sink>,
    tags: RefCell<Tags>,
}

impl TokenSink for Tap {
    type Handle = NodeId;

    fn process_token(&self, token: Token, line: u64) -> TokenSinkResult<NodeId> {
        let found = match &token {
            Token::TagToken(TagToken { kind, name, .. }) => {
                let kind = match kind {
                    TagKind::StartTag => Kind::Start,
                    TagKind::EndTag => Kind::End,
                };
                self.tags.borrow_mut().matching(kind, name, line)
            }
            Token::CommentToken(_) => self.tags.borrow_mut().matching(Kind::Comment, "", line),
            _ => None,
        };
        if !matches!(token, Token::CharacterTokens(_) | Token::NullCharacterToken) {
            self.builder.sink.current.set(found);
        }
        self.builder.process_token(token, line)
    }

    fn end(&self) {
        self.builder.sink.current.set(None);
        self.builder.end();
    }

    fn adjusted_current_node_present_but_not_in_html_namespace(&self) -> bool {
        self.builder
            .adjusted_current_node_present_but_not_in_html_namespace()
    }
}

struct Sink {
    nodes: RefCell<Vec<Node>>,
    /// The tag of the token being built from.
    current: Cell<Option<usize>>,
}

impl Sink {
    fn new_node(&self, data: Data) -> NodeId {
        let mut nodes = self.nodes.borrow_mut();
        nodes.push(Node {
            data,
            parent: None,
            children: Vec::new(),
        });
        nodes.len() - 1
    }

    fn detach(&self, node: NodeId) {
        let mut nodes = self.nodes.borrow_mut();
        if let Some(parent) = nodes[node].parent.take() {
            nodes[parent].children.retain(|&c| c != node);
        }
    }

    /// Inserts `child` into `parent` at `index`, text merged with a text node beside it.
    fn insert(&self, parent: NodeId, index: usize, child: NodeOrText<NodeId>) {
        let node = match child {
            NodeOrText::AppendNode(node) => {
                self.detach(node);
                node
            }
            NodeOrText::AppendText(text) => {
                let mut nodes = self.nodes.borrow_mut();
                let before = index.checked_sub(1).map(|i| nodes[parent].children[i]);
                if let Some(before) = before {
                    if let Data::Text(existing) = &mut nodes[before].data {
                        existing.push_str(&text);
                        return;
                    }
                }
                drop(nodes);
                self.new_node(Data::Text(text.to_string()))
            }
        };
        let mut nodes = self.nodes.borrow_mut();
        nodes[node].parent = Some(parent);
        nodes[parent].children.insert(index, node);
    }
}

/// An element's name as the tree builder asks for it.
#[derive(Debug)]
struct Name(QualName);

impl ElemName for Name {
    fn ns(&self) -> &Namespace {
        &self.0.ns
    }
    fn local_name(&self) -> &LocalName {
        &self.0.local
    }
}

impl TreeSink for Sink {
    type Handle = NodeId;
    type Output = ();
    type ElemName<'a> = Name;

    fn finish(self) {}

    fn parse_error(&self, _: Cow<'static, str>) {}

    fn get_document(&self) -> NodeId {
        0
    }

    fn elem_name(&self, target: &NodeId) -> Name {
        match &self.nodes.borrow()[*target].data {
            Data::Element { name, .. } => Name(name.clone()),
            _ => Name(QualName::new(
                None,
                Namespace::from(""),
                LocalName::from(""),
            )),
        }
    }

    fn create_element(&self, name: QualName, attrs: Vec<Attribute>, _: ElementFlags) -> NodeId {
        self.new_node(Data::Element {
            name,
            attrs,
            tag: self.current.get(),
            closed_by: None,
        })
    }

    fn create_comment(&self, _: StrTendril) -> NodeId {
        self.new_node(Data::Comment(self.current.get()))
    }

    fn create_pi(&self, _: StrTendril, _: StrTendril) -> NodeId {
        self.new_node(Data::Other)
    }

    fn append(&self, parent: &NodeId, child: NodeOrText<NodeId>) {
        let index = self.nodes.borrow()[*parent].children.len();
        self.insert(*parent, index, child);
    }

    fn append_based_on_parent_node(
        &self,
        element: &NodeId,
        prev_element: &NodeId,
        child: NodeOrText<NodeId>,
    ) {
        if self.nodes.borrow()[*element].parent.is_some() {
            self.append_before_sibling(element, child)
        } else {
            self.append(prev_element, child)
        }
    }

    fn append_doctype_to_document(&self, _: StrTendril, _: StrTendril, _: StrTendril) {}

    fn pop(&self, node: &NodeId) {
        if let Data::Element { closed_by, .. } = &mut self.nodes.borrow_mut()[*node].data {
            *closed_by = self.current.get();
        }
    }

    fn get_template_contents(&self, target: &NodeId) -> NodeId {
        // Template content is read as the template's own children.
        *target
    }

    fn same_node(&self, x: &NodeId, y: &NodeId) -> bool {
        x == y
    }

    fn set_quirks_mode(&self, _: QuirksMode) {}

    fn append_before_sibling(&self, sibling: &NodeId, child: NodeOrText<NodeId>) {
        let Some(parent) = self.nodes.borrow()[*sibling].parent else {
            return;
        };
        let index = self.nodes.borrow()[parent]
            .children
            .iter()
            .position(|c| c == sibling)
            .unwrap_or(0);
        self.insert(parent, index, child);
    }

    fn add_attrs_if_missing(&self, target: &NodeId, add: Vec<Attribute>) {
        if let Data::Element { attrs, .. } = &mut self.nodes.borrow_mut()[*target].data {
            for attr in add {
                if !attrs.iter().any(|a| a.name == attr.name) {
                    attrs.push(attr);
                }
            }
        }
    }

    fn remove_from_parent(&self, target: &NodeId) {
        self.detach(*target);
    }

    fn reparent_children(&self, node: &NodeId, new_parent: &NodeId) {
        let children = std::mem::take(&mut self.nodes.borrow_mut()[*node].children);
        let mut nodes = self.nodes.borrow_mut();
        for &child in &children {
            nodes[child].parent = Some(*new_parent);
        }
        nodes[*new_parent].children.extend(children);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The elements named `name`, in document order, each with the text from its start
    /// tag to the end of the tag that closed it (to the page's end when none did).
    fn elements(page: &str, name: &str) -> Vec<String> {
        let tree = Tree::parse(page);
        let list = &tree.tags.list;
        tree.nodes
            .iter()
            .filter_map(|node| match &node.data {
                Data::Element {
                    name: n,
                    tag: Some(t),
                    closed_by,
                    ..
                } if *n.local == *name => {
                    let end = closed_by.map_or(page.len(), |c| list[c].end);
                    Some(page[list[*t].start..end].to_string())
                }
                _ => None,
            })
            .collect()
    }

    #[test]
    fn x3d_elements_end_at_their_end_tags() {
        let page = "<x3d><scene><transform><transform><shape></shape></transform></transform>\
                    <shape><box></box></shape></scene></x3d><p>after</p>";
        assert_eq!(
            elements(page, "transform"),
            [
                "<transform><transform><shape></shape></transform></transform>",
                "<transform><shape></shape></transform>",
            ]
        );
        assert_eq!(
            elements(page, "shape"),
            ["<shape></shape>", "<shape><box></box></shape>"]
        );
    }

    #[test]
    fn an_end_tag_closes_the_elements_opened_inside_its_element() {
        // `</group>` closes the `<shape>` left open inside it, as the tree builder does.
        let page = "<x3d><scene><group><shape><box></box></group><shape></shape></scene></x3d>";
        assert_eq!(
            elements(page, "shape"),
            ["<shape><box></box></group>", "<shape></shape>"]
        );
        assert_eq!(
            elements(page, "group"),
            ["<group><shape><box></box></group>"]
        );
    }

    #[test]
    fn an_element_left_open_ends_with_the_page() {
        let page = "<x3d><scene><shape><box></box>";
        assert_eq!(elements(page, "shape"), ["<shape><box></box>"]);
    }
}
