//! The equivalent conicity of one pair from an existing Δr function (EN 15302): 96
//! amplitudes (0.5 to 10 mm every 0.1 mm) on the paper scene's Δr (301 positions, 6 jumps),
//! by both methods, and the Annex E table of case E1 (137 points, the amplitudes it supports).
//! Run with `cargo bench --bench conicity`.

use divan::black_box;
use std::path::Path;
use std::sync::OnceLock;
use wheelrail::conicity::{self, ConicityMethod, DeltaR};
use wheelrail::rigid::{self, RigidSweep, Solver};
use wheelrail::{pipeline, scene::Scene};

fn main() {
    divan::main();
}

fn paper_sweep() -> &'static RigidSweep {
    static R: OnceLock<RigidSweep> = OnceLock::new();
    R.get_or_init(|| {
        let scene = Scene::from_toml("", "paper defaults", Path::new(".")).unwrap();
        let placement = pipeline::place(&scene).unwrap();
        rigid::search(&placement, scene.sweep(), Solver::default())
    })
}

fn paper_delta_r() -> &'static DeltaR {
    static D: OnceLock<DeltaR> = OnceLock::new();
    D.get_or_init(|| {
        conicity::assess(paper_sweep(), &conicity::ConicitySettings::default()).delta_r
    })
}

fn annex_e1() -> &'static DeltaR {
    static D: OnceLock<DeltaR> = OnceLock::new();
    D.get_or_init(|| {
        let text = include_str!("../tests/data/en15302/annexE/E1_delta_r.csv");
        DeltaR::parse_csv(text, "E1").unwrap()
    })
}

/// Klingel (Annex B, the default) at 96 amplitudes on the paper's Δr.
#[divan::bench]
fn klingel_96_amplitudes() -> conicity::EquivalentConicity {
    let a = conicity::default_amplitudes_mm();
    conicity::equivalent_conicity(black_box(paper_delta_r()), &a, ConicityMethod::Klingel)
}

/// Regression (Annex C) at the same 96 amplitudes.
#[divan::bench]
fn regression_96_amplitudes() -> conicity::EquivalentConicity {
    let a = conicity::default_amplitudes_mm();
    conicity::equivalent_conicity(black_box(paper_delta_r()), &a, ConicityMethod::Regression)
}

/// Klingel on the Annex E table of E1, at the default amplitudes it supports (0.5-6.8 mm).
#[divan::bench]
fn klingel_annex_e1() -> conicity::EquivalentConicity {
    conicity::equivalent_conicity_clipped(black_box(annex_e1()), ConicityMethod::Klingel)
}

/// The whole stage from a rigid sweep: Δr with jumps, both methods, the pair's parameters.
#[divan::bench]
fn equivalent_conicity_stage() -> conicity::PairConicity {
    conicity::assess(
        black_box(paper_sweep()),
        &conicity::ConicitySettings::default(),
    )
}
