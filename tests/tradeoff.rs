//! The run time against error study on a small scene: errors are measured against the
//! reference (timings are never asserted).

use std::path::Path;
use wheelrail::scene::Scene;
use wheelrail::tradeoff::{self, Setting};

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
    // floor (measured on the paper sweep: 8 mm in contact position, 2.2 in a and b).
    let c = &m[1].errors;
    assert!(c.contact_mm > 1e-3 && c.a_rel.max(c.b_rel) > 1e-3, "{c:?}");
    // The paper's settings differ measurably from the reference too.
    let p = &m[2].errors;
    assert!(p.roll_rad > 1e-8 && p.a_rel.max(p.b_rel) > 1e-4, "{p:?}");
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
