//! Rigorous bounds of a profile's first and second derivatives over an interval, from the
//! profile's own representation: what the certificate of the gap's global minimum
//! ([`crate::gap`]) needs to bound the gap's second derivative on a cell.
//!
//! * a spline piece is a cubic: its second derivative is linear (extremes at the ends), its
//!   first derivative a parabola (extremes at the ends or the vertex);
//! * an arc (S1002 flange, UIC60 head) has a slope monotone along it and a second
//!   derivative monotone in the distance from its vertex: extremes at the ends or the vertex;
//! * a polynomial (S1002 tread and flange root) is expanded about the interval's midpoint,
//!   and the terms beyond the first are bounded by their absolute values (Taylor).
//!
//! Sections are bounded separately on their part of the interval; at a joint both one-sided
//! limits are included. Every bound is widened by [`BOUND_PAD`] for the rounding of its
//! evaluation. The unit tests check the bounds against dense evaluations.

use super::{Profile, Shape, s1002, uic60};

/// Relative widening of every bound (of the larger magnitude of its ends) for the rounding of
/// the formulas that give it (a few ulps each): far above rounding, far below any use.
pub const BOUND_PAD: f64 = 1e-9;

/// Ranges of a profile's `dv/du` and `d2v/du2` over an interval: `(min, max)` each.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DerivativeBounds {
    /// Range of the first derivative.
    pub d1: (f64, f64),
    /// Range of the second derivative (1/mm).
    pub d2: (f64, f64),
}

impl DerivativeBounds {
    /// The empty range (the neutral element of [`DerivativeBounds::include`]).
    pub const EMPTY: DerivativeBounds = DerivativeBounds {
        d1: (f64::INFINITY, f64::NEG_INFINITY),
        d2: (f64::INFINITY, f64::NEG_INFINITY),
    };

    /// Widens the ranges to hold the derivatives `[_, d1, d2]` of one evaluation.
    #[inline]
    pub fn include(&mut self, [_, d1, d2]: [f64; 3]) {
        self.d1 = (self.d1.0.min(d1), self.d1.1.max(d1));
        self.d2 = (self.d2.0.min(d2), self.d2.1.max(d2));
    }

    /// The union of two ranges.
    pub fn union(self, other: DerivativeBounds) -> DerivativeBounds {
        DerivativeBounds {
            d1: (self.d1.0.min(other.d1.0), self.d1.1.max(other.d1.1)),
            d2: (self.d2.0.min(other.d2.0), self.d2.1.max(other.d2.1)),
        }
    }

    /// The ranges widened by [`BOUND_PAD`].
    pub fn padded(self) -> DerivativeBounds {
        let pad = |(lo, hi): (f64, f64)| {
            let w = BOUND_PAD * lo.abs().max(hi.abs()) + f64::MIN_POSITIVE;
            (lo - w, hi + w)
        };
        DerivativeBounds {
            d1: pad(self.d1),
            d2: pad(self.d2),
        }
    }

    /// The largest magnitude of the second derivative.
    pub fn d2_abs(&self) -> f64 {
        self.d2.0.abs().max(self.d2.1.abs())
    }
}

impl Profile {
    /// Bounds of the profile's first and second derivatives over `[lo, hi]` (clamped to the
    /// domain, as [`Profile::eval`] clamps), including both one-sided limits at joints.
    pub fn derivative_bounds(&self, lo: f64, hi: f64) -> DerivativeBounds {
        let (d_lo, d_hi) = self.domain();
        let (lo, hi) = (lo.clamp(d_lo, d_hi), hi.clamp(d_lo, d_hi));
        let (lo, hi) = (lo.min(hi), lo.max(hi));
        let b = match &self.shape {
            Shape::S1002 => s1002::derivative_bounds(lo, hi),
            Shape::Uic60 => uic60::derivative_bounds(lo, hi),
            Shape::Sampled(sp) => sp.derivative_bounds(lo, hi),
        };
        b.padded()
    }
}

