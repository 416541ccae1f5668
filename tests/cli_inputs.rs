//! What the command line reads: character encodings (positions are those of the decoded
//! text), gzip-compressed input, and which files a directory walk finds.

mod common;

use std::io::Write;
use std::path::Path;
use std::process::Output;

use common::{scratch, stdout, x3dcheck};

/// A scene with a non-ASCII character and, after it on the same line, an unknown node.
const SCENE: &str = "<?xml version=\"1.0\" encoding=\"ENCODING\"?>\n\
<X3D profile=\"Interchange\" version=\"4.0\">\n\
  <Scene>\n\
    <WorldInfo title=\"Café\"/><Bogus/>\n\
  </Scene>\n\
</X3D>\n";

fn scene(encoding: &str) -> String {
    SCENE.replace("ENCODING", encoding)
}

fn write(dir: &Path, name: &str, bytes: &[u8]) {
    let path = dir.join(name);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, bytes).unwrap();
}

fn utf16(text: &str, big_endian: bool, bom: bool) -> Vec<u8> {
    let mut bytes = Vec::new();
    let units = bom.then_some(0xFEFF).into_iter().chain(text.encode_utf16());
    for unit in units {
        bytes.extend(if big_endian {
            unit.to_be_bytes()
        } else {
            unit.to_le_bytes()
        });
    }
    bytes
}

fn json(output: &Output) -> serde_json::Value {
    serde_json::from_str(&stdout(output)).unwrap()
}

/// (code, line, column) of each finding of the only file of a JSON report.
fn findings(output: &Output) -> Vec<(String, u64, u64)> {
    let report = json(output);
    report["files"][0]["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            (
                d["code"].as_str().unwrap().to_string(),
                d["line"].as_u64().unwrap(),
                d["column"].as_u64().unwrap(),
            )
        })
        .collect()
}

#[test]
fn every_character_encoding_reports_the_columns_an_editor_shows() {
    let dir = scratch("encodings", &[]);
    let utf8 = scene("UTF-8");
    let latin1: Vec<u8> = scene("ISO-8859-1").chars().map(|c| c as u8).collect();
    let mut bom = b"\xEF\xBB\xBF".to_vec();
    bom.extend(utf8.as_bytes());
    let files: Vec<(&str, Vec<u8>)> = vec![
        ("utf8.x3d", utf8.clone().into_bytes()),
        ("bom.x3d", bom),
        ("latin1.x3d", latin1),
        ("utf16le.x3d", utf16(&scene("UTF-16"), false, true)),
        ("utf16be.x3d", utf16(&scene("UTF-16"), true, true)),
        ("utf16le-no-bom.x3d", utf16(&scene("UTF-16"), false, false)),
    ];
    for (name, bytes) in &files {
        write(&dir, name, bytes);
    }
    for (name, _) in &files {
        let output = x3dcheck(&dir, &["--format", "json", name]);
        // The unknown node after "Café" on line 4: column 27 counts é as one character.
        let expected = vec![("NODE_UNKNOWN".to_string(), 4, 27)];
        assert_eq!(findings(&output), expected, "{name}");
        let human = x3dcheck(&dir, &["--no-color", name]);
        assert!(
            stdout(&human).contains("<WorldInfo title=\"Café\"/><Bogus/>"),
            "{name}: the source line shown is the decoded one:\n{}",
            stdout(&human)
        );
    }
}

