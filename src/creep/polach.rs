//! Polach's method: a closed form of the tangential force on an elliptic patch, with his
//! extension for spin (Polach 1999; restated in Polach 2005, §2, without that paper's
//! reduction factors for large creepage; cited by section: the equation numbers were not
//! checked against the papers).
//!
//! # Longitudinal and lateral creepage
//!
//! The tangential stress grows linearly from the leading edge in the adhesion zone, with
//! gradient `C s`, under Hertz's (ellipsoidal) pressure, and slips at `μ p` elsewhere. With
//! the combined creepage `s_C = √(ξ² + η_C²)` (below) and `Q = FN`:
//!
//! ```text
//! ε = (G π a b c_jj / (4 Q μ)) s_C,     c_jj = √((C11 ξ/s_C)² + (C22 η_C/s_C)²)
//! F = (2 Q μ / π) (ε / (1 + ε²) + arctan ε)
//! Fx = -F ξ / s_C,     Fy = -F η / s_C      (on the rail)
//! ```
//!
//! At small creepage `F → (8/3) C a² b s`, which with `C = 3 G c_jj / (8a)` is Kalker's
//! linear theory exactly for pure ξ or pure η (`F = G a b C11 ξ`); at large creepage
//! `F → μ Q`.
//!
//! # Spin
//!
//! The lateral creepage is replaced by `η_C = η + φ a` where that is larger in magnitude
//! than `η` (else `η_C = η`), and the spin adds a lateral force
//!
//! ```text
//! F_yS = (9/16) a Q μ K_M (1 + 6.3 (1 - e^(-a/b))) φ / s_C     (on the rail)
//! K_M  = |ε_M| (δ³/3 - δ²/2 + 1/6) - (1/3) √((1 - δ²)³),   δ = (ε_M² - 1)/(ε_M² + 1)
//! ε_M  = (8/3) (G b √(ab) / (Q μ)) C23 s_C / (1 + 6.3 (1 - e^(-a/b)))
//! ```
//!
//! `K_M ≈ -(2/3) ε_M` at small `ε_M`, so `F_yS → -G c³ C23 φ`: Kalker's linear spin term
//! exactly (test `small_creepage_tends_to_linear_theory`). Polach writes the forces on the
//! wheel; the signs here are turned for the rail. The two parentheses in `K_M` are formed
//! without cancellation: `δ³/3 - δ²/2 + 1/6 = (1 - δ)² (1 + 2δ)/6` with
//! `1 - δ = 2/(ε_M² + 1)`, and `1 - δ² = 4 ε_M²/(ε_M² + 1)²`.
//!
//! The method gives no spin moment: `mz_nmm` is NaN. The translational force `√(Fx² + Fy²)`
//! stays within `μ FN`; the spin's lateral force comes on top, as in Polach's papers.
//!
//! # Adhesion fraction
//!
//! Polach does not state it; it follows from his assumptions. On a strip of half-length
//! `l` the stick zone ends where `C s (l - x)` meets `μ p0 √(l² - x²)/a`, at
//! `x = l (ε² - 1)/(ε² + 1)`: the stick zone is the fraction `1/(1 + ε²)` of every strip,
//! hence of the patch. (Integrating the two zones' stresses over the strips gives back
//! Polach's `F` above, which checks the derivation.)

use super::Settings;
use super::coefficients::Coefficients;
use super::creepage::Creepages;
use super::tangential::{EllipticPatch, Tangential};
use std::f64::consts::PI;

/// Polach's method on `patch` (module docs).
pub(super) fn solve(
    patch: &EllipticPatch,
    creepages: &Creepages,
    coefficients: &Coefficients,
    settings: &Settings,
) -> Tangential {
    let (a, b, q) = (patch.a_mm(), patch.b_mm(), patch.normal_force_n());
    let (g, mu) = (settings.shear_modulus_mpa(), settings.friction());
    let Creepages {
        xi,
        eta,
        phi_per_mm: phi,
    } = *creepages;
    let eta_spin = eta + phi * a;
    let eta_c = if eta_spin.abs() > eta.abs() {
        eta_spin
    } else {
        eta
    };
    let s_c = xi.hypot(eta_c);
    if s_c == 0.0 {
        return Tangential {
            fx_n: 0.0,
            fy_n: 0.0,
            mz_nmm: f64::NAN,
            adhesion_fraction: 1.0,
            coefficients: *coefficients,
        };
    }
    let c_jj = (coefficients.c11 * xi / s_c).hypot(coefficients.c22 * eta_c / s_c);
    let epsilon = g * PI * a * b * c_jj / (4.0 * q * mu) * s_c;
    let f = 2.0 * q * mu / PI * (epsilon / (1.0 + epsilon * epsilon) + epsilon.atan());
    let shape = 1.0 + 6.3 * (1.0 - (-a / b).exp());
    let epsilon_m = 8.0 / 3.0 * g * b * (a * b).sqrt() / (q * mu) * coefficients.c23 * s_c / shape;
    let e2 = epsilon_m * epsilon_m;
    let one_minus_delta = 2.0 / (e2 + 1.0);
    let delta = 1.0 - one_minus_delta;
    let one_minus_delta2 = 4.0 * e2 / ((e2 + 1.0) * (e2 + 1.0));
    let k_m = epsilon_m.abs() * one_minus_delta * one_minus_delta * (1.0 + 2.0 * delta) / 6.0
        - one_minus_delta2 * one_minus_delta2.sqrt() / 3.0;
    let fy_spin = 9.0 / 16.0 * a * q * mu * k_m * shape * phi / s_c;
    Tangential {
        fx_n: -f * xi / s_c,
        fy_n: -f * eta / s_c + fy_spin,
        mz_nmm: f64::NAN,
        adhesion_fraction: 1.0 / (1.0 + epsilon * epsilon),
        coefficients: *coefficients,
    }
}
