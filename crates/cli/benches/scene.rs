//! Benchmarks of whole scenes: the paper scene without rendering, the rendering of its
//! report (bytes only, no files; SVG and PNG, and SVG only), and a batch of independent scenes sequential against
//! parallel (rayon). Run: `cargo bench --bench scene`.

use std::path::Path;
use wheelrail::sweep::Sweep;
use wheelrail::{pipeline, scene::Scene};
use wheelrail_report::outputs;

fn main() {
    divan::main();
}

fn paper_path() -> std::path::PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).join("reports/paper/scene.toml")
}

fn paper() -> Scene {
    Scene::load(&paper_path()).unwrap()
}

/// The paper scene's computation for its tables (rigid, quasi-elastic, Hertz; the eps
/// sensitivity and Hertz accuracy stages left out: they serve one figure each).
fn compute_only() -> Scene {
    paper().with_figures(vec![
        wheelrail::pipeline::Figure::SemiAxes,
        wheelrail::pipeline::Figure::ContactMap,
    ])
}

/// The EN 15302 reference pair (R-UIC519A on S-UIC519A, 141 positions, the Δr figure in
/// SVG: `benches/data/en15302_e1_delta_r.toml`) as `wheelrail report` runs it, in memory:
/// the scene and its two 1000-point files read, fitted and placed, the rigid sweep, the
/// tables, the figure and the page rendered (the process start and the folder written are
/// what the whole command adds: README, Speed).
#[divan::bench(sample_count = 20)]
fn en15302_delta_r_report_in_memory(bencher: divan::Bencher) {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .join("benches/data/en15302_e1_delta_r.toml");
    bencher.bench(|| {
        let scene = Scene::load(divan::black_box(&path)).unwrap();
        let results = pipeline::run(&scene).unwrap();
        outputs::render(&scene, &results, &[]).unwrap()
    });
}

#[divan::bench(sample_count = 20)]
fn paper_scene_without_rendering(bencher: divan::Bencher) {
    let scene = compute_only();
    bencher.bench(|| pipeline::run(divan::black_box(&scene)).unwrap());
}

#[divan::bench(sample_count = 20)]
fn paper_scene_all_stages_without_rendering(bencher: divan::Bencher) {
    let scene = paper();
    bencher.bench(|| pipeline::run(divan::black_box(&scene)).unwrap());
}

/// What the Python package's `wheelrail.run("reports/paper/scene.toml")` computes: the
/// scene read and checked, the stages its figures need, their tables (no rendering). The
/// package's call adds only its conversion to NumPy (docs/python-overhead.md).
#[divan::bench(sample_count = 100)]
fn paper_scene_tables(bencher: divan::Bencher) {
    let path = paper_path();
    bencher.bench(|| {
        let scene = Scene::load(divan::black_box(&path)).unwrap();
        let results = pipeline::run(&scene).unwrap();
        outputs::tables(&scene, &results).unwrap()
    });
}

#[divan::bench(sample_count = 10)]
fn paper_report_rendering(bencher: divan::Bencher) {
    let scene = paper();
    let results = pipeline::run(&scene).unwrap();
    bencher.bench(|| outputs::render(divan::black_box(&scene), &results, &[]).unwrap());
}

/// The same report with SVG figures only: the ratio of the two is the cost of the PNGs.
#[divan::bench(sample_count = 10)]
fn paper_report_rendering_svg_only(bencher: divan::Bencher) {
    let scene = paper().with_formats(vec![wheelrail::scene::ImageFormat::Svg]);
    let results = pipeline::run(&scene).unwrap();
    bencher.bench(|| outputs::render(divan::black_box(&scene), &results, &[]).unwrap());
}

/// Eight independent scenes (a batch of wheel radii, as a profile sweep would be).
fn batch() -> Vec<Scene> {
    (0..8)
        .map(|i| {
            let text = std::fs::read_to_string(paper_path()).unwrap().replace(
                "nominal_radius_mm = 460.0",
                &format!("nominal_radius_mm = {}.0", 440 + 5 * i),
            );
            Scene::from_toml(&text, "batch", Path::new("."))
                .unwrap()
                .with_figures(compute_only().figures().to_vec())
        })
        .collect()
}