#[test]
fn undeclared_non_utf8_says_what_to_do() {
    let dir = scratch("undeclared", &[]);
    let text = scene("UTF-8").replace("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", "");
    let latin1: Vec<u8> = text.chars().map(|c| c as u8).collect();
    write(&dir, "latin1.x3d", &latin1);
    let output = x3dcheck(&dir, &["--format", "json", "latin1.x3d"]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(
        findings(&output),
        vec![("XML_MALFORMED".to_string(), 3, 22)]
    );
    let report = json(&output);
    let help = report["files"][0]["diagnostics"][0]["help"]
        .as_str()
        .unwrap();
    assert!(help.contains("encoding=\"ISO-8859-1\""), "{help}");
}

#[test]
fn an_encoding_outside_the_whatwg_set_is_unsupported() {
    let dir = scratch("ebcdic", &[("e.x3d", &scene("EBCDIC-US"))]);
    let output = x3dcheck(&dir, &["--format", "json", "e.x3d"]);
    assert_eq!(output.status.code(), Some(1));
    // At the name in the declaration.
    let expected = vec![("XML_ENCODING_UNSUPPORTED".to_string(), 1, 31)];
    assert_eq!(findings(&output), expected);
}

#[test]
fn json_with_a_byte_order_mark_is_read() {
    let dir = scratch("json-bom", &[]);
    let text = "\u{FEFF}{\"X3D\": {\"@version\": \"4.0\", \"@profile\": \"Interchange\",\n\
                \"Scene\": {\"-children\": [{\"Bogus\": {}}]}}}\n";
    write(&dir, "bom.x3dj", text.as_bytes());
    let output = x3dcheck(&dir, &["--format", "json", "bom.x3dj"]);
    assert_eq!(findings(&output)[0].0, "NODE_UNKNOWN");
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut encoder = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    encoder.write_all(bytes).unwrap();
    encoder.finish().unwrap()
}

#[test]
fn a_gzip_file_reports_as_what_it_holds() {
    let dir = scratch("gzip", &[]);
    let text = scene("UTF-8");
    write(&dir, "plain.x3d", text.as_bytes());
    write(&dir, "packed.x3dz", &gzip(text.as_bytes()));
    let plain = json(&x3dcheck(&dir, &["--format", "json", "plain.x3d"]));
    let output = x3dcheck(&dir, &["--format", "json", "packed.x3dz"]);
    assert_eq!(output.status.code(), Some(1));
    let mut packed = json(&output);
    let file = &mut packed["files"][0];
    assert_eq!(file["compressed"], true);
    assert!(plain["files"][0].get("compressed").is_none());
    file.as_object_mut().unwrap().remove("compressed");
    file["path"] = "plain.x3d".into();
    assert_eq!(packed, plain);
    // The human report shows the decompressed line.
    let human = stdout(&x3dcheck(&dir, &["--no-color", "packed.x3dz"]));
    assert!(human.contains("<Bogus/>"), "{human}");
}

#[test]
fn a_damaged_gzip_file_is_gzip_corrupt() {
    let dir = scratch("gzip-cut", &[]);
    let packed = gzip(scene("UTF-8").as_bytes());
    write(&dir, "cut.x3d.gz", &packed[..packed.len() - 12]);
    let mut flipped = packed.clone();
    let n = flipped.len();
    flipped[n - 6] ^= 0xFF; // the CRC-32
    write(&dir, "crc.x3dz", &flipped);
    for name in ["cut.x3d.gz", "crc.x3dz"] {
        let output = x3dcheck(&dir, &["--format", "json", name]);
        assert_eq!(output.status.code(), Some(1), "{name}");
        assert_eq!(findings(&output), vec![("GZIP_CORRUPT".to_string(), 1, 1)]);
    }
}

#[test]
fn a_gzip_bomb_stops_at_the_limit_while_inflating() {
    // 64 MiB of zeros in 64 kB; with a 1 MiB limit, inflating stops past 1 MiB.
    let packed = gzip(&vec![0; 64 << 20]);
    let started = std::time::Instant::now();
    let decoded = x3dcheck::parse::decode::decode_within(&packed, 1 << 20, &());
    assert!(started.elapsed() < std::time::Duration::from_secs(1));
    let failure = decoded.failure.expect("refused");
    assert_eq!(failure.rule.code, "LIMIT_EXCEEDED");
    assert!(decoded.compressed);
    assert!(decoded.text.is_empty());
}

/// The files `--show-files` lists in `dir` for `args`.
fn shown(dir: &Path, args: &[&str]) -> Vec<String> {
    let mut all = vec!["--show-files"];
    all.extend(args);
    let output = x3dcheck(dir, &all);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    stdout(&output).lines().map(str::to_string).collect()
}

const X3D_JSON: &str =
    "{\"X3D\": {\"@version\": \"4.0\", \"@profile\": \"Interchange\", \"Scene\": {}}}";

#[test]
fn discovery_finds_every_scene_kind_and_honours_ignores() {
    let x3d = "<X3D profile='Interchange' version='4.0'><Scene/></X3D>";
    let dir = scratch(
        "discovery",
        &[
            ("t/a.x3d", x3d),
            ("t/b.x3dv", "#X3D V4.0 utf8\n"),
            ("t/c.x3dj", X3D_JSON),
            ("t/d.wrl", "#VRML V2.0 utf8\n"),
            ("t/e.X3DZ", x3d),
            ("t/f.x3dvz", x3d),
            ("t/g.x3djz", x3d),
            ("t/h.wrz", x3d),
            ("t/i.x3d.gz", x3d),
            ("t/j.wrl.gz", x3d),
            ("t/scene.json", X3D_JSON),
            (
                "t/package.json",
                "{\"name\": \"x3d\", \"version\": \"1.0.0\"}",
            ),
            ("t/notes.txt", "x3d"),
            ("t/.hidden/k.x3d", x3d),
            ("t/node_modules/l.x3d", x3d),
            ("t/build/m.x3d", x3d),
            ("t/legacy/n.x3d", x3d),
            ("t/legacy/keep/o.x3d", x3d),
            ("t/.gitignore", "node_modules/\n"),
            ("t/x3dcheck.toml", "exclude = [\"legacy/*.x3d\"]\n"),
        ],
    );
    let found = shown(&dir, &["t", "--exclude", "build"]);
    let expected = [
        "a.x3d",
        "b.x3dv",
        "c.x3dj",
        "d.wrl",
        "e.X3DZ",
        "f.x3dvz",
        "g.x3djz",
        "h.wrz",
        "i.x3d.gz",
        "j.wrl.gz",
        "legacy/keep/o.x3d",
        "scene.json",
    ];
    let expected: Vec<String> = expected.iter().map(|f| format!("t/{f}")).collect();
    assert_eq!(found, expected);
    // Named on the command line, an excluded file or a package.json is checked.
    assert_eq!(
        shown(&dir, &["t/package.json", "t/build/m.x3d"]),
        ["t/package.json", "t/build/m.x3d"]
    );
}

#[test]
#[cfg(unix)]
fn a_file_reached_twice_is_checked_once() {
    let x3d = "<X3D profile='Interchange' version='4.0'><Scene><Bogus/></Scene></X3D>";
    let dir = scratch("twice", &[("t/a.x3d", x3d)]);
    std::os::unix::fs::symlink("a.x3d", dir.join("t/link.x3d")).unwrap();
    assert_eq!(shown(&dir, &["t", "t/a.x3d", "./t"]), ["t/a.x3d"]);
    let output = x3dcheck(&dir, &["--format", "json", "t", "t/a.x3d"]);
    assert_eq!(json(&output)["summary"]["files"], 1);
}

#[test]
fn nothing_found_is_an_error() {
    let dir = scratch(
        "nothing",
        &[("t/package.json", "{\"name\": \"p\"}"), ("t/readme.md", "")],
    );
    let output = x3dcheck(&dir, &["t"]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("no X3D files found in t"), "{stderr}");
    assert!(output.stdout.is_empty());
}

/// A scene inlining `parts/lamp.x3d`, whose own finding (an unknown node) must be
/// reported once, under its own path.
const INLINING: &str = "<X3D profile='Immersive' version='4.0'><Scene>\
    <Inline url='\"parts/lamp.x3d\"'/><Transform><Inline url='\"parts/lamp.x3d\"'/></Transform>\
    </Scene></X3D>";
const INLINED: &str = "<X3D profile='Interchange' version='3.3'><Scene>\n<Bogus/>\n</Scene></X3D>";

/// Each file of a JSON report with the codes found in it.
fn files_and_codes(output: &Output) -> Vec<(String, Vec<String>)> {
    json(output)["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let codes = f["diagnostics"].as_array().unwrap().iter();
            (
                f["path"].as_str().unwrap().to_string(),
                codes
                    .map(|d| d["code"].as_str().unwrap().to_string())
                    .collect(),
            )
        })
        .collect()
}

