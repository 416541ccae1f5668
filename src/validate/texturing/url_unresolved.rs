//! URL_UNRESOLVED: no entry of a url field names a readable local file.

use super::files::{not_fetched, url_fields, Resolution, Resolver};
use crate::diagnostic::Diagnostic;
use crate::validate::document::validation_incomplete::VALIDATION_INCOMPLETE;
use crate::validate::prototypes::externs::{display_path, Resolved};
use crate::validate::shaders::source::is_source_text;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a url field none of whose entries resolves to a readable local file,
    /// relative to the document's directory. Checked fields: `url` of every node that
    /// loads it with the scene (ImageTexture, MovieTexture, AudioClip, Inline, Script,
    /// shader parts and programs, 3D and cube-map textures, FontLibrary, …; not Anchor,
    /// whose links are followed on demand, nor GeoMetadata), Background's six image
    /// urls, and the url of an ExternProtoDeclare (19775-1 4.4.5) whose entries are all
    /// local files and none exists, or that has none: its instances build nothing (a
    /// url with a network entry gets VALIDATION_INCOMPLETE: the browser falls back to it).
    ///
    /// - `%XX` escapes are decoded, `file:` URLs are local paths, a `#fragment` is
    ///   dropped, and a Windows backslash is also tried as `/`.
    /// - Network URLs (`http:`, `https:`, `ftp:`, `urn:`, …) are never fetched: a field
    ///   with no local file but a network entry gets VALIDATION_INCOMPLETE instead, as does
    ///   a relative URL of a document read from standard input.
    /// - `data:` URLs and script code (`ecmascript:`, `javascript:`, `vrmlscript:`,
    ///   `castlescript:`, `compiled:`, or a CDATA section, which the XML encoding adds as a
    ///   url entry) need no file, nor GLSL written in a shader part's url entry.
    /// - Files are read only inside the allowed tree: the directory given as the checking
    ///   root (the tree the user named on the command line), else the document's own
    ///   directory. `..` and symlinks are resolved first; an entry that leaves the tree is
    ///   not read and gets VALIDATION_INCOMPLETE.
    /// - When the only match differs in letter case, the message says so: it loads on
    ///   Windows and macOS but not from a case-sensitive file system or web server.
    /// - A node of an external prototype's body (another file) resolves its relative urls
    ///   against that file's directory, as browsers do. VRML97 14772-1 4.5.3 names
    ///   another base for them: "The file in which the prototype is instantiated, if the
    ///   statement is part of a prototype definition", the checked document. A url found
    ///   only there is reported too (the message says so): browsers differ on it.
    ///
    /// ## Why it matters
    /// 9.2.1 (URLs): a browser tries the entries in order and uses the first it can load;
    /// when none loads, the texture, sound, inlined scene or script is missing.
    ///
    /// ## Example
    /// ```xml
    /// <ImageTexture url='"textures/missing.png"'/>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 9.2.1 URLs, URNs and URIs; 18.4.1 ImageTexture; 14772-1 4.5.3 Relative URLs.
    pub static URL_UNRESOLVED = {
        severity: Warning,
        level: Deep,
        clause: "9.2.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let resolver = Resolver::new(ctx.base, ctx.config.root.as_deref());
    let mut found = Vec::new();
    for field in url_fields(ctx.doc) {
        let urls = field.entry.value.as_strings().unwrap_or_default();
        // Script and shader code in the element's CDATA is one more url entry (XML
        // encoding): the node has its content whatever the files.
        if urls.is_empty() || ctx.doc.node(field.node).source_code.is_some() {
            continue;
        }
        // GLSL written straight into a shader part's url entry is its content too.
        let node = ctx.doc.node(field.node);
        let shader = node.is_a("ShaderPart") || node.is_a("ShaderProgram");
        // A node of an external prototype's body: its urls are relative to its file.
        let library = resolver.for_node(ctx.doc, field.node);
        let resolutions: Vec<Resolution> = urls
            .iter()
            .map(|u| {
                if shader && is_source_text(u) {
                    Resolution::Inline
                } else {
                    library.as_ref().unwrap_or(&resolver).resolve(u)
                }
            })
            .collect();
        if resolutions
            .iter()
            .any(|r| matches!(r, Resolution::Local(_) | Resolution::Inline))
        {
            continue;
        }
        let library_file = ctx
            .doc
            .library_file_of(field.node)
            .map(|path| display_path(ctx.base, path));
        let type_name = ctx.doc.node(field.node).type_name();
        let what = format!("{type_name}.{}", field.entry.name());
        if let Some(file) = &library_file {
            let beside_document = urls
                .iter()
                .find(|u| matches!(resolver.resolve(u), Resolution::Local(_)));
            if let Some(url) = beside_document {
                found.push(
                    Diagnostic::new(&URL_UNRESOLVED, field.entry.span, format!(
                        "{what}: \"{url}\" is found next to the document that instantiates the prototype, not next to the prototype's file {file}: browsers that resolve it against the prototype's file do not load it"
                    ))
                    .help("put the file next to the prototype's file, or write a url relative to it")
                    .node(field.node),
                );
                continue;
            }
        }
        let unchecked = urls.iter().zip(&resolutions).find_map(|(url, r)| match r {
            Resolution::Network(_) => Some(format!("{what}: {}", not_fetched(url))),
            Resolution::Outside(_) => Some(format!(
                "{what}: \"{url}\" is outside the directory tree being checked and is not read"
            )),
            Resolution::NoBase => Some(format!(
                "{what}: relative URLs of a document read from standard input are not resolved"
            )),
            _ => None,
        });
        let diagnostic = match unchecked {
            Some(message) => Diagnostic::new(&VALIDATION_INCOMPLETE, field.entry.span, message),
            None => {
                let case_hint = resolutions.iter().find_map(|r| match r {
                    Resolution::Missing {
                        case_differs: Some(name),
                        ..
                    } => Some(name.clone()),
                    _ => None,
                });
                let listed: Vec<String> = urls.iter().map(|u| format!("\"{u}\"")).collect();
                let message = match &case_hint {
                    Some(name) => format!(
                        "{what}: no file {} — only `{name}`, which differs in letter case (it fails on case-sensitive servers)",
                        listed.join(" or ")
                    ),
                    None => format!(
                        "{what}: no readable file {} next to {}",
                        listed.join(" or "),
                        library_file.as_ref().map_or_else(
                            || "the document".to_string(),
                            |file| format!("the prototype's file {file} or the document")
                        )
                    ),
                };
                Diagnostic::new(&URL_UNRESOLVED, field.entry.span, message)
                    .help_opt(case_hint.map(|name| format!("write the name as `{name}`")))
            }
        };
        found.push(diagnostic.node(field.node));
    }
    found.extend(extern_protos(ctx, &resolver));
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// ExternProtoDeclares whose url names only local files, none of which exists.
fn extern_protos(ctx: &Ctx, resolver: &Resolver) -> Vec<Diagnostic> {
    let mut found = Vec::new();
    for (index, proto) in ctx.doc.protos.iter().enumerate() {
        if !matches!(ctx.externs.get(index), Some(Resolved::Unresolved)) {
            continue;
        }
        let resolutions: Vec<Resolution> = proto.url.iter().map(|u| resolver.resolve(u)).collect();
        if !resolutions
            .iter()
            .all(|r| matches!(r, Resolution::Missing { .. }))
        {
            continue;
        }
        let name = &proto.name.text;
        let listed: Vec<String> = proto.url.iter().map(|u| format!("\"{u}\"")).collect();
        let message = if listed.is_empty() {
            format!("ExternProtoDeclare `{name}` has no url: its instances build nothing")
        } else {
            format!(
                "ExternProtoDeclare `{name}`: no readable file {} next to the document: its instances build nothing",
                listed.join(" or ")
            )
        };
        let case_hint = resolutions.iter().find_map(|r| match r {
            Resolution::Missing {
                case_differs: Some(name),
                ..
            } => Some(format!("write the name as `{name}`")),
            _ => None,
        });
        found.push(Diagnostic::new(&URL_UNRESOLVED, proto.name.span, message).help_opt(case_hint));
    }
    found
}
