//! What the fleet tests share: generated wheels, the `wheelrail fleet` command, its CSV rows
//! read back, and a single report of the same scene to compare a row with.

use super::{bin, report_scene, stderr};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Output;
use wheelrail::fleet::synthetic;

/// `n` generated worn profiles (seed 14, the example fleet's) written into `dir`.
pub fn generated(dir: &Path, n: u64) -> Vec<PathBuf> {
    (0..n)
        .map(|i| {
            let path = dir.join(format!("worn_{i:04}.csv"));
            std::fs::write(&path, synthetic::csv_text(14, i).0).unwrap();
            path
        })
        .collect()
}

pub fn fleet(scene: &Path, args: &[&Path], out: &Path, extra: &[&str]) -> Output {
    let mut c = bin();
    c.arg("fleet").arg(scene).args(args).arg("--out").arg(out);
    c.args(extra);
    c.output().unwrap()
}

/// The data rows of a CSV with `#` comments, as maps from column to cell.
pub fn rows(text: &str) -> Vec<HashMap<String, String>> {
    let mut r = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let header = r.headers().unwrap().clone();
    r.records()
        .map(|rec| {
            let rec = rec.unwrap();
            header
                .iter()
                .zip(rec.iter())
                .map(|(h, c)| (h.to_string(), c.to_string()))
                .collect()
        })
        .collect()
}

pub fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Asserts that a fleet row holds the values of a report's `parameters.csv` (and of its
/// `hertz.csv`, the largest p0 and where), to the last printed digit.
pub fn assert_row_is_report(row: &HashMap<String, String>, report: &Path) {
    let parameters = rows(&read(&report.join("parameters.csv")));
    // Every parameter of the report is a column of the fleet (Parameters::rows).
    assert!(parameters.len() >= 11);
    for p in &parameters {
        let name = &p["parameter"];
        let (fleet, single) = (&row[name], &p["value"]);
        if p["unit"] == "count" {
            // Printed as an integer in fleet.csv, as a number in parameters.csv.
            assert_eq!(
                fleet.parse::<u64>().unwrap(),
                single.parse::<f64>().unwrap() as u64,
                "{name} of {}",
                row["id"]
            );
        } else {
            assert_eq!(fleet, single, "{name} of {}", row["id"]);
        }
    }
    if let Some(p0) = row.get("max_p0_MPa") {
        let hertz = rows(&read(&report.join("hertz.csv")));
        let mut best: Option<(f64, &str, &str, &str)> = None;
        for h in &hertz {
            for side in ["left", "right"] {
                let cell = &h[&format!("{side}_p0_MPa")];
                let v: f64 = cell.parse().unwrap();
                if v.is_finite() && best.is_none_or(|b| v > b.0) {
                    best = Some((v, cell, &h["y_ws_mm"], side));
                }
            }
        }
        let (_, cell, _, _) = best.expect("some Hertz ellipse");
        assert_eq!(p0, cell, "max_p0_MPa of {}", row["id"]);
        // The fleet picks the largest unrounded p0; positions whose printed p0 ties with it
        // (a symmetric scene's mirrored positions) are equally right as far as the report
        // shows.
        let tied: Vec<(&str, &str)> = hertz
            .iter()
            .flat_map(|h| ["left", "right"].map(|side| (h, side)))
            .filter(|(h, side)| h[&format!("{side}_p0_MPa")] == cell)
            .map(|(h, side)| (h["y_ws_mm"].as_str(), side))
            .collect();
        let at = (row["max_p0_y_ws_mm"].as_str(), row["max_p0_side"].as_str());
        assert!(
            tied.contains(&at),
            "{at:?} not among {tied:?} of {}",
            row["id"]
        );
    }
}

/// The output folder of `wheelrail report` on the scene `template` (run in `dir/name`).
pub fn single_report(dir: &Path, name: &str, template: &str) -> PathBuf {
    let d = dir.join(name);
    std::fs::create_dir_all(&d).unwrap();
    let o = report_scene(&d, template);
    assert!(o.status.success(), "{name}: {}", stderr(&o));
    d.join("out")
}
