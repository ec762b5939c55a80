//! The `compgeo` command line: a thin layer that parses arguments, reads input, calls the
//! library and prints JSON. See the command-line contract in `docs/design.md`.

use clap::Parser;

/// Exact computational geometry that measures its own complexity.
#[derive(Debug, Parser)]
#[command(name = "compgeo", version, about)]
pub struct Cli {}

/// Runs the command line with the process arguments and returns the exit code.
pub fn main() -> std::process::ExitCode {
    let _cli = Cli::parse();
    std::process::ExitCode::SUCCESS
}
