//! One Hertz solve (`hertz::ellipse`) for the exact and the paper method at curvature ratios
//! from elongated to circular. Run with `cargo bench --bench hertz`.

use divan::black_box;
use wheelrail::hertz::{Contact, EllipseMethod, HertzError, ellipse};

fn main() {
    divan::main();
}

/// Steel on steel (E = 210 GPa, ν = 0.3), MPa.
const E_STAR: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));
/// Lateral relative curvature of a 300 mm rail crown on a flat tread, 1/mm.
const B: f64 = 1.0 / 600.0;
/// The paper's wheel load, N.
const LOAD: f64 = 70_000.0;
/// Curvature ratios A/B.
const RATIOS: [f64; 4] = [1e-3, 0.1, 0.5, 1.0];

fn solve(ratio: f64, method: EllipseMethod) -> Result<Contact, HertzError> {
    ellipse(
        black_box(ratio * B),
        black_box(B),
        black_box(LOAD),
        black_box(E_STAR),
        method,
    )
}

#[divan::bench(args = RATIOS)]
fn exact(ratio: f64) -> Result<Contact, HertzError> {
    solve(ratio, EllipseMethod::Exact)
}

#[divan::bench(args = RATIOS)]
fn paper(ratio: f64) -> Result<Contact, HertzError> {
    solve(ratio, EllipseMethod::Paper)
}
