//! The paper's numerical scheme (Onat, Voltr & Lata 2014, section 5), kept as stated so that
//! its accuracy and cost can be measured against [`EllipseMethod::Exact`](super::EllipseMethod::Exact).
//!
//! * `K` and `E` by the power series in the eccentricity `e` (paper Eqs. 15-18):
//!   `K = Σ P_n`, `P₁ = π/2`, `P_{n+1} = P_n ((2n-1)/(2n))² e²`, and
//!   `E = π/2 - Σ_{n≥1} P_{n+1}/(2n-1)`, each summed until its newest term is below
//!   [`PaperSettings::series_term_tol`] (the paper's 10⁻³).
//! * The eccentricity by the fixed point of paper Eq. 14 rearranged,
//!   `e ← sqrt(1 - (A/B) (E - (1 - e²) K)/(K - E))` with `A ≤ B`, from `e = 0.5`, until
//!   `|Δe| ≤ 10⁻³` or 1000 iterations.
//! * The semi-axis `a` from paper Eq. 20, `a³ = 3 P (K - E)/(2 π E* e² A)`, and
//!   `b = a sqrt(1 - e²)`.
//!
//! The rearrangement is checked against paper Eq. 14, `A/B = (K - E)/((a/b)² E - K)`: with
//! `(a/b)² = 1/(1 - e²)` it reads `1 - e² = (A/B) (E - (1 - e²) K)/(K - E)`.
//!
//! Where an update would leave `0 < e < 1` (it does near the circle, because the truncated
//! series make `(E - (1 - e²)K)/(K - E)` exceed 1) or produce a non-finite value, the
//! iteration stops with [`Stop::LeftDomain`] and keeps the last valid `e`.

use super::Stop;
use std::f64::consts::FRAC_PI_2;

/// The paper's thresholds; [`Default`] gives the values the paper states.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperSettings {
    /// A series for `K` or `E` stops once its newest term is below this (absolute; the terms
    /// start at π/2). Paper: 10⁻³.
    pub series_term_tol: f64,
    /// The fixed point stops once `|e_{k+1} - e_k|` is at most this. Paper: 10⁻³.
    pub step_tol: f64,
    /// Fixed-point iteration cap. Paper: 10³.
    pub max_iterations: u32,
    /// Starting eccentricity. Paper: 0.5.
    pub start: f64,
}

impl Default for PaperSettings {
    fn default() -> Self {
        PaperSettings {
            series_term_tol: 1e-3,
            step_tol: 1e-3,
            max_iterations: 1000,
            start: 0.5,
        }
    }
}

/// Cap on series terms. With `e < 1` the terms fall below any positive `series_term_tol` in
/// finitely many steps (at `e = 1` the K terms are about `1/(2n)`: 500 terms for 10⁻³); the cap
/// only bounds the cost of a tiny user-supplied tolerance.
pub const SERIES_TERM_CAP: u32 = 100_000;

/// `K(e)` by the paper's series (Eqs. 15, 17), truncated after the first term below `tol`.
///
/// # Units
///
/// Dimensionless; `e` is the eccentricity (modulus `k = e`, parameter `m = e²`).
pub fn series_k(e: f64, tol: f64) -> f64 {
    let e_sq = e * e;
    let mut term = FRAC_PI_2;
    let mut sum = term;
    for n in 1..SERIES_TERM_CAP {
        let ratio = (2 * n - 1) as f64 / (2 * n) as f64;
        term *= ratio * ratio * e_sq;
        sum += term;
        if term < tol {
            break;
        }
    }
    sum
}

/// `E(e)` by the paper's series (Eqs. 16, 18), truncated after the first term below `tol`.
///
/// # Units
///
/// Dimensionless; `e` is the eccentricity.
pub fn series_e(e: f64, tol: f64) -> f64 {
    let e_sq = e * e;
    let mut k_term = FRAC_PI_2;
    let mut sum = k_term;
    for n in 1..SERIES_TERM_CAP {
        let ratio = (2 * n - 1) as f64 / (2 * n) as f64;
        k_term *= ratio * ratio * e_sq;
        let term = k_term / (2 * n - 1) as f64;
        sum -= term;
        if term < tol {
            break;
        }
    }
    sum
}

/// Result of the paper's fixed-point iteration for the eccentricity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperShape {
    /// Eccentricity `e = sqrt(1 - (b/a)²)` at the stop, in `(0, 1)`.
    pub eccentricity: f64,
    /// The series `K` at that `e`.
    pub k: f64,
    /// The series `E` at that `e`.
    pub e_integral: f64,
    /// Fixed-point updates attempted.
    pub iterations: u32,
    /// Why the iteration stopped.
    pub stop: Stop,
}

