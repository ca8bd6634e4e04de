//! Complete elliptic integrals by the arithmetic-geometric mean, in the cancellation-free
//! combinations the Hertz equations need.
//!
//! Everything is parametrised by the complementary modulus `g = b/a` (the axis ratio of the
//! contact ellipse), never by `m = 1 - g²`: forming `m` first throws away the digits of `g`
//! for elongated ellipses (g = 1e-4 leaves 8 significant digits in 1 - m).
//!
//! # EllipseMethod
//!
//! The AGM is started from `(a₀, b₀) = (1, g)`; `c_n² = a_n² - b_n²` is carried by the
//! subtraction-free recurrence `c₁ = (1 - g)/2`, `c_{n+1} = c_n² / (4 a_{n+1})`. With
//! `K = π / (2 a_∞)` and Legendre's `E = K (1 - Σ_{n≥0} 2^{n-1} c_n²)` (Abramowitz & Stegun
//! 17.6), the sum without its `n = 0` term, divided by `m²`, is
//!
//! `σ = Σ_{n≥1} 2^{n-1} c_n² / m²`, with `σ₁ = 1 / (4 (1 + g)²)` and
//! `σ_{n+1}/σ_n`-terms `u_{n+1} = u_n c_n² / (8 a_{n+1}²)`,
//!
//! all positive, so that
//!
//! * `D  = (K - E)/m      = K (1/2 + m σ)`,
//! * `D' = (E - g² K)/m   = K (1/2 - m σ)`,
//! * `W  = (2 D' - E)/m   = K (1/2 - (1 + g²) σ)`,
//!
//! are free of the `0/0` of the textbook forms at `g → 1` (σ → 1/16). For `g → 0` the last two
//! lose about `log10 K` digits (K ≈ ln(4/g); 1.2 digits at g = 1e-6), well inside the crate's
//! 1e-12 target. `D = R_D(0, g², 1)/3` and `D' = g² R_D(0, 1, g²)/3` in Carlson's notation.

use std::f64::consts::FRAC_PI_2;

/// Stop the AGM when the relative difference `(a_n - b_n)/a_n` of the current pair is at most
/// this; one more step is then taken without its square root (below).
///
/// The difference is computed as `2 c_{n+1}` (no subtraction), so it decreases quadratically
/// to zero and cannot stall at the last bit the way a computed `a - b` does. With
/// `ρ = c_{n+1}/a_{n+1} ≤ 5e-5` at the stop, the last step `a_{n+2} = a_{n+1} - c_{n+2}`,
/// `c_{n+2} ≈ c_{n+1}²/(4 a_{n+1})` and its σ term are formed directly, and what is left out is
/// of order `ρ⁴/64 < 1e-19` relative in `K` and in `σ`. This is the same result as iterating
/// to a relative difference of 1e-15, one or two square roots earlier.
pub(crate) const AGM_REL_TOL: f64 = 1e-4;

/// Hard cap on AGM steps. From `g = 5e-324` (the smallest f64) the AGM needs about 12 steps;
/// the cap only guards against a NaN sneaking in.
const AGM_ITERATION_CAP: u32 = 64;

/// `K` and the cancellation-free combinations of `K` and `E` at one axis ratio `g`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Integrals {
    /// `K(m)`, complete elliptic integral of the first kind, parameter `m = 1 - g²`.
    pub k: f64,
    /// `(K - E)/m`; `π/4` at the circle.
    pub d: f64,
    /// `(E - g² K)/m`; `π/4` at the circle.
    pub dp: f64,
    /// `(2 D' - E)/m`; `3π/16` at the circle. Equals `-dD/d(ln g)`.
    pub w: f64,
    /// `E(m)`, complete elliptic integral of the second kind, as `m D' + g² K`.
    pub e: f64,
}

