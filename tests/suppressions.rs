//! Inline suppression (issue 17): `<!-- x3dcheck: ignore CODE -->` in XML,
//! `# x3dcheck: ignore CODE` in ClassicVRML and `"#comment": "x3dcheck: ignore CODE"` in
//! JSON drop exactly the findings of those codes in what the comment applies to, and
//! nothing else; a comment that drops nothing is SUPPRESSION_UNUSED.
//!
//! One scene is written in each encoding. Its lines are told apart by a marker word (the
//! node type on them), and each finding is named by the marker of its line.

use x3dcheck::check::check_source;
use x3dcheck::config::CheckConfig;
use x3dcheck::report::FileReport;

/// The markers, in the order their lines come in every encoding.
const MARKERS: [&str; 6] = ["Group", "Foo", "Transform", "Bar", "Baz", "Switch"];

/// Without suppression: NODE_UNKNOWN on Foo, Bar and Baz; DEF_DUPLICATE on Transform and
/// Switch (the Group takes the name first). `{file}` is where a whole-file comment goes,
/// `{here}` the comment before the Transform.
const XML: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
{file}
<X3D profile='Immersive' version='4.0'>
  <Scene>
    <Group DEF='A'/>
    <Foo/>
    {here}
    <Transform DEF='A'>
      <Bar/>
    </Transform>
    <Baz/>
    <Switch DEF='A'/>
  </Scene>
</X3D>
"#;

const CLASSIC: &str = "#X3D V4.0 utf8
{file}
PROFILE Immersive
DEF A Group {}
Foo {}
{here}
DEF A Transform {
  children [
    Bar {}
  ]
}
Baz {}
DEF A Switch {}
";

const JSON: &str = r#"{ "X3D": { "encoding": "UTF-8", "@profile": "Immersive", "@version": "4.0",
    {file}
    "Scene": { "-children": [
        { "Group": { "@DEF": "A" } },
        { "Foo": {} },
        {here}
        { "Transform": { "@DEF": "A", "-children": [
            { "Bar": {} }
        ] } },
        { "Baz": {} },
        { "Switch": { "@DEF": "A" } }
    ] } } }
"#;

#[derive(Copy, Clone, Debug)]
enum Encoding {
    Xml,
    Classic,
    Json,
}

const ENCODINGS: [Encoding; 3] = [Encoding::Xml, Encoding::Classic, Encoding::Json];

