//! `x3dcheck completions SHELL` and `x3dcheck manpage`: generated from the same clap
//! definition the parser uses, so they cannot drift from the options (clap_complete and
//! clap_mangen, as ripgrep and many clap programs ship theirs).

use std::io::Write;

use clap::{Args, CommandFactory};
use clap_complete::Shell;

use super::Cli;

#[derive(Args, Debug)]
pub(super) struct CompletionsArgs {
    /// The shell to write the completion script for
    #[arg(value_enum)]
    shell: Shell,
}

/// Writes the completion script of `shell` to stdout.
pub(super) fn completions(args: &CompletionsArgs) -> Result<u8, String> {
    let mut command = Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut command, "x3dcheck", &mut script);
    write_stdout(&script)
}

/// Writes the manual page (roff, section 1) to stdout.
pub(super) fn manpage() -> Result<u8, String> {
    let mut page = Vec::new();
    clap_mangen::Man::new(Cli::command())
        .render(&mut page)
        .map_err(|error| format!("cannot write the manual page: {error}"))?;
    write_stdout(&page)
}

fn write_stdout(bytes: &[u8]) -> Result<u8, String> {
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_all(bytes)
        .and_then(|()| stdout.flush())
        .map_err(|error| format!("cannot write to stdout: {error}"))?;
    Ok(0)
}
