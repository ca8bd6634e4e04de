//! The exact shape solve: the axis ratio `g = b/a` from the curvature ratio, to machine
//! precision (Johnson 1985, §4.2; paper Eq. 14).
//!
//! With `A ≤ B` (so `a ≥ b`, `a` along the direction of `A`),
//!
//! `A/B = g² (K - E) / (E - g² K) = g² D / D'`   (paper Eq. 14 divided through by `m`),
//!
//! which has no subtraction once `D`, `D'` come from [`super::elliptic::integrals`]. Newton's
//! method is applied to `f(u) = ln(g² D/D') - ln(A/B)` in `u = ln g`, where `f` is nearly
//! linear (slope 3/2 at the circle, 2 for `g → 0`) with the exact derivative
//!
//! `f'(u) = 3 - W/D - W/D'`, from `dK/du = -D'`, `dD/du = -W`.
//!
//! The start is Greenwood's `g₀ = (A/B)^(2/3)` (exact slope at the circle) corrected by a
//! piecewise Chebyshev fit of `ln g - (2/3) ln(A/B)` that is accurate to 1e-9 for
//! `A/B ≥ e⁻²⁸ ≈ 7e-13`, so that the first Newton step is already below
//! [`NEWTON_STEP_TOL`] and one evaluation of the elliptic integrals suffices there. Below that
//! range Greenwood's start alone is used and Newton takes 3-5 steps. The fit only chooses the
//! starting point: the accuracy of the result comes from the Newton stop either way.

use super::Stop;
use super::elliptic::{Integrals, integrals};

/// Newton stops once a step in `ln g` is at most this. Convergence is quadratic with
/// `|f''/(2 f')| ≤ 0.03` over the whole range (maximum 0.029 near `b/a = 0.2`, evaluated with
/// mpmath), so after a step of `h ≤ 1e-8` the remaining error in `ln g` is below
/// `0.03 h² = 3e-18`: the accepted step is the last one. `K` and `D` are
/// carried over that step to first order (their error is again `O(h²)`), which saves one AGM.
pub(crate) const NEWTON_STEP_TOL: f64 = 1e-8;

/// Newton iteration cap. One step is needed inside the fitted range, at most 5 below it for any
/// `A/B` an f64 can hold (measured down to `A/B = 1e-300`); 50 is only a guard.
pub(crate) const NEWTON_ITERATION_CAP: u32 = 50;

/// One piece of the starting-value fit: `ln g ≈ (2/3) x + p(t)`, `t = (2x - lo - hi)/(hi - lo)`
/// for `x = ln(A/B) ∈ [lo, hi]`.
struct StartPiece {
    lo: f64,
    hi: f64,
    /// Coefficients of `p(t)`, highest degree first.
    coeffs: [f64; 13],
}

/// Least-squares Chebyshev fits from `python3 scripts/hertz_reference.py --fit` (mpmath
/// `chebyfit`, 30 digits); the comment gives each piece's maximum error in `ln g`.
const START_PIECES: [StartPiece; 3] = [
    // max error 5.8e-12
    StartPiece {
        lo: -3.0,
        hi: 0.0,
        coeffs: [
            2.0747766193540955e-07,
            3.97863750703823e-07,
            -1.5292358017779499e-06,
            -6.715864749867301e-06,
            -1.2640018484295304e-06,
            5.850850861051574e-05,
            0.00015389467198329812,
            -0.00021405030601703157,
            -0.002262278876139772,
            -0.0036453128177696844,
            0.02342344356159289,
            -0.02704552745734155,
            0.009540226481040553,
        ],
    },
    // max error 7.6e-10
    StartPiece {
        lo: -10.0,
        hi: -3.0,
        coeffs: [
            2.7769649583519955e-06,
            1.0145818379222879e-06,
            -2.0908610058643912e-05,
            -5.945335254116519e-05,
            -0.00011665472537471503,
            -0.0001797423613041034,
            -5.0609415914736844e-05,
            0.0009631148898785449,
            0.004758179112825601,
            0.016547623287146623,
            0.05421875546186916,
            -0.3593257389823707,
            0.3449670425399187,
        ],
    },
    // max error 2.8e-10
    StartPiece {
        lo: -28.0,
        hi: -10.0,
        coeffs: [
            4.048501381433589e-06,
            1.2101388814681128e-05,
            1.9691930288106316e-05,
            4.514416945395674e-05,
            0.00012057109095642278,
            0.00029467835647560434,
            0.0007233587527826408,
            0.0018498967027525883,
            0.0049643178002161375,
            0.014342982923507743,
            0.04727898576497699,
            -1.2875210623811209,
            1.9636770477405772,
        ],
    },
];

/// Starting value of `u = ln g` for `ln_ratio = ln(A/B) < 0`.
fn start(ln_ratio: f64) -> f64 {
    let greenwood = ln_ratio * (2.0 / 3.0);
    for piece in &START_PIECES {
        if ln_ratio >= piece.lo {
            let t = (2.0 * ln_ratio - piece.lo - piece.hi) / (piece.hi - piece.lo);
            // The fit is not exactly 0 at the circle (error 6e-12); g must stay <= 1.
            return (greenwood + estrin(&piece.coeffs, t)).min(0.0);
        }
    }
    greenwood
}

