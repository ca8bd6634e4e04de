//! Fixtures shared by the integration tests that run the `wheelrail` binary. Each test file
//! uses some of them (`mod common;`), hence the `dead_code` allowance.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `wheelrail` binary, run from the checkout's root.
pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_wheelrail"));
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    c
}

/// The checkout's root.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A fresh, empty folder under the target directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = root().join("target/test-scratch").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A run's standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}
