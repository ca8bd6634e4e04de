//! Regression tests for the adversarial scenes of issue 16: each reproducer that aborted,
//! ran without end, or wrote unflagged non-finite numbers, run through the binary as a user
//! runs it; and the check that every non-finite number of every table is flagged, on the
//! committed scenes.

mod common;

use common::{assert_clean_failure, report_scene, root, scratch, stderr};
use std::path::{Path, PathBuf};
use std::process::Output;
use wheelrail::quasi_elastic::{self, Quadrature, QuasiElasticSettings};
use wheelrail::scene::Scene;

/// Writes `text` as `scene.toml` in a fresh folder and runs `wheelrail report` on it.
fn run_scene(name: &str, text: &str) -> (PathBuf, Output) {
    let dir = scratch(&format!("robustness/{name}"));
    (dir.join("out"), report_scene(&dir, text))
}

/// Exit code 2, no panic, and every `words` in the message.
fn assert_refused(o: &Output, words: &[&str]) {
    assert_clean_failure(o, 2, words);
}

fn profile(name: &str) -> String {
    root()
        .join("tests/data/profiles")
        .join(name)
        .display()
        .to_string()
}

/// Aborted with SIGABRT: the trapezoid's halvings overflowed, the step became 0 and the node
/// list grew until allocation failed. Each offending key is now refused by name.
#[test]
fn trapezoid_step_at_the_largest_double_is_refused_not_aborted() {
    let base = "[rail]\ninclination = \"1:1e300\"\n[quasi_elastic]\nquadrature = \"trapezoid\"\n\
                max_step_mm = 1.7976931348623157e308\n[outputs]\nfigures = [\"qe_contact_points\"]\n\
                formats = []\n";
    let (_, o) = run_scene("abort", &format!("{base}[material]\npoisson = -0.967\n"));
    assert_refused(&o, &["material.poisson", "0 <= poisson < 0.5"]);
    let (_, o) = run_scene("abort_step", base);
    assert_refused(&o, &["quasi_elastic.max_step_mm", "10 mm"]);
}

/// The library path of the same abort: settings with a step beyond the accepted range are
/// refused by their constructor, and `quasi_elastic::search` with the largest accepted step
/// terminates with a patch at every position.
#[test]
fn trapezoid_search_with_the_largest_step_terminates() {
    let scene = Scene::from_toml(
        "[sweep]\nfrom_mm = -2.0\nto_mm = 2.0\nstep_mm = 1.0",
        "t.toml",
        Path::new("."),
    )
    .unwrap();
    let placement = wheelrail::pipeline::place(&scene).unwrap();
    let rigid = wheelrail::rigid::search(&placement, scene.sweep(), scene.rigid_solver());
    let huge = Quadrature::Trapezoid {
        max_step_mm: f64::MAX,
    };
    assert!(
        QuasiElasticSettings::default()
            .with_quadrature(huge)
            .is_err()
    );
    let largest = Quadrature::Trapezoid {
        max_step_mm: wheelrail::quasi_elastic::QuasiElasticSettings::TRAPEZOID_STEP_RANGE_MM.1,
    };
    let settings = QuasiElasticSettings::default()
        .with_quadrature(largest)
        .unwrap();
    let q = quasi_elastic::search(&placement, rigid.clone(), &settings);
    assert_eq!(q.positions().len(), 5);
    for p in q.positions() {
        for side in &p.sides {
            let c = side.main().expect("a patch on the tread");
            assert!(c.is_finite(), "{c:?}");
        }
    }
}

