//! The `wheelrail` command line (placeholder, being written).
fn main() {}
