//! `wheelrail fleet` run as a user runs it (issue 14): its rows against single `wheelrail
//! report` runs of the same scene (the same code path: equal to the last printed digit), the
//! same CSV on 1 and 2 threads and from shards, bad files in the middle of a fleet, pairs,
//! rails, and the failures that stop a fleet before anything is written.

mod common;

use common::fleet::{assert_row_is_report, fleet, generated, read, rows, single_report};
use common::{assert_clean_failure, bin, root, scratch, stderr};
use sha2::Digest;
use std::path::{Path, PathBuf};
use wheelrail::fleet::synthetic;

/// The default fleet scene's keys with a Hertz figure (rigid contact: cheap), so that the
/// rows carry `max_p0_MPa` too. `{wheel}` is replaced by the wheel profile.
const HERTZ_TEMPLATE: &str = r#"
name = "fleet_hertz"
[wheel]
profile = "{wheel}"
nominal_radius_mm = 460.0
smoothing_wavelength_mm = 4.0
drop_step_backs = true
[rail]
profile = "UIC60E1"
inclination = "1:40"
[sweep]
from_mm = -10.0
to_mm = 10.0
step_mm = 0.1
[hertz]
contact = "rigid"
[fleet]
conicity_limit = 0.3
[outputs]
figures = ["equivalent_conicity", "pressure"]
formats = ["svg"]
"#;

