//! Flange dimensions against an independent computation on the raw points: the Python script
//! `scripts/flange_dimensions.py` (its own readers, the points as the files list them joined
//! by straight lines, no points dropped, no smoothing) wrote `tests/data/flange_dimensions.csv`
//! for every wheel of the example fleet `reports/fleet/`: the MiniProf and SIMPACK wheels of
//! `tests/data/profiles/` and the 300 generated worn S1002 wheels (seed 14), by
//!
//! ```sh
//! cargo run --release --example worn_wheels -- target/worn_wheels 300
//! python3 scripts/flange_dimensions.py tests/data/profiles/*.whl tests/data/profiles/*.prw target/worn_wheels/*.csv > tests/data/flange_dimensions.csv
//! ```
//!
//! wheelrail reads the same files as the fleet's template scene does (its smoothing filter
//! for the contact, points that step back at the flange tip dropped) and measures the points.

use sha2::Digest;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use wheelrail::fleet::{Fleet, Inputs, items_of_files, synthetic};
use wheelrail::maintenance::flange_dimensions;
use wheelrail::scene::Scene;

/// The script prints six decimals: its numbers are within 5e-7 mm of what it computed, and
/// both sides measure the same straight lines between the same points, so they agree to
/// that rounding (the largest differences are printed with `--nocapture`). Far inside the
/// 0.01 mm (a gauge's resolution) that wheelrail must agree with the script to.
const SCRIPT_ROUNDING_MM: f64 = 1e-6;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// One row of the script's table.
#[derive(Debug, Clone)]
struct ScriptRow {
    file: String,
    sha256: String,
    /// Sh, Sd, qR and F(0) (mm); NaN where undefined.
    values: [f64; 4],
    status: String,
}

/// The script's table, in its row order.
fn reference() -> Vec<ScriptRow> {
    let text = std::fs::read_to_string(root().join("tests/data/flange_dimensions.csv")).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let cols = ["sh_mm", "sd_mm", "qr_mm", "taping_line_F_mm"].map(column);
    let (file, sha256, status) = (column("file"), column("sha256"), column("status"));
    lines
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            ScriptRow {
                file: cells[file].to_string(),
                sha256: cells[sha256].to_string(),
                values: cols.map(|c| cells[c].parse().unwrap()),
                status: cells[status].to_string(),
            }
        })
        .collect()
}

/// The wheel files of the example fleet, as the README's commands give them: the committed
/// `.whl` and `.prw` wheels in the shell's glob order, then the generated worn wheels
/// written into a folder of this test.
fn fleet_wheels() -> Vec<PathBuf> {
    let listed = |ext: &str| -> Vec<PathBuf> {
        let dir = root().join("tests/data/profiles");
        let mut names: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == ext))
            .collect();
        names.sort();
        names
    };
    let mut paths = listed("whl");
    paths.extend(listed("prw"));
    let generated = Path::new(env!("CARGO_TARGET_TMPDIR")).join("flange_dimensions_worn_wheels");
    std::fs::create_dir_all(&generated).unwrap();
    for i in 0..300 {
        let path = generated.join(format!("worn_{i:04}.csv"));
        std::fs::write(&path, synthetic::csv_text(14, i).0).unwrap();
        paths.push(path);
    }
    paths
}

