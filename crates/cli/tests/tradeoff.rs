//! The run time against error study on a small scene: errors are measured against the
//! reference (timings are never asserted).

use std::path::Path;
use wheelrail::scene::Scene;
use wheelrail_report::tradeoff::{self, Setting};

#[test]
fn reference_has_zero_error_and_a_coarse_setting_does_not() {
    let scene = Scene::from_toml(
        "[sweep]\nfrom_mm = -3.0\nto_mm = 8.0\nstep_mm = 1.0",
        "small",
        Path::new("."),
    )
    .unwrap();
    let coarse = Setting {
        label: "coarse".into(),
        profile_step_mm: Some(1.0),
        ..tradeoff::default_setting(&scene)
    };
    let settings = [
        tradeoff::reference_setting(),
        coarse,
        tradeoff::paper_setting(&scene),
    ];
    let mut calls = 0;
    let m = tradeoff::study(&scene, &settings, 1, |_, _, _| calls += 1).unwrap();
    assert_eq!(
        calls,
        2 * settings.len() + 1,
        "progress is reported per run (a warm-up round and one timed round) and at the end"
    );
    // The reference against itself: the same deterministic computation, error exactly 0.
    let r = &m[0].errors;
    for e in [
        r.contact_mm,
        r.qe_location_mm,
        r.roll_rad,
        r.a_rel,
        r.b_rel,
        r.p0_rel,
    ] {
        assert!(e.abs() < 1e-300, "{r:?}");
    }
    // Profiles sampled every 1 mm cannot carry the S1002 flange geometry: errors above a
    // floor (measured on this sweep: 0.19 mm in contact position, 1.66 in a; on the paper
    // sweep 8 mm and 2.2). Floors about a third of the measured errors.
    let c = &m[1].errors;
    assert!(c.contact_mm > 0.05 && c.a_rel.max(c.b_rel) > 0.5, "{c:?}");
    // The paper's settings differ measurably from the reference too (measured 4.5e-6 rad
    // in roll, 2.7 % in a and b).
    let p = &m[2].errors;
    assert!(p.roll_rad > 1.5e-6 && p.a_rel.max(p.b_rel) > 1e-2, "{p:?}");
    assert!(
        m.iter()
            .all(|x| x.median_s > 0.0 && x.range_s.0 <= x.median_s && x.median_s <= x.range_s.1)
    );
}

#[test]
fn pareto_front_keeps_only_undominated_settings() {
    let scene = Scene::from_toml(
        "[sweep]\nfrom_mm = 0.0\nto_mm = 1.0\nstep_mm = 1.0",
        "tiny",
        Path::new("."),
    )
    .unwrap();
    let mut m = tradeoff::study(
        &scene,
        &[tradeoff::default_setting(&scene)],
        1,
        |_, _, _| {},
    )
    .unwrap();
    let template = m.pop().unwrap();
    let point = |t: f64, e: f64| {
        let mut x = template.clone();
        x.median_s = t;
        x.errors.contact_mm = e;
        x
    };
    // (time, error): the second is dominated by the first, the fourth by the third.
    let m = vec![
        point(1.0, 1e-3),
        point(2.0, 1e-2),
        point(3.0, 1e-6),
        point(4.0, 1e-5),
    ];
    assert_eq!(tradeoff::pareto_front(&m, |e| e.contact_mm), vec![0, 2]);
}

/// FASTSIM's grid study as `fastsim_tradeoff.csv`: the columns and the `#` header (reference
/// grid, cases, units, machine-dependent times), the default grid labelled as such, and the
/// table read back for the chart gives the measured values.
#[test]
fn fastsim_table_states_its_reference_and_reads_back() {
    use wheelrail::creep::{DEFAULT_GRID, Grid};
    use wheelrail_report::tradeoff::fastsim;
    let grids = [
        Grid {
            strips: 8,
            elements: 8,
        },
        DEFAULT_GRID,
    ];
    let m = fastsim::study(&grids, 1, |_, _, _| {});
    let table = wheelrail_report::outputs::tables::fastsim_tradeoff(&m).unwrap();
    let csv = table.to_csv();
    let header = csv.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(
        header,
        "grid,strips,elements,median_us,min_us,max_us,force_error,moment_error,status"
    );
    let comments: String = csv.lines().filter(|l| l.starts_with('#')).collect();
    for part in [
        "reference grid 1000x1000",
        "the 24 cases of creep::fastsim::study_cases",
        "a = 6, b = 4 mm at FN = 50 kN",
        "/ (mu FN)",
        "/ (mu FN c)",
        "microseconds",
        "machine-dependent",
    ] {
        assert!(
            comments.contains(part),
            "no {part:?} in the header: {comments}"
        );
    }
    let points = fastsim::chart_points(&csv, "fastsim_tradeoff.csv").unwrap();
    let labels: Vec<&str> = points.iter().map(|p| p.label.as_str()).collect();
    assert_eq!(labels, ["8x8", "32x32 (default)"]);
    for (p, m) in points.iter().zip(&m) {
        // The table keeps 10 significant digits.
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
        assert!(close(p.median, 1e6 * m.timing.median_s), "{p:?} {m:?}");
        assert!(close(p.errors[0], m.force_error), "{p:?} {m:?}");
        assert!(close(p.errors[1], m.moment_error), "{p:?} {m:?}");
        assert!(m.force_error > 0.0 && m.moment_error > 0.0, "{m:?}");
    }
    // The coarse grid errs more than the default (the study's own result, 20 times).
    assert!(m[0].force_error > 10.0 * m[1].force_error, "{m:?}");
}

/// A table that is no `fastsim_tradeoff.csv` is refused with the file and the column named.
#[test]
fn a_bad_fastsim_table_is_refused_naming_file_and_column() {
    use wheelrail_report::tradeoff::fastsim::chart_points;
    let e = chart_points("grid,median_us\n8x8,1\n", "f.csv").unwrap_err();
    assert_eq!(
        e.to_string(),
        "f.csv: no column \"force_error\": not a fastsim_tradeoff.csv"
    );
    let text = "grid,median_us,force_error,moment_error\n8x8,fast,1e-2,1e-2\n";
    let e = chart_points(text, "f.csv").unwrap_err();
    assert_eq!(
        e.to_string(),
        "f.csv: column \"median_us\" has a cell that is no number (NaN is one)"
    );
    let e = chart_points("grid,median_us\n\"8x8,1\n", "f.csv").unwrap_err();
    assert!(e.to_string().starts_with("f.csv: "), "{e}");
}
