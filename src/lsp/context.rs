//! Where in the text being edited the cursor is, for completion: read from the newest text
//! (not the last check, which lags behind typing) by a small scanner per encoding that
//! keeps the stack of open elements, objects or node bodies up to the cursor. Hand-written
//! because the readers stop at the first syntax error, and text being typed is rarely
//! well-formed.

use memchr::memmem;

/// What is being written at the cursor.
#[derive(Debug, PartialEq, Eq)]
pub enum Context {
    /// A node type's name, going into `field` of `parent` (the field, when the encoding
    /// names it; the parent, unless at the top of the scene).
    NodeName {
        parent: Option<String>,
        field: Option<String>,
    },
    /// A field name of a node of type `node`; `written`: the fields it already sets.
    FieldName { node: String, written: Vec<String> },
    /// The value of field `field` of a `node`.
    Value { node: String, field: String },
    /// A DEF name: after USE, or a ROUTE's node name.
    DefName,
    /// XML element content, where a child element may start (a `<` is not typed yet):
    /// inside an element of type `parent`.
    ElementContent { parent: String },
}

/// The encodings completion knows, as the text's first bytes tell them.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Syntax {
    Xml,
    Json,
    Classic,
}

impl Syntax {
    pub fn of(text: &[u8]) -> Syntax {
        let start = text.iter().position(|b| !b.is_ascii_whitespace());
        match start.map(|i| text[i]) {
            Some(b'{') => Syntax::Json,
            Some(b'#') => Syntax::Classic,
            _ => Syntax::Xml,
        }
    }
}

/// Where the word the cursor ends starts (what a completion replaces).
pub fn word_start(text: &[u8], offset: usize) -> usize {
    let mut start = offset.min(text.len());
    while start > 0 && !b" \t\r\n<>\"'{}[],=:#/".contains(&text[start - 1]) {
        start -= 1;
    }
    start
}

pub fn context(syntax: Syntax, text: &[u8], offset: usize) -> Option<Context> {
    let text = &text[..offset.min(text.len())];
    match syntax {
        Syntax::Xml => xml(text),
        Syntax::Json => json(text),
        Syntax::Classic => classic(text),
    }
}

fn is_name_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b"_-.:".contains(&b) || b >= 0x80
}

