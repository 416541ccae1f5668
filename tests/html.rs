//! X3D in web pages (src/parse/html): the pages of `corpus/html` with their reports pinned,
//! the name mapping, the self-closing pitfall, positions, discovery and `--island`.

mod common;

use std::path::Path;

use common::{scratch, stdout, x3dcheck};
use x3dcheck::check::check_document;
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;

fn deep() -> CheckConfig {
    CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    }
}

fn concise(relative: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(relative);
    let source = std::fs::read(&path).unwrap();
    let report = x3dcheck::check_source(relative, &source, &deep());
    x3dcheck::report::concise::render(&report)
}

#[test]
fn page_reports_are_pinned() {
    for page in ["x3dom.html", "x_ite.html", "xhtml.xhtml", "no-island.html"] {
        let name = page.replace('.', "_");
        insta::assert_snapshot!(name, concise(&format!("corpus/html/{page}")));
    }
}

/// The line and column of each finding of `code` in `page`.
fn places(page: &str, code: &str) -> Vec<(usize, usize)> {
    let report = x3dcheck::check_source("page.html", page.as_bytes(), &deep());
    report
        .diagnostics
        .iter()
        .filter(|d| d.code == code)
        .map(|d| (d.line, d.column))
        .collect()
}

#[test]
fn lower_case_names_are_read_as_x3d_names() {
    // `diffusecolor` is Material's diffuseColor: its range is checked, at its own place.
    let page = "<html><body><x3d><scene><shape><appearance>\n  <material diffusecolor='2 0 0'></material>\n</appearance><box></box></shape></scene></x3d></body></html>";
    assert_eq!(places(page, "FIELD_OUT_OF_RANGE"), [(2, 27)]);
    assert!(places(page, "NODE_UNKNOWN").is_empty());
    assert!(places(page, "FIELD_UNKNOWN").is_empty());
}

#[test]
fn positions_are_those_of_the_page() {
    // Multi-line tags, a comment and a script with `<` before the island.
    let page = "<!DOCTYPE html>\n<script>if (a<b) {}</script><!-- <x3d> -->\n<p>é</p><x3d><scene>\n<transform\n   scale='1 1'\n></transform></scene></x3d>";
    assert_eq!(places(page, "FIELD_VALUE_SYNTAX"), [(5, 11)]);
}

#[test]
fn a_self_closed_element_that_swallowed_its_siblings_is_reported() {
    let page = "<x3d><scene><shape><box/><appearance></appearance></shape><group/></scene></x3d>";
    let report = x3dcheck::check_source("page.html", page.as_bytes(), &deep());
    let found: Vec<_> = report
        .diagnostics
        .iter()
        .filter(|d| d.code == "HTML_SELF_CLOSED")
        .collect();
    // `<group/>` is last in the scene: nothing followed it to be swallowed.
    assert_eq!(found.len(), 1, "{:?}", report.diagnostics);
    assert_eq!((found[0].line, found[0].column), (1, 20));
    assert!(
        found[0].message.contains("`Appearance`"),
        "{}",
        found[0].message
    );
    // As XHTML the same markup is XML, and `<box/>` is closed.
    let xhtml = format!("<?xml version='1.0'?>\n<html xmlns='http://www.w3.org/1999/xhtml'><body>{page}</body></html>");
    let report = x3dcheck::check_source("page.xhtml", xhtml.as_bytes(), &deep());
    assert!(report
        .diagnostics
        .iter()
        .all(|d| d.code != "HTML_SELF_CLOSED" && d.code != "CONTAINER_FIELD_INVALID"));
}

#[test]
fn each_island_is_checked_and_named_and_island_picks_the_document() {
    let page = "<x3d><scene><shape><box size='-1 1 1'></box></shape></scene></x3d>\n<x3d><scene><group></group><group></group></scene></x3d>";
    let report = x3dcheck::check_source("page.html", page.as_bytes(), &deep());
    assert!(report
        .diagnostics
        .iter()
        .any(|d| d.message.starts_with("island 1 of 2 (line 1): ")));
    for island in [1, 2] {
        let config = CheckConfig { island, ..deep() };
        let checked = check_document("page.html", page.as_bytes(), &config);
        let doc = checked.document.unwrap();
        let top = doc.scene.len();
        assert_eq!(top, island, "island {island}");
    }
}

