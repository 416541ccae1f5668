//! The language server's edit latency: `cargo run --release --example lsp-latency`.
//!
//! Opens the generated benchmark scene (examples/bench's, XML) in `x3dcheck server` at a
//! size of about 1 MB and at full size (about 86 MB), then times edits: each sends the
//! whole text (full sync, as editors do) with one Material's `shininess` toggled between a
//! valid and an out-of-range value, and waits for the diagnostics of that version. Prints
//! the median, minimum and maximum per size. No thresholds: the figures are for reading
//! (the target is 30 ms at 1 MB, standard level).

#[path = "../bench/scene.rs"]
#[allow(dead_code)]
mod scene;

mod client;

use std::path::Path;
use std::time::{Duration, Instant};

use client::Client;
use serde_json::json;

fn main() {
    let binary = std::env::current_exe()
        .ok()
        .and_then(|exe| Some(exe.parent()?.parent()?.join("x3dcheck")))
        .filter(|p| p.is_file())
        .expect("build the binary first: cargo build --release");
    let dir = std::env::temp_dir().join("x3dcheck-bench");
    std::fs::create_dir_all(&dir).unwrap();
    let full = std::env::args().all(|a| a != "--small-only");
    // Scale 1/86: about 1 MB of XML.
    measure(&binary, &dir, 1.0 / 86.0, 21);
    if full {
        measure(&binary, &dir, 1.0, 5);
    }
}

fn measure(binary: &Path, dir: &Path, scale: f64, edits: usize) {
    let scene = scene::ensure(dir, scale, false).expect("generate the scene");
    let text = std::fs::read_to_string(&scene.xml).unwrap();
    let mb = text.len() as f64 / 1e6;
    let mut client = Client::start(binary);
    client.timeout = Duration::from_secs(600);
    client.request(
        "initialize",
        json!({"processId": null, "rootUri": null, "capabilities": {}}),
    );
    client.notify("initialized", json!({}));
    let uri = file_uri(&scene.xml);
    let started = Instant::now();
    client.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "x3d", "version": 0, "text": text}}),
    );
    let first = client.wait_for("textDocument/publishDiagnostics", |p| p["version"] == 0);
    let open = started.elapsed();
    let valid = text.replacen("<Material ", "<Material shininess='0.5' ", 1);
    let invalid = text.replacen("<Material ", "<Material shininess='2' ", 1);
    let mut times = Vec::new();
    for version in 1..=edits as i64 {
        let edited = if version % 2 == 1 { &invalid } else { &valid };
        let started = Instant::now();
        client.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": edited}]}),
        );
        let published = client.wait_for("textDocument/publishDiagnostics", |p| {
            p["version"] == version
        });
        times.push(started.elapsed());
        let out_of_range = published["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .any(|d| d["code"] == "FIELD_OUT_OF_RANGE");
        assert_eq!(out_of_range, version % 2 == 1, "the edit's finding");
    }
    client.shutdown();
    times.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1000.0;
    println!(
        "{mb:.1} MB XML scene ({}), standard level: open → diagnostics {:.0} ms ({} findings); \
         edit → new diagnostics over {edits} edits: median {:.1} ms (min {:.1}, max {:.1})",
        scene.xml.display(),
        ms(open),
        first["diagnostics"].as_array().map_or(0, Vec::len),
        ms(times[times.len() / 2]),
        ms(times[0]),
        ms(times[times.len() - 1]),
    );
}

fn file_uri(path: &Path) -> String {
    format!("file://{}", path.display())
}