#[test]
fn a_single_file_run_reports_its_inlined_files_under_their_own_paths() {
    let dir = scratch(
        "inlined-single",
        &[("scene.x3d", INLINING), ("parts/lamp.x3d", INLINED)],
    );
    let deep = x3dcheck(&dir, &["--level", "deep", "--format", "json", "scene.x3d"]);
    assert_eq!(
        files_and_codes(&deep),
        [
            ("scene.x3d".to_string(), vec![]),
            (
                "parts/lamp.x3d".to_string(),
                vec!["NODE_UNKNOWN".to_string()]
            ),
        ]
    );
    // Its place is in its own text: line 2.
    assert_eq!(json(&deep)["files"][1]["diagnostics"][0]["line"], 2);
    let human = x3dcheck(&dir, &["--level", "deep", "--color", "never", "scene.x3d"]);
    assert!(
        stdout(&human).contains("parts/lamp.x3d:2:2"),
        "{}",
        stdout(&human)
    );
    // Below the deep level nothing is read.
    let standard = x3dcheck(&dir, &["--format", "json", "scene.x3d"]);
    assert_eq!(files_and_codes(&standard).len(), 1);
}

#[test]
fn an_inlined_file_the_batch_lists_is_reported_once() {
    let dir = scratch(
        "inlined-listed",
        &[("scene.x3d", INLINING), ("parts/lamp.x3d", INLINED)],
    );
    let output = x3dcheck(&dir, &["--level", "deep", "--format", "json", "."]);
    let files: Vec<String> = files_and_codes(&output)
        .into_iter()
        .map(|(p, _)| p)
        .collect();
    assert_eq!(files.len(), 2, "{files:?}");
    let named = x3dcheck(
        &dir,
        &[
            "--level",
            "deep",
            "--format",
            "json",
            "parts/../parts/lamp.x3d",
            "scene.x3d",
        ],
    );
    assert_eq!(files_and_codes(&named).len(), 2);
}
