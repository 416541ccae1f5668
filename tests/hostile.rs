//! Hostile input: whatever a file holds, x3dcheck finishes quickly with a report, reads
//! nothing outside the tree being checked, connects to nothing and writes no input. Each
//! limit of `x3dcheck::limits` is reported as LIMIT_EXCEEDED at its place.

mod common;

use std::fs;
use std::net::TcpListener;
use std::path::Path;
use std::time::{Duration, Instant, SystemTime};

use common::{scratch, x3dcheck};
use x3dcheck::check::{check_source, STDIN_NAME};
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;
use x3dcheck::limits::{
    MAX_DEPTH, MAX_DIAGNOSTICS, MAX_ENTITY_EXPANSION, MAX_FIELDS_PER_NODE, MAX_FIELD_VALUES,
    MAX_IMAGE_SIDE, MAX_NODES,
};
use x3dcheck::report::FileReport;

/// Far above what these inputs take when all is well (a few hundred milliseconds): a guard
/// against hangs and blow-ups, not a timing test (20 s tripped once at a load average of 9).
const QUICK: Duration = Duration::from_secs(60);

fn deep() -> CheckConfig {
    CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    }
}

/// Checks `source` at the deep level as if it were the file `path`, in a thread with the
/// default 2 MiB stack (so deep recursion would overflow), within [`QUICK`].
fn check_at(path: &str, source: impl Into<Vec<u8>>) -> FileReport {
    let (path, source) = (path.to_string(), source.into());
    let started = Instant::now();
    let report = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(move || check_source(&path, &source, &deep()))
        .unwrap()
        .join()
        .expect("the check panicked");
    assert!(started.elapsed() < QUICK, "took {:?}", started.elapsed());
    report
}

fn check(source: impl Into<Vec<u8>>) -> FileReport {
    check_at(STDIN_NAME, source)
}

fn codes(report: &FileReport) -> Vec<&'static str> {
    report.diagnostics.iter().map(|d| d.code).collect()
}

/// The LIMIT_EXCEEDED messages, each with its line.
fn limits_of(report: &FileReport) -> Vec<(usize, String)> {
    let limits = report
        .diagnostics
        .iter()
        .filter(|d| d.code == "LIMIT_EXCEEDED");
    limits.map(|d| (d.line, d.message.clone())).collect()
}

fn scene(body: &str) -> String {
    format!("<X3D profile='Full' version='4.0'><Scene>\n{body}\n</Scene></X3D>")
}

