//! `x3dcheck server` driven over stdio with real JSON-RPC messages (Content-Length
//! framing), as an editor drives it. Every wait has a timeout (the client's), so a server
//! that stops answering fails the test rather than hanging it.

#[path = "../examples/lsp-latency/client.rs"]
mod client;
mod common;

use std::path::Path;

use client::Client;
use serde_json::{json, Value};

/// A scene with a misspelt field after non-ASCII text on its line (UTF-16 columns differ
/// from byte and UTF-8 columns there), a duplicate DEF (related information), a USE and
/// a ROUTE.
const SCENE: &str = "<?xml version='1.0' encoding='UTF-8'?>
<X3D profile='Interchange' version='4.0'>
  <Scene>
    <Transform DEF='Häus𝄞'>
      <Shape DEF='Ball'>
        <Appearance>
          <!-- 𝄞 é --><Material DEF='Mat' diffusecolor='1 0 0'/>
        </Appearance>
        <Sphere/>
      </Shape>
    </Transform>
    <Transform DEF='Mat'/>
    <Shape USE='Ball'/>
    <TimeSensor DEF='Clock'/>
    <PositionInterpolator DEF='Move' key='0 1' keyValue='0 0 0 1 1 1'/>
    <ROUTE fromNode='Clock' fromField='fraction_changed' toNode='Move' toField='set_fraction'/>
  </Scene>
</X3D>
";

fn initialize(client: &mut Client, root: &Path, encodings: &[&str]) -> Value {
    client.request(
        "initialize",
        json!({
            "processId": null,
            "rootUri": uri(root),
            "capabilities": {"general": {"positionEncodings": encodings}},
        }),
    )
}

fn uri(path: &Path) -> String {
    format!("file://{}", path.display()).replace(' ', "%20")
}

/// The 0-based line and UTF-16 character of the first `needle` in `text` (plus `shift`
/// characters).
fn utf16_position(text: &str, needle: &str, shift: usize) -> (u64, u64) {
    let at = text.find(needle).unwrap();
    let line = text[..at].matches('\n').count();
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let character: usize = text[line_start..at].chars().map(char::len_utf16).sum();
    (line as u64, (character + shift) as u64)
}

fn position(text: &str, needle: &str, shift: usize) -> Value {
    let (line, character) = utf16_position(text, needle, shift);
    json!({"line": line, "character": character})
}

fn codes(diagnostics: &Value) -> Vec<String> {
    diagnostics["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["code"].as_str().unwrap_or("").to_string())
        .collect()
}

fn open(client: &mut Client, uri: &str, text: &str) -> Value {
    client.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "x3d", "version": 1, "text": text}}),
    );
    client.wait_for("textDocument/publishDiagnostics", |p| {
        p["uri"] == uri && p["version"] == 1
    })
}