fn text_of(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// XML: the element stack up to the cursor, and whether the cursor is in a start tag's
/// name, among its attributes, or in an attribute's value.
fn xml(text: &[u8]) -> Option<Context> {
    let mut stack: Vec<&[u8]> = Vec::new();
    let mut i = 0;
    while let Some(lt) = memchr::memchr(b'<', &text[i..]).map(|p| i + p) {
        let rest = &text[lt..];
        let skip_to = |from: usize, end: &[u8]| {
            memmem::find(&text[from..], end).map(|p| from + p + end.len())
        };
        if rest.starts_with(b"<!--") {
            i = skip_to(lt + 4, b"-->")?;
            continue;
        }
        if rest.starts_with(b"<![CDATA[") {
            i = skip_to(lt + 9, b"]]>")?;
            continue;
        }
        if rest.starts_with(b"<?") || rest.starts_with(b"<!") {
            i = skip_to(lt + 2, b">")?;
            continue;
        }
        if rest.starts_with(b"</") {
            let end = name_end(text, lt + 2);
            let name = &text[lt + 2..end];
            if let Some(open) = stack.iter().rposition(|n| *n == name) {
                stack.truncate(open);
            }
            i = skip_to(end, b">")?;
            continue;
        }
        let end = name_end(text, lt + 1);
        if end == text.len() {
            return Some(Context::NodeName {
                parent: stack.last().map(|n| text_of(n)),
                field: None,
            });
        }
        let name = &text[lt + 1..end];
        let mut written = Vec::new();
        let mut j = end;
        loop {
            while j < text.len() && text[j].is_ascii_whitespace() {
                j += 1;
            }
            if j == text.len() {
                return Some(Context::FieldName {
                    node: text_of(name),
                    written,
                });
            }
            match text[j] {
                b'>' => {
                    stack.push(name);
                    i = j + 1;
                    break;
                }
                b'/' if text.get(j + 1) == Some(&b'>') => {
                    i = j + 2;
                    break;
                }
                b'<' => {
                    // An unclosed tag: a new one starts here.
                    i = j;
                    break;
                }
                _ => {
                    let attr_end = name_end(text, j).max(j + 1);
                    if attr_end >= text.len() {
                        return Some(Context::FieldName {
                            node: text_of(name),
                            written,
                        });
                    }
                    let attr = text_of(&text[j..attr_end]);
                    j = attr_end;
                    while j < text.len() && text[j].is_ascii_whitespace() {
                        j += 1;
                    }
                    if text.get(j) == Some(&b'=') {
                        j += 1;
                        while j < text.len() && text[j].is_ascii_whitespace() {
                            j += 1;
                        }
                        let quote = *text.get(j)?;
                        if quote == b'"' || quote == b'\'' {
                            match memchr::memchr(quote, &text[j + 1..]) {
                                Some(p) => j += p + 2,
                                None => return Some(value_context(text_of(name), attr)),
                            }
                        }
                    }
                    written.push(attr);
                }
            }
        }
    }
    // Past the last tag: in the content of the innermost open element, if any (before the
    // root element, nothing goes).
    stack.last().map(|parent| Context::ElementContent {
        parent: text_of(parent),
    })
}

fn name_end(text: &[u8], from: usize) -> usize {
    let mut end = from;
    while end < text.len() && is_name_byte(text[end]) {
        end += 1;
    }
    end
}

/// The value of field `field` of `node`: a DEF name for USE and a ROUTE's node names.
fn value_context(node: String, field: String) -> Context {
    let field = field.trim_start_matches(['@', '-']).to_string();
    match (node.as_str(), field.as_str()) {
        (_, "USE") | ("ROUTE", "fromNode" | "toNode") => Context::DefName,
        _ => Context::Value { node, field },
    }
}

struct JsonFrame {
    object: bool,
    /// The key whose value this object or array is (for an array's element, the array's).
    owner: Option<String>,
    /// An object's keys so far; the last is the member being read.
    keys: Vec<String>,
    expecting_key: bool,
}

/// X3D JSON: the stack of objects and arrays up to the cursor; in a key or a string value.
fn json(text: &[u8]) -> Option<Context> {
    let mut frames: Vec<JsonFrame> = Vec::new();
    let mut i = 0;
    while i < text.len() {
        match text[i] {
            b'"' => {
                let mut j = i + 1;
                while j < text.len() && text[j] != b'"' {
                    j += if text[j] == b'\\' { 2 } else { 1 };
                }
                let top = frames.last_mut()?;
                if j >= text.len() {
                    return json_context(&frames);
                }
                if top.object && top.expecting_key {
                    top.keys.push(text_of(&text[i + 1..j]));
                    top.expecting_key = false;
                }
                i = j + 1;
                continue;
            }
            open @ (b'{' | b'[') => {
                let owner = frames.last().and_then(|f| {
                    if f.object {
                        f.keys.last().cloned()
                    } else {
                        f.owner.clone()
                    }
                });
                frames.push(JsonFrame {
                    object: open == b'{',
                    owner,
                    keys: Vec::new(),
                    expecting_key: open == b'{',
                });
            }
            b'}' | b']' => {
                frames.pop();
            }
            b',' => {
                if let Some(top) = frames.last_mut() {
                    top.expecting_key = top.object;
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// The context of a string the cursor is in, `frames` being the open containers.
fn json_context(frames: &[JsonFrame]) -> Option<Context> {
    let top = frames.last()?;
    if !top.object {
        // A string in an array: the value of an MFString field.
        let owner = top.owner.as_deref()?;
        let node = frames.iter().rev().nth(1)?.owner.clone()?;
        return Some(value_context(node, owner.to_string()));
    }
    let owner = top.owner.clone();
    if !top.expecting_key {
        let key = top.keys.last()?.clone();
        return Some(value_context(owner?, key));
    }
    match owner {
        // An object in a node field's value: its key is a node type's name.
        Some(field) if field.starts_with('-') => {
            let holder = frames
                .iter()
                .rev()
                .skip(1)
                .find(|f| f.object && f.keys.last() == Some(&field))?;
            Some(Context::NodeName {
                parent: holder.owner.clone(),
                field: Some(field[1..].to_string()),
            })
        }
        Some(node) => Some(Context::FieldName {
            node,
            written: top.keys.clone(),
        }),
        None => None,
    }
}

enum ClassicFrame {
    Node(String),
    List(String),
}

/// ClassicVRML: the stack of node bodies and MF lists up to the cursor, and the words
/// before it.
fn classic(text: &[u8]) -> Option<Context> {
    let mut frames: Vec<ClassicFrame> = Vec::new();
    let mut words: Vec<String> = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let b = text[i];
        match b {
            b'#' => match memchr::memchr(b'\n', &text[i..]) {
                Some(p) => i += p,
                None => return None,
            },
            b'"' => {
                let mut j = i + 1;
                while j < text.len() && text[j] != b'"' {
                    j += if text[j] == b'\\' { 2 } else { 1 };
                }
                if j >= text.len() {
                    let field = words.last()?.clone();
                    return match frames.last()? {
                        ClassicFrame::Node(node) => Some(value_context(node.clone(), field)),
                        ClassicFrame::List(_) => None,
                    };
                }
                words.push(String::new());
                i = j;
            }
            b'{' => {
                frames.push(ClassicFrame::Node(
                    words.last().cloned().unwrap_or_default(),
                ));
                words.clear();
            }
            b'[' => {
                frames.push(ClassicFrame::List(
                    words.last().cloned().unwrap_or_default(),
                ));
                words.clear();
            }
            b'}' | b']' => {
                frames.pop();
                words.clear();
            }
            _ if b.is_ascii_whitespace() || b == b',' => {}
            _ => {
                let mut j = i;
                while j < text.len() && !b" \t\r\n,{}[]\"#".contains(&text[j]) {
                    j += 1;
                }
                if j == text.len() {
                    break; // the word being written
                }
                words.push(text_of(&text[i..j]));
                i = j;
                continue;
            }
        }
        i += 1;
    }
    let previous = words.last().map(String::as_str);
    if matches!(previous, Some("USE" | "ROUTE" | "TO")) {
        return Some(Context::DefName);
    }
    if matches!(previous, Some("DEF")) || previous.is_some_and(|w| w.contains('.')) {
        return None;
    }
    // After `DEF name`, a node type.
    let after_def = words.len() >= 2 && words[words.len() - 2] == "DEF";
    match frames.last() {
        None => Some(Context::NodeName {
            parent: None,
            field: None,
        }),
        Some(ClassicFrame::List(field)) => {
            let parent = frames.iter().rev().nth(1).and_then(|f| match f {
                ClassicFrame::Node(node) => Some(node.clone()),
                ClassicFrame::List(_) => None,
            });
            Some(Context::NodeName {
                parent,
                field: (!field.is_empty()).then(|| field.clone()),
            })
        }
        Some(ClassicFrame::Node(node)) => match previous {
            Some(word) if after_def || word.starts_with(|c: char| c.is_ascii_lowercase()) => {
                let field = if after_def {
                    words.get(words.len().wrapping_sub(3)).cloned()
                } else {
                    Some(word.to_string())
                };
                Some(Context::NodeName {
                    parent: Some(node.clone()),
                    field,
                })
            }
            _ => Some(Context::FieldName {
                node: node.clone(),
                written: Vec::new(),
            }),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at_cursor(syntax: Syntax, text: &str) -> Option<Context> {
        let offset = text.find('|').unwrap();
        let text = text.replace('|', "");
        context(syntax, text.as_bytes(), offset)
    }

    fn node_name(parent: Option<&str>, field: Option<&str>) -> Option<Context> {
        Some(Context::NodeName {
            parent: parent.map(String::from),
            field: field.map(String::from),
        })
    }

    #[test]
    fn xml_contexts() {
        let head = "<X3D><Scene><!-- <Group> --><Transform DEF='T'>";
        assert_eq!(
            at_cursor(Syntax::Xml, &format!("{head}<Sha|")),
            node_name(Some("Transform"), None)
        );
        assert_eq!(
            at_cursor(Syntax::Xml, &format!("{head}<Shape/></Transform><|")),
            node_name(Some("Scene"), None)
        );
        assert_eq!(
            at_cursor(
                Syntax::Xml,
                &format!("{head}<Material diffuseColor='1 0 0' s|")
            ),
            Some(Context::FieldName {
                node: "Material".into(),
                written: vec!["diffuseColor".into()]
            })
        );
        assert_eq!(
            at_cursor(Syntax::Xml, &format!("{head}<Shape USE='|")),
            Some(Context::DefName)
        );
        assert_eq!(
            at_cursor(Syntax::Xml, &format!("{head}<Fog fogType=\"L|")),
            Some(Context::Value {
                node: "Fog".into(),
                field: "fogType".into()
            })
        );
        // In element content a child element may start: completion inserts its `<`.
        assert_eq!(
            at_cursor(Syntax::Xml, &format!("{head} te|xt")),
            Some(Context::ElementContent {
                parent: "Transform".into()
            })
        );
        assert_eq!(at_cursor(Syntax::Xml, "<?xml version='1.0'?>\n|"), None);
    }

    #[test]
    fn json_contexts() {
        let head = r#"{"X3D": {"Scene": {"-children": [{"Transform": {"@DEF": "T", "-children": ["#;
        assert_eq!(
            at_cursor(Syntax::Json, &format!("{head}{{\"Sh|")),
            node_name(Some("Transform"), Some("children"))
        );
        assert_eq!(
            at_cursor(
                Syntax::Json,
                &format!("{head}{{\"Fog\": {{\"@color\": [1,1,1], \"@|")
            ),
            Some(Context::FieldName {
                node: "Fog".into(),
                written: vec!["@color".into()]
            })
        );
        assert_eq!(
            at_cursor(Syntax::Json, &format!("{head}{{\"Shape\": {{\"@USE\": \"|")),
            Some(Context::DefName)
        );
        assert_eq!(
            at_cursor(
                Syntax::Json,
                &format!("{head}{{\"Fog\": {{\"@fogType\": \"L|")
            ),
            Some(Context::Value {
                node: "Fog".into(),
                field: "fogType".into()
            })
        );
    }

    #[test]
    fn classic_contexts() {
        let head = "#X3D V4.0 utf8\n# { a comment\nDEF T Transform { children [ ";
        assert_eq!(
            at_cursor(Syntax::Classic, &format!("{head}Sha|")),
            node_name(Some("Transform"), Some("children"))
        );
        assert_eq!(
            at_cursor(Syntax::Classic, &format!("{head}Shape {{ geometry Bo|")),
            node_name(Some("Shape"), Some("geometry"))
        );
        assert_eq!(
            at_cursor(
                Syntax::Classic,
                &format!("{head}Material {{ diffuseColor 1 0 0 sh|")
            ),
            Some(Context::FieldName {
                node: "Material".into(),
                written: vec![]
            })
        );
        assert_eq!(
            at_cursor(Syntax::Classic, &format!("{head}USE |")),
            Some(Context::DefName)
        );
        assert_eq!(
            at_cursor(Syntax::Classic, "#X3D V4.0 utf8\nTra|"),
            node_name(None, None)
        );
    }
}