#[test]
fn billion_laughs_through_entities_stops_at_the_expansion_budget() {
    let mut subset = String::from(r#"<!ENTITY a0 "lol">"#);
    for level in 1..=9 {
        let refs = format!("&a{};", level - 1).repeat(10);
        subset.push_str(&format!(r#"<!ENTITY a{level} "{refs}">"#));
    }
    let source = format!(
        "<?xml version='1.0'?>\n<!DOCTYPE X3D [{subset}]>\n{}",
        scene("<WorldInfo title='&a9;'/>\n<WorldInfo title='&a2;'/>\n<Foo/>")
    );
    let report = check(source);
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1, "{limits:?}");
    assert_eq!(limits[0].0, 4, "at the first WorldInfo");
    assert!(limits[0].1.contains(&MAX_ENTITY_EXPANSION.to_string()));
    // The rest of the document is read.
    assert!(codes(&report).contains(&"NODE_UNKNOWN"), "{report:?}");
}

#[test]
fn recursive_entities_are_refused() {
    let source = format!(
        "<!DOCTYPE X3D [<!ENTITY a 'x&b;'><!ENTITY b '&a;'>]>\n{}",
        scene("<WorldInfo title='&a;'/>")
    );
    let limits = limits_of(&check(source));
    assert_eq!(limits.len(), 1);
    assert!(limits[0].1.contains("recursive"), "{limits:?}");
}

#[test]
fn internal_entities_expand_and_external_ones_are_never_read() {
    let source = format!(
        "<?xml version='1.0'?>\n<!DOCTYPE X3D PUBLIC 'ISO//Web3D//DTD X3D 4.0//EN' \
         'http://127.0.0.1:9/x3d-4.0.dtd' [<!ENTITY v '0 1 0'><!ENTITY v 'ignored'>]>\n{}",
        scene("<Shape><PointSet><Coordinate point='&v; &v; &amp;#48; 0 0'/></PointSet></Shape>")
    );
    // `&amp;#48;` is the text `&#48;`: a syntax error in an MFVec3f, found at its place.
    let parsed = x3dcheck::parse::xml::read(source.as_bytes());
    let doc = parsed.document.expect("a document");
    let coordinate = doc
        .iter()
        .find(|(_, n)| n.type_name() == "Coordinate")
        .unwrap();
    let point = &coordinate.1.fields[0].value;
    assert!(
        matches!(point, x3dcheck::model::Value::Unparsed(text) if text == "0 1 0 0 1 0 &#48; 0 0")
    );
    let fine = source.replace(" &amp;#48; 0 0", "");
    let doc = x3dcheck::parse::xml::read(fine.as_bytes())
        .document
        .unwrap();
    let coordinate = doc
        .iter()
        .find(|(_, n)| n.type_name() == "Coordinate")
        .unwrap();
    assert_eq!(
        coordinate.1.fields[0].value.as_floats(),
        Some(&[0., 1., 0., 0., 1., 0.][..])
    );

    let external = format!(
        "<!DOCTYPE X3D [<!ENTITY secret SYSTEM 'file:///etc/passwd'>]>\n{}",
        scene("<WorldInfo title='&secret;'/>")
    );
    let report = check(external);
    assert_eq!(codes(&report), ["XML_MALFORMED"]);
    assert!(report.diagnostics[0]
        .message
        .contains("unknown entity `&secret;`"));
    assert_eq!(
        (report.diagnostics[0].line, report.diagnostics[0].column),
        (3, 19)
    );
}

#[test]
fn billion_laughs_through_def_and_use_is_checked_quickly() {
    // 60 levels of ten USEs of the level below: 10^60 node instances.
    let mut body = String::from("<Group DEF='L0'><Shape><Box/></Shape></Group>\n");
    for level in 1..60 {
        let uses = format!("<Group USE='L{}'/>", level - 1).repeat(10);
        body.push_str(&format!("<Group DEF='L{level}'>{uses}</Group>\n"));
    }
    let report = check(scene(&body));
    assert!(!codes(&report).contains(&"LIMIT_EXCEEDED"), "{report:?}");
    assert_eq!(report.stats.nodes, 62);
}

#[test]
fn nesting_a_hundred_thousand_levels_deep_does_not_overflow_the_stack() {
    let levels = 100_000;
    let xml = scene(&format!(
        "{}{}",
        "<Group>".repeat(levels),
        "</Group>".repeat(levels)
    ));
    let report = check(xml);
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1);
    assert!(limits[0].1.contains(&format!("deeper than {MAX_DEPTH}")));

    let node = r#"{"Group":{"-children":["#;
    let json = format!(
        r#"{{"X3D":{{"@version":"4.0","Scene":{{"-children":[{}{}]}}}}}}"#,
        node.repeat(levels),
        "]}}".repeat(levels)
    );
    let report = check(json);
    assert_eq!(codes(&report), ["JSON_MALFORMED"], "{report:?}");
    assert!(report.diagnostics[0].message.contains("nested too deeply"));
}

#[test]
fn more_nodes_than_the_limit_are_not_read() {
    let report = check(scene(&"<Group/>".repeat(MAX_NODES + 5)));
    assert_eq!(report.stats.nodes, MAX_NODES);
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1);
    assert!(limits[0]
        .1
        .contains(&format!("more than {MAX_NODES} nodes")));
}

#[test]
fn more_fields_than_the_limit_are_not_read() {
    let attributes: String = (0..MAX_FIELDS_PER_NODE + 10)
        .map(|i| format!(" a{i}=''"))
        .collect();
    let report = check(scene(&format!("<Group{attributes}/>")));
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1, "{limits:?}");
    assert!(limits[0]
        .1
        .contains(&format!("more than {MAX_FIELDS_PER_NODE} attributes")));
    let unknown = codes(&report)
        .iter()
        .filter(|c| **c == "FIELD_UNKNOWN")
        .count();
    assert_eq!(unknown, MAX_FIELDS_PER_NODE);

    let members: Vec<String> = (0..MAX_FIELDS_PER_NODE + 10)
        .map(|i| format!(r#""@a{i}":"""#))
        .collect();
    let json = format!(
        r#"{{"X3D":{{"@version":"4.0","Scene":{{"-children":[{{"Group":{{{}}}}}]}}}}}}"#,
        members.join(",")
    );
    let limits = limits_of(&check(json));
    assert_eq!(limits.len(), 1, "{limits:?}");
    assert!(limits[0]
        .1
        .contains(&format!("more than {MAX_FIELDS_PER_NODE} fields")));
}

#[test]
fn a_field_of_more_values_than_the_limit_is_not_read() {
    let values = "0 ".repeat(MAX_FIELD_VALUES + 1);
    let report = check(scene(&format!(
        "<Shape><IndexedFaceSet coordIndex='{values}'><Coordinate/></IndexedFaceSet></Shape>"
    )));
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1, "{limits:?}");
    assert_eq!(limits[0].0, 2);
    assert!(limits[0]
        .1
        .contains(&format!("more than {MAX_FIELD_VALUES}")));
}