#[test]
fn a_session_from_initialize_to_exit() {
    let dir = common::scratch("lsp-session", &[]);
    let file = dir.join("scene.x3d");
    let uri = uri(&file);
    let mut client = Client::start(Path::new(env!("CARGO_BIN_EXE_x3dcheck")));
    let init = initialize(&mut client, &dir, &["utf-16"]);
    assert_eq!(init["capabilities"]["positionEncoding"], "utf-16");
    assert_eq!(init["serverInfo"]["name"], "x3dcheck");
    client.notify("initialized", json!({}));

    // didOpen → diagnostics, with code, severity, doc link and UTF-16 positions.
    let published = open(&mut client, &uri, SCENE);
    let found = codes(&published);
    assert!(found.contains(&"FIELD_UNKNOWN".into()), "{found:?}");
    assert!(found.contains(&"DEF_DUPLICATE".into()), "{found:?}");
    let diagnostics = published["diagnostics"].as_array().unwrap();
    let unknown = diagnostics
        .iter()
        .find(|d| d["code"] == "FIELD_UNKNOWN")
        .unwrap();
    assert_eq!(unknown["severity"], 1);
    assert_eq!(unknown["source"], "x3dcheck");
    assert_eq!(
        unknown["range"]["start"],
        position(SCENE, "diffusecolor", 0)
    );
    assert_eq!(unknown["range"]["end"], position(SCENE, "diffusecolor", 12));
    assert!(unknown["message"]
        .as_str()
        .unwrap()
        .contains("diffuseColor"));
    let href = unknown["codeDescription"]["href"].as_str().unwrap();
    assert!(
        href.starts_with("file://") && href.ends_with("FIELD_UNKNOWN.md"),
        "{href}"
    );
    let duplicate = diagnostics
        .iter()
        .find(|d| d["code"] == "DEF_DUPLICATE")
        .unwrap();
    let related = &duplicate["relatedInformation"][0]["location"];
    assert_eq!(related["uri"], uri.as_str());
    assert_eq!(related["range"]["start"]["line"], 6);

    // didChange → new diagnostics for the new version.
    let fixed = SCENE.replace("diffusecolor", "diffuseColor");
    client.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": uri, "version": 2}, "contentChanges": [{"text": fixed}]}),
    );
    let published = client.wait_for("textDocument/publishDiagnostics", |p| p["version"] == 2);
    let found = codes(&published);
    assert!(!found.contains(&"FIELD_UNKNOWN".into()), "{found:?}");
    assert!(found.contains(&"DEF_DUPLICATE".into()), "{found:?}");

    // Hover on a node name, a field name, a USE, and a finding's place.
    let td = json!({"uri": uri});
    let hover = |client: &mut Client, needle: &str, shift: usize| {
        client.request(
            "textDocument/hover",
            json!({"textDocument": td, "position": position(&fixed, needle, shift)}),
        )["contents"]["value"]
            .as_str()
            .unwrap_or("")
            .to_string()
    };
    let on_node = hover(&mut client, "Material DEF", 2);
    assert!(
        on_node.contains("**Material**") && on_node.contains("component Shape"),
        "{on_node}"
    );
    assert!(on_node.contains("12.4."), "the clause: {on_node}");
    assert!(
        on_node.contains("| diffuseColor | SFColor | inputOutput | `0.8 0.8 0.8` |"),
        "the fields, with their types and defaults: {on_node}"
    );
    assert!(
        on_node.contains("Material specifies surface rendering properties"),
        "the UOM's description: {on_node}"
    );
    let on_field = hover(&mut client, "diffuseColor", 3);
    assert!(
        on_field.contains("SFColor") && on_field.contains("inputOutput"),
        "{on_field}"
    );
    assert!(
        on_field.contains("default `0.8 0.8 0.8`") && on_field.contains("range [0"),
        "{on_field}"
    );
    assert!(
        on_field.contains("how much direct, angle-dependent light is reflected"),
        "the UOM's description: {on_field}"
    );
    let on_use = hover(&mut client, "USE='Ball'", 6);
    assert!(
        on_use.contains("DEF Ball") && on_use.contains("line 5"),
        "{on_use}"
    );
    let on_finding = hover(&mut client, "<Transform DEF='Mat'", 17);
    assert!(
        on_finding.contains("DEF_DUPLICATE") && on_finding.contains("## What it does"),
        "{on_finding}"
    );

    // Completion: node names the field accepts, attributes, enumerations, DEF names.
    let labels = |client: &mut Client, text: &str, version: i64| {
        let at = text.find('|').unwrap();
        let text = text.replace('|', "");
        let (line, character) = utf16_position(&text, &text[at..], 0);
        client.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": text}]}),
        );
        let items = client.request(
            "textDocument/completion",
            json!({"textDocument": td, "position": {"line": line, "character": character}}),
        );
        items
            .as_array()
            .unwrap()
            .iter()
            .map(|i| i["label"].as_str().unwrap().to_string())
            .collect::<Vec<_>>()
    };
    let in_shape = labels(&mut client, &fixed.replace("<Sphere/>", "<Sph|"), 3);
    assert!(
        in_shape.contains(&"Sphere".into()) && !in_shape.contains(&"Transform".into()),
        "{in_shape:?}"
    );
    let attributes = labels(&mut client, &fixed.replace("<Sphere/>", "<Sphere r|/>"), 4);
    assert!(attributes.contains(&"radius".into()), "{attributes:?}");
    let uses = labels(&mut client, &fixed.replace("USE='Ball'", "USE='|'"), 5);
    assert!(
        uses.contains(&"Ball".into()) && uses.contains(&"Clock".into()),
        "{uses:?}"
    );
    let fog = labels(
        &mut client,
        &fixed.replace("<Sphere/>", "<Fog fogType='|'/>"),
        6,
    );
    assert!(fog.contains(&"EXPONENTIAL".into()), "{fog:?}");
    // In a prototype body a USE names the body's DEFs, in the scene the scene's (4.4.4.3).
    let protos = "<X3D profile='Immersive' version='4.0'><Scene>\
        <ProtoDeclare name='P'><ProtoBody><Group DEF='Inner'/><Group USE='Inner'/></ProtoBody>\
        </ProtoDeclare><Group DEF='Outer'/><Group USE='Outer'/></Scene></X3D>";
    client.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": uri, "version": 7}, "contentChanges": [{"text": protos}]}),
    );
    client.wait_for("textDocument/publishDiagnostics", |p| p["version"] == 7);
    let in_body = labels(&mut client, &protos.replace("USE='Inner", "USE='|Inner"), 8);
    assert_eq!(in_body, ["Inner"], "in the body");
    let in_scene = labels(&mut client, &protos.replace("USE='Outer", "USE='|Outer"), 9);
    assert_eq!(in_scene, ["Outer"], "in the scene");
    client.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": uri, "version": 10}, "contentChanges": [{"text": fixed}]}),
    );
    client.wait_for("textDocument/publishDiagnostics", |p| p["version"] == 10);

    // Definition from a USE and from a ROUTE's node names.
    let definition = |client: &mut Client, needle: &str, shift: usize| {
        client.request(
            "textDocument/definition",
            json!({"textDocument": td, "position": position(&fixed, needle, shift)}),
        )["range"]["start"]
            .clone()
    };
    assert_eq!(
        definition(&mut client, "USE='Ball'", 6),
        position(&fixed, "Ball'>", 0)
    );
    assert_eq!(
        definition(&mut client, "fromNode='Clock'", 11),
        position(&fixed, "Clock'/>", 0)
    );
    assert_eq!(
        definition(&mut client, "toNode='Move'", 9),
        position(&fixed, "Move' key", 0)
    );

    // Document symbols: the DEF tree.
    let symbols = client.request("textDocument/documentSymbol", json!({"textDocument": td}));
    let top: Vec<&str> = symbols
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(top, ["Häus𝄞", "Mat", "Clock", "Move"]);
    assert_eq!(symbols[0]["children"][0]["name"], "Ball");
    assert_eq!(symbols[0]["children"][0]["children"][0]["name"], "Mat");
    assert_eq!(symbols[0]["children"][0]["detail"], "Shape");

    // Code actions: no rule sets a fix yet on this branch, so none are offered (the
    // conversion of fixes is tested in src/lsp/convert.rs); the request is answered.
    let actions = client.request(
        "textDocument/codeAction",
        json!({"textDocument": td, "range": {"start": position(&fixed, "<Transform DEF='Mat'", 0), "end": position(&fixed, "<Transform DEF='Mat'", 5)}, "context": {"diagnostics": []}}),
    );
    assert!(actions.is_array(), "{actions}");

    // An unknown request gets an error, not silence.
    let unknown = client.request_raw("textDocument/rename", json!({}));
    assert!(unknown.get("error").is_some(), "{unknown}");

    assert!(client.shutdown().success());
}

