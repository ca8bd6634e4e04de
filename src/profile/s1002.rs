//! The S1002 wheel profile (EN 13715, UIC 510-2), flange height 28 mm, flange thickness
//! 32.5 mm, from its piecewise analytic definition (DLR, H. Netter), with exact derivatives.
//!
//! Coordinates are the wheel side frame of the crate docs: `s` (mm) from the taping line,
//! positive towards the field side, and `F(s)` (mm) the radius increase over the nominal
//! radius, positive towards the flange tip. The definition spans `-70 <= s <= 60` (the back
//! face of the flange is at `s = -70`).
//!
//! The definition is C1 apart from two value jumps of 3.6e-5 mm at `s = -26` and 1.2e-4 mm at
//! `s = -35`; its curvature jumps at every section joint. Both are kept as defined, not
//! smoothed: a user should see them.

use super::bounds::{DerivativeBounds, arc_bounds, polynomial_bounds};

/// Lowest profile coordinate of the definition (back face of the flange), mm.
pub const S_MIN: f64 = -70.0;
/// Highest profile coordinate of the definition (field-side end of the outer slope), mm.
pub const S_MAX: f64 = 60.0;

/// Section joints, from the field side to the flange back (mm).
pub const JOINTS: [f64; 7] = [
    32.15796,
    -26.0,
    -35.0,
    -38.426669071,
    -39.764473993,
    -49.662510381,
    -62.764705882,
];

// Section A: straight outer slope.
const AA: f64 = 1.364323640;
const BA: f64 = 0.066666667;
// Section B: tread polynomial, F = AB - BB s + CB s^2 - DB s^3 + ... + IB s^8.
const B_POLY: [f64; 9] = [
    0.0,
    -3.358537058e-02,
    1.565681624e-03,
    -2.810427944e-05,
    5.844240864e-08,
    -1.562379023e-08,
    5.309217349e-15,
    -5.957839843e-12,
    2.646656573e-13,
];
// Section C: flange root polynomial, F = -(AC + BC s + ... + HC s^7).
const C_POLY: [f64; 8] = [
    -4.320221063e+03,
    -1.038384026e+03,
    -1.065501873e+02,
    -6.051367875,
    -2.054332446e-01,
    -4.169739389e-03,
    -4.687195829e-05,
    -2.252755540e-07,
];
// Section D: arc R13, F = AD - sqrt(BD^2 - (s + CD)^2).
const AD: f64 = 16.446;
const BD: f64 = 13.0;
const CD: f64 = 26.210665;
// Section E: straight flank (70 degrees), F = -AE - BE s.
const AE: f64 = 93.576667419;
const BE: f64 = 2.747477419;
// Sections F, G, H: arcs R20, R12, R20.5, F = A + sqrt(B^2 - (s + C)^2).
const ARC_F: (f64, f64, f64) = (8.834924130, 20.0, 58.558326413);
const ARC_G: (f64, f64, f64) = (16.0, 12.0, 55.0);
const ARC_H: (f64, f64, f64) = (9.519259302, 20.5, 49.5);

/// `[F, dF/ds, d2F/ds2]` of S1002 at `s` (mm).
///
/// `s` is clamped to `[S_MIN, S_MAX]`. At a joint the section on the field side of the
/// joint is used.
#[inline]
pub fn eval(s: f64) -> [f64; 3] {
    let s = s.clamp(S_MIN, S_MAX);
    if s >= JOINTS[0] {
        [AA - BA * s, -BA, 0.0]
    } else if s >= JOINTS[1] {
        horner(&B_POLY, s)
    } else if s >= JOINTS[2] {
        horner(&C_POLY, s)
    } else if s >= JOINTS[3] {
        // Concave arc seen from below: F = AD - sqrt(R^2 - u^2).
        let u = s + CD;
        let root = (BD * BD - u * u).max(0.0).sqrt();
        [AD - root, u / root, BD * BD / (root * root * root)]
    } else if s >= JOINTS[4] {
        [-AE - BE * s, -BE, 0.0]
    } else if s >= JOINTS[5] {
        convex_arc(ARC_F, s)
    } else if s >= JOINTS[6] {
        convex_arc(ARC_G, s)
    } else {
        convex_arc(ARC_H, s)
    }
}

