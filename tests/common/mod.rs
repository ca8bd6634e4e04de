//! Fixtures shared by the integration tests of the numerics and of the program
//! (`crates/cli/tests/common` includes this file): the checkout's root, scratch folders, the
//! Manchester cases, and the check that every non-finite number of a CSV output is flagged.
//! Each test file uses some of them (`mod common;`), hence the `dead_code` allowance.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Output;

/// The checkout's root.
pub fn root() -> &'static Path {
    // This file is compiled into the tests of the root package and of `crates/cli`.
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest
        .ancestors()
        .find(|dir| dir.join("reports/paper/scene.toml").is_file())
        .unwrap_or(manifest)
}

/// A fresh, empty folder under the target directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = root().join("target/test-scratch").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Exit code `code`, no panic, and every piece of `must_contain` in standard error.
pub fn assert_clean_failure(o: &Output, code: i32, must_contain: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(code), "stderr: {err}");
    assert!(!err.contains("panicked"), "panic: {err}");
    for m in must_contain {
        assert!(err.contains(m), "expected {m:?} in: {err}");
    }
}

/// A run's standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Parts of a status that say a row was computed normally: a non-finite number next to
/// only these is unflagged.
const SUCCESS: [&str; 7] = [
    "ok",
    "converged",
    "two patches",
    "two-point contact left",
    "two-point contact right",
    // The profile tables' `face` column: an ordinary face of the profile.
    "regular",
    "running",
];

/// Whether a status cell says why its row is not a normal result: some `;`-separated part
/// of it is not a plain success word.
fn flags(status: &str) -> bool {
    status
        .split(';')
        .map(str::trim)
        .any(|part| !part.is_empty() && !SUCCESS.contains(&part))
}

/// Splits one CSV line on commas outside double quotes (the tables quote text with commas).
fn cells(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            _ => out.last_mut().unwrap().push(c),
        }
    }
    out
}

/// The non-finite numbers of `csv` (the text of `file`) that no status explains, as
/// `file: column, row n (status "...")` lines.
///
/// A non-finite cell is flagged when
/// * its column is documented to hold NaN for "none" (`second_*` columns: "NaN if none" in
///   the table's header), or
/// * a status column of its row flags the row: the side's own `left_status`/`right_status`
///   for `left_*`/`right_*` columns where the table has one, else any column whose name
///   contains `status` or `flag`, or the profile tables' `face` column (`vertical`,
///   `flank`).
pub fn unflagged_non_finite(file: &str, csv: &str) -> Vec<String> {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let Some(header) = lines.next() else {
        return Vec::new();
    };
    let header = cells(header);
    let status_columns: Vec<usize> = header
        .iter()
        .enumerate()
        .filter(|(_, h)| h.contains("status") || h.contains("flag") || *h == "face")
        .map(|(i, _)| i)
        .collect();
    let mut out = Vec::new();
    for (n, line) in lines.enumerate() {
        let row = cells(line);
        for (i, cell) in row.iter().enumerate() {
            let Ok(v) = cell.trim().parse::<f64>() else {
                continue;
            };
            if v.is_finite() {
                continue;
            }
            let column = header.get(i).map_or("?", String::as_str);
            if column.contains("second") {
                continue;
            }
            let side_status: Vec<usize> = ["left_", "right_"]
                .iter()
                .filter(|p| column.starts_with(*p))
                .filter_map(|p| header.iter().position(|h| *h == format!("{p}status")))
                .collect();
            let relevant = if side_status.is_empty() {
                &status_columns
            } else {
                &side_status
            };
            let statuses: Vec<&str> = relevant
                .iter()
                .filter_map(|&j| row.get(j).map(String::as_str))
                .collect();
            if !statuses.iter().any(|s| flags(s)) {
                out.push(format!(
                    "{file}: {column} = {cell}, data row {} (status {statuses:?})",
                    n + 1
                ));
            }
        }
    }
    out
}

/// [`unflagged_non_finite`] over every CSV file of a folder.
pub fn unflagged_in_folder(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return out;
    };
    let mut files: Vec<_> = entries.flatten().map(|e| e.path()).collect();
    files.sort();
    for f in files {
        if f.extension().is_some_and(|e| e == "csv") {
            let text = std::fs::read_to_string(&f).unwrap_or_default();
            out.extend(unflagged_non_finite(&f.display().to_string(), &text));
        }
    }
    out
}

/// The `y_ws_mm` column of a CSV text, if it has one.
pub fn y_ws_column(csv: &str) -> Option<Vec<f64>> {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let header = cells(lines.next()?);
    let i = header.iter().position(|h| h == "y_ws_mm")?;
    Some(
        lines
            .map(|l| {
                cells(l)
                    .get(i)
                    .and_then(|c| c.trim().parse().ok())
                    .unwrap_or(f64::NAN)
            })
            .collect(),
    )
}

/// Whether `v` increases strictly (NaN fails).
pub fn strictly_increasing(v: &[f64]) -> bool {
    v.windows(2).all(|w| w[0] < w[1])
}

/// One row of CONTACT's given wheel-cases of the Manchester case
/// (`tests/data/contact/manchester_a22_given.csv`): its wheel and its numbers by column name,
/// as printed (CONTACT's frame: read the file's header).
pub struct GivenCase {
    /// The wheel.
    pub side: wheelrail::track::Side,
    header: std::rc::Rc<Vec<String>>,
    fields: Vec<String>,
}

impl GivenCase {
    /// The number in column `name` (a trailing `.` of CONTACT's print dropped).
    pub fn num(&self, name: &str) -> f64 {
        let i = self.header.iter().position(|h| h == name).unwrap();
        self.fields[i].trim_end_matches('.').parse().unwrap()
    }
}

/// CONTACT's six given wheel-cases of, in the file's order.
pub fn manchester_given() -> Vec<GivenCase> {
    let text = std::fs::read_to_string(root().join("tests/data/contact/manchester_a22_given.csv"))
        .unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let header = std::rc::Rc::new(header);
    lines
        .map(|l| {
            let fields: Vec<String> = l.split(',').map(String::from).collect();
            let side = if fields[0] == "left" {
                wheelrail::track::Side::Left
            } else {
                wheelrail::track::Side::Right
            };
            GivenCase {
                side,
                header: std::rc::Rc::clone(&header),
                fields,
            }
        })
        .collect()
}
