//! `cargo run -p x3dcheck-codegen`: regenerates `src/schema/generated.rs` and
//! `src/schema/descriptions.rs`.

use std::fs;
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    let started = Instant::now();
    let oracle_dir = x3dcheck_codegen::default_oracle_dir();
    let generated = match x3dcheck_codegen::generate(&oracle_dir) {
        Ok(generated) => generated,
        Err(e) => {
            eprintln!("codegen: {e}");
            return ExitCode::FAILURE;
        }
    };
    for (path, text) in &generated {
        let output = x3dcheck_codegen::workspace_root().join(path);
        if let Err(e) = fs::write(&output, text) {
            eprintln!("codegen: {}: {e}", output.display());
            return ExitCode::FAILURE;
        }
        eprintln!("codegen: wrote {path} ({} bytes)", text.len());
    }
    eprintln!("codegen: done in {:.2?}", started.elapsed());
    ExitCode::SUCCESS
}
