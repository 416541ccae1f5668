//! Fails when the checked-in tables or descriptions no longer match what the generator makes of the UOM.

use std::fs;

#[test]
fn generated_is_fresh() {
    let expected = x3dcheck_codegen::generate(&x3dcheck_codegen::default_oracle_dir())
        .unwrap_or_else(|e| panic!("codegen failed: {e}"));
    for (path, text) in &expected {
        let actual =
            fs::read_to_string(x3dcheck_codegen::workspace_root().join(path)).unwrap_or_default();
        assert!(
            &actual == text,
            "{path} is stale: run `cargo run -p x3dcheck-codegen`"
        );
    }
}
