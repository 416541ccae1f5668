//! X3D inside web pages: the islands of an HTML page (`<x3d>` of X3DOM, `<X3D>` inside an
//! X_ITE `<x3d-canvas>`, or `<x3d-canvas src=…>`), each read into the scene model by the
//! XML reader's own element handling (`XmlReader`), so that every rule applies.
//!
//! An HTML page is parsed as a browser parses it (html5ever, the HTML standard's
//! tokenizer and tree construction): an element written `<Box/>` stays open and takes
//! what follows as children, and names arrive lower-cased; `names` gives them their X3D
//! spelling back as X3DOM and X_ITE do. Positions are those of the page: `tags` finds
//! each tag of the tree in the text. An XHTML page is XML, and is read by the XML reader
//! over the island's text, the rest of the page blanked out.

mod names;
mod tags;
mod tree;
pub mod x3dom;

use std::borrow::Cow;
use std::cell::RefCell;

use super::behind::Progress;
use super::rules::{
    ENCODING_UNSUPPORTED, HTML_SCENE_MISSING, HTML_SELF_CLOSED, ROOT_NOT_X3D, X3DOM_EXTENSION,
    X3DOM_VALUE_SYNTAX,
};
use super::xml::{Attr, XmlReader};
use super::{KeepValues, Parsed};
use crate::diagnostic::Diagnostic;
use crate::model::text::xml_value;
use crate::model::{Encoding, Span};
use crate::schema::FieldType;
use tags::Kind;
use tree::{Data, NodeId, Tree};

/// One X3D island of a page, read.
pub struct Island {
    pub parsed: Parsed,
    /// Its element's start tag (`<x3d …>`, `<x3d-canvas …>`).
    pub span: Span,
}

/// Reads every X3D island of an HTML page (`xhtml`: an XHTML page, read as XML).
pub fn read_islands(
    source: &[u8],
    xhtml: bool,
    keep: KeepValues,
    progress: &dyn Progress,
) -> Result<Vec<Island>, Box<Diagnostic>> {
    let text = std::str::from_utf8(source).map_err(|e| {
        // Boxed: a Diagnostic is large, and this error is rare.
        Box::new(Diagnostic::new(
            &ENCODING_UNSUPPORTED,
            Span::new(e.valid_up_to(), e.valid_up_to()),
            "an HTML page that is not UTF-8 after decoding".to_string(),
        ))
    })?;
    if xhtml {
        return Ok(xhtml_islands(source, keep, progress));
    }
    let tree = Tree::parse(text);
    let mut roots = Vec::new();
    find_islands(&tree, 0, Library::X3dom, &mut roots);
    Ok(roots
        .into_iter()
        .map(|(root, library)| {
            Page {
                source,
                tree: &tree,
                library,
                templates: RefCell::default(),
                library_nodes: RefCell::default(),
            }
            .island(root, keep, progress)
        })
        .collect())
}

/// Reads the first island of a page, or reports that it has none: what a caller that takes
/// one document per file (an Inline naming a page) reads.
pub fn read_with(source: &[u8], xhtml: bool, keep: KeepValues, progress: &dyn Progress) -> Parsed {
    match read_islands(source, xhtml, keep, progress) {
        Ok(islands) => match islands.into_iter().next() {
            Some(island) => island.parsed,
            None => Parsed {
                encoding: Some(Encoding::Xml),
                document: None,
                diagnostics: vec![no_island()],
            },
        },
        Err(diagnostic) => Parsed {
            encoding: None,
            document: None,
            diagnostics: vec![*diagnostic],
        },
    }
}

/// ROOT_NOT_X3D for a page with no island.
pub fn no_island() -> Diagnostic {
    Diagnostic::new(
        &ROOT_NOT_X3D,
        Span::new(0, 0),
        "an HTML page with no X3D in it (no `<x3d>` element, no `<x3d-canvas>`)".to_string(),
    )
    .help("X3DOM scenes are `<x3d><scene>…</scene></x3d>`; X_ITE's are `<x3d-canvas>` holding `<X3D>`, or `<x3d-canvas src='scene.x3d'>`")
}