/// Ran for minutes: a fine sweep of the CONTACT circles with the five-eps sensitivity, and
/// a fine trapezoid with a huge cut-off. Now refused before running, with the estimate and
/// the keys that drive it (or the key out of its range).
#[test]
fn runaway_scenes_are_refused_with_their_estimate() {
    let circles = format!(
        "[wheel]\nprofile = \"{}\"\ndrop_step_backs = true\n[rail]\nprofile = \"{}\"\n\
         drop_step_backs = true\n[sweep]\nfrom_mm = -50.0\nto_mm = 100.0\nstep_mm = 0.003\n\
         [outputs]\nfigures = [\"qe_epsilon\"]\nformats = []\n",
        profile("circ_r100.prw"),
        profile("circ_r300.prr")
    );
    let (_, o) = run_scene("long_circles", &circles);
    assert_refused(
        &o,
        &[
            "refused",
            "--allow-long",
            "50001 positions",
            "sensitivity_epsilon_mm",
        ],
    );
    let trapezoid = |cutoff: &str| {
        format!(
            "[wheel]\nprofile = \"{}\"\n[quasi_elastic]\nquadrature = \"trapezoid\"\n\
             max_step_mm = 0.0001\ncutoff = {cutoff}\n[outputs]\nfigures = [\"qe_contact_points\"]\n\
             formats = []\n",
            profile("avg_wheel.whl")
        )
    };
    let (_, o) = run_scene("long_cutoff", &trapezoid("1.2e57"));
    assert_refused(&o, &["quasi_elastic.cutoff", "1.2e57", "1 to 700"]);
    let (_, o) = run_scene("long_trapezoid", &trapezoid("700.0"));
    assert_refused(
        &o,
        &[
            "refused",
            "quasi_elastic.max_step_mm",
            "quasi_elastic.cutoff",
        ],
    );
}

/// Positions repeated after the 1e-9 mm rounding (0 five times, then 1e-9 six times).
#[test]
fn a_sweep_step_below_the_rounding_is_refused() {
    let (_, o) = run_scene(
        "repeat",
        "[sweep]\nfrom_mm = 0.0\nto_mm = 1e-9\nstep_mm = 1e-10\n[outputs]\nfigures = [\"roll\"]\n",
    );
    assert_refused(&o, &["sweep.step_mm", "1e-6 mm"]);
}

/// "internal error building a table: duplicate column" from a repeated sensitivity eps.
#[test]
fn a_repeated_sensitivity_epsilon_is_refused() {
    let (_, o) = run_scene(
        "duplicate_eps",
        "[quasi_elastic]\nsensitivity_epsilon_mm = [0.01, 0.01]\n\
         [outputs]\nfigures = [\"qe_epsilon\"]\nformats = []\n",
    );
    assert_refused(&o, &["quasi_elastic.sensitivity_epsilon_mm", "twice"]);
}

