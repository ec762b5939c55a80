//! The `compgeo` binary: everything lives in [`compgeo::cli`].

fn main() -> std::process::ExitCode {
    compgeo::cli::main()
}
