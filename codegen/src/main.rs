//! `cargo run -p x3dcheck-codegen`: regenerates `src/schema/generated.rs`.

use std::fs;
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    let started = Instant::now();
    let oracle_dir = x3dcheck_codegen::default_oracle_dir();
    let text = match x3dcheck_codegen::generate(&oracle_dir) {
        Ok(text) => text,
        Err(e) => {
            eprintln!("codegen: {e}");
            return ExitCode::FAILURE;
        }
    };
    let output = x3dcheck_codegen::workspace_root().join(x3dcheck_codegen::OUTPUT);
    if let Err(e) = fs::write(&output, &text) {
        eprintln!("codegen: {}: {e}", output.display());
        return ExitCode::FAILURE;
    }
    eprintln!(
        "codegen: wrote {} ({} bytes) in {:.2?}",
        x3dcheck_codegen::OUTPUT,
        text.len(),
        started.elapsed()
    );
    ExitCode::SUCCESS
}
