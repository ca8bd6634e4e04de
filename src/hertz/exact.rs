//! The exact shape solve: the axis ratio `g = b/a` from the curvature ratio, to machine
//! precision (Johnson 1985, Eq. 4.39; paper Eq. 14).
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
//! The start is Greenwood's `g₀ = (A/B)^(2/3)` (exact slope at the circle).

use super::StopReason;
use super::elliptic::{Integrals, integrals};

/// Newton stops once a step in `ln g` is at most this. Convergence is quadratic with
/// `|f''/(2 f')| < 0.2` over the whole range, so after a step of `h ≤ 1e-8` the remaining error
/// in `ln g` is below `0.2 h² = 2e-17`: the accepted step is the last one. `K` and `D` are
/// carried over that step to first order (their error is again `O(h²)`), which saves one AGM.
pub(crate) const NEWTON_STEP_TOL: f64 = 1e-8;

/// Newton iteration cap. From Greenwood's start, 1-5 steps are needed for any `A/B` an f64 can
/// hold (measured: at most 5 for `A/B = 1e-300`); 50 is only a guard.
pub(crate) const NEWTON_ITERATION_CAP: u32 = 50;

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
    pub stop: StopReason,
}

/// Solves `A/B = g² D/D'` for `g`, given `ln(A/B) ≤ 0`.
pub(crate) fn shape(ln_ratio: f64) -> Shape {
    debug_assert!(ln_ratio <= 0.0 && ln_ratio.is_finite());
    if ln_ratio == 0.0 {
        // The circle: K = π/2, D = π/4, no iteration.
        let i = integrals(1.0);
        return Shape {
            g: 1.0,
            k: i.k,
            d: i.d,
            iterations: 0,
            stop: StopReason::Converged,
        };
    }
    let mut u = ln_ratio * (2.0 / 3.0);
    let mut iterations = 0;
    loop {
        iterations += 1;
        let g = u.exp();
        let Integrals { k, d, dp, w, .. } = integrals(g);
        let residual = 2.0 * u + (d / dp).ln() - ln_ratio;
        let slope = 3.0 - w / d - w / dp;
        let step = -residual / slope;
        if step.abs() <= NEWTON_STEP_TOL {
            let u_new = u + step;
            return Shape {
                g: u_new.exp(),
                k: k - dp * step,
                d: d - w * step,
                iterations,
                stop: StopReason::Converged,
            };
        }
        if iterations >= NEWTON_ITERATION_CAP || !step.is_finite() {
            return Shape {
                g,
                k,
                d,
                iterations,
                stop: StopReason::IterationCap,
            };
        }
        // The root has g ≤ 1; an overshoot past the circle is pulled back onto it.
        u = (u + step).min(0.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn newton_converges_in_few_steps_over_the_whole_f64_range() {
        for k in 0..=300 {
            let ln_ratio = -(k as f64) * std::f64::consts::LN_10;
            let s = shape(ln_ratio);
            assert_eq!(s.stop, StopReason::Converged, "A/B = 1e-{k}");
            // 5: measured maximum, see NEWTON_ITERATION_CAP.
            assert!(s.iterations <= 5, "A/B = 1e-{k}: {} steps", s.iterations);
            assert!(s.g > 0.0 && s.g <= 1.0);
        }
    }

    #[test]
    fn residual_vanishes_at_the_solution() {
        for ln_ratio in [-1e-12, -1e-6, -0.1, -1.0, -5.0, -20.0] {
            let s = shape(ln_ratio);
            let i = integrals(s.g);
            let residual = 2.0 * s.g.ln() + (i.d / i.dp).ln() - ln_ratio;
            // 4e-16: a few rounding errors of ln of numbers near 1 and of 2 ln g.
            assert!(
                residual.abs() <= 4e-16 * (1.0 + ln_ratio.abs()),
                "{ln_ratio}: {residual}"
            );
            // Carried-over K and D agree with a fresh evaluation (first-order carry is exact
            // to O(h²) ≤ 1e-16).
            assert!((s.k - i.k).abs() <= 2e-15 * i.k);
            assert!((s.d - i.d).abs() <= 2e-15 * i.d);
        }
    }
}
