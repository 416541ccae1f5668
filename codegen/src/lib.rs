//! Generates `src/schema/generated.rs`, the checker's node and field tables,
//! `src/schema/descriptions.rs`, their documentation text, and `src/validate/hanim/names.rs`,
//! the HAnim 2.0 joint and segment names, from the X3D Unified Object Model
//! files in `../shared/oracle`.

mod apply;
mod describe;
mod emit;
mod hanim;
mod uom;
mod xml;

// The generator parses field and access types with the checker's own definitions. They are
// included by path rather than through a dependency on the `x3dcheck` crate, which cannot
// build while `generated.rs` is stale or broken, exactly when the generator is needed.
#[allow(dead_code)] // the checker's lookup helpers in types.rs have no use here
#[path = "../../src/schema/types.rs"]
mod types;

// The corrections the spec clauses make to the UOM: data kept next to the tables it changes,
// included by path for the same reason as types.rs. The checker does not compile it.
#[allow(dead_code)] // `why` documents each entry; the generator reports only the clause
#[path = "../../src/schema/overrides.rs"]
mod overrides;

// VRML97's table as a difference from X3D 3.0's: data, included by path like overrides.rs.
#[allow(dead_code)] // `x3d` documents each entry; the generator reports only 14772-1's subclause
#[path = "../../src/schema/vrml97.rs"]
mod vrml97;

use std::fs;
use std::path::{Path, PathBuf};

use types::Version;
use uom::Notes;

/// The workspace root, where `src/schema/generated.rs` lives.
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Where the UOM files are: `<workspace root>/../shared/oracle`.
pub fn default_oracle_dir() -> PathBuf {
    workspace_root().join("../shared/oracle")
}

/// A generated file's path relative to the workspace root, and its text.
pub type Generated = (&'static str, String);

/// Reads `X3dUnifiedObjectModel-<version>.xml` for every X3D version from `oracle_dir`,
/// applies the corrections of `src/schema/overrides.rs`, derives VRML97's table from X3D
/// 3.0's with `src/schema/vrml97.rs` and returns the text of `generated.rs`, with the
/// descriptions of the nodes and fields in `descriptions.rs`.
/// Prints to stderr what it left out of the tables and what the corrections did.
pub fn generate(oracle_dir: &Path) -> Result<[Generated; 3], String> {
    let mut notes = Notes::default();
    let mut applied = apply::Applied::default();
    let mut descriptions = describe::Descriptions::default();
    let mut schemas = Vec::new();
    let mut hanim_names = None;
    for version in Version::X3D {
        let path = oracle_dir.join(format!("X3dUnifiedObjectModel-{version}.xml"));
        let in_file = |e: String| format!("{}: {e}", path.display());
        let text = fs::read_to_string(&path).map_err(|e| in_file(e.to_string()))?;
        let root = xml::parse(&text).map_err(in_file)?;
        descriptions.read(&root);
        if version.to_string() == hanim::SOURCE {
            hanim_names = Some(hanim::render(&root).map_err(in_file)?);
        }
        let mut schema = uom::read(version, &root, &mut notes).map_err(in_file)?;
        apply::apply(&mut schema, &mut applied)?;
        schemas.push(schema);
    }
    let x3d_3_0 = schemas
        .iter()
        .find(|s| s.version == Version::V3_0)
        .expect("X3D 3.0 is read above");
    let vrml97 = apply::vrml97(x3d_3_0, &mut applied)?;
    // In Version::ALL order, VRML97 first.
    schemas.insert(0, vrml97);
    print_notes(&notes);
    eprintln!(
        "codegen: src/schema/overrides.rs and vrml97.rs changed {} table entries",
        applied.changes
    );
    print_list(
        "overrides the UOM already agrees with (kept to pin the value)",
        &applied.no_ops,
    );
    Ok([
        ("src/schema/generated.rs", emit::render(&schemas)),
        ("src/schema/descriptions.rs", descriptions.render(&schemas)),
        (
            "src/validate/hanim/names.rs",
            hanim_names.ok_or(format!("no UOM of version {}", hanim::SOURCE))?,
        ),
    ])
}

fn print_notes(notes: &Notes) {
    let pseudo: Vec<String> = notes
        .pseudo_fields
        .iter()
        .map(|(name, count)| format!("{name} x{count}"))
        .collect();
    let total: usize = notes.pseudo_fields.values().sum();
    eprintln!(
        "codegen: skipped {total} pseudo-field entries (XML encoding, not X3D fields): {}",
        pseudo.join(", ")
    );
    print_list(
        "skipped fields whose type is no X3D field type",
        &notes.untyped_fields,
    );
    print_list("read xs:NMTOKEN as SFString", &notes.nmtoken_fields);
    print_list("unparsable bounds, left unbounded", &notes.bad_bounds);
    for (version, fields) in &notes.strict_enumerations {
        print_list(&format!("{version} strict enumerations"), fields);
    }
}

fn print_list(what: &str, items: &[String]) {
    eprintln!(
        "codegen: {what} ({}): {}",
        items.len(),
        if items.is_empty() {
            "none".to_owned()
        } else {
            items.join(", ")
        }
    );
}