/// The library that draws an island: X_ITE for what an `<x3d-canvas>` holds, X3DOM for
/// an `<x3d>` elsewhere.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Library {
    X3dom,
    XIte,
}

/// The islands under `node`, outermost first, with their library: `<x3d>` elements, and
/// `<x3d-canvas>` elements holding none (X_ITE loading `src`).
/// The islands below `node`, in document order. Iterative, as every walk over the page's
/// tree: its depth is the page's nesting, which nothing bounds.
fn find_islands(tree: &Tree, node: NodeId, library: Library, out: &mut Vec<(NodeId, Library)>) {
    let mut stack = vec![(node, library)];
    while let Some((node, mut library)) = stack.pop() {
        if let Some((name, _)) = tree.element(node) {
            match &*name.local {
                "x3d" => {
                    out.push((node, library));
                    continue;
                }
                "x3d-canvas" if !holds_x3d(tree, node) => {
                    out.push((node, Library::XIte));
                    continue;
                }
                "x3d-canvas" => library = Library::XIte,
                _ => {}
            }
        }
        stack.extend(
            tree.nodes[node]
                .children
                .iter()
                .rev()
                .map(|&c| (c, library)),
        );
    }
}

fn holds_x3d(tree: &Tree, node: NodeId) -> bool {
    let mut stack = tree.nodes[node].children.clone();
    while let Some(c) = stack.pop() {
        if tree.element(c).is_some_and(|(n, _)| &*n.local == "x3d") {
            return true;
        }
        stack.extend(&tree.nodes[c].children);
    }
    false
}

struct Page<'a> {
    source: &'a [u8],
    tree: &'a Tree,
    library: Library,
    /// The attribute values left out as template placeholders (`{{ model.url }}`).
    templates: RefCell<Vec<Span>>,
    /// The elements of the library's own nodes, left out (`<plane>`).
    library_nodes: RefCell<Vec<Span>>,
}

/// An element's place in the page: its start tag, and the end of what closed it.
#[derive(Clone, Copy)]
struct Place {
    start: usize,
    tag_end: usize,
    /// Where its content ends (the closing tag's start) and the element ends.
    content_end: usize,
    end: usize,
}

impl<'a> Page<'a> {
    fn island(&self, root: NodeId, keep: KeepValues, progress: &dyn Progress) -> Island {
        let place = self.place(root, None);
        let span = Span::new(place.start, place.tag_end);
        let mut reader = XmlReader::new(self.source, keep, progress);
        let mut found = Vec::new();
        let is_canvas = self
            .tree
            .element(root)
            .is_some_and(|(n, _)| &*n.local == "x3d-canvas");
        let result = if is_canvas {
            self.canvas(root, place, &mut reader)
        } else {
            self.element(root, place, &mut reader, &mut found, 0)
        };
        let mut parsed = reader.finish(result);
        if let Some(document) = &mut parsed.document {
            document.in_page = true;
            document.template_values = self.templates.take();
            document.library_nodes = self.library_nodes.take();
        }
        if !is_canvas && !self.has_scene(root) {
            parsed.diagnostics.push(
                Diagnostic::new(
                    &HTML_SCENE_MISSING,
                    Span::new(place.start + 1, place.start + 4),
                    "this X3D island has no `<scene>`: nothing is drawn".to_string(),
                )
                .help("put the nodes inside `<scene>…</scene>` within the `<x3d>` element"),
            );
        }
        parsed.diagnostics.extend(found);
        Island { parsed, span }
    }

    fn has_scene(&self, root: NodeId) -> bool {
        self.tree.nodes[root].children.iter().any(|&c| {
            self.tree
                .element(c)
                .is_some_and(|(n, _)| &*n.local == "scene")
        })
    }

