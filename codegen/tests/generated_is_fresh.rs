//! Fails when the checked-in tables no longer match what the generator makes of the UOM.

use std::fs;

#[test]
fn generated_is_fresh() {
    let expected = x3dcheck_codegen::generate(&x3dcheck_codegen::default_oracle_dir())
        .unwrap_or_else(|e| panic!("codegen failed: {e}"));
    let path = x3dcheck_codegen::workspace_root().join(x3dcheck_codegen::OUTPUT);
    let actual = fs::read_to_string(&path).unwrap_or_default();
    assert!(
        actual == expected,
        "src/schema/generated.rs is stale: run `cargo run -p x3dcheck-codegen`"
    );
}