#[test]
fn fleet_rows_equal_single_reports_of_the_same_scene() {
    let dir = scratch("fleet-equal");
    let mut files = generated(&dir, 5);
    files.push(root().join("tests/data/profiles/Car7216_0001r.whl"));
    let template = |wheel: &Path| HERTZ_TEMPLATE.replace("{wheel}", &wheel.display().to_string());
    let scene = dir.join("fleet.toml");
    std::fs::write(&scene, template(Path::new("S1002"))).unwrap();
    let args: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    // Without --reports the summary computes the conicity of one method from the rigid
    // sweep; with it the whole stage runs for the pair's report: the same rows.
    let plain = dir.join("plain");
    let o = fleet(&scene, &args, &plain, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = dir.join("out");
    let o = fleet(&scene, &args, &out, &["--reports"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let fleet_rows = rows(&read(&plain.join("fleet.csv")));
    assert_eq!(fleet_rows, rows(&read(&out.join("fleet.csv"))));
    assert_eq!(fleet_rows.len(), files.len());
    for (row, file) in fleet_rows.iter().zip(&files) {
        assert_eq!(row["status"], "ok");
        assert_eq!(Path::new(&row["wheel_file"]), file.as_path());
        assert_eq!(
            row["wheel_sha256"],
            format!("{:x}", sha2::Sha256::digest(std::fs::read(file).unwrap()))
        );
        // An independent run: `wheelrail report` on the template with this wheel.
        let id = &row["id"];
        let report = single_report(&dir, &format!("single-{id}"), &template(file));
        assert_row_is_report(row, &report);
        // The pair's report written by --reports holds the same numbers.
        assert_row_is_report(row, &out.join(id));
        assert!(out.join(id).join("pressure.svg").exists());
    }
    assert!(!out.join(wheelrail_cli::fleet::PARTIAL_CSV).exists());
    let page = read(&out.join("index.html"));
    assert!(
        page.contains("Pairs over the limit tan γe(3 mm) &gt; 0.3"),
        "{page}"
    );
}

#[test]
fn one_or_two_threads_and_shards_give_the_same_csv() {
    let dir = scratch("fleet-threads");
    let files = generated(&dir, 24);
    let args: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let scene = root().join("reports/fleet/scene.toml");
    let run = |name: &str, threads: &str, extra: &[&str]| -> String {
        let out = dir.join(name);
        let o = bin()
            .env("RAYON_NUM_THREADS", threads)
            .arg("fleet")
            .arg(&scene)
            .args(&args)
            .arg("--out")
            .arg(&out)
            .args(extra)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
        read(&out.join("fleet.csv"))
    };
    let one = run("one", "1", &[]);
    let two = run("two", "2", &[]);
    assert_eq!(rows(&one).len(), 24);
    assert!(one == two, "fleet.csv differs between 1 and 2 threads");
    // Parts concatenated in order, each without its header lines, are the whole file.
    for n in [2, 3, 5] {
        let mut joined = String::new();
        for k in 1..=n {
            let part = run(
                &format!("shard-{k}-of-{n}"),
                "2",
                &["--shard", &format!("{k}/{n}")],
            );
            if k == 1 {
                joined.push_str(&part);
            } else {
                let body: Vec<&str> = part
                    .lines()
                    .filter(|l| !l.starts_with('#'))
                    .skip(1)
                    .collect();
                for l in body {
                    joined.push_str(l);
                    joined.push('\n');
                }
            }
        }
        assert!(
            joined == one,
            "shards of {n} do not concatenate to the whole"
        );
    }
}

#[test]
fn bad_files_in_the_middle_give_error_rows_and_exit_3() {
    let dir = scratch("fleet-bad");
    let good = generated(&dir, 3);
    // Wheel files, each broken in one way (the reader's fixtures in tests/data/profiles/bad
    // are mostly rail files: wheel versions are written here).
    let empty = dir.join("empty.csv");
    std::fs::write(&empty, "").unwrap();
    let text = read(&good[0]);
    let non_numeric = dir.join("non_numeric.csv");
    std::fs::write(&non_numeric, text.replacen("-60.000,", "-60.000x,", 1)).unwrap();
    let metres = dir.join("metres.csv");
    let in_metres: String = text
        .lines()
        .map(|l| match l.split_once(',') {
            Some((s, f)) if !l.starts_with('#') && s != "s_mm" => format!(
                "{},{}\n",
                s.parse::<f64>().unwrap() / 1000.0,
                f.parse::<f64>().unwrap() / 1000.0
            ),
            _ => format!("{l}\n"),
        })
        .collect();
    std::fs::write(&metres, in_metres).unwrap();
    // A measured wheel that folds back at its flange tip (line 223), under a template that
    // refuses such points.
    let folded = root().join("tests/data/profiles/Car7216_0001r.whl");
    let scene = dir.join("strict.toml");
    std::fs::write(
        &scene,
        read(&root().join("reports/fleet/scene.toml"))
            .replace("drop_step_backs = true", "drop_step_backs = false"),
    )
    .unwrap();
    let list: Vec<&Path> = vec![
        &good[0],
        &empty,
        &good[1],
        &non_numeric,
        &metres,
        &folded,
        &good[2],
    ];
    let out = dir.join("out");
    let o = fleet(&scene, &list, &out, &[]);
    assert_clean_failure(&o, 3, &["7 rows (3 ok, 4 failed)"]);
    let text = read(&out.join("fleet.csv"));
    // Every NaN is explained: by the status of a failed row, by undefined_status otherwise.
    assert_eq!(
        common::unflagged_non_finite("fleet.csv", &text),
        Vec::<String>::new()
    );
    let got = rows(&text);
    assert_eq!(got.len(), 7);
    let expect_error = [
        (1, "empty.csv", "empty"),
        (3, "non_numeric.csv:", "non-numeric"),
        (4, "metres.csv", "metres"),
        (5, "Car7216_0001r.whl:223", "drop_step_backs"),
    ];
    for (i, file, words) in expect_error {
        let status = &got[i]["status"];
        assert!(status.contains(file), "row {i}: {status}");
        assert!(status.to_lowercase().contains(words), "row {i}: {status}");
        assert_eq!(got[i]["tan_gamma_e_3mm"], "NaN");
        assert_eq!(
            got[i]["wheel_sha256"].len(),
            64,
            "row {i}: the file was readable"
        );
    }
    // The good rows are complete: the same as a fleet of the good files alone.
    let alone = dir.join("alone");
    let good_args: Vec<&Path> = good.iter().map(PathBuf::as_path).collect();
    let o = fleet(&scene, &good_args, &alone, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let expected = rows(&read(&alone.join("fleet.csv")));
    for (row, want) in [0, 2, 6].iter().map(|&i| &got[i]).zip(&expected) {
        assert_eq!(row, want);
        assert_eq!(row["status"], "ok");
        assert!(row["tan_gamma_e_3mm"].parse::<f64>().unwrap().is_finite());
    }
    // The page lists the failed rows.
    let page = read(&out.join("index.html"));
    assert!(page.contains("non_numeric"), "{page}");
}

#[test]
fn a_fleet_that_cannot_run_exits_2_and_writes_nothing() {
    let dir = scratch("fleet-nothing");
    let files = generated(&dir, 1);
    let good_scene = root().join("reports/fleet/scene.toml");
    let bad_scene = dir.join("bad.toml");
    std::fs::write(&bad_scene, "[fleet]\nconicity_limit = -0.4\n").unwrap();
    let long = dir.join("long.toml");
    std::fs::write(
        &long,
        "[quasi_elastic]\nquadrature = \"trapezoid\"\nmax_step_mm = 0.0001\ncutoff = 700\n[outputs]\nfigures = [\"qe_contact_points\"]\n",
    )
    .unwrap();
    let unknown = dir.join("unknown.toml");
    std::fs::write(&unknown, "[fleet]\nlimit = 0.4\n").unwrap();
    let pairs = |name: &str, text: &str| -> PathBuf {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let header_only = pairs("header_only.csv", "id,left_wheel,right_wheel\n");
    let twice = pairs(
        "twice.csv",
        "id,left_wheel,right_wheel\nws1,a.csv,b.csv\nws1,c.csv,d.csv\n",
    );
    let bad_column = pairs("bad_column.csv", "id,left,right\nws1,a.csv,b.csv\n");
    let clash = pairs(
        "clash.csv",
        "id,left_wheel,right_wheel\nindex.html,a.csv,b.csv\n",
    );
    let cases: Vec<(Vec<String>, Vec<&str>)> = vec![
        (
            vec![
                bad_scene.display().to_string(),
                files[0].display().to_string(),
            ],
            vec!["fleet.conicity_limit"],
        ),
        (
            vec![
                unknown.display().to_string(),
                files[0].display().to_string(),
            ],
            vec!["limit", "unknown field"],
        ),
        (
            vec![long.display().to_string(), files[0].display().to_string()],
            vec!["each pair", "gap evaluations", "--allow-long"],
        ),
        (
            vec![
                good_scene.display().to_string(),
                "--pairs".into(),
                header_only.display().to_string(),
            ],
            vec!["header_only.csv", "no pairs"],
        ),
        (
            vec![
                good_scene.display().to_string(),
                "--pairs".into(),
                twice.display().to_string(),
            ],
            vec!["twice.csv:3", "ws1", "twice"],
        ),
        (
            vec![
                good_scene.display().to_string(),
                "--pairs".into(),
                bad_column.display().to_string(),
            ],
            vec!["bad_column.csv:1", "unknown column \"left\""],
        ),
        (
            vec![
                good_scene.display().to_string(),
                files[0].display().to_string(),
                "--shard".into(),
                "3/2".into(),
            ],
            vec!["--shard", "K/N"],
        ),
        (
            vec![
                good_scene.display().to_string(),
                "--pairs".into(),
                clash.display().to_string(),
                "--reports".into(),
            ],
            vec!["\"index.html\"", "--reports"],
        ),
    ];
    for (i, (args, words)) in cases.iter().enumerate() {
        let out = dir.join(format!("out-{i}"));
        let o = bin()
            .arg("fleet")
            .args(args)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        assert_clean_failure(&o, 2, words);
        assert!(!out.exists(), "case {i}: {} was created", out.display());
    }
    // No profile at all: the command line refuses (clap's usage error, also exit 2).
    let o = bin()
        .arg("fleet")
        .arg(&good_scene)
        .arg("--out")
        .arg(dir.join("none"))
        .output()
        .unwrap();
    assert_clean_failure(&o, 2, &["PROFILES"]);
}

/// A run stopped half-way keeps every row it finished, whole and in order, in
/// `fleet.csv.partial`; `fleet.csv` appears only when a run completes.
#[test]
fn an_interrupted_fleet_keeps_its_finished_rows() {
    let dir = scratch("fleet-interrupted");
    let files = generated(&dir, 1000);
    let out = dir.join("out");
    let mut child = bin()
        .env("RAYON_NUM_THREADS", "1")
        .arg("fleet")
        .arg(root().join("reports/fleet/scene.toml"))
        .args(&files)
        .arg("--out")
        .arg(&out)
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let partial = out.join(wheelrail_cli::fleet::PARTIAL_CSV);
    // About 2 ms a profile on one thread: 1000 take seconds; stop after 20 rows.
    let start = std::time::Instant::now();
    loop {
        let done = std::fs::read_to_string(&partial)
            .map(|t| t.lines().filter(|l| l.starts_with("worn_")).count())
            .unwrap_or(0);
        if done >= 20 {
            break;
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it was stopped"
        );
        assert!(start.elapsed().as_secs() < 60, "no rows after 60 s");
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(!out.join("fleet.csv").exists());
    // `rows` reads with the csv crate, which refuses a row with fewer cells than the header.
    let kept = rows(&read(&partial));
    assert!(kept.len() >= 20 && kept.len() < 1000, "{} rows", kept.len());
    for (i, row) in kept.iter().enumerate() {
        assert_eq!(row["id"], format!("worn_{i:04}"));
        assert_eq!(row["status"], "ok");
    }
}

/// The committed example fleet `reports/fleet/` is what the README's two commands write:
/// the generated wheels (the example `worn_wheels`, seed 14) under `target/worn_wheels`, and
/// the fleet of the CONTACT wheels and those, in the shell's glob order. Every file the
/// fleet writes is compared byte for byte, so a change that moves a number, a chart or the
/// page shows here and is committed with the regenerated folder.
#[test]
fn the_committed_example_fleet_regenerates() {
    let generated = root().join("target/worn_wheels");
    std::fs::create_dir_all(&generated).unwrap();
    for i in 0..300 {
        let (text, _) = synthetic::csv_text(14, i);
        std::fs::write(generated.join(format!("worn_{i:04}.csv")), text).unwrap();
    }
    let listed = |dir: &str, ext: &str| -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(root().join(dir))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(ext))
            .map(|n| format!("{dir}/{n}"))
            .collect();
        names.sort(); // the shell's glob order in the C locale: bytes
        names
    };
    let mut profiles = listed("tests/data/profiles", ".whl");
    profiles.extend(listed("tests/data/profiles", ".prw"));
    profiles.extend((0..300).map(|i| format!("target/worn_wheels/worn_{i:04}.csv")));
    let out = scratch("example_fleet");
    let o = bin()
        .current_dir(root())
        .arg("fleet")
        .arg("reports/fleet/scene.toml")
        .args(&profiles)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let committed = root().join("reports/fleet");
    let mut compared = 0;
    for entry in std::fs::read_dir(&out).unwrap() {
        let name = entry.unwrap().file_name();
        let name = name.to_string_lossy();
        if name.starts_with('.') {
            continue; // the manifest names the folder's own history
        }
        let fresh = std::fs::read(out.join(name.as_ref())).unwrap();
        let kept = std::fs::read(committed.join(name.as_ref()))
            .unwrap_or_else(|e| panic!("reports/fleet/{name}: {e}: commit the regenerated folder"));
        assert!(
            fresh == kept,
            "reports/fleet/{name} differs from a fresh run: regenerate it with the README's commands and review the diff"
        );
        compared += 1;
    }
    assert!(compared >= 8, "only {compared} files compared");
}

/// Generated wheel 49 of the example fleet (seed 14) at `y_ws = +-3.1` mm: the scan at the
/// root puts two minima of one wheel 0.27 mm apart in one bracket (s = 16.287 and 16.554 mm)
/// and Newton finds the higher; the certificate finds the lower, and the basin of the next
/// scan that holds both must take the lower known one, not the first (which cycled between
/// the two roots 1.6e-8 rad apart up to the iteration cap and lost the row's conicity).
/// Every position of the fleet's sweep converges.
#[test]
fn two_minima_in_one_bracket_of_a_generated_wheel_converge() {
    let dir = scratch("fleet_worn_0049");
    let wheel = dir.join("worn_0049.csv");
    std::fs::write(&wheel, synthetic::csv_text(14, 49).0).unwrap();
    let template = std::fs::read_to_string(root().join("reports/fleet/scene.toml")).unwrap();
    let text = template.replace(
        "profile = \"S1002\"",
        &format!("profile = \"{}\"", wheel.display()),
    );
    let scene = wheelrail::scene::Scene::from_toml(&text, "worn_0049.toml", &dir).unwrap();
    let placement = wheelrail::pipeline::place(&scene).unwrap();
    let sweep = wheelrail::rigid::search(
        &placement,
        scene.sweep(),
        wheelrail::rigid::Solver::default(),
    );
    for p in sweep.positions() {
        assert_eq!(p.stop, wheelrail::Stop::Converged, "y_ws = {}", p.y_ws);
    }
}

/// The fleet's rows as one table (`outputs::fleet::table`, what the Python package returns)
/// hold what `fleet.csv` prints: the same columns, and each cell written as the CSV writes
/// it is the CSV's text (a good row with Hertz columns, a row whose file is missing, and a
/// count column among the numbers).
#[test]
fn the_fleet_table_holds_the_csv_lines() {
    use wheelrail::fleet::{Fleet, Inputs, items_of_files};
    use wheelrail_report::ColumnData;
    use wheelrail_report::outputs::{self, CSV_FORMAT};
    use wheelrail_report::table::format_number;

    let dir = scratch("fleet-table");
    let mut files = generated(&dir, 2);
    files.insert(1, dir.join("missing.csv"));
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, HERTZ_TEMPLATE.replace("{wheel}", "S1002")).unwrap();
    let template = wheelrail::scene::Scene::load(&scene).unwrap();
    let items = items_of_files(&files, false);
    let fleet = Fleet::new(template, Inputs::Wheels, &items, false).unwrap();
    let mut rows = Vec::new();
    fleet.assess_in_order(&items, |item| fleet.assess(item), |_, row| rows.push(row));
    let table = outputs::fleet::table(&fleet, &rows).unwrap();
    assert_eq!(
        table.column_names().collect::<Vec<_>>(),
        outputs::fleet::columns(&fleet)
    );
    assert!(
        table.numeric("max_p0_MPa").is_some() && table.numeric("contact_point_jumps").is_some()
    );
    let csv: String = rows
        .iter()
        .map(|r| outputs::fleet::csv_line(&fleet, r))
        .collect();
    let expected = self::rows(&format!(
        "{}\n{csv}",
        outputs::fleet::columns(&fleet).join(",")
    ));
    assert_eq!(expected.len(), 3);
    assert!(
        expected[1]["status"].contains("missing.csv"),
        "{:?}",
        expected[1]
    );
    for column in table.columns() {
        for (i, row) in expected.iter().enumerate() {
            let cell = match &column.data {
                ColumnData::Numeric(v)
                    if ["contact_point_jumps", "sampling_artefacts"]
                        .contains(&column.name.as_str()) =>
                {
                    format!("{}", v[i])
                }
                ColumnData::Numeric(v) => format_number(v[i], CSV_FORMAT),
                ColumnData::Text(t) => t[i].to_string(),
            };
            assert_eq!(cell, row[&column.name], "row {i}, column {}", column.name);
        }
    }
}
