//! Scripts, RULES.md §8: the ECMAScript code of each Script node, found where a browser
//! finds it, parsed (`ecmascript`) and checked for syntax errors and for the functions
//! its input fields need.
//!
//! Where the code is, in the order a browser tries it (19775-1 9.2.1, 29.4.1: the url
//! entries in order, the first that loads is used; the XML encoding's CDATA, JSON's
//! `#sourceCode`, counts as one more entry after them, as X_ITE adds it):
//! - inline code: an `ecmascript:`, `javascript:` or `vrmlscript:` url entry, the
//!   element's CDATA and text (with or without the scheme), `data:` URLs of a JavaScript
//!   MIME type;
//! - local `.js` files, read at the deep level only, resolved as texture urls are (never
//!   outside the tree being checked, never from the network);
//! - anything else is not checked and says why (VALIDATION_INCOMPLETE): Java classes,
//!   CastleScript, `compiled:` code, network URLs, `.js` files below the deep level.
//!
//! Nothing here runs for a document without Scripts, and the parser is only started for
//! code that was found.

mod ecmascript;
mod mapped;
pub mod script_handler_missing;
pub mod script_syntax_error;
mod sources;

use std::path::Path;

use super::{Check, Ctx};
use crate::diagnostic::Level;
use crate::model::data_url;
use crate::model::{Encoding, Node, NodeId, Origin, Span};
use crate::validate::texturing::files::{not_fetched, Resolution, Resolver};
use mapped::Mapped;

/// This group's rules, in catalogue order.
pub static RULES: &[&Check] = &[&script_syntax_error::CHECK, &script_handler_missing::CHECK];

/// What was read of each Script's code (the Scripts the document writes).
#[derive(Default)]
pub struct Scripts {
    pub scripts: Vec<ScriptCode>,
}

pub struct ScriptCode {
    pub node: NodeId,
    /// The pieces of code parsed, in the order a browser tries them.
    pub parsed: Vec<ParsedCode>,
    /// Why code a browser may run instead of (or before) the parsed code was not checked;
    /// None when the code a browser runs first was parsed, or there is no code.
    pub unchecked: Option<String>,
    /// Whether every entry a browser could load was parsed: then the parsed code is all the
    /// Script can hold.
    pub complete: bool,
}

pub struct ParsedCode {
    pub result: ecmascript::Parsed,
    pub place: Place,
}

impl ParsedCode {
    /// The code as parsed.
    pub fn code(&self) -> &str {
        self.place.code()
    }
}

impl Place {
    fn code(&self) -> &str {
        match self {
            Place::Document(mapped) => &mapped.text,
            Place::Elsewhere { code, .. } => code,
        }
    }
}

/// Where parsed code is written.
pub enum Place {
    /// In the document: the decoded code with the place of each character.
    Document(Mapped),
    /// Elsewhere (a `.js` file, a data: URL): the url entry naming it, how messages name
    /// it, and the code, for lines and columns.
    Elsewhere {
        entry: Span,
        name: String,
        code: String,
    },
}

impl Scripts {
    /// Reads the code of every Script the document writes (a copy made for a prototype
    /// instance is the same Script, with its url passed in through IS).
    pub fn read(ctx: &Ctx) -> Scripts {
        let mut scripts = Vec::new();
        let written = ctx.doc.written_nodes().len();
        let mut resolver = None;
        for (id, node) in ctx.doc.iter().take(written) {
            if node.is_a("Script") {
                scripts.push(read_script(ctx, id, node, &mut resolver));
            }
        }
        Scripts { scripts }
    }
}

/// Why the code of Script `id` is (partly) not checked, for VALIDATION_INCOMPLETE; None
/// when the code that runs was parsed (or there is none).
pub fn unchecked(ctx: &Ctx, id: NodeId) -> Option<String> {
    let checked = ctx.config.level >= Level::Standard
        && ctx.config.runs(&script_syntax_error::SCRIPT_SYNTAX_ERROR);
    if !checked {
        return Some("Script code is not checked".to_string());
    }
    let script = ctx.scripts().scripts.iter().find(|s| s.node == id)?;
    script.unchecked.clone()
}

