//! The `x3dcheck` command; everything it does is in [`cli`].

mod cli;

use clap::Parser;

fn main() -> std::process::ExitCode {
    // Before any thread starts: changing the environment later would race with readers.
    x3dcheck::render::prepare_environment();
    cli::run(cli::Cli::parse())
}
