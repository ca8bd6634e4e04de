//! Accuracy of the paper's numerics against the exact ones, as plain numbers for tables and
//! charts.

use super::elliptic::integrals;
use super::exact;
use super::paper::{PaperSettings, eccentricity, series_e, series_k};

/// Relative errors `(K_series/K - 1, E_series/E - 1)` of the paper's truncated series (paper
/// Eqs. 15-18, terms summed until one is below 10⁻³) at eccentricity `e`, against the AGM
/// values (accurate to ~1e-15).
///
/// Signed: the truncated `K` series is too small (negative error), the `E` series too large.
///
/// # Units
///
/// Dimensionless; `e` in `[0, 1)` (NaN otherwise).
///
/// # Example
///
/// ```
/// use wheelrail::hertz::accuracy::series_error;
/// let (k_err, e_err) = series_error(0.99);
/// // About -1.0 % for K and +0.8 % for E with the paper's 10⁻³ term threshold.
/// assert!(k_err < -0.005 && k_err > -0.02 && e_err > 0.005 && e_err < 0.012);
/// ```
pub fn series_error(e: f64) -> (f64, f64) {
    if !(0.0..1.0).contains(&e) {
        return (f64::NAN, f64::NAN);
    }
    let tol = PaperSettings::default().series_term_tol;
    // g = sqrt(1 - e²) without cancellation.
    let g = ((1.0 - e) * (1.0 + e)).sqrt();
    let exact = integrals(g);
    (
        series_k(e, tol) / exact.k - 1.0,
        series_e(e, tol) / exact.e - 1.0,
    )
}

/// Relative error of the axis ratio `b/a` from the paper's fixed-point iteration (with its
/// thresholds, [`PaperSettings::default`]) against the exact one, and the number of fixed-point
/// updates, at the curvature ratio `a_over_b_curv = A/B` (either order; the smaller over the
/// larger is used).
///
/// # Units
///
/// Dimensionless.
///
/// # Example
///
/// ```
/// use wheelrail::hertz::accuracy::paper_ratio_error;
/// // The paper's b/a is 16 % too large at A/B = 1e-3 (the K series is 17 % short near e = 1).
/// let (err, iterations) = paper_ratio_error(1e-3);
/// assert!(err > 0.15 && err < 0.17 && iterations == 2);
/// ```
pub fn paper_ratio_error(a_over_b_curv: f64) -> (f64, u32) {
    let ratio = if a_over_b_curv > 1.0 {
        1.0 / a_over_b_curv
    } else {
        a_over_b_curv
    };
    if ratio.is_nan() || ratio <= 0.0 {
        return (f64::NAN, 0);
    }
    let paper = eccentricity(ratio, &PaperSettings::default());
    let e = paper.eccentricity;
    let g_paper = ((1.0 - e) * (1.0 + e)).sqrt();
    let g_exact = exact::shape(ratio, ratio.ln()).g;
    (g_paper / g_exact - 1.0, paper.iterations)
}