/// One place code may come from, before it is looked at.
struct Candidate {
    text: Mapped,
    span: Span,
    /// The element's content (CDATA, `#sourceCode`): code even without a scheme.
    content: bool,
}

fn read_script(ctx: &Ctx, id: NodeId, node: &Node, resolver: &mut Option<Resolver>) -> ScriptCode {
    let mut code = ScriptCode {
        node: id,
        parsed: Vec::new(),
        unchecked: None,
        complete: true,
    };
    let mut candidates = Vec::new();
    if let Some(url) = node.entry("url") {
        if url.origin == Origin::Is || node.is_connected("url") {
            code.complete = false;
            code.unchecked = Some("its url is passed in through IS and is not checked".into());
        } else {
            let entries = match ctx.doc.encoding {
                Encoding::Xml => sources::xml_attribute_strings(ctx.source, url.span),
                Encoding::Json => sources::json_strings(ctx.source, url.span),
                Encoding::ClassicVrml | Encoding::Vrml97 => {
                    sources::classic_strings(ctx.source, url.span)
                }
            };
            candidates.extend(entries.into_iter().map(|e| Candidate {
                text: e.text,
                span: e.span,
                content: false,
            }));
        }
    }
    if let Some(span) = node.source_code {
        let text = match ctx.doc.encoding {
            Encoding::Json => sources::json_source_code(ctx.source, span),
            _ => sources::xml_content(ctx.source, span),
        };
        candidates.push(Candidate {
            text,
            span,
            content: true,
        });
    }
    // Whether code a browser surely loads was parsed already: later entries never run.
    let mut runs = false;
    for candidate in candidates {
        let unknown = match look_at(ctx, &candidate, resolver) {
            Look::Code(parsed) => {
                code.parsed.push(parsed);
                runs = true;
                continue;
            }
            Look::Nothing => continue,
            Look::Unknown(why) => why,
        };
        code.complete = false;
        if !runs && code.unchecked.is_none() {
            code.unchecked = Some(unknown);
        }
    }
    code
}

/// What a candidate turned out to be.
enum Look {
    Code(ParsedCode),
    /// Nothing a browser can load (empty, a missing local file, a broken data: URL).
    Nothing,
    /// Code x3dcheck does not read, and why.
    Unknown(String),
}

const ECMASCRIPT_SCHEMES: [&str; 3] = ["ecmascript:", "javascript:", "vrmlscript:"];

fn look_at(ctx: &Ctx, candidate: &Candidate, resolver: &mut Option<Resolver>) -> Look {
    let text = candidate.text.text.as_str();
    let start = text.len() - text.trim_start().len();
    let trimmed = text[start..].trim_end();
    if trimmed.is_empty() {
        return Look::Nothing;
    }
    let lower = trimmed
        .get(..trimmed.len().min(16))
        .unwrap_or(trimmed)
        .to_ascii_lowercase();
    if let Some(scheme) = ECMASCRIPT_SCHEMES.iter().find(|s| lower.starts_with(**s)) {
        let code = candidate
            .text
            .slice(start + scheme.len(), candidate.text.len());
        return parse_in_document(code);
    }
    let shown = shown(trimmed);
    if let Some(language) = other_language(&lower, trimmed) {
        return Look::Unknown(format!(
            "its code \"{shown}\" is {language}, which x3dcheck does not check"
        ));
    }
    if candidate.content {
        return parse_in_document(candidate.text.clone());
    }
    if data_url::is_data_url(trimmed) {
        return data(trimmed, candidate.span);
    }
    if ctx.config.level < Level::Deep {
        return match Resolver::new(None, None).resolve(trimmed) {
            Resolution::Network(_) => Look::Unknown(format!("its code at {}", not_fetched(&shown))),
            _ => Look::Unknown(format!(
                "its code in \"{shown}\" is read at the deep level only"
            )),
        };
    }
    let resolver =
        resolver.get_or_insert_with(|| Resolver::new(ctx.base, ctx.config.root.as_deref()));
    match resolver.resolve(trimmed) {
        Resolution::Local(path) => file(ctx, &path, trimmed, candidate.span),
        Resolution::Missing { .. } | Resolution::Inline => Look::Nothing,
        Resolution::Network(_) => Look::Unknown(format!("its code at {}", not_fetched(&shown))),
        Resolution::Outside(_) => Look::Unknown(format!(
            "its code in \"{shown}\" is outside the directory tree being checked and is not read"
        )),
        Resolution::NoBase => Look::Unknown(format!(
            "its code in \"{shown}\" is not read: relative URLs of a document read from standard input are not resolved"
        )),
    }
}

