//! The README says only what is true: the statements a test can hold to the code are held
//! here (golden tolerances, the command list).

fn readme() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap()
}

#[test]
fn the_golden_tolerance_table_is_the_codes() {
    let table = wheelrail::app::golden_policy().markdown();
    assert!(
        readme().contains(&table),
        "README's golden tolerance table differs from app::golden_policy; expected:\n{table}"
    );
}

#[test]
fn every_command_is_in_the_readme() {
    use clap::CommandFactory;
    let readme = readme();
    for command in wheelrail::app::Cli::command().get_subcommands() {
        let name = command.get_name();
        assert!(
            readme.contains(&format!("wheelrail {name}")),
            "`wheelrail {name}` is not in the README"
        );
    }
}