/// Bounds of `F'` and `F''` over `[lo, hi]` (inside the domain): each section on its part
/// of the interval, from its own formula (both one-sided limits at a joint).
pub(super) fn derivative_bounds(lo: f64, hi: f64) -> DerivativeBounds {
    // Sections from the flange back to the field side: `(start, end)` and their bounds.
    let j = JOINTS;
    let concave = |s: f64| {
        let u = s + CD;
        let root = (BD * BD - u * u).max(0.0).sqrt();
        [AD - root, u / root, BD * BD / (root * root * root)]
    };
    let line = |slope: f64| DerivativeBounds {
        d1: (slope, slope),
        d2: (0.0, 0.0),
    };
    let mut b = DerivativeBounds::EMPTY;
    let mut part = |start: f64, end: f64, f: &dyn Fn(f64, f64) -> DerivativeBounds| {
        let (a, c) = (lo.max(start), hi.min(end));
        if a <= c {
            b = b.union(f(a, c));
        }
    };
    part(S_MIN, j[6], &|a, c| {
        arc_bounds(|s| convex_arc(ARC_H, s), -ARC_H.2, a, c)
    });
    part(j[6], j[5], &|a, c| {
        arc_bounds(|s| convex_arc(ARC_G, s), -ARC_G.2, a, c)
    });
    part(j[5], j[4], &|a, c| {
        arc_bounds(|s| convex_arc(ARC_F, s), -ARC_F.2, a, c)
    });
    part(j[4], j[3], &|_, _| line(-BE));
    part(j[3], j[2], &|a, c| arc_bounds(concave, -CD, a, c));
    part(j[2], j[1], &|a, c| polynomial_bounds(&C_POLY, a, c));
    part(j[1], j[0], &|a, c| polynomial_bounds(&B_POLY, a, c));
    part(j[0], S_MAX, &|_, _| line(-BA));
    b
}

/// Value, first and second derivative of `sum c[k] s^k` by Horner's scheme, for `f64` or
/// for SIMD lanes of `f64`: the same operations in the same order, so each lane rounds
/// exactly as the scalar evaluation (no fused multiply-add).
#[inline(always)]
fn horner<T, const N: usize>(c: &[f64; N], s: T) -> [T; 3]
where
    T: Copy + From<f64> + std::ops::Add<Output = T> + std::ops::Mul<Output = T>,
{
    let two = T::from(2.0);
    let (mut p, mut dp, mut ddp) = (T::from(0.0), T::from(0.0), T::from(0.0));
    for &ck in c.iter().rev() {
        ddp = ddp * s + two * dp;
        dp = dp * s + p;
        p = p * s + T::from(ck);
    }
    [p, dp, ddp]
}

