//! The `wheelrail` command: parses arguments, runs, maps errors to exit codes
//! (see [`wheelrail::app`]).

fn main() -> std::process::ExitCode {
    wheelrail::app::main()
}
