//! The creep stage's table as a report writes it (`creep.csv`).

use wheelrail::pipeline;
use wheelrail::scene::Scene;
use wheelrail_report::outputs;

fn manchester_scene() -> Scene {
    Scene::load(
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../reports/manchester_a22/scene.toml"
        )
        .as_ref(),
    )
    .unwrap()
}

/// `creep.csv` and `contact_table.csv` as a report writes them: the columns the brief of
/// the format fixes, one creep row per position, wheel and patch.
#[test]
fn the_tables_have_their_columns() {
    let scene = manchester_scene();
    let results = pipeline::run(&scene).unwrap();
    let tables = outputs::tables(&scene, &results).unwrap();
    let creep = tables.iter().find(|t| t.file == "creep.csv").unwrap();
    let csv = creep.table.to_csv_with(outputs::CSV_FORMAT);
    let header = csv.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(
        header,
        "y_ws_mm,yaw_rad,side,patch,contact_angle_rad,lead_mm,xi,eta,phi_per_mm,fn_N,fx_N,fy_N,mz_Nmm,adhesion_fraction,status"
    );
    let c = results.creep.unwrap().unwrap();
    let rows: usize = c
        .positions()
        .iter()
        .map(|p| {
            p.sides
                .iter()
                .map(|s| s.patches.len().max(1))
                .sum::<usize>()
        })
        .sum();
    assert_eq!(
        csv.lines().filter(|l| !l.starts_with('#')).count(),
        rows + 1
    );
    assert!(rows > 2 * c.positions().len(), "a second patch somewhere");
}
