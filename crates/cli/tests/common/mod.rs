//! The fixtures of `tests/common` (the checkout's root, scratch folders, the check of a
//! CSV's non-finite numbers) and the `wheelrail` program these tests run.
#![allow(dead_code)]

#[path = "../../../../tests/common/mod.rs"]
mod shared;

pub mod fleet;

pub use shared::*;
use std::path::Path;
use std::process::{Command, Output};

/// The `wheelrail` binary, run from the checkout's root.
pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_wheelrail"));
    c.current_dir(root());
    c
}

/// Writes `text` as `dir/scene.toml` and runs `wheelrail report` on it into `dir/out`.
pub fn report_scene(dir: &Path, text: &str) -> Output {
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    bin()
        .arg("report")
        .arg(&scene)
        .arg("--out")
        .arg(dir.join("out"))
        .output()
        .unwrap()
}
