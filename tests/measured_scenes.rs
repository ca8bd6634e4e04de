//! The measured-profile scenes of `reports/` run through the whole pipeline and render (in
//! memory): every row is finite and plausible, or carries a status that says why not.

use std::path::Path;
use wheelrail::report::Table;
use wheelrail::scene::Scene;
use wheelrail::{outputs, pipeline};

fn table<'a>(tables: &'a [outputs::NamedTable], name: &str) -> &'a Table {
    &tables.iter().find(|t| t.file == name).unwrap().table
}

#[test]
fn measured_scenes_complete_with_finite_or_flagged_rows() {
    for name in ["measured_car7216", "measured_car7358", "measured_average"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
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
