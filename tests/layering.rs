//! Dependencies point one way. From the bottom up:
//!
//! 1. `diagnostic` (findings, rules, severities), `schema`, `limits`, `shard`;
//! 2. the model, then the readers (`parse`, `read`) above it, then `library` and `config`;
//! 3. `validate` (the rules) and `report` (the formats), side by side: neither uses the
//!    other, and the rule metadata a format prints is handed to it;
//! 4. `check`, `suppress`, `config_file`, `fix`, `render`, `lsp`;
//! 5. `batch` (what a run over many files adds), then `api`, then `cli`.
//!
//! A `use` (or a path) that reaches up a layer, in non-test code, fails here; so does a
//! re-export of the diagnostics core from a module above it, the detour that lets imports
//! hide the layer they come from. Inside a module, files that split a job import one way:
//! `model::instantiate` does not use `model::builder` (both write to `model::draft`),
//! `render::polygons` does not use `render::geometry` (both make `render::mesh`). What is checked is the text: a glob import (`use super::*`) and
//! a path built by a macro are not seen.

use std::fs;
use std::path::{Path, PathBuf};

/// Each lower part (a folder or file under `src/`), with the modules above it that it must
/// not name. A file inside a forbidden module is that module's own and is not checked.
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
        &[
            "parse", "check", "validate", "report", "render", "config", "lsp",
        ],
    ),
    (
        "src/parse",
        &["check", "validate", "report", "render", "config", "lsp"],
    ),
    (
        "src/config.rs",
        &[
            "validate",
            "report",
            "check",
            "config_file",
            "suppress",
            "fix",
            "render",
            "lsp",
            "batch",
        ],
    ),
    (
        "src/report",
        &[
            "validate",
            "check",
            "config",
            "config_file",
            "suppress",
            "fix",
            "render",
            "lsp",
            "batch",
        ],
    ),
    (
        "src/validate",
        &[
            "report",
            "check",
            "config_file",
            "suppress",
            "fix",
            "render",
            "lsp",
            "batch",
        ],
    ),
    ("src/render", &["validate", "check", "fix", "lsp", "batch"]),
    // Within a module: the file that shares out the work is above the one that does it.
    ("src/model/instantiate.rs", &["model::builder"]),
    ("src/render/polygons.rs", &["render::geometry"]),
];

/// Uses that break the layers and are known, each with why it is left.
const KNOWN: &[(&str, &str)] = &[(
    // The renderer reports what it cannot draw under the rule whose check is in validate;
    // the rule's declaration is to move below both.
    "src/render/mod.rs",
    "crate::validate::document::validation_incomplete::VALIDATION_INCOMPLETE",
)];

/// The top, from below: what runs a batch of files, the library API, the command line.
/// Each uses only those before it, and no other module uses any of them.
const TOP: &[&str] = &["batch", "api", "cli"];

/// The one module above the diagnostics core that hands its items on: the library API,
/// for programs that use the crate. Anywhere else, import them from `crate::diagnostic`.
const REEXPORTERS: &[&str] = &["src/api.rs"];

/// Items of the diagnostics core that are imported from there and nowhere else.
const CORE_ITEMS: &[&str] = &["Diagnostic", "Level", "Rule", "Severity"];

/// Why the file at `path` (relative to the crate, `src/...`) with `text` breaks the layers;
/// empty when it does not.
fn problems_in(path: &str, text: &str) -> Vec<String> {
    let module = module_of(path);
    // Unit tests may drive the whole pipeline.
    let code = text.split("#[cfg(test)]").next().unwrap();
    let mut problems = Vec::new();
    for (line, used, reexported) in paths_used(code) {
        let Some(used) = absolute(&used, &module) else {
            continue;
        };
        if KNOWN.contains(&(path, used.as_str())) {
            continue;
        }
        for (part, forbidden) in LAYERS {
            if !path.starts_with(part) {
                continue;
            }
            for above in *forbidden {
                let above = format!("crate::{above}");
                let own = module == above || module.starts_with(&format!("{above}::"));
                let names = used == above || used.starts_with(&format!("{above}::"));
                if names && !own {
                    problems.push(format!("{path}:{line}: uses `{above}`: {used}"));
                }
            }
        }
        let rank = |module: &str| {
            TOP.iter().position(|top| {
                let top = format!("crate::{top}");
                module == top || module.starts_with(&format!("{top}::"))
            })
        };
        if let Some(used_rank) = rank(&used) {
            if rank(&module).is_none_or(|own| own < used_rank) {
                let top = TOP[used_rank];
                problems.push(format!("{path}:{line}: uses `crate::{top}`: {used}"));
            }
        }
        let core_item = CORE_ITEMS
            .iter()
            .any(|item| used == format!("crate::diagnostic::{item}"));
        if reexported
            && core_item
            && !path.starts_with("src/diagnostic")
            && !REEXPORTERS.contains(&path)
        {
            problems.push(format!(
                "{path}:{line}: re-exports `{used}`: import it from `crate::diagnostic`"
            ));
        }
    }
    problems
}

