//! The `x3dcheck` command; everything it does is in [`cli`].

mod cli;

use clap::Parser;

fn main() -> std::process::ExitCode {
    cli::run(cli::Cli::parse())
}