    /// Where `node` stands; `inherited` for an element the tree builder implied.
    fn place(&self, node: NodeId, inherited: Option<Place>) -> Place {
        let Data::Element { tag, closed_by, .. } = &self.tree.nodes[node].data else {
            return inherited.unwrap_or(Place {
                start: 0,
                tag_end: 0,
                content_end: 0,
                end: 0,
            });
        };
        let tags = &self.tree.tags.list;
        let Some(tag) = tag.map(|t| &tags[t]) else {
            return inherited.unwrap_or(Place {
                start: 0,
                tag_end: 0,
                content_end: 0,
                end: 0,
            });
        };
        let (content_end, end) = match closed_by.map(|c| &tags[c]) {
            Some(close) if close.kind == Kind::End => (close.start, close.end),
            // Closed by a later start tag, or by its own (void): it ends before that tag.
            Some(close) if close.start > tag.start => (close.start, close.start),
            Some(_) => (tag.end, tag.end),
            None => (self.source.len(), self.source.len()),
        };
        Place {
            start: tag.start,
            tag_end: tag.end,
            content_end: content_end.max(tag.end),
            end: end.max(tag.end),
        }
    }

    /// Feeds `node` and what it holds to the reader, X3DOM's own elements and attributes
    /// left out and reported.
    fn element(
        &self,
        node: NodeId,
        place: Place,
        reader: &mut XmlReader,
        found: &mut Vec<Diagnostic>,
        depth: usize,
    ) -> Result<(), Box<Diagnostic>> {
        // The model reads no node deeper than MAX_DEPTH (and says so, LIMIT_EXCEEDED); the
        // page's own nesting is unbounded, and this walk recurses.
        if depth > crate::limits::MAX_DEPTH + 16 {
            return Ok(());
        }
        let Some((qual, html_attrs)) = self.tree.element(node) else {
            return Ok(());
        };
        let lower: &str = &qual.local;
        let root = lower == "x3d";
        let name_span = Span::new(place.start + 1, place.start + 1 + lower.len());
        if x3dom::NODES.contains(&lower) {
            let as_written = self.text(name_span);
            found.push(Diagnostic::new(
                &X3DOM_EXTENSION,
                name_span,
                format!("`<{as_written}>` is an X3DOM node, not X3D: only X3DOM reads it, and its content is not checked"),
            ));
            self.library_nodes
                .borrow_mut()
                .push(Span::new(place.start, place.end));
            return Ok(());
        }
        if self.library == Library::X3dom && x3dom::RENAMED_NODES.contains(&lower) {
            let as_written = self.text(name_span);
            found.push(Diagnostic::new(
                &X3DOM_EXTENSION,
                name_span,
                format!("`<{as_written}>` is X3DOM's node of that name, with other fields than X3D's: only X3DOM reads it, and its content is not checked"),
            ));
            self.library_nodes
                .borrow_mut()
                .push(Span::new(place.start, place.end));
            return Ok(());
        }
        let name = if root {
            "X3D"
        } else {
            names::element(lower).unwrap_or(lower)
        };
        let tag = self.start_tag(node);
        let mut attrs = Vec::new();
        for attr in html_attrs {
            let written: &str = &attr.name.local;
            let at = tag.and_then(|t| t.attrs.iter().find(|a| a.name == written));
            let (name_span, value_span) = match at {
                Some(a) => (
                    Span::new(a.name_start, a.name_end),
                    Span::new(a.value_start, a.value_end),
                ),
                None => (name_span, name_span),
            };
            // The node type's own fields, then X3DOM's, then any X3D name (names.rs).
            let own = match root {
                true => ["version", "profile"].into_iter().find(|&n| n == written),
                false => names::own_field(name, written).map(|f| f.name),
            };
            if own.is_none() && x3dom::is_attribute(written, root) {
                let as_written = self.text(name_span);
                found.push(Diagnostic::new(
                    &X3DOM_EXTENSION,
                    name_span,
                    format!("`{as_written}` is X3DOM's, not an X3D attribute: only X3DOM reads it"),
                ));
                continue;
            }
            let mapped = own.or_else(|| (!root).then(|| names::attribute(name, written))?);
            if is_template(&attr.value) {
                self.templates.borrow_mut().push(value_span);
                continue;
            }
            let raw = &self.source[value_span.start as usize..value_span.end as usize];
            let mut verbatim = raw == attr.value.as_bytes().as_ref();
            let mut value = match std::str::from_utf8(raw) {
                Ok(raw) if verbatim => Cow::Borrowed(raw),
                _ => Cow::Owned(attr.value.to_string()),
            };
            let field = mapped.and_then(|m| names::own_field(name, m));
            if let Some(read) = field.and_then(|f| self.library_value(f.ty, &value)) {
                let field = mapped.unwrap_or(written);
                found.push(
                    Diagnostic::new(
                        &X3DOM_VALUE_SYNTAX,
                        value_span,
                        format!(
                            "`{field}`: `{}` {}: {} reads it as `{}`, the X3D encodings do not read it",
                            crate::parse::xml::truncate(&value, 40),
                            read.what,
                            self.library.name(),
                            crate::parse::xml::truncate(&read.value, 40),
                        ),
                    )
                    .help(format!("write {field}='{}' for every X3D browser", read.value)),
                );
                value = Cow::Owned(read.value);
                verbatim = false;
            }
            attrs.push(Attr {
                name: mapped.unwrap_or(written),
                name_span,
                value,
                value_span,
                verbatim,
            });
        }
        self.self_closed(node, name, found);
        let children = &self.tree.nodes[node].children;
        reader.open(
            name,
            &attrs,
            place.start,
            place.tag_end,
            children.is_empty(),
        )?;
        let text = children
            .iter()
            .any(|&c| matches!(&self.tree.nodes[c].data, Data::Text(t) if !t.trim().is_empty()));
        if text {
            reader.text(place.tag_end, place.content_end, false)?;
        }
        for &child in children {
            match &self.tree.nodes[child].data {
                // HTML in the `<x3d>` element is the page's: X3DOM takes its scene from the
                // `scene` child alone (`x3dom.findScene`: "if ( sceneElem.localName.
                // toLowerCase() === "scene" )") and leaves the rest to the browser (the
                // `<div class="x3dom-statdiv">` a page writes there).
                Data::Element { .. } if root && self.is_html(child) => {}
                Data::Element { .. } => {
                    let at = self.place(child, Some(place));
                    self.element(child, at, reader, found, depth + 1)?;
                }
                Data::Comment(Some(tag)) => {
                    let tag = &self.tree.tags.list[*tag];
                    reader.comment(tag.start, tag.end);
                }
                _ => {}
            }
        }
        reader.end(place.end);
        Ok(())
    }