/// K, E and the Hertz combinations for the axis ratio `g`.
///
/// # Units
///
/// Dimensionless.
///
/// `g` must lie in `(0, 1]`; callers guarantee it (debug-asserted).
pub(crate) fn integrals(g: f64) -> Integrals {
    debug_assert!(g > 0.0 && g <= 1.0, "axis ratio {g} outside (0, 1]");
    let one_plus_g = 1.0 + g;
    let m = (1.0 - g) * one_plus_g;
    // State after the first AGM step: a₁, b₁, c₁ and the first term of σ.
    let mut a = 0.5 * one_plus_g;
    let mut b = g.sqrt();
    let mut c = 0.5 * (1.0 - g);
    let mut term = 0.25 / (one_plus_g * one_plus_g);
    let mut sigma = term;
    for _ in 0..AGM_ITERATION_CAP {
        let a_next = 0.5 * (a + b);
        let inv_a_next = 1.0 / a_next;
        let c_sq = c * c;
        let c_next = 0.25 * c_sq * inv_a_next;
        term *= 0.125 * c_sq * inv_a_next * inv_a_next;
        sigma += term;
        let converged = 2.0 * c_next <= AGM_REL_TOL * a;
        if converged {
            // The final step, without its square root (see AGM_REL_TOL).
            let c_next_sq = c_next * c_next;
            term *= 0.125 * c_next_sq * inv_a_next * inv_a_next;
            sigma += term;
            a = a_next - 0.25 * c_next_sq * inv_a_next;
            break;
        }
        b = (a * b).sqrt();
        a = a_next;
        c = c_next;
    }
    let k = FRAC_PI_2 / a;
    let m_sigma = m * sigma;
    let d = k * (0.5 + m_sigma);
    let dp = k * (0.5 - m_sigma);
    let w = k * (0.5 - (1.0 + g * g) * sigma);
    let e = m * dp + g * g * k;
    Integrals { k, d, dp, w, e }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Relative agreement with 20-digit values of K and E: measured exact on the circle and
    /// 1.2e-16 at g = sqrt(1/2) (the AGM is accurate to a few rounding errors); two ulps.
    const TOL: f64 = 4.5e-16;

    fn rel(x: f64, y: f64) -> f64 {
        (x - y).abs() / y.abs()
    }

    #[test]
    fn circle_is_exact() {
        let i = integrals(1.0);
        assert!(rel(i.k, PI / 2.0) <= TOL);
        assert!(rel(i.e, PI / 2.0) <= TOL);
        assert!(rel(i.d, PI / 4.0) <= TOL);
        assert!(rel(i.dp, PI / 4.0) <= TOL);
        assert!(rel(i.w, 3.0 * PI / 16.0) <= TOL);
    }

    #[test]
    fn matches_tabulated_values() {
        // mpmath 1.3, 30 digits: ellipk(0.5), ellipe(0.5) (g = sqrt(1/2)).
        let i = integrals(0.5_f64.sqrt());
        assert!(rel(i.k, 1.854_074_677_301_371_9) <= TOL);
        assert!(rel(i.e, 1.350_643_881_047_675_5) <= TOL);
        // mpmath 1.3, 30 digits: ellipk(1 - 1e-12), ellipe(1 - 1e-12) (g = 1e-6). Measured:
        // K exact, E 1.8e-15 (E = m D' + g² K loses digits for small g, module docs).
        let i = integrals(1e-6);
        assert!(rel(i.k, 15.201_804_919_087_715) <= TOL);
        assert!(rel(i.e, 1.000_000_000_007_351) <= 4e-15);
    }

    #[test]
    fn matches_mpmath_over_the_range() {
        // (g, K, E, (K - E)/m, (E - g² K)/m): mpmath 1.3 at 40 digits with m = 1 - g² formed
        // exactly, rounded to f64. Tolerance (4 + 2 K) ε: a few roundings, plus the
        // factor ~K the form D' = K (1/2 - m σ) (and E = m D' + g² K) loses for small g
        // (module docs). Measured at most 0.44 of it (E and D' at g = 1e-12).
        let table = [
            (
                0.999999,
                1.570797112193551,
                1.5707955413968313,
                0.7853987524465127,
                0.7853983597470383,
            ),
            (
                0.99,
                1.5786997420390116,
                1.5629522119875925,
                0.7913331684130303,
                0.7873665736259814,
            ),
            (
                0.9,
                1.654616667522527,
                1.493290108131207,
                0.8490871546911566,
                0.8055295128313704,
            ),
            (
                0.3,
                2.627773332084344,
                1.0964775173922272,
                1.6827426535078205,
                0.9450306785765235,
            ),
            (
                0.05,
                4.38414323213416,
                1.0048564047864903,
                3.3877562178924,
                0.9963870142417594,
            ),
            (
                1e-3,
                8.29405146361544,
                1.0000038970261722,
                7.2940548606441284,
                0.9999966029713114,
            ),
            (1e-12, 29.017315477048438, 1.0, 28.017315477048438, 1.0),
        ];
        for (g, k, e, d, dp) in table {
            let i = integrals(g);
            let tol = (4.0 + 2.0 * k) * f64::EPSILON;
            for (got, want, name) in [
                (i.k, k, "K"),
                (i.e, e, "E"),
                (i.d, d, "D"),
                (i.dp, dp, "D'"),
            ] {
                assert!(
                    rel(got, want) <= tol,
                    "g = {g}: {name} = {got:e}, mpmath {want:e}, tol {tol:e}"
                );
            }
        }
    }

    #[test]
    fn combinations_are_consistent_with_k_and_e() {
        // Where m is not small the textbook forms are accurate enough to cross-check:
        // measured at most 2.2e-16, 1.3e-16 and 4.8e-16; bounds about twice these.
        for g in [0.1, 0.3, 0.5, 0.7] {
            let i = integrals(g);
            let m = 1.0 - g * g;
            assert!(rel(i.d, (i.k - i.e) / m) <= 5e-16, "g = {g}");
            assert!(rel(i.dp, (i.e - g * g * i.k) / m) <= 3e-16, "g = {g}");
            assert!(rel(i.w, (2.0 * i.dp - i.e) / m) <= 1e-15, "g = {g}");
        }
    }
}