impl Encoding {
    fn name(self) -> &'static str {
        match self {
            Encoding::Xml => "scene.x3d",
            Encoding::Classic => "scene.x3dv",
            Encoding::Json => "scene.x3dj",
        }
    }

    /// The suppression comment for `codes` in this encoding, as the statement before the
    /// Transform (`file`: at the top of the file).
    fn comment(self, codes: &str, file: bool) -> String {
        match self {
            Encoding::Xml => format!("<!-- x3dcheck: ignore {codes} -->"),
            Encoding::Classic => format!("# x3dcheck: ignore {codes}"),
            Encoding::Json if file => format!(r##""#comment": "x3dcheck: ignore {codes}","##),
            Encoding::Json => format!(r##"{{ "#comment": "x3dcheck: ignore {codes}" }},"##),
        }
    }

    fn scene(self, file: &str, here: &str) -> String {
        let template = match self {
            Encoding::Xml => XML,
            Encoding::Classic => CLASSIC,
            Encoding::Json => JSON,
        };
        template.replace("{file}", file).replace("{here}", here)
    }
}

/// The findings of `source` as `CODE@Marker`, in order.
fn findings(name: &str, source: &str, config: &CheckConfig) -> (Vec<String>, FileReport) {
    let report = check_source(name, source.as_bytes(), config);
    let lines: Vec<&str> = source.lines().collect();
    let found = report
        .diagnostics
        .iter()
        .filter(|d| !["PROFILE_MISSING", "COMPONENT_LEVEL_INSUFFICIENT"].contains(&d.code))
        .map(|d| {
            let line = lines.get(d.line - 1).copied().unwrap_or_default();
            let marker = MARKERS
                .iter()
                .find(|m| line.contains(*m))
                .copied()
                .unwrap_or(if line.contains("x3dcheck:") {
                    "comment"
                } else {
                    "?"
                });
            format!("{}@{marker}", d.code)
        })
        .collect();
    (found, report)
}

/// The findings with a comment for `codes` before the Transform (or at the top of the
/// file), and how many it suppressed.
fn with_comment(encoding: Encoding, codes: &str, file: bool) -> (Vec<String>, usize) {
    let comment = encoding.comment(codes, file);
    let scene = if file {
        encoding.scene(&comment, "")
    } else {
        encoding.scene("", &comment)
    };
    let (found, report) = findings(encoding.name(), &scene, &CheckConfig::default());
    (found, report.suppressed)
}

fn strings(items: &[&str]) -> Vec<String> {
    items.iter().map(|s| s.to_string()).collect()
}

const ALL_FINDINGS: [&str; 5] = [
    "NODE_UNKNOWN@Foo",
    "DEF_DUPLICATE@Transform",
    "NODE_UNKNOWN@Bar",
    "NODE_UNKNOWN@Baz",
    "DEF_DUPLICATE@Switch",
];

/// The findings outside the element a comment before `Transform` covers.
const OUTSIDE_THE_COVERED_ELEMENT: [&str; 3] = [
    "NODE_UNKNOWN@Foo",
    "NODE_UNKNOWN@Baz",
    "DEF_DUPLICATE@Switch",
];

#[test]
fn without_a_comment_every_finding_is_reported() {
    for encoding in ENCODINGS {
        let (found, report) = findings(
            encoding.name(),
            &encoding.scene("", ""),
            &CheckConfig::default(),
        );
        assert_eq!(found, strings(&ALL_FINDINGS), "{encoding:?}");
        assert_eq!(report.suppressed, 0);
    }
}

#[test]
fn a_comment_suppresses_its_code_in_what_follows_and_nowhere_else() {
    for encoding in ENCODINGS {
        let (found, suppressed) = with_comment(encoding, "NODE_UNKNOWN", false);
        assert_eq!(
            found,
            strings(&[
                "NODE_UNKNOWN@Foo",
                "DEF_DUPLICATE@Transform",
                "NODE_UNKNOWN@Baz",
                "DEF_DUPLICATE@Switch",
            ]),
            "{encoding:?}: the Bar inside the Transform, only"
        );
        assert_eq!(suppressed, 1, "{encoding:?}");
    }
}

#[test]
fn several_codes_in_one_comment() {
    for encoding in ENCODINGS {
        let (found, suppressed) = with_comment(encoding, "NODE_UNKNOWN, DEF_DUPLICATE", false);
        assert_eq!(found, strings(&OUTSIDE_THE_COVERED_ELEMENT), "{encoding:?}");
        assert_eq!(suppressed, 2, "{encoding:?}");
    }
}

#[test]
fn prefixes_all_and_any_case_as_for_ignore() {
    for encoding in ENCODINGS {
        let (found, _) = with_comment(encoding, "node_", false);
        assert!(
            !found.contains(&"NODE_UNKNOWN@Bar".to_string()),
            "{encoding:?}: {found:?}"
        );
        assert!(
            found.contains(&"DEF_DUPLICATE@Transform".to_string()),
            "{encoding:?}"
        );
        let (found, suppressed) = with_comment(encoding, "ALL", false);
        assert_eq!(found, strings(&OUTSIDE_THE_COVERED_ELEMENT), "{encoding:?}");
        assert_eq!(suppressed, 2, "{encoding:?}");
    }
}

#[test]
fn a_comment_at_the_top_covers_the_whole_file() {
    for encoding in ENCODINGS {
        let (found, suppressed) = with_comment(encoding, "NODE_UNKNOWN", true);
        assert_eq!(
            found,
            strings(&["DEF_DUPLICATE@Transform", "DEF_DUPLICATE@Switch"]),
            "{encoding:?}"
        );
        assert_eq!(suppressed, 3, "{encoding:?}");
    }
}

#[test]
fn a_comment_that_suppresses_nothing_is_reported() {
    for encoding in ENCODINGS {
        let (found, suppressed) = with_comment(encoding, "USE_UNDEFINED", false);
        let mut expected = strings(&ALL_FINDINGS);
        expected.insert(1, "SUPPRESSION_UNUSED@comment".into());
        assert_eq!(found, expected, "{encoding:?}");
        assert_eq!(suppressed, 0);
        // Used in one place, unused in the other: the unused code alone is reported.
        let (found, _) = with_comment(encoding, "NODE_UNKNOWN, USE_UNDEFINED", false);
        assert_eq!(
            found
                .iter()
                .filter(|f| f.starts_with("SUPPRESSION_UNUSED"))
                .count(),
            1,
            "{encoding:?}: {found:?}"
        );
    }
}

#[test]
fn an_unknown_code_is_reported_with_the_nearest() {
    for encoding in ENCODINGS {
        let scene = encoding.scene("", &encoding.comment("NODE_UNKNWN", false));
        let (found, report) = findings(encoding.name(), &scene, &CheckConfig::default());
        assert!(found.contains(&"NODE_UNKNOWN@Bar".to_string()), "{found:?}");
        let unused: Vec<_> = report
            .diagnostics
            .iter()
            .filter(|d| d.code == "SUPPRESSION_UNUSED")
            .collect();
        assert_eq!(unused.len(), 1, "{encoding:?}");
        assert!(
            unused[0].message.contains("did you mean `NODE_UNKNOWN`"),
            "{}",
            unused[0].message
        );
    }
}

#[test]
fn a_comment_with_nothing_after_it_in_its_parent_applies_to_nothing() {
    let scenes = [
        (
            "a.x3d",
            "<X3D profile='Immersive' version='4.0'><Scene><Group><Foo/>\n<!-- x3dcheck: ignore NODE_UNKNOWN -->\n</Group><Bar/></Scene></X3D>",
        ),
        (
            "a.x3dv",
            "#X3D V4.0 utf8\nPROFILE Immersive\nGroup { children [ Foo {}\n# x3dcheck: ignore NODE_UNKNOWN\n] }\nBar {}\n",
        ),
        (
            "a.x3dj",
            r##"{ "X3D": { "@profile": "Immersive", "@version": "4.0", "Scene": { "-children": [
              { "Group": { "-children": [ { "Foo": {} },
                { "#comment": "x3dcheck: ignore NODE_UNKNOWN" } ] } },
              { "Bar": {} } ] } } }"##,
        ),
    ];
    for (name, scene) in scenes {
        let report = check_source(name, scene.as_bytes(), &CheckConfig::default());
        let codes: Vec<&str> = report.diagnostics.iter().map(|d| d.code).collect();
        assert_eq!(
            codes.iter().filter(|c| **c == "NODE_UNKNOWN").count(),
            2,
            "{name}: {codes:?}"
        );
        assert!(codes.contains(&"SUPPRESSION_UNUSED"), "{name}: {codes:?}");
    }
}

