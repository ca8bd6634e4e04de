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
/// default thresholds) against the exact one, and the number of fixed-point
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

/// Errors of the paper's Hertz numerics on fixed grids (scene-independent).
#[derive(Debug, Clone)]
pub struct HertzAccuracy {
    /// `(e, relative error of K, relative error of E)` of the paper's series.
    pub series: Vec<(f64, f64, f64)>,
    /// `(A/B, relative error of b/a, iterations)` of the paper's fixed-point iteration.
    pub ratio: Vec<(f64, f64, u32)>,
    /// `(A/B, relative error of b/a)` of the exact method against the mpmath references
    /// of `tests/data/hertz_reference.csv` (50 digits, `scripts/hertz_reference.py`).
    pub exact_ratio: Vec<(f64, f64)>,
}

/// The mpmath references, compiled in so that the accuracy figure needs no files.
const HERTZ_REFERENCE: &str = include_str!("../../tests/data/hertz_reference.csv");

/// The paper's Hertz numerics against the exact ones, on log-spaced grids (the stage
/// `hertz_accuracy`: scene-independent, no files read).
pub fn study() -> HertzAccuracy {
    let series = (0..=200)
        .map(|i| {
            // e from 0.01 to 1 - 1e-6, denser near 1 (log-spaced in 1 - e).
            let e = 1.0 - 10f64.powf(-0.0043648 - 5.9956352 * f64::from(i) / 200.0);
            let (k, ee) = series_error(e);
            (e, k, ee)
        })
        .collect();
    let ratio = (0..=120)
        .map(|i| {
            let r = 10f64.powf(-6.0 + 6.0 * f64::from(i) / 120.0);
            let (err, it) = paper_ratio_error(r);
            (r, err, it)
        })
        .collect();
    let exact_ratio = HERTZ_REFERENCE
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("A_per_mm"))
        .filter_map(|l| {
            let v: Vec<f64> = l.split(',').filter_map(|x| x.trim().parse().ok()).collect();
            let [a, b, load, e_star, ra, rb, ..] = v[..] else {
                return None;
            };
            let e = super::ellipse(a, b, load, e_star, super::EllipseMethod::Exact).ok()?;
            let e = e.ellipse()?;
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            Some((lo / hi, (e.b_mm / e.a_mm) / (rb / ra) - 1.0))
        })
        .collect();
    HertzAccuracy {
        series,
        ratio,
        exact_ratio,
    }
}