/// Bounds of the derivatives of `p(x) = sum c[k] x^k` over `[lo, hi]`: the Taylor expansion
/// about the midpoint, its higher terms bounded by their absolute values.
pub(super) fn polynomial_bounds(c: &[f64], lo: f64, hi: f64) -> DerivativeBounds {
    let m = 0.5 * (lo + hi);
    let r = 0.5 * (hi - lo);
    // Taylor coefficients q[k] = p^(k)(m) / k! by repeated synthetic division.
    let mut q = c.to_vec();
    let n = q.len();
    for k in 0..n {
        for j in (k..n - 1).rev() {
            q[j] += m * q[j + 1];
        }
    }
    // p'(m + t) = q1 + sum_{k>=2} k q_k t^(k-1); p''(m + t) = 2 q2 + sum_{k>=3} k(k-1) q_k t^(k-2).
    let (mut r1, mut r2) = (0.0, 0.0);
    for (k, &qk) in q.iter().enumerate().skip(2) {
        let kf = k as f64;
        r1 += kf * qk.abs() * r.powi(k as i32 - 1);
        if k >= 3 {
            r2 += kf * (kf - 1.0) * qk.abs() * r.powi(k as i32 - 2);
        }
    }
    let q1 = q.get(1).copied().unwrap_or(0.0);
    let q2 = 2.0 * q.get(2).copied().unwrap_or(0.0);
    DerivativeBounds {
        d1: (q1 - r1, q1 + r1),
        d2: (q2 - r2, q2 + r2),
    }
}

/// Bounds over `[lo, hi]` of a section whose slope is monotone and whose second derivative
/// is monotone on each side of `vertex` (an arc; a line has both constant): the extremes
/// lie at the ends or at the vertex.
pub(super) fn arc_bounds(
    eval: impl Fn(f64) -> [f64; 3],
    vertex: f64,
    lo: f64,
    hi: f64,
) -> DerivativeBounds {
    let mut b = DerivativeBounds::EMPTY;
    b.include(eval(lo));
    b.include(eval(hi));
    if lo < vertex && vertex < hi {
        b.include(eval(vertex));
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dense evaluation (and the one-sided limits at joints) stays inside the bounds of
    /// random intervals, and the bounds are tight to what the evaluation reaches plus the
    /// Taylor remainder of a short interval.
    fn check(profile: &Profile, widths: &[f64]) {
        let (lo, hi) = profile.domain();
        let mut worst_excess: f64 = 0.0;
        for &w in widths {
            let mut a = lo;
            while a + w <= hi {
                let b = profile.derivative_bounds(a, a + w);
                let mut seen = DerivativeBounds::EMPTY;
                let grid = (0..=200).map(|i| a + w * f64::from(i) / 200.0);
                for u in grid.chain(profile.joints()) {
                    for v in [u, u - 1e-12, u + 1e-12] {
                        if (a..=a + w).contains(&v) {
                            let e = profile.eval(v);
                            seen.include(e);
                        }
                    }
                }
                assert!(
                    b.d1.0 <= seen.d1.0 && seen.d1.1 <= b.d1.1,
                    "{} d1 on [{a}, {}]: {b:?} vs {seen:?}",
                    profile.name(),
                    a + w
                );
                assert!(
                    b.d2.0 <= seen.d2.0 && seen.d2.1 <= b.d2.1,
                    "{} d2 on [{a}, {}]: {b:?} vs {seen:?}",
                    profile.name(),
                    a + w
                );
                if w <= 0.25 {
                    let excess = (seen.d2.0 - b.d2.0).max(b.d2.1 - seen.d2.1);
                    worst_excess = worst_excess.max(excess / b.d2_abs().max(1.0));
                }
                a += 0.37 * w;
            }
        }
        // Not loose: on 0.25 mm cells the second-derivative range is hardly wider than the
        // profile's own (the arcs' are attained exactly, the polynomials' remainder is small),
        // relative to its magnitude where that exceeds 1/mm (the flange back's vertical
        // tangent). Measured at most 3.5e-4 (the sampled profiles); bound about three times.
        assert!(worst_excess < 1e-3, "{}: {worst_excess}", profile.name());
    }

    #[test]
    fn analytic_profiles_stay_within_their_bounds() {
        check(&Profile::s1002(), &[0.25, 1.3, 9.0]);
        check(&Profile::uic60e1(), &[0.25, 1.3, 9.0]);
    }

    #[test]
    fn sampled_profiles_stay_within_their_bounds() {
        use crate::profile::read::{ProfileFormat, parse_str};
        let mut noise = crate::rng::SplitMix64::new(7);
        let mut text = String::from("s_mm,F_mm\n");
        let mut s = -60.0;
        while s <= 50.0 {
            let f = s1002::eval(s)[0] + 0.02 * noise.normal();
            text.push_str(&format!("{s},{f}\n"));
            s += 0.47;
        }
        let points = parse_str(
            &text,
            ProfileFormat::Csv,
            crate::profile::ProfileKind::Wheel,
            "noisy",
        )
        .unwrap();
        for smoothing in [0.0, 4.0] {
            let p = Profile::from_points(points.clone(), smoothing).unwrap();
            check(&p, &[0.25, 1.3]);
        }
    }
}