/// [`eval`] of four points in SIMD lanes, to the bit, when all four lie in the same
/// section; `None` otherwise (the caller takes [`eval`] per point).
///
/// Only the polynomial sections (tread B and flange root C) are done in lanes: the lines
/// cost nothing and the arcs are rare under the contact.
#[inline]
pub(crate) fn eval_x4(s: [f64; 4]) -> Option<[[f64; 3]; 4]> {
    let s = s.map(|x| x.clamp(S_MIN, S_MAX));
    let (lo, hi) = (
        s.iter().copied().fold(f64::INFINITY, f64::min),
        s.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    let x = wide::f64x4::from(s);
    let [p, dp, ddp] = if lo >= JOINTS[1] && hi < JOINTS[0] {
        horner(&B_POLY, x)
    } else if lo >= JOINTS[2] && hi < JOINTS[1] {
        horner(&C_POLY, x)
    } else {
        return None;
    };
    let (p, dp, ddp) = (p.to_array(), dp.to_array(), ddp.to_array());
    Some(std::array::from_fn(|i| [p[i], dp[i], ddp[i]]))
}

/// `F = a + sqrt(r^2 - (s + c)^2)` and its derivatives (the flange arcs, convex downwards).
///
/// The flange-back arc R20.5 reaches its vertical tangent at `S_MIN`, where the derivatives
/// are infinite and the curvature `inf / inf`. The derivatives are therefore taken with the
/// root at least [`MIN_ARC_ROOT`] times the radius: the slope stays finite (1e6) and the
/// curvature `-F'' / (1 + F'^2)^1.5` is the arc's `1/r` to 1e-12. Only points within about
/// 1e-11 mm of the vertical tangent are affected; `F` itself is exact.
fn convex_arc((a, r, c): (f64, f64, f64), s: f64) -> [f64; 3] {
    let u = s + c;
    let root = (r * r - u * u).max(0.0).sqrt();
    let d = root.max(MIN_ARC_ROOT * r);
    [a + root, -u / d, -r * r / (d * d * d)]
}

/// Smallest `sqrt(r^2 - u^2) / r` used for the derivatives of an arc (see [`convex_arc`]).
const MIN_ARC_ROOT: f64 = 1e-6;

#[cfg(test)]
mod tests {
    use super::*;

    /// The check values of EN 13715 are given to 6 decimals.
    const CHECK_TOL_MM: f64 = 1e-6;

    #[test]
    fn reference_values() {
        assert!(eval(0.0)[0].abs() < CHECK_TOL_MM);
        assert!((eval(60.0)[0] + 2.635676).abs() < CHECK_TOL_MM);
        assert!((eval(-70.0)[0] - 9.519259).abs() < CHECK_TOL_MM);
        assert!((eval(-55.0)[0] - 28.0).abs() < CHECK_TOL_MM);
        // The R13 arc at -37.5 (measured 5.8e-8 mm off 10).
        assert!((eval(-37.5)[0] - 10.0).abs() < 1.2e-7, "{}", eval(-37.5)[0]);
        // Flank slope: tan(70 deg) = 2.747477; the definition gives BE to 9 decimals
        // (measured 4.5e-10 off).
        assert!((-eval(-39.0)[1] - 70f64.to_radians().tan()).abs() < 1e-9);
        // Tread slope at the taping line: -0.03359 (5 decimals in the reference).
        assert!((eval(0.0)[1] + 0.03359).abs() < 5e-6);
    }

    #[test]
    fn derivatives_match_finite_differences() {
        // Central differences with h = 1e-4 have truncation error h^2 f'''/6 ~ 1e-9 and
        // rounding error ~ eps F / h ~ 1e-11; measured 1.3e-7 in F' and 6.1e-7 in F''
        // (relative to 1 + |F'|, 1 + |F''|, where the arcs' third derivative is large).
        let h = 1e-4;
        let mut s = -69.9;
        while s < 59.9 {
            if JOINTS.iter().all(|j| (s - j).abs() > 2.0 * h) {
                let [_, d1, d2] = eval(s);
                let fd1 = (eval(s + h)[0] - eval(s - h)[0]) / (2.0 * h);
                let fd2 = (eval(s + h)[1] - eval(s - h)[1]) / (2.0 * h);
                assert!((d1 - fd1).abs() < 3e-7 * (1.0 + d1.abs()), "F' at {s}");
                assert!((d2 - fd2).abs() < 1.5e-6 * (1.0 + d2.abs()), "F'' at {s}");
            }
            s += 0.013;
        }
    }

    #[test]
    fn lanes_are_eval_to_the_bit() {
        // Every polynomial section, 4000 groups of 4 points each (irregular spacing).
        for (a, b) in [(JOINTS[1], JOINTS[0]), (JOINTS[2], JOINTS[1])] {
            for i in 0..4000 {
                let x = |k: f64| a + (b - a) * ((f64::from(i) * 0.618_034 + k * 0.173) % 1.0);
                let s = [x(0.0), x(1.0), x(2.0), x(3.0)];
                let lanes = eval_x4(s).expect("one section");
                for (l, &si) in lanes.iter().zip(&s) {
                    assert_eq!(l.map(f64::to_bits), eval(si).map(f64::to_bits), "s = {si}");
                }
            }
        }
        assert!(eval_x4([0.0, 0.0, 0.0, 40.0]).is_none(), "two sections");
    }

    #[test]
    fn value_jumps_at_joints_are_as_documented() {
        let jump = |j: f64| (eval(j)[0] - eval(j - 1e-12)[0]).abs();
        assert!(jump(-26.0) < 5e-5 && jump(-26.0) > 2e-5, "{}", jump(-26.0));
        assert!(jump(-35.0) < 2e-4 && jump(-35.0) > 5e-5, "{}", jump(-35.0));
        for j in [JOINTS[0], JOINTS[3], JOINTS[4], JOINTS[5], JOINTS[6]] {
            assert!(jump(j) < 1e-6, "joint {j}: {}", jump(j));
        }
    }

    /// A known value of `eval`.
    #[test]
    fn eval_example() {
        let [f, _, _] = crate::profile::s1002::eval(-55.0);
        assert!((f - 28.0).abs() < 1e-9); // flange tip, EN 13715
    }
}