/// Unequal radii: the centred wheelset has no contact, so l0 and the reference height are
/// NaN; the rows that carry those NaN say so instead of `converged` alone.
#[test]
fn unequal_radii_without_centred_contact_flag_their_nan() {
    let (out, o) = run_scene(
        "radii",
        "[wheel]\nleft_nominal_radius_mm = 700.0\nright_nominal_radius_mm = 1000.0\n\
         [sweep]\nfrom_mm = 100.0\nto_mm = 100.0\n\
         [outputs]\nfigures = [\"contact_points\", \"qe_contact_points\", \"semi_axes\", \"equivalent_conicity\"]\n\
         formats = []\n",
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rigid = std::fs::read_to_string(out.join("rigid.csv")).unwrap();
    assert!(rigid.contains("no contact at y_ws = 0"), "{rigid}");
    let unflagged = common::unflagged_in_folder(&out);
    assert!(unflagged.is_empty(), "{unflagged:#?}");
}

/// The paper's solver stops microns above the minimum; with eps = 1e-6 mm the weights of
/// the nodes below its point overflowed and the patch was NaN under status `ok`. The pass
/// now measures from the lowest node: a finite patch.
#[test]
fn paper_solver_with_tiny_epsilon_gives_a_finite_patch() {
    let (out, o) = run_scene(
        "paper_eps",
        "[rigid]\nsolver = \"paper\"\n[quasi_elastic]\nepsilon_mm = 1e-6\n\
         [sweep]\nfrom_mm = 7.0\nto_mm = 7.0\n[outputs]\nfigures = [\"qe_contact_points\"]\nformats = []\n",
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let qe = std::fs::read_to_string(out.join("quasi_elastic.csv")).unwrap();
    let unflagged = common::unflagged_non_finite("quasi_elastic.csv", &qe);
    assert!(unflagged.is_empty(), "{unflagged:#?}");
    // The flange contact of the left wheel at 7 mm: contact angle above 1 rad.
    let row = qe.lines().rfind(|l| !l.starts_with('#')).unwrap();
    let gamma: f64 = row.split(',').nth(5).unwrap().parse().unwrap();
    assert!(gamma > 1.0, "{row}");
}

/// The check itself: NaN under a plain success status is reported; under a reason, in a
/// `second_*` column, or with the side's own status flagging it, it is not.
#[test]
fn the_non_finite_check_can_fail() {
    let csv = "# t\ny_ws_mm,a_mm,second_s_mm,status\n0,NaN,NaN,ok\n1,inf,1,converged; two patches\n\
               2,NaN,NaN,no contact\n3,1,NaN,ok\n";
    let found = common::unflagged_non_finite("t.csv", csv);
    assert_eq!(found.len(), 2, "{found:#?}");
    let sided = "y_ws_mm,left_a,right_a,left_status,right_status\n0,NaN,1,not Hertzian: A <= 0,ok\n\
                 1,1,NaN,not Hertzian: A <= 0,ok\n";
    let found = common::unflagged_non_finite("h.csv", sided);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert!(found[0].contains("right_a"), "{found:#?}");
}

/// Every table of the committed scenes (the paper's, a measured one, an EN 15302 one)
/// flags each of its non-finite numbers.
#[test]
fn committed_scenes_flag_every_non_finite_number() {
    for name in ["paper", "measured_average", "en15302_e9"] {
        let scene = root().join("reports").join(name).join("scene.toml");
        let text = std::fs::read_to_string(&scene).unwrap();
        let scene = Scene::from_toml(&text, name, scene.parent().unwrap()).unwrap();
        let results = wheelrail::pipeline::run(&scene).unwrap();
        let tables = wheelrail_report::outputs::tables(&scene, &results).unwrap();
        assert!(!tables.is_empty());
        let csv: Vec<(String, String)> = tables
            .iter()
            .map(|t| (t.file.clone(), t.table.to_csv()))
            .collect();
        for (file, text) in &csv {
            let unflagged = common::unflagged_non_finite(&format!("{name}/{file}"), text);
            assert!(unflagged.is_empty(), "{unflagged:#?}");
        }
    }
}

/// Issue 32: a sweep of 0.00025 mm steps with every figure ran in 7 s and wrote 198 MB,
/// one SVG of 69 MB. Its charts are now drawn at their resolution and the budget counts
/// the bytes a run writes: refused without `--allow-long` (the tables alone are over 100
/// MB), and with it every SVG under 2 MB, the files within the estimate.
#[test]
fn a_fine_sweep_writes_charts_of_bounded_size_and_counts_its_bytes() {
    let text = "[sweep]\nfrom_mm = -12.5\nto_mm = 12.5\nstep_mm = 0.00025\n\
                [outputs]\nformats = [\"svg\"]\n";
    let (_, o) = run_scene("fine_sweep_refused", text);
    assert_refused(
        &o,
        &[
            "MB of files (budget 100 MB)",
            "sweep.step_mm = 100001 positions",
            "--allow-long",
        ],
    );
    let dir = scratch("robustness/fine_sweep");
    std::fs::write(dir.join("scene.toml"), text).unwrap();
    let o = common::bin()
        .arg("report")
        .arg(dir.join("scene.toml"))
        .arg("--out")
        .arg(dir.join("out"))
        .arg("--allow-long")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let mut written = 0;
    let mut svgs = 0;
    for file in std::fs::read_dir(dir.join("out")).unwrap() {
        let path = file.unwrap().path();
        let bytes = std::fs::metadata(&path).unwrap().len();
        written += bytes;
        if path.extension().is_some_and(|e| e == "svg") {
            svgs += 1;
            assert!(bytes < 2_000_000, "{}: {bytes} bytes", path.display());
        }
    }
    assert_eq!(svgs, 17);
    let scene = Scene::load(&dir.join("scene.toml")).unwrap();
    let estimate = wheelrail::cost::estimate(&scene, &wheelrail::pipeline::place(&scene).unwrap());
    // The estimate errs high, by at most a third here.
    let ratio = estimate.bytes / written as f64;
    assert!(
        (1.0..1.33).contains(&ratio),
        "{} estimated, {written} written",
        estimate.bytes
    );
}