    /// Whether `node` is an element that is neither X3D's nor X3DOM's (`<div>`).
    fn is_html(&self, node: NodeId) -> bool {
        self.tree.element(node).is_some_and(|(name, _)| {
            names::element(&name.local).is_none() && !x3dom::NODES.contains(&&*name.local)
        })
    }

    /// How this island's library reads `text`, a value of a field of type `ty` that the
    /// XML encoding does not read, when it reads it at all.
    fn library_value(&self, ty: FieldType, text: &str) -> Option<LibraryValue> {
        if xml_value::parse_value(ty, text).is_ok() {
            return None;
        }
        let x3dom = self.library == Library::X3dom;
        match ty {
            // X3DOM's `MFString.parse`: "if ( str.length && str[ 0 ] == '\"' ) … else {
            // arr.push( str ); }" after `str.trim()`; X_ITE's XMLParser: "make sure to
            // separate each individual string with double quotation marks!", then
            // `field.setValue ([this.input])`.
            FieldType::MFString if !text.trim_start().starts_with('"') => Some(LibraryValue {
                value: format!(
                    "\"{}\"",
                    text.trim().replace('\\', "\\\\").replace('"', "\\\"")
                ),
                what: "has no quotes",
            }),
            // X3DOM's `addField_SFBool`: "getAttribute( name ).toLowerCase() === "true"".
            FieldType::SFBool
                if x3dom
                    && (text.eq_ignore_ascii_case("true")
                        || text.eq_ignore_ascii_case("false")) =>
            {
                Some(LibraryValue {
                    value: text.to_ascii_lowercase(),
                    what: "is not lower case",
                })
            }
            FieldType::SFColor | FieldType::SFColorRGBA if x3dom => {
                let [r, g, b, a] = css_color(text)?;
                let value = match ty {
                    FieldType::SFColor => [r, g, b].map(number).join(" "),
                    _ => [r, g, b, a].map(number).join(" "),
                };
                Some(LibraryValue {
                    value,
                    what: "is a CSS colour",
                })
            }
            _ => None,
        }
    }