#[test]
fn utf8_positions_when_the_client_offers_them() {
    let dir = common::scratch("lsp-utf8", &[]);
    let uri = uri(&dir.join("scene.x3d"));
    let mut client = Client::start(Path::new(env!("CARGO_BIN_EXE_x3dcheck")));
    let init = initialize(&mut client, &dir, &["utf-8", "utf-16"]);
    assert_eq!(init["capabilities"]["positionEncoding"], "utf-8");
    client.notify("initialized", json!({}));
    let published = open(&mut client, &uri, SCENE);
    let unknown = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "FIELD_UNKNOWN")
        .unwrap()
        .clone();
    let at = SCENE.find("diffusecolor").unwrap();
    let line_start = SCENE[..at].rfind('\n').unwrap() + 1;
    assert_eq!(unknown["range"]["start"]["character"], at - line_start);
    assert!(client.shutdown().success());
}

#[test]
fn the_x3dcheck_toml_of_the_file_applies_and_other_encodings_are_checked() {
    let dir = common::scratch(
        "lsp-config",
        &[("x3dcheck.toml", "[severity]\nFIELD_UNKNOWN = \"hint\"\n")],
    );
    let mut client = Client::start(Path::new(env!("CARGO_BIN_EXE_x3dcheck")));
    initialize(&mut client, &dir, &[]);
    client.notify("initialized", json!({}));
    let scene_uri = uri(&dir.join("scene.x3d"));
    let published = open(&mut client, &scene_uri, SCENE);
    let unknown = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "FIELD_UNKNOWN")
        .unwrap()
        .clone();
    assert_eq!(unknown["severity"], 4, "x3dcheck.toml made it a hint");

    let json_uri = uri(&dir.join("scene.x3dj"));
    let json_scene = r#"{"X3D": {"@profile": "Interchange", "@version": "4.0",
  "Scene": {"-children": [{"Shape": {"-geometry": {"Sphere": {"@radius": -1}}}}]}}}"#;
    let found = codes(&open(&mut client, &json_uri, json_scene));
    assert!(found.contains(&"FIELD_OUT_OF_RANGE".into()), "{found:?}");

    let classic_uri = uri(&dir.join("scene.x3dv"));
    let classic = "#X3D V4.0 utf8\nPROFILE Interchange\nShape { geometry Sphere { radius -1 } }\n";
    let published = open(&mut client, &classic_uri, classic);
    let out_of_range = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "FIELD_OUT_OF_RANGE")
        .unwrap_or_else(|| panic!("{published}"))
        .clone();
    assert_eq!(out_of_range["range"]["start"]["line"], 2);

    // Closing a document clears its diagnostics.
    client.notify(
        "textDocument/didClose",
        json!({"textDocument": {"uri": classic_uri}}),
    );
    let cleared = client.wait_for("textDocument/publishDiagnostics", |p| {
        p["uri"] == classic_uri.as_str()
    });
    assert_eq!(cleared["diagnostics"], json!([]));
    assert!(client.shutdown().success());
}