#[test]
fn a_json_comment_member_applies_to_its_node() {
    let scene = r##"{ "X3D": { "@profile": "Immersive", "@version": "4.0", "Scene": { "-children": [
        { "Group": { "@DEF": "A" } },
        { "Transform": { "#comment": "x3dcheck: ignore DEF_DUPLICATE, NODE_UNKNOWN", "@DEF": "A",
            "-children": [ { "Foo": {} } ] } },
        { "Bar": {} },
        { "Switch": { "@DEF": "A" } } ] } } }"##;
    let report = check_source("a.x3dj", scene.as_bytes(), &CheckConfig::default());
    let codes: Vec<&str> = report.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(
        codes
            .iter()
            .filter(|c| ["DEF_DUPLICATE", "NODE_UNKNOWN", "SUPPRESSION_UNUSED"].contains(c))
            .collect::<Vec<_>>(),
        [&"NODE_UNKNOWN", &"DEF_DUPLICATE"],
        "Bar and Switch are outside the Transform"
    );
    assert_eq!(report.suppressed, 2);
}

#[test]
fn a_json_comment_in_head_covers_the_whole_file() {
    let scene = r##"{ "X3D": { "@profile": "Immersive", "@version": "4.0",
        "head": { "-children": [ { "#comment": "x3dcheck: ignore NODE_UNKNOWN" } ] },
        "Scene": { "-children": [ { "Foo": {} }, { "Bar": {} } ] } } }"##;
    let report = check_source("a.x3dj", scene.as_bytes(), &CheckConfig::default());
    assert!(
        report.diagnostics.iter().all(|d| d.code != "NODE_UNKNOWN"),
        "{:?}",
        report.diagnostics
    );
    assert_eq!(report.suppressed, 2);
}