    /// The page's text at `span`, as written.
    fn text(&self, span: Span) -> Cow<'a, str> {
        String::from_utf8_lossy(&self.source[span.start as usize..span.end as usize])
    }

    fn start_tag(&self, node: NodeId) -> Option<&tags::Tag> {
        match &self.tree.nodes[node].data {
            Data::Element { tag: Some(tag), .. } => Some(&self.tree.tags.list[*tag]),
            _ => None,
        }
    }

    /// HTML_SELF_CLOSED when `node` was written `<name/>` and took elements after it.
    fn self_closed(&self, node: NodeId, name: &str, found: &mut Vec<Diagnostic>) {
        let Some(tag) = self.start_tag(node).filter(|t| t.self_closing) else {
            return;
        };
        let taken: Vec<String> = self.tree.nodes[node]
            .children
            .iter()
            .filter_map(|&c| {
                let (child, _) = self.tree.element(c)?;
                let child = names::element(&child.local)
                    .unwrap_or(&child.local)
                    .to_string();
                Some(format!("`{child}`"))
            })
            .collect();
        if taken.is_empty() {
            return;
        }
        let list = match taken.len() {
            1..=4 => taken.join(", "),
            n => format!("{} and {} more", taken[..3].join(", "), n - 3),
        };
        let (was, became) = if taken.len() == 1 {
            ("it", "its child")
        } else {
            ("they", "its children")
        };
        found.push(
            Diagnostic::new(
                &HTML_SELF_CLOSED,
                Span::new(tag.start, tag.end),
                format!(
                    "`<{name}/>` is not closed in HTML (only void elements such as `<br/>` are): {list} after it became {became}, where {was} {}",
                    if taken.len() == 1 { "was written as its sibling" } else { "were written as its siblings" }
                ),
            )
            .help(format!("write `<{name} …></{name}>`, or serve the page as XHTML")),
        );
    }

    /// An X_ITE `<x3d-canvas src=…>`: a scene of one Inline loading `src`, so that the deep
    /// level follows it as it follows an Inline.
    fn canvas(
        &self,
        node: NodeId,
        place: Place,
        reader: &mut XmlReader,
    ) -> Result<(), Box<Diagnostic>> {
        let tag = self.start_tag(node);
        let src = tag.and_then(|t| t.attrs.iter().find(|a| a.name == "src"));
        let (start, end) = (place.start, place.tag_end);
        reader.open("X3D", &[], start, end, false)?;
        reader.open("Scene", &[], start, end, false)?;
        if let Some(src) = src {
            let text = String::from_utf8_lossy(&self.source[src.value_start..src.value_end]);
            let url = Attr {
                name: "url",
                name_span: Span::new(src.name_start, src.name_end),
                value: Cow::Owned(format!("\"{}\"", text.trim())),
                value_span: Span::new(src.value_start, src.value_end),
                verbatim: false,
            };
            reader.open("Inline", &[url], start, end, true)?;
            reader.end(end);
        }
        reader.end(place.end);
        reader.end(place.end);
        Ok(())
    }
}

/// A value as the island's library reads it.
struct LibraryValue {
    /// Its X3D XML spelling.
    value: String,
    /// What the library accepts in it.
    what: &'static str,
}

impl Library {
    fn name(self) -> &'static str {
        match self {
            Library::X3dom => "X3DOM",
            Library::XIte => "X_ITE",
        }
    }
}

/// Whether an attribute value is a template placeholder that a server fills in (Jinja,
/// Django, Handlebars: `{{ model.inline }}`, `{% url … %}`): not a value yet.
fn is_template(value: &str) -> bool {
    value.contains("{{") || value.contains("{%")
}