/// The paper's fixed-point iteration for the eccentricity at the curvature ratio
/// `ratio = A/B ≤ 1` (smaller over larger).
///
/// # Units
///
/// Dimensionless.
pub fn eccentricity(ratio: f64, settings: &PaperSettings) -> PaperShape {
    let tol = settings.series_term_tol;
    let mut e = settings.start;
    let mut k = series_k(e, tol);
    let mut e_int = series_e(e, tol);
    let mut iterations = 0;
    let stop = loop {
        if iterations >= settings.max_iterations {
            break Stop::IterationCap;
        }
        iterations += 1;
        let radicand = 1.0 - ratio * (e_int - (1.0 - e * e) * k) / (k - e_int);
        // `!(x > 0 && x < 1)` also catches NaN.
        if !(radicand > 0.0 && radicand < 1.0) {
            break Stop::LeftDomain;
        }
        let e_new = radicand.sqrt();
        let k_new = series_k(e_new, tol);
        let e_int_new = series_e(e_new, tol);
        if !(k_new - e_int_new > 0.0 && k_new.is_finite()) {
            break Stop::LeftDomain;
        }
        let step = (e_new - e).abs();
        e = e_new;
        k = k_new;
        e_int = e_int_new;
        if step <= settings.step_tol {
            break Stop::Converged;
        }
    };
    PaperShape {
        eccentricity: e,
        k,
        e_integral: e_int,
        iterations,
        stop,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn series_agree_with_the_first_terms() {
        // Tolerance 0 on the number of terms: with tol = 1 only P₂ is added after P₁
        // (it is below 1), so K = π/2 (1 + e²/4), E = π/2 (1 - e²/4). Measured within one
        // ulp; bound two ulps of π/2.
        let e: f64 = 0.6;
        let k = series_k(e, 1.0);
        let ee = series_e(e, 1.0);
        assert!((k - PI / 2.0 * (1.0 + e * e / 4.0)).abs() <= 4.5e-16);
        assert!((ee - PI / 2.0 * (1.0 - e * e / 4.0)).abs() <= 4.5e-16);
    }

    #[test]
    fn tight_series_converge_to_k_and_e() {
        // mpmath 1.3: ellipk(0.25), ellipe(0.25) (e = 0.5). Series with tol 1e-17 converge
        // geometrically (ratio 1/4): measured within one ulp, bound 4.5e-16 relative.
        let k = series_k(0.5, 1e-17);
        let e = series_e(0.5, 1e-17);
        assert!((k / 1.685_750_354_812_596 - 1.0).abs() <= 4.5e-16);
        assert!((e / 1.467_462_209_339_427_2 - 1.0).abs() <= 4.5e-16);
    }

    #[test]
    fn never_returns_nan() {
        for i in 0..=200 {
            let ratio = 10f64.powf(-(i as f64) / 10.0);
            let s = eccentricity(ratio, &PaperSettings::default());
            assert!(
                s.eccentricity > 0.0 && s.eccentricity < 1.0,
                "A/B = {ratio}"
            );
            assert!(s.k - s.e_integral > 0.0);
        }
    }

    /// A known value of `series_k`.
    #[test]
    fn series_k_example() {
        use crate::hertz::paper::series_k;
        // Two terms at e = 0.05: π/2 (1 + e²/4) = 1.5717779...
        let k = series_k(0.05, 1e-3);
        assert!((k - 1.571_778_074_499_143).abs() < 1e-15);
    }

    /// A known value of `series_e`.
    #[test]
    fn series_e_example() {
        use crate::hertz::paper::series_e;
        // Two terms at e = 0.05: π/2 (1 - e²/4) = 1.5698183...
        let e = series_e(0.05, 1e-3);
        // Measured one ulp off; two allowed.
        assert!((e - 1.569_814_579_090_65).abs() < 4.5e-16);
    }

    /// A known value of `eccentricity`.
    #[test]
    fn eccentricity_example() {
        use crate::hertz::Stop;
        use crate::hertz::paper::{PaperSettings, eccentricity};
        let s = eccentricity(0.1, &PaperSettings::default());
        assert_eq!(s.stop, Stop::Converged);
        // The exact b/a at A/B = 0.1 is 0.222250 (mpmath); the paper lands within 3 %
        // (measured 1.3 %).
        let g = (1.0 - s.eccentricity * s.eccentricity).sqrt();
        assert!((g / 0.222_250 - 1.0).abs() < 0.03);
    }
}