/// The module path of a file: `src/model/builder.rs` is `crate::model::builder`.
fn module_of(path: &str) -> String {
    let inside = path.strip_prefix("src/").unwrap_or(path);
    let inside = inside.strip_suffix(".rs").unwrap_or(inside);
    let inside = inside.strip_suffix("/mod").unwrap_or(inside);
    match inside {
        "lib" | "main" => "crate".to_string(),
        _ => format!("crate::{}", inside.replace('/', "::")),
    }
}

/// `used` from `crate`, resolving `self::` and `super::` against `module`; None for a path
/// that starts elsewhere (`std::`, a dependency, a local name).
fn absolute(used: &str, module: &str) -> Option<String> {
    let mut base: Vec<&str> = module.split("::").collect();
    let mut parts = used.split("::").peekable();
    match parts.peek() {
        Some(&"crate") => return Some(used.to_string()),
        Some(&"self") => {
            parts.next();
        }
        Some(&"super") => {
            while parts.peek() == Some(&"super") {
                parts.next();
                base.pop();
            }
        }
        _ => return None,
    }
    Some(base.into_iter().chain(parts).collect::<Vec<_>>().join("::"))
}

/// Every path from `crate`, `self` or `super` in `code`, outside comments, with the line it
/// starts on and whether a `pub use` hands it on. Grouped imports (`use crate::{a, b::c}`,
/// over several lines too) are spelled out path by path; `$crate` paths (inside macros,
/// expanded where they are used) are left out.
fn paths_used(code: &str) -> Vec<(usize, String, bool)> {
    let mut found = Vec::new();
    let mut statement = String::new();
    let mut statement_line = 0;
    for (number, line) in code.lines().enumerate() {
        let line = line.trim();
        if line.starts_with("//") {
            continue;
        }
        let line = line.split(" //").next().unwrap();
        if statement.is_empty() {
            let import = line
                .strip_prefix("pub use ")
                .or_else(|| line.strip_prefix("pub(crate) use "))
                .or_else(|| line.strip_prefix("pub(super) use "))
                .map(|rest| (rest, true))
                .or_else(|| line.strip_prefix("use ").map(|rest| (rest, false)));
            if let Some((rest, reexported)) = import {
                statement = format!("{}{rest}", if reexported { "!" } else { "" });
                statement_line = number + 1;
            } else {
                for used in inline_paths(line) {
                    found.push((number + 1, used, false));
                }
                continue;
            }
        } else {
            statement.push_str(line);
        }
        if let Some(end) = statement.find(';') {
            // ` as ` goes before the spaces do, so that `a as b` does not read `aasb`.
            let body: String = statement[..end]
                .replace(" as ", "@")
                .chars()
                .filter(|c| !c.is_whitespace())
                .collect();
            let (body, reexported) = match body.strip_prefix('!') {
                Some(body) => (body.to_string(), true),
                None => (body, false),
            };
            for used in spelled_out(&body) {
                found.push((statement_line, used, reexported));
            }
            statement.clear();
        }
    }
    found
}