/// The degree-12 polynomial with coefficients `c` (highest degree first) at `t`, by Estrin's
/// scheme: 4 dependent multiply-add levels instead of Horner's 12 (the start is on the
/// critical path of every solve).
fn estrin(c: &[f64; 13], t: f64) -> f64 {
    let t2 = t * t;
    let t4 = t2 * t2;
    let t8 = t4 * t4;
    // c[12 - i] multiplies t^i.
    let p0 = c[12] + c[11] * t + (c[10] + c[9] * t) * t2;
    let p1 = c[8] + c[7] * t + (c[6] + c[5] * t) * t2;
    let p2 = c[4] + c[3] * t + (c[2] + c[1] * t) * t2;
    p0 + p1 * t4 + (p2 + c[0] * t4) * t8
}

/// `ln q`, by a three-term series in `x = q - 1` (exact by Sterbenz's lemma) where that is
/// exact to rounding (`|x| ≤ 1e-4`: truncation `x⁴/4 ≤ 2.5e-17`), else the library logarithm.
/// Near the solution the Newton residual is of this form with `|x| ~ 1e-9`, and the series
/// saves a logarithm per solve.
fn ln_near_one(q: f64) -> f64 {
    let x = q - 1.0;
    if x.abs() <= 1e-4 {
        x * (1.0 - x * (0.5 - x * (1.0 / 3.0)))
    } else {
        q.ln()
    }
}

/// Solution of the shape problem.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Shape {
    /// `g = b/a ∈ (0, 1]`.
    pub g: f64,
    /// `K(1 - g²)`.
    pub k: f64,
    /// `(K - E)/m` at `g`.
    pub d: f64,
    /// Newton steps taken (0 for the circle).
    pub iterations: u32,
    /// Why Newton stopped.
    pub stop: Stop,
}

/// Solves `A/B = g² D/D'` for `g`, given `ratio = A/B ∈ [0, 1]` and `ln_ratio = ln(A/B)`
/// (both, because `A/B` may underflow where its logarithm is still finite).
pub(crate) fn shape(ratio: f64, ln_ratio: f64) -> Shape {
    debug_assert!(ln_ratio <= 0.0 && ln_ratio.is_finite());
    // Below this the residual is formed from logarithms: g² D/(D' A/B) could overflow.
    let ratio_is_normal = ratio >= f64::MIN_POSITIVE;
    if ln_ratio == 0.0 {
        // The circle: K = π/2, D = π/4, no iteration.
        let i = integrals(1.0);
        return Shape {
            g: 1.0,
            k: i.k,
            d: i.d,
            iterations: 0,
            stop: Stop::Converged,
        };
    }
    let mut u = start(ln_ratio);
    let mut iterations = 0;
    loop {
        iterations += 1;
        let g = u.exp();
        let Integrals { k, d, dp, w, .. } = integrals(g);
        let quotient = g * g * d / (dp * ratio);
        let residual = if ratio_is_normal && quotient.is_normal() {
            ln_near_one(quotient)
        } else {
            2.0 * u + (d / dp).ln() - ln_ratio
        };
        let slope = 3.0 - w / d - w / dp;
        let step = -residual / slope;
        if step.abs() <= NEWTON_STEP_TOL {
            return Shape {
                // exp(u + step) to within step²/2 <= 5e-17.
                g: g * (1.0 + step),
                k: k - dp * step,
                d: d - w * step,
                iterations,
                stop: Stop::Converged,
            };
        }
        if iterations >= NEWTON_ITERATION_CAP || !step.is_finite() {
            return Shape {
                g,
                k,
                d,
                iterations,
                stop: Stop::IterationCap,
            };
        }
        // The root has g ≤ 1; an overshoot past the circle is pulled back onto it.
        u = (u + step).min(0.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(ln_ratio: f64) -> Shape {
        super::shape(ln_ratio.exp(), ln_ratio)
    }

    #[test]
    fn newton_converges_in_few_steps_over_the_whole_f64_range() {
        for k in 0..=300 {
            let ln_ratio = -(k as f64) * std::f64::consts::LN_10;
            let s = shape(ln_ratio);
            assert_eq!(s.stop, Stop::Converged, "A/B = 1e-{k}");
            // 5: measured maximum, see NEWTON_ITERATION_CAP.
            assert!(s.iterations <= 5, "A/B = 1e-{k}: {} steps", s.iterations);
            assert!(s.g > 0.0 && s.g <= 1.0);
        }
    }

    #[test]
    fn one_evaluation_inside_the_fitted_range() {
        // The fits are within 1e-9 of the solution, below NEWTON_STEP_TOL, so the first step
        // is accepted.
        for k in 0..=2800 {
            let ln_ratio = -(k as f64) / 100.0;
            let s = shape(ln_ratio);
            let expected = if k == 0 { 0 } else { 1 };
            assert_eq!(s.iterations, expected, "ln(A/B) = {ln_ratio}");
        }
    }

    #[test]
    fn residual_vanishes_at_the_solution() {
        for ln_ratio in [-1e-12, -1e-6, -0.1, -1.0, -5.0, -20.0] {
            let s = shape(ln_ratio);
            let i = integrals(s.g);
            let residual = 2.0 * s.g.ln() + (i.d / i.dp).ln() - ln_ratio;
            // A few rounding errors of ln of numbers near 1 and of 2 ln g: measured up to
            // 3.6e-16 (1 + |ln(A/B)|); bound about twice that.
            assert!(
                residual.abs() <= 8e-16 * (1.0 + ln_ratio.abs()),
                "{ln_ratio}: {residual}"
            );
            // Carried-over K and D agree with a fresh evaluation (first-order carry is exact
            // to O(h²) ≤ 1e-16; measured 2.1e-16 and 3.8e-16 relative).
            assert!((s.k - i.k).abs() <= 8e-16 * i.k);
            assert!((s.d - i.d).abs() <= 8e-16 * i.d);
        }
    }
}