#[test]
fn findings_stop_at_the_limit() {
    let report = check(scene(&"<Foo/>".repeat(3 * MAX_DIAGNOSTICS)));
    assert!(report.diagnostics.len() <= MAX_DIAGNOSTICS + 2);
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1, "{limits:?}");
    assert!(limits[0]
        .1
        .contains(&format!("more than {MAX_DIAGNOSTICS} findings")));
}

#[test]
fn huge_claimed_counts_cost_nothing() {
    let big = i32::MAX;
    let report = check(scene(&format!(
        "<Shape><Appearance><PixelTexture image='{big} {big} 4 0'/></Appearance>\
         <ElevationGrid xDimension='{big}' zDimension='{big}' height='0 0 0 0'/></Shape>\
         <Shape><IndexedFaceSet coordIndex='{big} 0 1 -1 0 {big} 1' texCoordIndex='{big} 1 2'>\
         <Coordinate point='0 0 0 1 0 0 0 1 0'/><TextureCoordinate point='0 0'/></IndexedFaceSet></Shape>\
         <Shape><IndexedTriangleStripSet index='{big} 1 2 3 -1'><Coordinate point='0 0 0'/></IndexedTriangleStripSet></Shape>\
         <Shape><LineSet vertexCount='{big} 2'><Coordinate point='0 0 0 1 1 1'/></LineSet></Shape>\
         <Shape><TriangleFanSet fanCount='{big}'><Coordinate point='0 0 0'/></TriangleFanSet></Shape>"
    )));
    assert!(!report.diagnostics.is_empty());
}

/// A PNG whose header claims `width`×`height` pixels, with one byte of image data.
fn png_claiming(width: u32, height: u32) -> Vec<u8> {
    fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
        out.extend((data.len() as u32).to_be_bytes());
        let start = out.len();
        out.extend(kind);
        out.extend(data);
        let crc = crc32(&out[start..]);
        out.extend(crc.to_be_bytes());
    }
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut header = Vec::new();
    header.extend(width.to_be_bytes());
    header.extend(height.to_be_bytes());
    header.extend([8, 6, 0, 0, 0]); // 8-bit RGBA
    chunk(&mut png, b"IHDR", &header);
    chunk(&mut png, b"IDAT", b"\x78\x9c\x03\x00\x00\x00\x00\x01");
    chunk(&mut png, b"IEND", b"");
    png
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &byte in bytes {
        crc ^= byte as u32;
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// A GIF whose screen and one frame claim 65535×65535 pixels.
fn gif_bomb() -> Vec<u8> {
    let mut gif = b"GIF89a\xff\xff\xff\xff\x00\x00\x00".to_vec();
    gif.extend(b",\x00\x00\x00\x00\xff\xff\xff\xff\x00\x02\x02D\x01\x00;");
    gif
}

#[test]
fn image_bombs_are_refused_before_decoding() {
    let dir = scratch("image-bombs", &[]);
    fs::write(dir.join("bomb.png"), png_claiming(100_000, 100_000)).unwrap();
    fs::write(dir.join("wide.png"), png_claiming(MAX_IMAGE_SIDE + 1, 1)).unwrap();
    fs::write(dir.join("bomb.gif"), gif_bomb()).unwrap();
    let source = scene(
        "<Shape><Appearance><ImageTexture url='\"bomb.png\"'/></Appearance><Box/></Shape>\n\
         <Background frontUrl='\"bomb.gif\"' backUrl='\"wide.png\"'/>",
    );
    let path = dir.join("scene.x3d");
    let report = check_at(path.to_str().unwrap(), source);
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 3, "{report:?}");
    assert_eq!((limits[0].0, limits[1].0, limits[2].0), (2, 3, 3));
    assert!(limits[0].1.contains("(100000×100000)"), "{limits:?}");
    assert!(!codes(&report).contains(&"IMAGE_UNREADABLE"));
}

