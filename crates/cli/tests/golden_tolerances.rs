//! The golden tolerances (`wheelrail_cli::golden_policy`) accept what another platform may
//! change: a rounding-level perturbation of the paper scene, its mirrored half solved
//! position by position instead of mirrored. Prints the largest difference of each column
//! inside and outside the conformal region the policy treats apart.

use wheelrail::pipeline;
use wheelrail::scene::Scene;
use wheelrail_report::{ColumnData, compare, outputs};

#[test]
fn the_golden_tolerances_accept_a_rounding_level_perturbation() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../reports/paper/scene.toml"
    );
    let scene = Scene::load(path.as_ref()).unwrap();
    let placement = pipeline::place(&scene).unwrap();
    assert!(placement.mirrors(), "the paper scene is mirror-symmetric");
    let mirrored = pipeline::run(&scene).unwrap();
    let solved = pipeline::run_on(
        &scene,
        placement.without_mirroring(),
        &pipeline::needed_stages(&scene),
    );
    let expected = outputs::tables(&scene, &mirrored).unwrap();
    let actual = outputs::tables(&scene, &solved).unwrap();
    assert_eq!(expected.len(), actual.len());
    let policy = wheelrail_cli::golden_policy();
    let mut perturbed = 0;
    for (e, a) in expected.iter().zip(&actual) {
        let keys = e.table.numeric("y_ws_mm");
        for column in e.table.columns() {
            let (ColumnData::Numeric(u), Some(ColumnData::Numeric(v))) =
                (&column.data, a.table.column(&column.name).map(|c| &c.data))
            else {
                continue;
            };
            // The largest difference outside and inside the conformal region.
            let mut worst = [0.0f64; 2];
            for (i, (x, y)) in u.iter().zip(v).enumerate() {
                let inside = keys.is_some_and(|k| (5.0..=6.5).contains(&k[i].abs()));
                let w = &mut worst[usize::from(inside)];
                *w = w.max((x - y).abs());
            }
            if worst.iter().any(|&w| w > 0.0) {
                perturbed += 1;
                println!(
                    "{} {}: {:.1e} outside, {:.1e} inside",
                    e.file, column.name, worst[0], worst[1]
                );
            }
        }
        let comparison = compare(&e.table, &a.table, &policy);
        assert!(comparison.is_match(), "{}: {comparison}", e.file);
    }
    // The perturbation reaches most columns (79 when this was written): a test of the
    // tolerances, not of equal tables.
    assert!(perturbed >= 40, "only {perturbed} columns perturbed");
}