#[test]
fn a_walk_takes_pages_that_hold_x3d() {
    let dir = scratch(
        "html-walk",
        &[
            (
                "scene.html",
                "<html><body><x3d><scene></scene></x3d></body></html>",
            ),
            ("canvas.htm", "<x3d-canvas src='a.x3d'></x3d-canvas>"),
            ("plain.html", "<html><body><p>x3d</p></body></html>"),
        ],
    );
    let listed = stdout(&x3dcheck(&dir, &["--show-files", "."]));
    assert!(listed.contains("scene.html"), "{listed}");
    assert!(listed.contains("canvas.htm"), "{listed}");
    assert!(!listed.contains("plain.html"), "{listed}");
}

#[test]
fn what_x3dom_reads_is_no_error_on_its_page() {
    // isPickable is X3DOM's on Shape; HTML in <x3d> is the page's; X3DOM's RenderedTexture
    // is not checked as X3D 4.1's.
    let page = "<html><body><x3d><div class='x3dom-statdiv'></div><scene>\n<shape isPickable='false'><appearance><renderedtexture update='always'></renderedtexture></appearance><box></box></shape>\n</scene></x3d></body></html>";
    assert_eq!(places(page, "X3DOM_EXTENSION"), [(2, 8), (2, 40)]);
    for code in ["FIELD_UNKNOWN", "ROOT_CONTENT_IGNORED"] {
        assert!(places(page, code).is_empty(), "{code}");
    }
    // Unquoted MFString, TRUE, CSS colour: X3DOM_VALUE_SYNTAX; a value X3DOM does not read
    // either stays FIELD_VALUE_SYNTAX.
    let page = "<x3d><scene>\n<pointlight on='TRUE'></pointlight><pointlight on='yes'></pointlight>\n<material diffusecolor='#f63'></material><inline url='a.x3d'></inline>\n</scene></x3d>";
    assert_eq!(
        places(page, "X3DOM_VALUE_SYNTAX"),
        [(2, 17), (3, 25), (3, 55)]
    );
    assert_eq!(places(page, "FIELD_VALUE_SYNTAX"), [(2, 52)]);
    // In an X_ITE island only the unquoted MFString is read.
    let page = "<html><body><x3d-canvas><x3d><scene>\n<pointlight on='TRUE'></pointlight><inline url='a.x3d'></inline>\n</scene></x3d></x3d-canvas></body></html>";
    assert_eq!(places(page, "X3DOM_VALUE_SYNTAX"), [(2, 49)]);
    assert_eq!(places(page, "FIELD_VALUE_SYNTAX"), [(2, 17)]);
}

#[test]
fn a_server_template_is_a_page_and_its_placeholders_are_not_values() {
    let page = "{% extends \"base.html\" %}\n{% block content %}<x3d><scene>\n<inline url=\"{{ model.inline }}\"></inline>\n</scene></x3d>{% endblock %}";
    assert!(places(page, "JSON_MALFORMED").is_empty());
    assert!(places(page, "FIELD_VALUE_SYNTAX").is_empty());
    assert_eq!(places(page, "VALIDATION_INCOMPLETE"), [(3, 14)]);
}

#[test]
fn a_page_nested_past_the_depth_limit_is_reported_not_a_stack_overflow() {
    // The HTML walk recurses per element: 20,000 levels overflowed a 2 MB test thread's
    // stack before it stopped past the model's depth limit.
    let depth = 20_000;
    let page = format!(
        "<html><body><x3d><scene>{}{}</scene></x3d></body></html>",
        "<transform>".repeat(depth),
        "</transform>".repeat(depth)
    );
    let report = x3dcheck::check_source("deep.html", page.as_bytes(), &deep());
    let text = x3dcheck::report::concise::render(&report);
    assert!(text.contains("LIMIT_EXCEEDED"), "{text}");
}
