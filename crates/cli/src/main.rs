//! The `wheelrail` program: parses arguments, runs, maps errors to exit codes
//! (see [`wheelrail_cli::main`]).

fn main() -> std::process::ExitCode {
    wheelrail_cli::main()
}