#[cfg(feature = "render")]
#[test]
fn image_bombs_are_not_drawn() {
    if !x3dcheck::render::adapter_for_test("image_bombs_are_not_drawn") {
        return;
    }
    use x3dcheck::render::{render_image, ImageSize, Quality, RenderArgs};
    let dir = scratch("render-bomb", &[]);
    fs::write(dir.join("bomb.png"), png_claiming(100_000, 100_000)).unwrap();
    let path = dir.join("scene.x3d");
    let source =
        scene("<Shape><Appearance><ImageTexture url='\"bomb.png\"'/></Appearance><Box/></Shape>");
    let x3dcheck::check::Checked {
        mut report,
        document: doc,
        ..
    } = x3dcheck::check::check_document(
        path.to_str().unwrap(),
        source.as_bytes(),
        &CheckConfig::default(),
    );
    let args = RenderArgs {
        render: None,
        size: ImageSize {
            width: 32,
            height: 24,
        },
        quality: Quality::Fast,
        camera: "auto".to_string(),
        island: 1,
    };
    let started = Instant::now();
    render_image(
        &args,
        &path,
        None,
        source.as_bytes(),
        doc.as_ref(),
        &mut report,
    )
    .unwrap();
    assert!(started.elapsed() < QUICK);
    let limits = limits_of(&report);
    assert_eq!(limits.len(), 1, "{report:?}");
    assert!(limits[0].1.contains("100000×100000"), "{limits:?}");
}

#[test]
fn urls_leaving_the_tree_are_not_read() {
    let outer = scratch("outside", &[]);
    let tree = outer.join("tree");
    fs::create_dir_all(&tree).unwrap();
    // Were any of these read, the bomb would be reported as LIMIT_EXCEEDED.
    fs::write(outer.join("secret.png"), png_claiming(100_000, 100_000)).unwrap();
    fs::write(outer.join("secret.x3d"), scene("<Foo/>")).unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(outer.join("secret.png"), tree.join("link.png")).unwrap();
    let absolute = outer.join("secret.png").display().to_string();
    let source = scene(&format!(
        "<Shape><Appearance><ImageTexture url='\"../secret.png\" \"tree/../../secret.png\" \
         \"{absolute}\" \"file://{absolute}\" \"file:///etc/passwd\" \"link.png\" \"..%2Fsecret.png\"'/>\
         </Appearance><Box/></Shape>\n<Inline url='\"../secret.x3d\" \"/etc/passwd\"'/>"
    ));
    let report = check_at(tree.join("scene.x3d").to_str().unwrap(), source);
    assert!(limits_of(&report).is_empty(), "{report:?}");
    let messages: Vec<&str> = report
        .diagnostics
        .iter()
        .map(|d| d.message.as_str())
        .collect();
    let outside = |field: &str| {
        messages
            .iter()
            .any(|m| m.starts_with(field) && m.contains("outside the directory tree"))
    };
    assert!(
        outside("ImageTexture.url") && outside("Inline.url"),
        "{messages:#?}"
    );
    assert!(
        !codes(&report).contains(&"IMAGE_UNREADABLE"),
        "{messages:#?}"
    );
}

