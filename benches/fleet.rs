//! The fleet benchmark of issue 14: 1000 generated worn S1002 profiles
//! (`fleet::synthetic`, seed 14) through the default fleet scene (`reports/fleet/scene.toml`),
//! each read from its file, fitted, placed on the shared rails, swept and assessed, rows in
//! input order; on a pool of 1 and of 2 threads. Also the parts of one profile's
//! assessment, and the clone of the shared rails. Run: `cargo bench --bench fleet`.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use wheelrail::fleet::{self, Fleet, Inputs, Item, synthetic};
use wheelrail::pipeline;
use wheelrail::scene::Scene;

fn main() {
    divan::main();
}

/// The number of profiles of the fleet benchmark.
const FLEET: u64 = 1000;

/// The generated profiles, written once per benchmark run under `target/`.
fn files() -> &'static [PathBuf] {
    static FILES: OnceLock<Vec<PathBuf>> = OnceLock::new();
    FILES.get_or_init(|| {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/bench-fleet");
        std::fs::create_dir_all(&dir).unwrap();
        (0..FLEET)
            .map(|i| {
                let path = dir.join(format!("worn_{i:04}.csv"));
                std::fs::write(&path, synthetic::csv_text(14, i).0).unwrap();
                path
            })
            .collect()
    })
}

fn template() -> Scene {
    Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("reports/fleet/scene.toml")).unwrap()
}

fn prepared() -> (Fleet, Vec<Item>) {
    let items = fleet::items_of_files(files(), false);
    let fleet = Fleet::new(template(), Inputs::Wheels, &items, false).unwrap();
    (fleet, items)
}

/// 1000 profiles, rows in input order, on a pool of `threads` threads.
#[divan::bench(args = [1, 2], sample_count = 5, sample_size = 1)]
fn fleet_of_1000(bencher: divan::Bencher, threads: usize) {
    let (fleet, items) = prepared();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    bencher.bench(|| {
        let mut ok = 0;
        pool.install(|| {
            fleet.assess_in_order(
                &items,
                |item| fleet.assess(item),
                |_, row| ok += usize::from(row.outcome.is_ok()),
            );
        });
        assert_eq!(ok, items.len());
    });
}

/// One profile's assessment on one thread: read, fit, place, sweep, conicity.
#[divan::bench(sample_count = 200)]
fn one_profile(bencher: divan::Bencher) {
    let (fleet, items) = prepared();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let mut i = 0;
    bencher.bench_local(|| {
        i = (i + 1) % items.len();
        pool.install(|| fleet.assess(&items[i]))
    });
}

/// Its first part: the file read, the spline fitted, the wheel placed (both sides).
#[divan::bench(sample_count = 200)]
fn one_profile_read_and_place(bencher: divan::Bencher) {
    let (fleet, items) = prepared();
    let mut i = 0;
    bencher.bench_local(|| {
        i = (i + 1) % items.len();
        pipeline::place_wheels(&fleet.scene_for(&items[i])).unwrap()
    });
}

/// Its flange dimensions Sh, Sd, qR (`maintenance::flange_dimensions`, part of every
/// profile's assessment): one fitted wheel measured, the placement made outside the loop.
#[divan::bench(sample_count = 200)]
fn one_profile_flange_dimensions(bencher: divan::Bencher) {
    let (fleet, items) = prepared();
    let wheels: Vec<_> = items
        .iter()
        .take(20)
        .map(|item| pipeline::place_wheels(&fleet.scene_for(item)).unwrap())
        .collect();
    let mut i = 0;
    bencher.bench_local(|| {
        i = (i + 1) % wheels.len();
        wheelrail::maintenance::flange_dimensions(wheels[i][0].profile())
    });
}

/// What each profile's placement takes of the shared rails: two reference counts, no copy
/// of the rails' tables.
#[divan::bench(sample_count = 200)]
fn shared_rails_clone(bencher: divan::Bencher) {
    let rails = pipeline::place_rails(&template()).unwrap();
    bencher.bench_local(|| rails.clone());
}
