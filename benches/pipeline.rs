//! The pipeline's stages on the paper scene (defaults of an empty scene file: S1002 on
//! UIC60 1:40, 301 positions from -15 to 15 mm every 0.1 mm): profile placement, the rigid
//! sweep with both solvers, the quasi-elastic pass and the Hertz ellipses over the sweep.
//! Run with `cargo bench --bench pipeline`; compare the solvers as ratios of medians taken
//! in the same run (the machine is shared).

use divan::black_box;
use std::path::Path;
use std::sync::OnceLock;
use wheelrail::quasi_elastic::{self, QuasiElasticSweep};
use wheelrail::rigid::{self, RigidSweep, Solver};
use wheelrail::scene::Scene;
use wheelrail::track::Placement;
use wheelrail::{hertz, pipeline};

fn main() {
    divan::main();
}

fn scene() -> &'static Scene {
    static S: OnceLock<Scene> = OnceLock::new();
    S.get_or_init(|| Scene::from_toml("", "paper defaults", Path::new(".")).unwrap())
}

fn placement() -> &'static Placement {
    static P: OnceLock<Placement> = OnceLock::new();
    P.get_or_init(|| pipeline::place(scene()).unwrap())
}

fn rigid_sweep() -> &'static RigidSweep {
    static R: OnceLock<RigidSweep> = OnceLock::new();
    R.get_or_init(|| rigid::search(placement(), scene().sweep_mm(), Solver::default()))
}

fn quasi_elastic_sweep() -> &'static QuasiElasticSweep {
    static Q: OnceLock<QuasiElasticSweep> = OnceLock::new();
    Q.get_or_init(|| quasi_elastic::search(placement(), rigid_sweep(), scene().quasi_elastic()))
}

/// Loading and placing the four profiles.
#[divan::bench]
fn place() -> Placement {
    pipeline::place(black_box(scene())).unwrap()
}

/// The rigid sweep with the project's solver.
#[divan::bench]
fn rigid_default() -> RigidSweep {
    rigid::search(
        black_box(placement()),
        scene().sweep_mm(),
        black_box(Solver::default()),
    )
}

/// The rigid sweep with the paper's solver.
#[divan::bench(sample_count = 30)]
fn rigid_paper() -> RigidSweep {
    rigid::search(
        black_box(placement()),
        scene().sweep_mm(),
        black_box(Solver::Paper),
    )
}

/// The quasi-elastic pass over the default rigid sweep.
#[divan::bench]
fn quasi_elastic() -> QuasiElasticSweep {
    quasi_elastic::search(
        black_box(placement()),
        rigid_sweep(),
        scene().quasi_elastic(),
    )
}

/// Hertz ellipses over the sweep, from the quasi-elastic contacts (the scene's default).
#[divan::bench]
fn hertz_sweep() -> Vec<hertz::sweep::Position> {
    let s = scene();
    let e_star = hertz::effective_modulus(s.wheel_material(), s.rail_material());
    hertz::sweep::sweep(
        black_box(rigid_sweep()),
        Some(quasi_elastic_sweep()),
        s.wheel_load_n(),
        e_star,
        s.hertz(),
    )
}