#[test]
fn a_code_whose_rule_does_not_run_is_not_unused() {
    let config = CheckConfig {
        ignore: ["USE_UNDEFINED".to_string()].into(),
        ..CheckConfig::default()
    };
    for encoding in ENCODINGS {
        let scene = encoding.scene("", &encoding.comment("USE_UNDEFINED", false));
        let (found, _) = findings(encoding.name(), &scene, &config);
        assert_eq!(found, strings(&ALL_FINDINGS), "{encoding:?}");
    }
}

#[test]
fn suppression_unused_yields_only_to_a_whole_file_comment() {
    for encoding in ENCODINGS {
        let top = encoding.comment("SUPPRESSION_UNUSED", true);
        let here = encoding.comment("USE_UNDEFINED", false);
        let (found, report) = findings(
            encoding.name(),
            &encoding.scene(&top, &here),
            &CheckConfig::default(),
        );
        assert_eq!(found, strings(&ALL_FINDINGS), "{encoding:?}");
        assert_eq!(report.suppressed, 1);
        // A comment does not suppress its own finding.
        let here = encoding.comment("USE_UNDEFINED, SUPPRESSION_UNUSED", false);
        let (found, _) = findings(
            encoding.name(),
            &encoding.scene("", &here),
            &CheckConfig::default(),
        );
        assert!(
            found.contains(&"SUPPRESSION_UNUSED@comment".to_string()),
            "{encoding:?}: {found:?}"
        );
    }
}

#[test]
fn an_x3dcheck_comment_that_is_no_suppression_is_reported() {
    let scene = XML
        .replace("{file}", "")
        .replace("{here}", "<!-- x3dcheck: ignor NODE_UNKNOWN -->");
    let (found, _) = findings("a.x3d", &scene, &CheckConfig::default());
    assert!(
        found.contains(&"SUPPRESSION_UNUSED@comment".to_string()),
        "{found:?}"
    );
    assert!(found.contains(&"NODE_UNKNOWN@Bar".to_string()), "{found:?}");
    // Other comments are none of x3dcheck's business.
    let scene = XML
        .replace("{file}", "")
        .replace("{here}", "<!-- ignore NODE_UNKNOWN -->");
    let (found, _) = findings("a.x3d", &scene, &CheckConfig::default());
    assert_eq!(found, strings(&ALL_FINDINGS));
}

#[test]
fn suppression_comes_before_max_diagnostics() {
    let config = CheckConfig {
        max_diagnostics: Some(1),
        ..CheckConfig::default()
    };
    let scene = XML
        .replace("{file}", "<!-- x3dcheck: ignore NODE_UNKNOWN -->")
        .replace("{here}", "");
    let (found, report) = findings("a.x3d", &scene, &config);
    assert_eq!(found, ["DEF_DUPLICATE@Transform"]);
    assert!(report.truncated);
}

#[test]
fn the_json_report_counts_suppressed_findings() {
    let scene = XML
        .replace("{file}", "")
        .replace("{here}", "<!-- x3dcheck: ignore NODE_UNKNOWN -->");
    let report = check_source("a.x3d", scene.as_bytes(), &CheckConfig::default());
    let json = x3dcheck::report::json::render(std::slice::from_ref(&report), None);
    let value: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(value["files"][0]["suppressed"], 1, "{json}");
    assert_eq!(value["summary"]["suppressed"], 1, "{json}");
    let clean = check_source(
        "b.x3d",
        XML.replace("{file}", "").replace("{here}", "").as_bytes(),
        &CheckConfig::default(),
    );
    let json = x3dcheck::report::json::render(std::slice::from_ref(&clean), None);
    assert!(!json.contains("suppressed"), "said only when some were");
}