/// `--render` reads Inlines from the tree the check reads from: for a file named on the
/// command line, the current directory when the file lies in it (`cli/discover.rs`), so a
/// scene's `../models/` Inline is drawn from the directory above and refused from its own.
#[cfg(feature = "render")]
#[test]
fn render_reads_inlines_from_the_tree_being_checked() {
    let dir = scratch(
        "render-tree",
        &[
            (
                "scenes/s.x3d",
                &scene("<Inline url='\"../models/box.x3d\"'/>"),
            ),
            ("models/box.x3d", &scene("<Shape><Box/></Shape>")),
        ],
    );
    let inline_notes = |cwd: &Path, file: &str| -> Vec<String> {
        let output = x3dcheck(
            cwd,
            &[
                file,
                "--render",
                "out.png",
                "--size",
                "32x24",
                "--format",
                "json",
                "--exit-zero",
            ],
        );
        let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
        report["files"][0]["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|d| d["message"].as_str())
            .filter(|m| m.contains("Inline not drawn"))
            .map(str::to_string)
            .collect()
    };
    assert_eq!(inline_notes(&dir, "scenes/s.x3d"), Vec::<String>::new());
    let refused = inline_notes(&dir.join("scenes"), "s.x3d");
    assert!(
        refused.len() == 1 && refused[0].contains("is outside"),
        "{refused:?}"
    );
}

#[test]
fn network_urls_get_no_connection() {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    listener.set_nonblocking(true).unwrap();
    let port = listener.local_addr().unwrap().port();
    let dir = scratch("network", &[]);
    let url = |path: &str| format!("http://127.0.0.1:{port}/{path}");
    let source = scene(&format!(
        "<Shape><Appearance><ImageTexture url='\"{}\"'/></Appearance><Box/></Shape>\n\
         <Inline url='\"{}\"'/><Script url='\"{}\"'/><AudioClip url='\"{}\"'/>\n\
         <ExternProtoDeclare name='P' url='\"{}\"'/>",
        url("t.png"),
        url("i.x3d"),
        url("s.js"),
        url("a.wav"),
        url("p.x3d#P")
    ));
    let path = dir.join("scene.x3d");
    fs::write(&path, &source).unwrap();
    let report = check_at(path.to_str().unwrap(), source);
    // Each network url is said not to be fetched (a Script's by its url field and by the
    // note on its code).
    for path in ["t.png", "i.x3d", "s.js", "a.wav", "p.x3d#P"] {
        let said = report
            .diagnostics
            .iter()
            .any(|d| d.message.contains("is not fetched") && d.message.contains(&url(path)));
        assert!(said, "{path}: {report:?}");
    }
    let mut args = vec!["--level", "deep", "scene.x3d"];
    if cfg!(feature = "render") {
        args.extend(["--render", "out.png", "--size", "32x24"]);
    }
    let output = x3dcheck(&dir, &args);
    assert!(output.status.code().is_some_and(|c| c < 2), "{output:?}");
    match listener.accept() {
        Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => {}
        other => panic!("x3dcheck connected to the listener: {other:?}"),
    }
}

/// Every file under `dir` with its bytes and modification time.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>, SystemTime)> {
    let mut files: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .flatten()
        .filter(|e| e.file_type().unwrap().is_file())
        .map(|e| {
            let meta = e.metadata().unwrap();
            let name = e.file_name().to_string_lossy().into_owned();
            (name, fs::read(e.path()).unwrap(), meta.modified().unwrap())
        })
        .collect();
    files.sort();
    files
}

#[test]
fn input_files_are_never_written() {
    let texture = png_claiming(1, 1);
    let dir = scratch(
        "read-only",
        &[
            ("scene.x3d", &scene("<Shape><Appearance><ImageTexture url='\"t.png\"'/></Appearance><Box/></Shape><Inline url='\"other.x3d\"'/>")),
            ("other.x3d", &scene("<Foo/>")),
            ("scene.json", r#"{"X3D":{"@version":"4.0","Scene":{"-children":[{"Foo":{}}]}}}"#),
        ],
    );
    fs::write(dir.join("t.png"), &texture).unwrap();
    let inputs = dir.join("in");
    fs::create_dir_all(&inputs).unwrap();
    for name in ["scene.x3d", "other.x3d", "scene.json", "t.png"] {
        fs::rename(dir.join(name), inputs.join(name)).unwrap();
    }
    let before = snapshot(&inputs);
    std::thread::sleep(Duration::from_millis(20));
    for format in ["json", "sarif", "junit", "human"] {
        let output = x3dcheck(
            &dir,
            &["--level", "deep", "--format", format, "-o", "report", "in"],
        );
        assert_eq!(output.status.code(), Some(1), "{output:?}");
    }
    if cfg!(feature = "render") {
        let output = x3dcheck(
            &dir,
            &["--render", "out.png", "--size", "32x24", "in/scene.x3d"],
        );
        assert!(output.status.code().is_some_and(|c| c < 2), "{output:?}");
    }
    assert_eq!(snapshot(&inputs), before);

    // An output that is an input, by any name, is refused before anything is written.
    let mut refused = vec![
        vec!["-o", "in/scene.x3d", "in"],
        vec!["-o", "in/../in/other.x3d", "in/other.x3d"],
        vec!["--output", "in/scene.json", "in/scene.json", "in/scene.x3d"],
    ];
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink("in/scene.x3d", dir.join("link.x3d")).unwrap();
        fs::hard_link(inputs.join("scene.json"), dir.join("hard.json")).unwrap();
        refused.push(vec!["-o", "link.x3d", "in/scene.x3d"]);
        refused.push(vec!["-o", "hard.json", "in/scene.json"]);
    }
    if cfg!(feature = "render") {
        refused.push(vec!["--render", "in/scene.x3d", "in/scene.x3d"]);
    }
    for args in refused {
        let output = x3dcheck(&dir, &args);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {output:?}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains("is an input file"), "{args:?}: {stderr}");
        assert!(output.stdout.is_empty());
    }
    assert_eq!(snapshot(&inputs), before);
}

