//! Creep forces of one patch: the tangential models on CONTACT's FASTSIM example (a = 8,
//! b = 4 mm, 82 kN, η = -6.25e-4, φ = 6.25e-4 /mm: 42 % of the patch slips, with spin),
//! FASTSIM on the grids of its discretisation study, Kalker's coefficients, the creepages
//! from the motion, and the whole stage on a flange patch (normal-force solve included).
//! Run with `cargo bench --bench creep`.

use divan::black_box;
use wheelrail::creep::coefficients::{Coefficients, kalker};
use wheelrail::creep::creepage::{ContactPoint, Creepages, Motion, creepages};
use wheelrail::creep::tangential::{EllipticPatch, Tangential, solve};
use wheelrail::creep::{
    CreepError, Grid, Method, Patch, PatchForces, Scheme, Settings, Shape, forces,
};

fn main() {
    divan::main();
}

fn example() -> (EllipticPatch, Creepages) {
    (
        EllipticPatch::new(8.0, 4.0, 82_000.0).unwrap(),
        Creepages {
            xi: 0.0,
            eta: -6.25e-4,
            phi_per_mm: 6.25e-4,
        },
    )
}

fn method(method: Method) -> Settings {
    Settings::new(method, 0.3, 82_000.0, 0.28).unwrap()
}

/// FASTSIM with the default grid (the speed goal: at most 10 µs per patch).
#[divan::bench]
fn fastsim_default() -> Tangential {
    let (p, c) = example();
    solve(black_box(&p), black_box(&c), &method(Method::Fastsim))
}

/// FASTSIM with Kalker's own update of slipping tractions, on the default grid (the
/// second-order update's cost, as a ratio to `fastsim_default`).
#[divan::bench]
fn fastsim_kalker_scheme() -> Tangential {
    let (p, c) = example();
    let s = method(Method::Fastsim).with_scheme(Scheme::Kalker);
    solve(black_box(&p), black_box(&c), &s)
}

/// FASTSIM on n × n grids: the run-time side of `fastsim::study`.
#[divan::bench(args = [8, 12, 16, 20, 24, 28, 32, 40, 48, 64])]
fn fastsim_grid(n: u32) -> Tangential {
    let (p, c) = example();
    let s = method(Method::Fastsim)
        .with_grid(Grid {
            strips: n,
            elements: n,
        })
        .unwrap();
    solve(black_box(&p), black_box(&c), &s)
}

/// Polach's method (the speed goal: at most 0.3 µs per patch).
#[divan::bench]
fn polach() -> Tangential {
    let (p, c) = example();
    solve(black_box(&p), black_box(&c), &method(Method::Polach))
}

/// Kalker's linear theory.
#[divan::bench]
fn linear() -> Tangential {
    let (p, c) = example();
    solve(black_box(&p), black_box(&c), &method(Method::Linear))
}

/// Kalker's coefficients alone (part of every model above).
#[divan::bench]
fn coefficients() -> Coefficients {
    kalker(black_box(2.0), black_box(0.28))
}

/// The creepages of a yawed flange contact (A-2.2's right wheel at 7 mm).
#[divan::bench]
fn creepages_flange() -> Result<Creepages, CreepError> {
    creepages(black_box(&flange_motion()), black_box(&flange_point()))
}

fn flange_motion() -> Motion {
    Motion {
        speed_mm_s: 2000.0,
        pitch_rate_rad_s: 4.2635629,
        lateral_velocity_mm_s: 0.0,
        roll_rad: -0.006393,
        yaw_rad: -0.0168,
        yaw_rate_rad_s: 0.0,
    }
}

fn flange_point() -> ContactPoint {
    ContactPoint {
        lead_mm: 14.2687,
        lateral_mm: -708.86,
        rolling_radius_mm: 478.66,
        contact_angle_rad: -1.0634,
    }
}

/// The whole stage on that flange patch, 10 kN vertical: creepages, normal-force solve
/// (each step a Hertz ellipse and FASTSIM), forces.
#[divan::bench(args = [Method::Fastsim, Method::Polach])]
fn forces_flange(m: Method) -> Result<PatchForces, CreepError> {
    let patch = Patch {
        shape: Shape::Curvatures {
            a_per_mm: 0.5 / 478.66 * 1.0634_f64.cos(),
            b_per_mm: 0.02,
        },
        point: flange_point(),
        vertical_load_n: 10_000.0,
    };
    forces(black_box(&patch), &flange_motion(), &method(m))
}
