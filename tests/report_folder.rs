//! A report folder shows exactly one run: a failed run leaves the old report byte for byte,
//! files of an earlier run that the new run does not write disappear, and files wheelrail
//! did not write are kept (issue: "one run per folder, all or nothing").

mod common;

use common::{bin, scratch, stderr};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Output;

fn report(scene: &Path, out: &Path) -> Output {
    bin()
        .arg("report")
        .arg(scene)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// Two small scenes: profiles and slopes, and profiles only (SVG only, to stay fast).
fn scenes(dir: &Path) -> (PathBuf, PathBuf) {
    let write = |name: &str, figures: &str| {
        let path = dir.join(name);
        std::fs::write(
            &path,
            format!(
                "name = \"{}\"\n[outputs]\nfigures = [{figures}]\nformats = [\"svg\"]\n",
                name.trim_end_matches(".toml")
            ),
        )
        .unwrap();
        path
    };
    (
        write("two.toml", "\"profiles\", \"conicity\""),
        write("one.toml", "\"profiles\""),
    )
}

/// Every entry under `dir` (relative path -> contents, `None` for a folder).
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Option<Vec<u8>>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let path = e.path();
            let rel = path.strip_prefix(dir).unwrap().to_path_buf();
            if path.is_dir() {
                out.insert(rel, None);
                stack.push(path);
            } else {
                out.insert(rel, Some(std::fs::read(&path).unwrap()));
            }
        }
    }
    out
}

#[test]
fn a_folder_in_the_way_fails_the_run_and_leaves_the_old_report_byte_for_byte() {
    let dir = scratch("folder-in-the-way");
    let (two, one) = scenes(&dir);
    let out = dir.join("X");
    assert!(report(&two, &out).status.success());
    std::fs::remove_file(out.join("wheel_profile.csv")).unwrap();
    std::fs::create_dir(out.join("wheel_profile.csv")).unwrap();
    let before = snapshot(&out);
    let o = report(&one, &out);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("wheel_profile.csv: is a folder, not a file") && !err.contains("panicked"),
        "{err}"
    );
    assert_eq!(snapshot(&out), before);
}

#[test]
fn a_new_run_removes_the_old_runs_files_and_keeps_the_users() {
    let dir = scratch("stale-files");
    let (two, one) = scenes(&dir);
    let out = dir.join("X");
    assert!(report(&two, &out).status.success());
    assert!(out.join("conicity.svg").exists());
    std::fs::write(out.join("notes.txt"), "my notes").unwrap();
    let o = report(&one, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!out.join("conicity.svg").exists(), "stale figure kept");
    assert_eq!(
        std::fs::read_to_string(out.join("notes.txt")).unwrap(),
        "my notes"
    );
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(!index.contains("conicity.svg"));
    // No staging or backup folder is left behind.
    let hidden: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".wheelrail-") && n != ".wheelrail-manifest")
        .collect();
    assert!(hidden.is_empty(), "{hidden:?}");
}

#[test]
fn an_existing_file_as_the_output_folder_is_named() {
    let dir = scratch("out-is-a-file");
    let (_, one) = scenes(&dir);
    let file = dir.join("report.txt");
    std::fs::write(&file, "keep").unwrap();
    let o = report(&one, &file);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("report.txt: is a file, not a folder"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep");
}
