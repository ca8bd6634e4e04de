//! A scan along a spline at increasing `x` that carries its interval along.

use super::{SmoothingSpline, cubic};

/// A scan along a spline at increasing `x` ([`SmoothingSpline::walk_from_start`]): the
/// interval of the previous `x` carried along and stepped forward to the last `i` with
/// `knots[i] <= x`, instead of the bucket lookup of every [`SmoothingSpline::eval`] (half
/// its work); the same interval, so the same bits as `eval`; an `x` below the previous
/// interval, or NaN, takes the lookup. The spline's knots and coefficients are held as
/// slices of its own, which a loop keeps in registers (through the spline, every
/// evaluation reloads them after the loop's stores).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Walk<'a> {
    knots: &'a [f64],
    coeffs: &'a [[f64; 4]],
    interval: usize,
    spline: &'a SmoothingSpline,
}

impl<'a> Walk<'a> {
    /// A walk from the first interval of `spline`.
    pub(super) fn new(spline: &'a SmoothingSpline) -> Walk<'a> {
        Walk {
            knots: &spline.knots,
            coeffs: &spline.coeffs,
            interval: 0,
            spline,
        }
    }

    /// The value and slope of [`SmoothingSpline::eval`] at `x` (inside the domain, or NaN):
    /// the same interval, the same operations, without the second derivative.
    #[inline(always)]
    pub(crate) fn eval_slope(&mut self, x: f64) -> [f64; 2] {
        let i = self.step(x);
        let [a, b, c, d] = self.coeffs[i];
        let t = x - self.knots[i];
        [
            a + t * (b + t * (c + t * d)),
            b + t * (2.0 * c + 3.0 * t * d),
        ]
    }

    /// [`SmoothingSpline::eval`] at `x` (inside the domain, or NaN): the same interval, the
    /// same cubic.
    #[inline(always)]
    pub(crate) fn eval(&mut self, x: f64) -> [f64; 3] {
        let i = self.step(x);
        cubic(self.coeffs[i], x - self.knots[i])
    }

    /// The interval of `x`, the walk moved to it (the lookup on a step back or NaN).
    #[inline(always)]
    fn step(&mut self, x: f64) -> usize {
        let i = walk_forward(self.knots, self.interval, x)
            .unwrap_or_else(|| self.spline.interval_cold(x));
        self.interval = i;
        i
    }
}

/// The interval of `x` walking forward from the interval `from` (clamped to the last): the
/// last `i` with `knots[i] <= x`; `None` where `x` is below `knots[from]` (a step back) or
/// NaN.
#[inline(always)]
fn walk_forward(knots: &[f64], from: usize, x: f64) -> Option<usize> {
    let last = knots.len() - 2;
    let mut i = from.min(last);
    if knots[i] <= x {
        while i < last && knots[i + 1] <= x {
            i += 1;
        }
        Some(i)
    } else {
        None
    }
}