/// The codes and lines of a report's findings.
fn found(report: &FileReport) -> Vec<(&'static str, usize)> {
    report
        .diagnostics
        .iter()
        .map(|d| (d.code, d.line))
        .collect()
}

#[test]
fn characters_outside_xml_are_malformed_wherever_they_are() {
    for (place, text) in [
        ("character data", "<Script><![CDATA[a\u{0}b]]></Script>"),
        ("a comment", "<!-- a\u{0}b -->"),
        ("an element name", "<Gro\u{0}up/>"),
        ("an attribute value", "<WorldInfo title='a\u{1}b'/>"),
        ("a noncharacter", "<WorldInfo title='a\u{FFFE}b'/>"),
    ] {
        let report = check(scene(text));
        assert_eq!(codes(&report), ["XML_MALFORMED"], "{place}: {report:?}");
        assert_eq!(report.diagnostics[0].line, 2, "{place}");
        assert!(report.diagnostics[0].message.contains("XML 1.0 2.2 Char"));
    }
    // Tabs, line feeds and carriage returns are characters.
    assert!(check(scene("<WorldInfo title='a\tb\r\nc'/>"))
        .diagnostics
        .is_empty());
}

#[test]
fn an_entity_holding_a_less_than_sign_is_refused_in_attribute_values() {
    for entity in ["a<b", "&#60;", "&#x3C;", "&inner;"] {
        let source = format!(
            "<!DOCTYPE X3D [<!ENTITY inner 'x<y'><!ENTITY e '{entity}'>]>\n{}",
            scene("<WorldInfo title='&e;'/>")
        );
        let report = check(source);
        assert_eq!(codes(&report), ["XML_MALFORMED"], "{entity}: {report:?}");
        assert!(report.diagnostics[0]
            .message
            .contains("No < in Attribute Values"));
    }
    // `&#38;#60;` stands for the text `&#60;`: a character reference, which is fine.
    let source = format!(
        "<!DOCTYPE X3D [<!ENTITY e '&#38;#60;'>]>\n{}",
        scene("<WorldInfo title='&e;'/>")
    );
    assert!(check(source).diagnostics.is_empty());
}

#[test]
fn a_repeated_top_level_x3d_is_reported() {
    let json = r#"{"X3D": {"@version": "4.0", "@profile": "Full", "Scene": {}},
"X3D": {"@version": "4.0", "@profile": "Full", "Scene": {}}}"#;
    assert_eq!(found(&check(json)), [("FIELD_DUPLICATE", 2)]);
}

#[test]
fn content_beside_head_and_scene_is_reported() {
    let xml = "<X3D profile='Full' version='4.0'>\n<Transform><Shape><Box/></Shape></Transform>\n\
               <Bogus/><head/><Scene/>\n<ds:Signature xmlns:ds='http://www.w3.org/2000/09/xmldsig#'/></X3D>";
    let report = check(xml);
    assert_eq!(
        found(&report),
        [("ROOT_CONTENT_IGNORED", 2), ("ROOT_CONTENT_IGNORED", 3)]
    );
    assert_eq!(
        report.diagnostics[0].help.as_deref(),
        Some("nodes belong in the Scene")
    );
    let json = r##"{"X3D": {"@version": "4.0", "@profile": "Full", "encoding": "UTF-8",
"-children": [{"#comment": "fine"}, {"Transform": {}}],
"Scene": {}, "Bogus": 1}}"##;
    assert_eq!(
        found(&check(json)),
        [("ROOT_CONTENT_IGNORED", 2), ("ROOT_CONTENT_IGNORED", 3)]
    );
}

