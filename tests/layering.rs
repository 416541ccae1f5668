//! Dependencies point one way: the diagnostics core, the schema, the model and the
//! readers never use what is built on them (`check`, `validate`, `report`, `render`,
//! the CLI). A `use` of a higher layer in their non-test code fails here.

use std::fs;
use std::path::Path;

/// Each low layer, with the modules above it that it must not name.
const LAYERS: &[(&str, &[&str])] = &[
    (
        "src/diagnostic",
        &[
            "model", "schema", "parse", "check", "validate", "report", "render", "config", "lsp",
        ],
    ),
    (
        "src/schema",
        &[
            "model", "parse", "check", "validate", "report", "render", "config", "lsp",
        ],
    ),
    (
        "src/model",
        &["check", "validate", "report", "render", "config", "lsp"],
    ),
    (
        "src/parse",
        &["check", "validate", "report", "render", "config", "lsp"],
    ),
];

fn rust_files(dir: &Path, found: &mut Vec<std::path::PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, found);
        } else if path.extension().is_some_and(|e| e == "rs") {
            found.push(path);
        }
    }
}

#[test]
fn lower_layers_do_not_use_higher_ones() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut problems = Vec::new();
    for (layer, forbidden) in LAYERS {
        let mut files = Vec::new();
        rust_files(&root.join(layer), &mut files);
        assert!(!files.is_empty(), "{layer} has no Rust files");
        for file in files {
            let text = fs::read_to_string(&file).unwrap();
            // Unit tests may drive the whole pipeline.
            let code = text.split("#[cfg(test)]").next().unwrap();
            for (number, line) in code.lines().enumerate() {
                let line = line.trim_start();
                if line.starts_with("//") {
                    continue;
                }
                for module in *forbidden {
                    // `$crate::validate::Check` in `declare_rule!` expands inside
                    // `validate` only (the arm with a check function).
                    let uses = line.contains(&format!("crate::{module}::"))
                        || line.contains(&format!("crate::{module};"))
                        || line.contains(&format!("crate::{module}::{{"));
                    if uses && !line.contains("$crate::validate::Check") {
                        problems.push(format!(
                            "{}:{}: uses `{module}`: {line}",
                            file.strip_prefix(root).unwrap().display(),
                            number + 1
                        ));
                    }
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
