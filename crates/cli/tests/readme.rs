//! The README says only what is true: the statements a test can hold to the code are held
//! here (the command list; the golden tolerances, in docs/golden-files.md).

fn readme() -> String {
    std::fs::read_to_string(concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/README.md"
    ))
    .unwrap()
}

#[test]
fn the_golden_tolerance_table_is_the_codes() {
    let table = wheelrail_cli::golden_policy().markdown();
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/golden-files.md"
    ))
    .unwrap();
    assert!(
        doc.contains(&table),
        "docs/golden-files.md's tolerance table differs from wheelrail_cli::golden_policy; expected:\n{table}"
    );
}

#[test]
fn every_command_is_in_the_readme() {
    use clap::CommandFactory;
    let readme = readme();
    for command in wheelrail_cli::Cli::command().get_subcommands() {
        let name = command.get_name();
        assert!(
            readme.contains(&format!("wheelrail {name}")),
            "`wheelrail {name}` is not in the README"
        );
    }
}

/// The README's library example is `examples/own_profiles.rs` (which CI runs): each of its
/// lines of code is a line of the example, in order.
#[test]
fn the_library_example_is_the_examples() {
    let readme = readme();
    let section = &readme[readme.find("## Use as a library").unwrap()..];
    let start = section.find("```rust\n").unwrap() + "```rust\n".len();
    let block = &section[start..start + section[start..].find("```").unwrap()];
    let example = std::fs::read_to_string(concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/examples/own_profiles.rs"
    ))
    .unwrap();
    let mut lines = example.lines().map(str::trim);
    let code = |l: &&str| !l.is_empty() && !l.starts_with("//");
    for wanted in block.lines().map(str::trim).filter(code) {
        assert!(
            lines.any(|l| l == wanted),
            "README line {wanted:?} is not in examples/own_profiles.rs (in order)"
        );
    }
}

/// The README is for users: what the tool does, how to run and use it, what it was
/// validated against and how fast it is, in at most 450 lines; the record of measurements
/// lives in `docs/`.
#[test]
fn the_readme_stays_short() {
    let lines = readme().lines().count();
    assert!(lines <= 450, "README.md has {lines} lines, at most 450");
}