#[test]
fn head_content_and_statement_attributes_are_checked() {
    let xml = "<X3D profile='Full' version='4.0'><head>\n<metta name='a' content='b'/>\n\
               <meta name='a' contnet='b' xmlns:x='urn:x'/>\n<unit category='length' name='m' conversionFactor='1' id='u'/>\n\
               </head><Scene/></X3D>";
    let report = check(xml);
    assert_eq!(
        found(&report),
        [("ROOT_CONTENT_IGNORED", 2), ("FIELD_UNKNOWN", 3)]
    );
    assert_eq!(
        report.diagnostics[0].help.as_deref(),
        Some("did you mean `meta`?")
    );
    assert_eq!(
        report.diagnostics[1].help.as_deref(),
        Some("did you mean `content`?")
    );
    let json = r#"{"X3D": {"@version": "4.0", "@profile": "Full", "head": {
"metta": [{}], "meta": [{"@name": "a", "@contnet": "b"}]}, "Scene": {}}}"#;
    assert_eq!(
        found(&check(json)),
        [("ROOT_CONTENT_IGNORED", 2), ("FIELD_UNKNOWN", 2)]
    );
    // As many attributes as a node may have, then LIMIT_EXCEEDED, in both encodings.
    let members: Vec<String> = (0..MAX_FIELDS_PER_NODE + 10)
        .map(|i| format!(r#""@a{i}": "x""#))
        .collect();
    let json = format!(
        r#"{{"X3D": {{"@version": "4.0", "@profile": "Full", "head": {{"meta": [{{{}}}]}}, "Scene": {{}}}}}}"#,
        members.join(", ")
    );
    let report = check(json);
    assert_eq!(limits_of(&report).len(), 1, "{:?}", limits_of(&report));
    let unknown = codes(&report)
        .iter()
        .filter(|&&c| c == "FIELD_UNKNOWN")
        .count();
    assert_eq!(unknown, MAX_FIELDS_PER_NODE);
}

#[test]
fn elevation_grid_heights_must_fill_the_grid() {
    let grid = |x: &str, z: &str, heights: &str| {
        scene(&format!(
            "<Shape><ElevationGrid xDimension='{x}' zDimension='{z}' height='{heights}'/></Shape>"
        ))
    };
    let report = check(grid("3", "3", "1"));
    assert_eq!(codes(&report), ["HEIGHT_COUNT_MISMATCH"], "{report:?}");
    let report = check(grid("2147483647", "2147483647", "1"));
    assert_eq!(codes(&report), ["HEIGHT_COUNT_MISMATCH"]);
    assert!(report.diagnostics[0]
        .message
        .contains("2147483647 × 2147483647 = 4611686014132420609"));
    assert_eq!(
        codes(&check(grid("2", "3", "0 0 0 0 0 0 0"))),
        ["HEIGHT_COUNT_MISMATCH"]
    );
    assert!(check(grid("2", "3", "0 0 0 0 0 0")).diagnostics.is_empty());
}

#[test]
fn render_keeps_the_findings_of_a_file_it_cannot_draw() {
    let dir = scratch(
        "render-unreadable",
        &[
            ("broken.x3d", "<X3D><Scene><Shape></Scene></X3D>"),
            ("broken.x3dj", "{\"X3D\": {"),
            ("vrml.x3d", "#VRML V1.0 ascii\n"),
        ],
    );
    for (file, code) in [
        ("broken.x3d", "XML_MALFORMED"),
        ("broken.x3dj", "JSON_MALFORMED"),
        ("vrml.x3d", "ENCODING_UNSUPPORTED"),
    ] {
        let output = x3dcheck(&dir, &[file, "--render", "out.png", "--format", "json"]);
        let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
        let files = report["files"].as_array().unwrap();
        assert_eq!(files.len(), 1, "{file}: {report}");
        assert_eq!(files[0]["diagnostics"][0]["code"], code, "{file}");
        assert_eq!(output.status.code(), Some(2), "{file}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains("no scene to render"), "{file}: {stderr}");
        assert!(!dir.join("out.png").exists());
    }
}

/// Runs x3dcheck in `dir` (through `sh -c` when `shell` is given, with `$0` the binary),
/// killing it after [`QUICK`]: a hang fails the test instead of stalling it.
#[cfg(unix)]
fn x3dcheck_within(dir: &Path, args: &[&str], shell: Option<&str>) -> std::process::Output {
    use std::process::{Command, Stdio};
    let binary = env!("CARGO_BIN_EXE_x3dcheck");
    let mut command = match shell {
        Some(script) => {
            let mut c = Command::new("sh");
            c.arg("-c").arg(script).arg(binary);
            c
        }
        None => Command::new(binary),
    };
    let mut child = command
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if started.elapsed() > QUICK {
            child.kill().unwrap();
            panic!("x3dcheck {args:?} did not finish within {QUICK:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[cfg(unix)]
fn stderr_of(output: &std::process::Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let status = std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .unwrap();
    assert!(status.success());
}

#[test]
#[cfg(unix)]
fn special_files_named_directly_are_refused_without_reading() {
    let dir = scratch("special-named", &[]);
    mkfifo(&dir.join("pipe.x3d"));
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.x3d")).unwrap();
    for (name, kind) in [
        ("pipe.x3d", "a FIFO (named pipe)"),
        ("zero.x3d", "a character device"),
        ("/dev/zero", "a character device"),
    ] {
        let output = x3dcheck_within(&dir, &[name], None);
        assert_eq!(output.status.code(), Some(2), "{name}");
        let stderr = stderr_of(&output);
        assert!(
            stderr.contains(&format!("it is {kind}, not a regular file")),
            "{stderr}"
        );
    }
}

#[test]
#[cfg(unix)]
fn a_walk_reports_every_entry_it_cannot_read() {
    let scene = "<X3D profile='Interchange' version='4.0'><Scene/></X3D>";
    let dir = scratch("special-walk", &[("t/good.x3d", scene)]);
    let tree = dir.join("t");
    mkfifo(&tree.join("pipe.x3d"));
    let _socket = std::os::unix::net::UnixListener::bind(tree.join("socket.x3d")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", tree.join("zero.x3d")).unwrap();
    std::os::unix::fs::symlink("missing.x3d", tree.join("dangling.x3d")).unwrap();
    std::os::unix::fs::symlink("loop.x3d", tree.join("loop.x3d")).unwrap();
    let output = x3dcheck_within(&dir, &["--format", "json", "t"], None);
    assert_eq!(output.status.code(), Some(2));
    let stderr = stderr_of(&output);
    for expected in [
        "t/pipe.x3d: it is a FIFO (named pipe), not a regular file",
        "t/socket.x3d: it is a socket, not a regular file",
        // A link to a device is a link out of the tree.
        "not checked: t/zero.x3d is a symbolic link to /dev/zero",
        "t/dangling.x3d: a symbolic link that leads nowhere readable",
        "t/loop.x3d: a symbolic link that leads nowhere readable",
    ] {
        assert!(stderr.contains(expected), "no `{expected}` in:\n{stderr}");
    }
    // The readable file is still checked and reported.
    let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(report["files"][0]["path"], "t/good.x3d");
}

#[test]
#[cfg(unix)]
fn a_walk_does_not_follow_a_file_link_out_of_the_tree() {
    let scene = "<X3D profile='Interchange' version='4.0'><Scene/></X3D>";
    let dir = scratch("link-out", &[("t/in.x3d", scene), ("outside/x.x3d", scene)]);
    std::os::unix::fs::symlink("../outside/x.x3d", dir.join("t/out.x3d")).unwrap();
    std::os::unix::fs::symlink("in.x3d", dir.join("t/same.x3d")).unwrap();
    let output = x3dcheck_within(&dir, &["--format", "json", "t"], None);
    assert_eq!(output.status.code(), Some(2));
    let stderr = stderr_of(&output);
    assert!(
        stderr.contains("not checked: t/out.x3d is a symbolic link to"),
        "{stderr}"
    );
    let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    // The link inside the tree leads to a file already taken.
    assert_eq!(report["summary"]["files"], 1);
    // Named on the command line, the link is checked.
    let named = x3dcheck_within(&dir, &["t/out.x3d"], None);
    assert_eq!(named.status.code(), Some(0), "{}", stderr_of(&named));
}

#[test]
#[cfg(unix)]
fn a_closed_stdout_is_an_error() {
    let dir = scratch(
        "closed-stdout",
        &[(
            "a.x3d",
            "<X3D profile='Interchange' version='4.0'><Scene/></X3D>",
        )],
    );
    for format in ["human", "json"] {
        let script = format!("exec \"$0\" --format {format} a.x3d >&-");
        let output = x3dcheck_within(&dir, &[], Some(&script));
        assert_eq!(output.status.code(), Some(2), "{format}");
        assert!(stderr_of(&output).contains("standard output is closed"));
    }
}