/// The paths of a `use` tree: `a::{b, c::{d, e}}` is `a::b`, `a::c::d`, `a::c::e`
/// (`self` inside braces is the prefix; renames, marked `@`, are dropped).
fn spelled_out(tree: &str) -> Vec<String> {
    let Some(open) = tree.find('{') else {
        let path = tree.split('@').next().unwrap_or(tree);
        let path = path.strip_suffix("::self").unwrap_or(path);
        return vec![path.to_string()];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let mut items = Vec::new();
    let mut depth = 0;
    let mut start = 0;
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    items.push(&inner[start..]);
    items
        .into_iter()
        .filter(|item| !item.is_empty())
        .flat_map(|item| spelled_out(&format!("{prefix}{item}")))
        .collect()
}

/// The paths from `crate`, `self` or `super` in a line of code that is no `use`.
fn inline_paths(line: &str) -> Vec<String> {
    let mut found = Vec::new();
    for start in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(at) = line[from..].find(start) {
            let at = from + at;
            from = at + start.len();
            let before = line[..at].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '$' || c == ':') {
                continue;
            }
            let path: String = line[at..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            found.push(path.trim_end_matches(':').to_string());
        }
    }
    found
}

fn rust_files(dir: &Path, found: &mut Vec<PathBuf>) {
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
    for (part, _) in LAYERS {
        assert!(root.join(part).exists(), "{part} is gone: mend LAYERS");
    }
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    let mut problems = Vec::new();
    for file in files {
        let path = file.strip_prefix(root).unwrap().to_str().unwrap();
        problems.extend(problems_in(path, &fs::read_to_string(&file).unwrap()));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The check itself finds a back-edge of each kind it guards against, so that the test
/// above cannot pass for reading nothing.
#[test]
fn a_back_edge_of_each_kind_is_found() {
    let broken = [
        // The library API on the command line.
        ("src/api.rs", "use crate::cli::codes;"),
        (
            "src/check.rs",
            "    let root = crate::batch::file_root(path);",
        ),
        (
            "src/batch/inlined.rs",
            "    super::super::cli::render_text(r)",
        ),
        // The diagnostics core through a detour, and the configuration on the rules.
        (
            "src/validate/mod.rs",
            "pub use crate::diagnostic::{Level, Rule, Severity};",
        ),
        (
            "src/report/mod.rs",
            "pub use crate::diagnostic::Diagnostic;",
        ),
        (
            "src/config.rs",
            "use crate::validate::{Level, Rule, Severity};",
        ),
        ("src/validate/shape/x.rs", "use crate::report::Diagnostic;"),
        // The formats on the rule registry, a grouped import over lines too.
        (
            "src/report/json.rs",
            "use crate::{\n    model::Span,\n    validate::find_rule,\n};",
        ),
        (
            "src/report/sarif.rs",
            "    let rules = crate::validate::RULES.iter();",
        ),
        // Two files of one module importing each other, and render on validate.
        (
            "src/model/instantiate.rs",
            "use super::builder::{Builder, Limit};",
        ),
        ("src/render/polygons.rs", "use super::geometry::LocalMesh;"),
        (
            "src/render/textures.rs",
            "use crate::validate::texturing::data_url;",
        ),
        ("src/render/mod.rs", "use crate::validate::Ctx;"),
        // The model on a reader.
        ("src/model/fields.rs", "use crate::parse::xml_value;"),
    ];
    for (path, text) in broken {
        assert!(!problems_in(path, text).is_empty(), "{path}: {text}");
    }
    let sound = [
        ("src/cli/rules.rs", "use crate::api::RuleInfo;"),
        ("src/parse/xml.rs", "use crate::model::text::xml_value;"),
        ("src/api.rs", "use crate::batch::{self, codes as selected};"),
        ("src/lib.rs", "pub use check::check_source;"),
        (
            "src/api.rs",
            "pub use crate::diagnostic::{Level, Severity};",
        ),
        (
            "src/model/builder.rs",
            "        super::instantiate::instantiate_all(&mut self, &none);",
        ),
        (
            "src/render/geometry.rs",
            "use super::polygons::{self, Faces};",
        ),
        (
            "src/report/json.rs",
            "// Unlike crate::validate::find_rule, ...",
        ),
        (
            "src/report/json.rs",
            "#[cfg(test)]\nmod tests { use crate::validate::RULES; }",
        ),
        (
            "src/diagnostic/rule.rs",
            "pub static CHECK: $crate::validate::Check = x;",
        ),
        (
            "src/validate/mod.rs",
            "use crate::diagnostic::{Level, Rule, Severity};",
        ),
        (
            "src/render/mod.rs",
            "use crate::validate::document::validation_incomplete::VALIDATION_INCOMPLETE;",
        ),
    ];
    for (path, text) in sound {
        assert_eq!(
            problems_in(path, text),
            Vec::<String>::new(),
            "{path}: {text}"
        );
    }
}