/// Every wheel of the example fleet, read as the fleet's template scene reads it (the 4 mm
/// contact filter, points that step back dropped), against the script on its raw points:
/// Sh, Sd, qR and F(0) agree to the script's rounding, far inside the 0.01 mm asked for.
/// Car7216's tip steps back 0.6 mm and zig-zags (its lines 223-229): the points the reader
/// drops there lie 0.2 to 0.4 mm below the tip it keeps, above both flank levels, so they
/// change no dimension. The wheel the script finds too low to measure (circ_r100, an arc
/// with its top on the taping line) is undefined in wheelrail too.
#[test]
fn measured_wheels_match_the_independent_script() {
    let script = reference();
    let paths = fleet_wheels();
    assert_eq!(script.len(), paths.len(), "one script row per fleet wheel");
    let template = Scene::load(&root().join("reports/fleet/scene.toml")).unwrap();
    let items = items_of_files(&paths, false);
    let fleet = Fleet::new(template, Inputs::Wheels, &items, false).unwrap();
    let (mut compared, mut undefined) = (0, 0);
    let mut largest = [0.0_f64; 4];
    for ((item, path), row) in items.iter().zip(&paths).zip(&script) {
        let name = path.file_name().unwrap().to_string_lossy();
        assert_eq!(row.file, name, "the script's rows in the fleet's order");
        let bytes = std::fs::read(path).unwrap();
        assert_eq!(
            row.sha256,
            format!("{:x}", sha2::Sha256::digest(&bytes)),
            "{name}: the script measured other bytes (regenerate its table)"
        );
        let scene = fleet.scene_for(item);
        let wheels = wheelrail::pipeline::place_wheels(&scene).unwrap();
        let d = flange_dimensions(wheels[0].profile());
        if row.status != "ok" {
            assert!(
                d.is_err(),
                "{name}: the script says {}, got {d:?}",
                row.status
            );
            undefined += 1;
            continue;
        }
        let d = d.unwrap_or_else(|e| panic!("{name}: {e}"));
        let got = [d.sh_mm, d.sd_mm, d.qr_mm, d.taping_line_height_mm];
        for (k, (what, (got, want))) in ["Sh", "Sd", "qR", "F(0)"]
            .iter()
            .zip(got.iter().zip(row.values))
            .enumerate()
        {
            let diff = (got - want).abs();
            largest[k] = largest[k].max(diff);
            assert!(
                diff < SCRIPT_ROUNDING_MM,
                "{name} {what}: {got} against the script's {want}"
            );
        }
        if !name.starts_with("worn_") {
            println!(
                "{name}: Sh {:.4} Sd {:.4} qR {:.4} mm",
                d.sh_mm, d.sd_mm, d.qr_mm
            );
        }
        compared += 1;
    }
    println!(
        "{compared} wheels compared, {undefined} undefined; largest differences from the script: Sh {:.1e}, Sd {:.1e}, qR {:.1e}, F(0) {:.1e} mm",
        largest[0], largest[1], largest[2], largest[3]
    );
    // 3 MiniProf, 1 SIMPACK S1002 and 300 generated wheels; the R100 arc has no flange.
    assert_eq!((compared, undefined), (304, 1));
}

/// The committed example fleet (`reports/fleet/fleet.csv`, which `crates/cli/tests/fleet.rs` checks is
/// what the fleet writes) reports the script's dimensions for each of its wheels, matched
/// by the SHA-256 of the file: within the script's rounding and the table's ten
/// significant digits, NaN where the script finds no flange to measure.
#[test]
fn the_example_fleet_reports_the_scripts_dimensions() {
    let script: HashMap<String, ScriptRow> = reference()
        .into_iter()
        .map(|r| (r.sha256.clone(), r))
        .collect();
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_path(root().join("reports/fleet/fleet.csv"))
        .unwrap();
    let header = reader.headers().unwrap().clone();
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let sha = column("wheel_sha256");
    let cols = ["sh_mm", "sd_mm", "qr_mm"].map(column);
    let (mut compared, mut undefined) = (0, 0);
    for record in reader.records() {
        let record = record.unwrap();
        let row = &script[&record[sha]];
        let got = cols.map(|c| record[c].parse::<f64>().unwrap());
        if row.status != "ok" {
            assert!(got.iter().all(|v| v.is_nan()), "{}: {got:?}", row.file);
            undefined += 1;
            continue;
        }
        for (what, (got, want)) in ["Sh", "Sd", "qR"].iter().zip(got.iter().zip(row.values)) {
            // Ten significant digits of a number below 100: within 1e-8 mm.
            assert!(
                (got - want).abs() < SCRIPT_ROUNDING_MM + 1e-8,
                "{} {what}: fleet.csv {got}, the script {want}",
                row.file
            );
        }
        compared += 1;
    }
    assert_eq!((compared, undefined), (304, 1));
}

/// The MiniProf header line `32.58 37.11 14.71 (Sd/Sh/qR)` is the same in all three files
/// and is not these wheels' measurement: Sh = 37.11 mm would put the taping-line point 9 mm
/// below the tread (the tip of Car7216 is 27.7 mm above the file's F(0) = 0.10 mm).
#[test]
fn the_files_header_dimensions_are_not_the_profiles() {
    let script = reference();
    let car7216 = script
        .iter()
        .find(|r| r.file == "Car7216_0001r.whl")
        .unwrap();
    let points = wheelrail::profile::read::read_profile_with(
        &root().join("tests/data/profiles/Car7216_0001r.whl"),
        wheelrail::profile::ProfileKind::Wheel,
        &wheelrail::profile::read::ReadOptions::new(wheelrail::profile::read::StepBack::Drop),
    )
    .unwrap();
    let wheel = wheelrail::profile::Profile::from_points(points, 0.0).unwrap();
    let d = flange_dimensions(&wheel).unwrap();
    assert!((d.sh_mm - 37.11).abs() > 9.0, "{d:?}");
    assert!((car7216.values[0] - 37.11).abs() > 9.0, "{car7216:?}");
}