/// A CSS colour as X3DOM's `_colorParse` reads it, as red, green, blue and alpha ratios:
/// a name of its table (`x3dom::COLOR_NAMES`), `#rgb`, `#rgba`, `#rrggbb`, `#rrggbbaa`,
/// `rgb(r, g, b)` and `rgba(r, g, b, a)` with 0–255 channels. None for what it does not
/// read (it reads that as black).
fn css_color(text: &str) -> Option<[f64; 4]> {
    if let Some(rgb) = x3dom::color_name(text) {
        let channel = |shift: u32| f64::from((rgb >> shift) & 0xff) / 255.0;
        return Some([channel(16), channel(8), channel(0), 1.0]);
    }
    if let Some(hex) = text.strip_prefix('#') {
        if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
            return None;
        }
        let digit = |i: usize, width: usize| {
            let max = if width == 1 { 15.0 } else { 255.0 };
            u8::from_str_radix(&hex[i * width..(i + 1) * width], 16).map(|v| f64::from(v) / max)
        };
        let (count, width) = match hex.len() {
            3 => (3, 1),
            4 => (4, 1),
            6 => (3, 2),
            8 => (4, 2),
            _ => return None,
        };
        let mut rgba = [1.0; 4];
        for (i, channel) in rgba.iter_mut().take(count).enumerate() {
            *channel = digit(i, width).ok()?;
        }
        return Some(rgba);
    }
    // `rgb(\d{1,3},\s{0,1}\d{1,3},\s{0,1}\d{1,3})`, and rgba with an alpha in 0–1.
    let (inner, alpha) = match text.strip_prefix("rgba(") {
        Some(rest) => (rest.strip_suffix(')')?, true),
        None => (text.strip_prefix("rgb(")?.strip_suffix(')')?, false),
    };
    let parts: Vec<&str> = inner
        .split(',')
        .map(|p| p.strip_prefix(' ').unwrap_or(p))
        .collect();
    if parts.len() != if alpha { 4 } else { 3 } {
        return None;
    }
    let mut rgba = [1.0; 4];
    for (i, part) in parts.iter().enumerate() {
        rgba[i] = if i == 3 {
            part.parse::<f64>()
                .ok()
                .filter(|a| (0.0..=1.0).contains(a))?
        } else if (1..=3).contains(&part.len()) && part.bytes().all(|b| b.is_ascii_digit()) {
            part.parse::<f64>().ok()? / 255.0
        } else {
            return None;
        };
    }
    Some(rgba)
}

/// A ratio written as X3D writes numbers: at most four decimals, no trailing zeros.
fn number(value: f64) -> String {
    let text = format!("{value:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    text.to_string()
}

/// The islands of an XHTML page: each `X3D` element (any case), read by the XML reader from
/// a copy of the page where everything else is blanked (line breaks kept) and the element
/// names spelt as X3D spells them, so that offsets are the page's.
fn xhtml_islands(source: &[u8], keep: KeepValues, progress: &dyn Progress) -> Vec<Island> {
    let tags = tags::Tags::scan(source);
    let mut islands = Vec::new();
    let mut depth = 0usize;
    let mut open: Option<usize> = None;
    for (i, tag) in tags.list.iter().enumerate() {
        if tag.name != "x3d" {
            continue;
        }
        match tag.kind {
            Kind::Start if tag.self_closing => {}
            Kind::Start => {
                if depth == 0 {
                    open = Some(i);
                }
                depth += 1;
            }
            Kind::End => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    if let Some(first) = open.take() {
                        islands.push((first, i));
                    }
                }
            }
            Kind::Comment => {}
        }
    }
    islands
        .into_iter()
        .map(|(first, last)| {
            let (start, end) = (tags.list[first].start, tags.list[last].end);
            let mut copy: Vec<u8> = source
                .iter()
                .enumerate()
                .map(|(i, &b)| {
                    if (start..end).contains(&i) || b == b'\n' {
                        b
                    } else {
                        b' '
                    }
                })
                .collect();
            for tag in &tags.list[first..=last] {
                if tag.kind == Kind::Comment {
                    continue;
                }
                let at = tag.start + if tag.kind == Kind::End { 2 } else { 1 };
                let written = &source[at..at + tag.name.len()];
                let name = std::str::from_utf8(written).unwrap_or("");
                if let Some(x3d) = names::element(name) {
                    copy[at..at + x3d.len()].copy_from_slice(x3d.as_bytes());
                }
            }
            let mut parsed = super::xml::read_with(&copy, keep, progress);
            if let Some(document) = &mut parsed.document {
                document.in_page = true;
            }
            Island {
                parsed,
                span: Span::new(start, tags.list[first].end),
            }
        })
        .collect()
}