/// The language of a url entry that is not ECMAScript, when it says so.
fn other_language(lower: &str, text: &str) -> Option<&'static str> {
    let path = text.split(['#', '?']).next().unwrap_or(text);
    if lower.starts_with("castlescript:") || lower.starts_with("kambiscript:") {
        Some("CastleScript")
    } else if lower.starts_with("compiled:") {
        Some("code compiled into the browser (`compiled:`)")
    } else if path.to_ascii_lowercase().ends_with(".class")
        || path.to_ascii_lowercase().ends_with(".jar")
    {
        Some("Java")
    } else {
        None
    }
}

fn parse_in_document(code: Mapped) -> Look {
    parsed(Place::Document(code))
}

fn parsed(place: Place) -> Look {
    match ecmascript::parse(place.code()) {
        Ok(result) => Look::Code(ParsedCode { result, place }),
        Err(why) => Look::Unknown(format!("its code {why}")),
    }
}

/// A data: URL: JavaScript by its MIME type is parsed, anything else is not code.
fn data(url: &str, entry: Span) -> Look {
    let Ok(data_url) = ::data_url::DataUrl::process(url) else {
        return Look::Nothing;
    };
    let mime = data_url.mime_type();
    let subtype = mime.subtype.to_ascii_lowercase();
    if !subtype.contains("javascript") && !subtype.contains("ecmascript") {
        return Look::Unknown(format!(
            "its code \"{}\" is of type {}/{}, which x3dcheck does not check",
            shown(url),
            mime.type_,
            mime.subtype
        ));
    }
    let Ok((bytes, _)) = data_url.decode_to_vec() else {
        return Look::Nothing;
    };
    let code = String::from_utf8_lossy(&bytes).into_owned();
    parsed(Place::Elsewhere {
        entry,
        name: "the data: URL's code".to_string(),
        code,
    })
}

/// A local file (deep level): a `.js` file is parsed; another is not ECMAScript.
fn file(ctx: &Ctx, path: &Path, url: &str, entry: Span) -> Look {
    let name = crate::validate::prototypes::externs::display_path(ctx.base, path);
    let is_js = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("js"));
    if !is_js {
        return Look::Unknown(format!(
            "its code in \"{url}\" is not a .js file and is not checked"
        ));
    }
    match crate::read::read_path(path, crate::limits::MAX_INPUT_BYTES) {
        Ok(crate::read::Contents::Bytes(bytes)) => {
            let code = String::from_utf8_lossy(&bytes).into_owned();
            parsed(Place::Elsewhere {
                entry,
                name: format!("`{name}`"),
                code,
            })
        }
        Ok(crate::read::Contents::TooLarge) => Look::Unknown(format!(
            "its code in `{name}` is larger than the input limit and is not read"
        )),
        Err(why) => Look::Unknown(why),
    }
}

/// A url entry as messages name it: its first line, cut after 40 characters (inline code
/// and data: URLs can be long).
fn shown(url: &str) -> String {
    const SHOWN: usize = 40;
    let line = url.lines().next().unwrap_or_default().trim_end();
    let head: String = line.chars().take(SHOWN).collect();
    if head.len() < url.trim_end().len() {
        format!("{head}…")
    } else {
        head
    }
}

/// Line and column (from 1, in characters) of byte `offset` of `code`.
pub fn line_column(code: &str, offset: usize) -> (usize, usize) {
    let before = &code[..offset.min(code.len())];
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    let line = before.matches('\n').count() + 1;
    (line, before[line_start..].chars().count() + 1)
}