#[divan::bench(sample_count = 5)]
fn batch_of_8_sequential(bencher: divan::Bencher) {
    let scenes = batch();
    bencher.bench(|| {
        scenes
            .iter()
            .map(|s| pipeline::run(s).unwrap())
            .collect::<Vec<_>>()
    });
}

#[divan::bench(sample_count = 5)]
fn batch_of_8_parallel(bencher: divan::Bencher) {
    use rayon::prelude::*;
    let scenes = batch();
    bencher.bench(|| {
        scenes
            .par_iter()
            .map(|s| pipeline::run(s).unwrap())
            .collect::<Vec<_>>()
    });
}

/// One sweep split into two calls run in parallel (each continues from its own start),
/// against one call (which itself runs its two directions from the centre in parallel).
#[divan::bench(sample_count = 10)]
fn rigid_sweep_two_calls_in_parallel(bencher: divan::Bencher) {
    let scene = paper();
    let placement = pipeline::place(&scene).unwrap();
    let shifts = scene.sweep().shifts_mm();
    let (a, b) = shifts.split_at(shifts.len() / 2);
    let (a, b) = (Sweep::from_slice(a).unwrap(), Sweep::from_slice(b).unwrap());
    bencher.bench(|| {
        rayon::join(
            || wheelrail::rigid::search(&placement, &a, scene.rigid_solver()),
            || wheelrail::rigid::search(&placement, &b, scene.rigid_solver()),
        )
    });
}

#[divan::bench(sample_count = 10)]
fn rigid_sweep_one_call(bencher: divan::Bencher) {
    let scene = paper();
    let placement = pipeline::place(&scene).unwrap();
    bencher.bench(|| wheelrail::rigid::search(&placement, scene.sweep(), scene.rigid_solver()));
}

/// The Manchester scene (A-2.2, 21 positions) as committed, with `[creep]` and its two creep
/// figures: placement, rigid, quasi-elastic, Hertz and creep, no rendering.
fn manchester() -> Scene {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .join("reports/manchester_a22/scene.toml");
    Scene::load(&path).unwrap()
}

/// The same scene without its `[creep]` table and creep figures: the ratio of the two is
/// the cost of the creep stage (issue goal: at most 2).
fn manchester_without_creep() -> Scene {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .join("reports/manchester_a22/scene.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let start = text.find("[creep]").unwrap();
    let end = text.find("[outputs]").unwrap();
    let text = format!("{}{}", &text[..start], &text[end..])
        .replace("\"creep_forces\", \"creep_curve\",", "");
    let scene = Scene::from_toml(&text, "manchester", path.parent().unwrap()).unwrap();
    assert!(!pipeline::needed_stages(&scene).contains(&pipeline::Stage::Creep));
    scene
}

#[divan::bench(sample_count = 20)]
fn manchester_scene_with_creep(bencher: divan::Bencher) {
    let scene = manchester();
    bencher.bench(|| pipeline::run(divan::black_box(&scene)).unwrap());
}

#[divan::bench(sample_count = 20)]
fn manchester_scene_without_creep(bencher: divan::Bencher) {
    let scene = manchester_without_creep();
    bencher.bench(|| pipeline::run(divan::black_box(&scene)).unwrap());
}

/// The creep stage alone on the Manchester scene's quasi-elastic patches (42 wheel-cases,
/// 44 patches): what `manchester_scene_with_creep` adds to `manchester_scene_without_creep`.
#[divan::bench(sample_count = 50)]
fn manchester_creep_stage_alone(bencher: divan::Bencher) {
    let scene = manchester();
    let results = pipeline::run(&scene).unwrap();
    let qe = results.quasi_elastic.as_ref().unwrap();
    let creep = scene.creep();
    bencher.bench(|| {
        wheelrail::creep::sweep::sweep(
            &results.placement,
            wheelrail::hertz::Contacts::QuasiElastic(divan::black_box(qe)),
            scene.wheel_load_n(),
            &creep.kinematics,
            &creep.settings,
        )
        .unwrap()
    });
}
