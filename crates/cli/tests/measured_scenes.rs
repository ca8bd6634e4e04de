//! The measured-profile scenes of `reports/` run through the whole pipeline and render (in
//! memory): every row is finite and plausible, or carries a status that says why not.

use std::path::Path;
use wheelrail::pipeline;
use wheelrail::scene::Scene;
use wheelrail_report::Table;
use wheelrail_report::outputs;

fn table<'a>(tables: &'a [outputs::NamedTable], name: &str) -> &'a Table {
    &tables.iter().find(|t| t.file == name).unwrap().table
}

#[test]
fn measured_scenes_complete_with_finite_or_flagged_rows() {
    for name in ["measured_car7216", "measured_car7358", "measured_average"] {
        let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .join("reports")
            .join(name)
            .join("scene.toml");
        let scene = Scene::load(&path).unwrap();
        let results = pipeline::run(&scene).unwrap();
        let tables = outputs::tables(&scene, &results).unwrap();

        // Rigid: a converged row has finite contact quantities in plausible ranges; any other
        // row says why in its status.
        let rigid = table(&tables, "rigid.csv");
        let status = rigid.text("status").unwrap();
        let roll = rigid.numeric("roll_rad").unwrap();
        let mut converged = 0;
        for (i, st) in status.iter().enumerate() {
            if st.starts_with("converged") {
                converged += 1;
                assert!(roll[i].abs() < 0.05, "{name} row {i}: roll {}", roll[i]);
                for side in ["left", "right"] {
                    let s = rigid.numeric(&format!("{side}_s_mm")).unwrap()[i];
                    let r = rigid.numeric(&format!("{side}_r_mm")).unwrap()[i];
                    let g = rigid.numeric(&format!("{side}_gamma_rad")).unwrap()[i];
                    assert!((-70.0..=70.0).contains(&s), "{name} row {i}: {side} s {s}");
                    assert!((440.0..500.0).contains(&r), "{name} row {i}: {side} r {r}");
                    assert!(g.abs() < 1.4, "{name} row {i}: {side} gamma {g}");
                }
            } else {
                assert!(!st.is_empty());
                assert!(
                    roll[i].is_nan(),
                    "{name} row {i}: a flagged row carries NaN"
                );
            }
        }
        assert!(
            converged as f64 > 0.9 * status.len() as f64,
            "{name}: {converged} of {}",
            status.len()
        );

        // Hertz: finite positive semi-axes and pressure, or NaN with a status other than ok.
        let hertz = table(&tables, "hertz.csv");
        for side in ["left", "right"] {
            let a = hertz.numeric(&format!("{side}_a_mm")).unwrap();
            let p0 = hertz.numeric(&format!("{side}_p0_MPa")).unwrap();
            let st = hertz.text(&format!("{side}_status")).unwrap();
            for i in 0..a.len() {
                if a[i].is_finite() {
                    assert!(
                        a[i] > 0.0 && p0[i] > 0.0 && p0[i] < 1e5,
                        "{name} {side} row {i}"
                    );
                } else {
                    assert!(
                        !st[i].starts_with("ok"),
                        "{name} {side} row {i}: NaN without a reason"
                    );
                }
            }
        }
        // The figures render (statuses are gaps in the lines, never joined).
        let files = outputs::render(&scene, &results, &[]).unwrap();
        assert!(files.iter().any(|f| f.name == "contact_points.png"));
    }
}

/// The quasi-elastic averages on measured (spline) profiles against a much finer quadrature
/// (panels of a tenth of a weight width, cut-off exp(-60)): a regression test for panels
/// that crossed the spline's knots (the curvature kinks at every knot; a and b were off by
/// up to 1.5 %), and for a contact on the end of the rail's running surface (y_ws = -8.4 mm,
/// right wheel), where the weight decays within eps / |d'| and the integrand ends with the
/// surface. Measured on this scene: at most 2.2e-9 relative in a and b, 4.9e-11 mm in the
/// location, and curvatures within 0.32 of 1e-12 1/mm + 1e-8 relative; bounds about twice
/// these (three times for the curvatures).
#[test]
fn quasi_elastic_on_measured_profiles_is_converged() {
    use wheelrail::hertz;
    use wheelrail::quasi_elastic::{self, Quadrature, QuasiElasticSettings};
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .join("reports/measured_average/scene.toml");
    let scene = Scene::load(&path).unwrap();
    let placement = pipeline::place(&scene).unwrap();
    let rigid = wheelrail::rigid::search(&placement, scene.sweep(), Default::default());
    let e_star = hertz::effective_modulus(scene.wheel_material(), scene.rail_material());
    let run = |settings: &QuasiElasticSettings| {
        let qe = quasi_elastic::search(&placement, rigid.clone(), settings);
        let contacts = hertz::Contacts::QuasiElastic(&qe);
        let h = hertz::sweep(contacts, scene.wheel_load_n(), e_star, scene.hertz());
        (qe, h)
    };
    let (qe, default) = run(scene.quasi_elastic());
    let reference_settings = scene
        .quasi_elastic()
        .with_cutoff(60.0)
        .and_then(|s| s.with_quadrature(Quadrature::GaussLegendre { panel_widths: 0.1 }))
        .unwrap();
    let (qe_ref, reference) = run(&reference_settings);
    let mut compared = 0;
    for (d, r) in default.positions().iter().zip(reference.positions()) {
        for k in 0..2 {
            let (Some(x), Some(y)) = (d.sides[k].ellipse(), r.sides[k].ellipse()) else {
                continue;
            };
            compared += 1;
            for (u, v) in [(x.a_mm, y.a_mm), (x.b_mm, y.b_mm)] {
                assert!(
                    (u - v).abs() <= 5e-9 * v.abs(),
                    "y_ws {} side {k}: {u} against {v}",
                    d.y_ws
                );
            }
        }
    }
    // Measured: 481 ellipses.
    assert!(compared > 400, "{compared} ellipses compared");
    // The averaged quantities themselves (the rail curvature is the most sensitive).
    let mut compared = 0;
    for (d, r) in qe.positions().iter().zip(qe_ref.positions()) {
        for k in 0..2 {
            let (Some(x), Some(y)) = (d.sides[k].main(), r.sides[k].main()) else {
                continue;
            };
            compared += 1;
            assert!(
                (x.s - y.s).abs() < 1e-10,
                "y_ws {} side {k}: s {} against {}",
                d.y_ws,
                x.s,
                y.s
            );
            for (u, v) in [
                (x.wheel_curvature, y.wheel_curvature),
                (x.rail_curvature, y.rail_curvature),
            ] {
                assert!(
                    (u - v).abs() <= 1e-12 + 1e-8 * v.abs(),
                    "y_ws {} side {k}: curvature {u} against {v}",
                    d.y_ws
                );
            }
        }
    }
    // Measured: 482 patches.
    assert!(compared > 400, "{compared} patches compared");
}
