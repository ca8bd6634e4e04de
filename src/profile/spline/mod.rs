//! Cubic smoothing splines and non-uniform finite-difference weights for sampled profiles:
//! values, slopes and curvatures of measured wheels and rails.
//!
//! Raw differences of measured points are useless for curvature: 0.5 micrometre of noise at
//! 0.1 mm spacing gives three-point curvature errors of about 100 1/m, while a rail crown
//! (R300) has 3.3 1/m. A [`SmoothingSpline`] with [`default_lambda`] filters out wavelengths
//! shorter than [`DEFAULT_FILTER_WAVELENGTH_MM`] and keeps the rest, in millimetres whatever
//! the point spacing. [`fornberg_weights`] gives the finite-difference alternative of the
//! paper (its ref. 12), exact for polynomials, for comparison.
//!
//! # Units
//!
//! Everything in millimetres: x and y in mm, slope dimensionless, second derivative and
//! curvature in 1/mm, the smoothing parameter `lambda` in mm^3 (see [`SmoothingSpline::fit`]).
//!
//! # Curvature sign
//!
//! [`curvature`] is the signed curvature of the graph `y(x)`, positive where the graph bends
//! upwards. In the side frames of [`crate::profile::read`] a convex rail crown (z up) has
//! curvature `-1/R`, and so has a crowned wheel tread in `(s, F)` (F grows towards the flange
//! tip, i.e. away from the axle): `circ_r300.prr` gives -1/300 and `circ_r100.prw` -1/100.
//!
//! The parts: the spline and its evaluation (here), its fit (`fit.rs`), the filter that
//! chooses its smoothing (`filter.rs`), the scan along it at increasing `x` (`walk.rs`), its
//! errors (`error.rs`), and [`fornberg_weights`] (`fornberg.rs`).

mod error;
mod filter;
mod fit;
mod fornberg;
mod walk;

pub use error::SplineError;
pub use filter::{DEFAULT_FILTER_WAVELENGTH_MM, default_lambda, lambda_for_wavelength};
pub use fornberg::fornberg_weights;
pub(crate) use walk::Walk;

use super::bounds::DerivativeBounds;

/// Signed curvature (1/mm) of a graph with slope `d1` and second derivative `d2` (1/mm):
/// `d2 / (1 + d1^2)^(3/2)`. Positive where the graph bends upwards.
///
/// ```
/// use wheelrail::profile::spline::curvature;
/// // Circle of radius 10 at 45 degrees: y = -sqrt(100 - x^2) + c has y' = 1, y'' = 2^1.5 / 10.
/// assert!((curvature(1.0, 2f64.powf(1.5) / 10.0) - 0.1).abs() < 1e-12);
/// ```
pub fn curvature(d1: f64, d2: f64) -> f64 {
    d2 / (1.0 + d1 * d1).powf(1.5)
}

/// A cubic smoothing spline `f(x)` (Reinsch 1967; de Boor, *A Practical Guide to Splines*,
/// ch. XIV; Green & Silverman 1994, sect. 2.3): among all functions with square-integrable
/// second derivative, the one minimising
///
/// ```text
/// sum_i (y_i - f(x_i))^2 + lambda * integral f''(x)^2 dx
/// ```
///
/// It is a natural cubic spline with knots at the data points (`f'' = 0` at both ends).
/// `lambda = 0` gives the natural interpolating cubic spline. The fit is one O(n) banded
/// (pentadiagonal LDL^T) solve.
///
/// Evaluation ([`eval`](Self::eval)) finds the interval in O(1) for roughly uniform spacing
/// (a table of equal-width buckets maps x to a knot index, then a binary search within the
/// bucket, which holds one or two knots unless the spacing is very uneven), and allocates
/// nothing. Outside the knots the spline is **extrapolated linearly** with its end value and
/// slope; as `f'' = 0` at the ends this keeps value, slope and second derivative continuous.
///
/// ```
/// use wheelrail::profile::spline::SmoothingSpline;
/// // The interpolating spline reproduces straight lines exactly, inside and outside.
/// let x = [0.0, 0.5, 1.5, 2.0, 3.5];
/// let y: Vec<f64> = x.iter().map(|x| 2.0 * x - 1.0).collect();
/// let s = SmoothingSpline::fit(&x, &y, 0.0)?;
/// let [f, d1, d2] = s.eval(5.0);
/// assert!((f - 9.0).abs() < 1e-12 && (d1 - 2.0).abs() < 1e-12 && d2.abs() < 1e-12);
/// # Ok::<(), wheelrail::profile::spline::SplineError>(())
/// ```
#[derive(Debug, Clone)]
pub struct SmoothingSpline {
    knots: Vec<f64>,
    values: Vec<f64>,
    /// Per interval i: `[a, b, c, d]` of `a + b t + c t^2 + d t^3`, `t = x - knots[i]`.
    coeffs: Vec<[f64; 4]>,
    /// `buckets[k]`: the interval holding `knots[0] + k / bucket_scale`; one more entry than
    /// there are buckets.
    buckets: Vec<usize>,
    bucket_scale: f64,
    end_slopes: [f64; 2],
}

impl SmoothingSpline {
    /// Whether `other` is this spline to the bit: the same knots, values and coefficients
    /// (and so the same numbers everywhere).
    pub(crate) fn same_data(&self, other: &SmoothingSpline) -> bool {
        let bits = |a: &[f64], b: &[f64]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
        };
        bits(&self.knots, &other.knots)
            && bits(&self.values, &other.values)
            && bits(self.coeffs.as_flattened(), other.coeffs.as_flattened())
            && self.buckets == other.buckets
            && bits(&[self.bucket_scale], &[other.bucket_scale])
            && bits(&self.end_slopes, &other.end_slopes)
    }

    /// `[f(x), f'(x), f''(x)]`; linear extrapolation outside [`domain`](Self::domain)
    /// (f'' = 0 there). NaN in, NaN out.
    pub fn eval(&self, x: f64) -> [f64; 3] {
        let (x0, x1) = self.domain();
        if x < x0 {
            let v = self.values[0];
            let s = self.end_slopes[0];
            return [v + s * (x - x0), s, 0.0];
        }
        if x > x1 {
            let v = self.values[self.values.len() - 1];
            let s = self.end_slopes[1];
            return [v + s * (x - x1), s, 0.0];
        }
        self.eval_inside(x)
    }

    /// [`eval`](Self::eval) at `x` inside the [`domain`](Self::domain) (or NaN): the
    /// interval looked up and its cubic evaluated in one function, without the tests for
    /// extrapolation (a profile clamps to the domain first): what
    /// [`Profile::eval`](crate::profile::Profile::eval) of a sampled profile runs.
    #[inline]
    pub(crate) fn eval_inside(&self, x: f64) -> [f64; 3] {
        self.eval_piece(self.interval_inline(x), x)
    }

    /// The cubic of interval `i` at `x`: the one formula of every evaluation, so that a
    /// [`Walk`] gives the same bits as [`eval`](Self::eval).
    #[inline(always)]
    fn eval_piece(&self, i: usize, x: f64) -> [f64; 3] {
        cubic(self.coeffs[i], x - self.knots[i])
    }

    /// A scan at increasing `x` from the first interval ([`Walk`]).
    pub(crate) fn walk_from_start(&self) -> Walk<'_> {
        Walk::new(self)
    }

    /// Bounds of `f'` and `f''` over `[lo, hi]` (inside the domain): per cubic piece,
    /// `f''` is linear (extremes at the ends) and `f'` a parabola (ends or vertex).
    pub(crate) fn derivative_bounds(&self, lo: f64, hi: f64) -> DerivativeBounds {
        let mut b = DerivativeBounds::EMPTY;
        let last = self.knots.len() - 2;
        let mut i = self.interval(lo);
        loop {
            let (k0, k1) = (self.knots[i], self.knots[i + 1]);
            let [_, p1, c, d] = self.coeffs[i];
            let (t0, t1) = (lo.max(k0) - k0, hi.min(k1) - k0);
            let at = |t: f64| [0.0, p1 + t * (2.0 * c + 3.0 * t * d), 2.0 * c + 6.0 * t * d];
            b.include(at(t0));
            b.include(at(t1));
            if d != 0.0 {
                let vertex = -c / (3.0 * d);
                if t0 < vertex && vertex < t1 {
                    b.include(at(vertex));
                }
            }
            if i >= last || k1 >= hi {
                break;
            }
            i += 1;
        }
        b
    }

    /// The knots: the x values the spline was fitted to (mm).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The spline's values at the knots (equal to the data for `lambda = 0`).
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// First and last knot (mm).
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[0], self.knots[self.knots.len() - 1])
    }

    /// [`interval`](Self::interval) out of line: the walk's rare step back stays out of the
    /// short loop that scans.
    #[cold]
    #[inline(never)]
    fn interval_cold(&self, x: f64) -> usize {
        self.interval(x)
    }

    /// Index of the interval `[knots[i], knots[i + 1]]` holding `x` (x inside the domain):
    /// the last `i < knots.len() - 1` with `knots[i] <= x`.
    #[inline]
    fn interval(&self, x: f64) -> usize {
        self.interval_inline(x)
    }

    /// [`interval`](Self::interval), inlined into [`eval_inside`](Self::eval_inside).
    #[inline(always)]
    fn interval_inline(&self, x: f64) -> usize {
        let nb = self.buckets.len() - 1;
        let last = self.knots.len() - 2;
        // Saturating float-to-int cast: NaN gives 0, huge values nb. Through i32 (a bucket
        // table is far shorter): one conversion, where usize costs a dozen instructions for
        // its saturation and sign handling; the cast saturates and maps NaN to 0 as well.
        let k = ((((x - self.knots[0]) * self.bucket_scale) as i32).max(0) as usize).min(nb);
        // The bucket's interval, then a step or two to the interval holding x (a bucket holds
        // one or two knots unless the spacing is very uneven, and rounding of the bucket edge
        // can put x one interval before the bucket's): one or two comparisons, where a binary
        // search over the neighbouring buckets took a loop. A bucket holding many knots
        // takes the binary search.
        let mut i = self.buckets[k];
        if i > 0 && self.knots[i] > x {
            i -= 1;
        }
        for _ in 0..WALK_STEPS {
            if i < last && self.knots[i + 1] <= x {
                i += 1;
            } else if self.knots[i] <= x || i == 0 {
                return i;
            } else {
                break;
            }
        }
        // One bucket of margin on each side absorbs rounding of the bucket edges.
        let lo = self.buckets[k.saturating_sub(1)];
        let hi = self.buckets[(k + 2).min(nb)];
        lo + self.knots[lo + 1..=hi].partition_point(|&knot| knot <= x)
    }
}

/// `[f, f', f'']` of the cubic `a + b t + c t^2 + d t^3` at `t`: the one formula of every
/// evaluation of a spline piece.
#[inline(always)]
fn cubic([a, b, c, d]: [f64; 4], t: f64) -> [f64; 3] {
    [
        a + t * (b + t * (c + t * d)),
        b + t * (2.0 * c + 3.0 * t * d),
        2.0 * c + 6.0 * t * d,
    ]
}

/// Steps from a bucket's interval after which [`SmoothingSpline::eval`] searches the
/// neighbouring buckets by bisection instead (very uneven spacing).
const WALK_STEPS: usize = 3;

/// Equal-width buckets over the knots, one per interval on average.
fn bucket_table(x: &[f64]) -> (Vec<usize>, f64) {
    let intervals = x.len() - 1;
    let nb = intervals.max(1);
    let scale = nb as f64 / (x[x.len() - 1] - x[0]);
    let mut buckets = Vec::with_capacity(nb + 1);
    let mut i = 0;
    for k in 0..=nb {
        let edge = x[0] + k as f64 / scale;
        while i + 1 < intervals && x[i + 1] <= edge {
            i += 1;
        }
        buckets.push(i);
    }
    (buckets, scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Exact reproduction of the data is limited by rounding only: measured 5.6e-17 on
    /// values below 1; two ulps of 1.
    const ROUNDING_TOL: f64 = 4.5e-16;

    /// Deterministic "Gaussian-ish" noise: a fixed-seed 64-bit LCG (Knuth's MMIX constants),
    /// twelve uniforms summed minus six (Irwin-Hall: mean 0, variance 1).
    pub(crate) struct Noise(u64);

    impl Noise {
        pub(crate) fn new(seed: u64) -> Self {
            Noise(seed)
        }
        fn uniform(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        pub(crate) fn gaussian(&mut self) -> f64 {
            (0..12).map(|_| self.uniform()).sum::<f64>() - 6.0
        }
    }

    /// Max errors of value, slope and curvature of `spline` against the exact function on a
    /// dense grid (10 points per knot interval) over `[a, b]`.
    fn max_errors(
        spline: &SmoothingSpline,
        exact: impl Fn(f64) -> [f64; 3],
        a: f64,
        b: f64,
    ) -> [f64; 3] {
        let samples = 10 * spline.knots().len();
        let mut worst = [0.0_f64; 3];
        for k in 0..=samples {
            let t = a + (b - a) * k as f64 / samples as f64;
            let [f, d1, d2] = spline.eval(t);
            let [g, e1, e2] = exact(t);
            worst[0] = worst[0].max((f - g).abs());
            worst[1] = worst[1].max((d1 - e1).abs());
            worst[2] = worst[2].max((curvature(d1, d2) - curvature(e1, e2)).abs());
        }
        worst
    }

    fn sampled(a: f64, b: f64, h: f64, f: impl Fn(f64) -> f64) -> (Vec<f64>, Vec<f64>) {
        let n = ((b - a) / h).round() as usize;
        let x: Vec<f64> = (0..=n).map(|i| a + i as f64 * h).collect();
        let y = x.iter().map(|&x| f(x)).collect();
        (x, y)
    }

    /// Sine of wavelength 20 mm, amplitude 1 mm, on [0, 40] mm: f'' = 0 at both ends, as the
    /// natural spline assumes, so the errors are the interior interpolation errors.
    fn sine(x: f64) -> [f64; 3] {
        let k = 2.0 * PI / 20.0;
        [(k * x).sin(), k * (k * x).cos(), -k * k * (k * x).sin()]
    }

    /// Circle arc of radius 13 mm (the UIC60 gauge corner), crest at 0, slope 2.4 at
    /// |x| = 10.4 mm.
    fn arc13(x: f64) -> [f64; 3] {
        let r: f64 = 13.0;
        let w = (r * r - x * x).sqrt();
        [w - r, -x / w, -r * r / (w * w * w)]
    }

    /// Asserts measured max errors `[value, slope, curvature]` against tolerances set just
    /// above the values measured when the test was written (listed in the tolerance table).
    fn assert_within(what: &str, got: [f64; 3], tol: [f64; 3]) {
        println!(
            "{what}: max errors value {:.3e} mm, slope {:.3e}, curvature {:.3e} 1/mm",
            got[0], got[1], got[2]
        );
        for (k, name) in ["value", "slope", "curvature"].iter().enumerate() {
            assert!(
                got[k] <= tol[k],
                "{what}: {name} error {:.3e} > {:.3e}",
                got[k],
                tol[k]
            );
        }
    }

    /// Interpolating spline (lambda = 0) on exact samples. Measured max errors (value mm,
    /// slope, curvature 1/mm), tolerances about 1.3x these:
    ///
    /// | function | spacing | value | slope | curvature |
    /// |---|---|---|---|---|
    /// | sine, wavelength 20 mm, on [0, 40] | 0.1 mm | 2.5e-9 | 7.8e-8 | 7.6e-6 |
    /// | sine | 0.5 mm | 1.6e-6 | 9.8e-6 | 1.9e-4 |
    /// | arc R13 sampled on [-12.5, 12.5], checked on [-6, 6] | 0.1 mm | 1.5e-9 | 4.5e-8 | 3.4e-6 |
    /// | arc R13 | 0.5 mm | 8.4e-7 | 5.2e-6 | 8.5e-5 |
    ///
    /// Errors scale as h^4, h^3, h^2. Near the ends of an arc the natural end condition
    /// (f'' = 0) is wrong: the curvature is forced to 0 at the end point and is off by up to
    /// 100 % within about 1 mm of it; hence the arc is checked away from its ends.
    #[test]
    fn interpolation_errors_on_analytic_functions() {
        let cases: [(f64, [f64; 3], [f64; 3]); 2] = [
            (0.1, [3.3e-9, 1.0e-7, 1.0e-5], [2.0e-9, 6.0e-8, 4.5e-6]),
            (0.5, [2.1e-6, 1.3e-5, 2.5e-4], [1.1e-6, 6.8e-6, 1.1e-4]),
        ];
        for (h, tol_sine, tol_arc) in cases {
            let (x, y) = sampled(0.0, 40.0, h, |x| sine(x)[0]);
            let s = SmoothingSpline::fit(&x, &y, 0.0).unwrap();
            assert_within(
                &format!("sine h={h}"),
                max_errors(&s, sine, 0.0, 40.0),
                tol_sine,
            );
            let (x, y) = sampled(-12.5, 12.5, h, |x| arc13(x)[0]);
            let s = SmoothingSpline::fit(&x, &y, 0.0).unwrap();
            assert_within(
                &format!("arc R13 h={h}"),
                max_errors(&s, arc13, -6.0, 6.0),
                tol_arc,
            );
        }
    }

    /// Smoothing against noise: a rail crown (R300, curvature -3.33e-3 1/mm) sampled every
    /// 0.1 mm on [-40, 40] with 0.5 micrometre Gaussian-ish noise (fixed seed), checked on
    /// [-30, 30]. Measured max curvature errors: 0.81 1/mm (810 1/m, 240 times the crown's
    /// curvature) interpolating, 4.9e-4 1/mm (0.49 1/m) with [`default_lambda`]. The default
    /// costs little on exact data: on the R13 arc its curvature bias is 5.7e-4 1/mm (0.7 %),
    /// its value bias 0.6 micrometres.
    #[test]
    fn default_smoothing_removes_noise_induced_curvature() {
        let r300 = |x: f64| {
            let r: f64 = 300.0;
            let w = (r * r - x * x).sqrt();
            [w - r, -x / w, -r * r / (w * w * w)]
        };
        let mut noise = Noise::new(2024);
        let (x, exact) = sampled(-40.0, 40.0, 0.1, |x| r300(x)[0]);
        let y: Vec<f64> = exact
            .iter()
            .map(|y| y + 0.5e-3 * noise.gaussian())
            .collect();
        let raw = SmoothingSpline::fit(&x, &y, 0.0).unwrap();
        let smooth = SmoothingSpline::fit(&x, &y, default_lambda(&x)).unwrap();
        let raw_err = max_errors(&raw, r300, -30.0, 30.0)[2];
        let smooth_err = max_errors(&smooth, r300, -30.0, 30.0)[2];
        println!("noisy R300: curvature error {raw_err:.3e} (lambda 0) vs {smooth_err:.3e} 1/mm");
        assert!(
            raw_err > 0.5,
            "interpolating noise should ruin curvature: {raw_err}"
        );
        assert!(smooth_err < 6e-4, "default smoothing: {smooth_err}");

        let (x, y) = sampled(-12.5, 12.5, 0.1, |x| arc13(x)[0]);
        let s = SmoothingSpline::fit(&x, &y, default_lambda(&x)).unwrap();
        assert_within(
            "arc R13 smoothed",
            max_errors(&s, arc13, -6.0, 6.0),
            [8e-4, 4.5e-4, 7e-4],
        );
    }

    #[test]
    fn interpolating_spline_passes_through_the_data() {
        let x: Vec<f64> = (0..30).map(|i| (i as f64 * 0.37).powf(1.3)).collect();
        let y: Vec<f64> = x.iter().map(|x| (x * 0.7).sin()).collect();
        let s = SmoothingSpline::fit(&x, &y, 0.0).unwrap();
        for (xi, yi) in x.iter().zip(&y) {
            assert!((s.eval(*xi)[0] - yi).abs() < ROUNDING_TOL);
        }
    }

    #[test]
    fn smoothing_never_changes_a_straight_line() {
        // A line has f'' = 0, so the penalty is zero and the fit is the line for any lambda,
        // to rounding: measured 7.1e-14 mm in value (up to 10 mm), 7.1e-15 in slope and
        // 2.9e-14 1/mm in f''; bounds about twice these.
        let x: Vec<f64> = (0..50)
            .map(|i| i as f64 * 0.2 + (i % 3) as f64 * 0.05)
            .collect();
        let y: Vec<f64> = x.iter().map(|x| 0.3 * x + 4.0).collect();
        for lambda in [0.0, 0.1, 10.0, 1e4] {
            let s = SmoothingSpline::fit(&x, &y, lambda).unwrap();
            for t in [-1.0, 0.0, 3.3, 9.9, 20.0] {
                let [f, d1, d2] = s.eval(t);
                assert!(
                    (f - (0.3 * t + 4.0)).abs() < 1.5e-13,
                    "lambda {lambda} t {t}: {f}"
                );
                assert!((d1 - 0.3).abs() < 1.5e-14 && d2.abs() < 6e-14);
            }
        }
    }

    #[test]
    fn huge_lambda_tends_to_least_squares_line() {
        let x: Vec<f64> = (0..21).map(|i| i as f64).collect();
        let y: Vec<f64> = x
            .iter()
            .map(|x| {
                if (*x as usize).is_multiple_of(2) {
                    1.0
                } else {
                    -1.0
                }
            })
            .collect();
        let s = SmoothingSpline::fit(&x, &y, 1e12).unwrap();
        // Least-squares line through alternating +-1 on 0..=20 (11 "+1", 10 "-1"); at
        // lambda = 1e12 the fit is within 4.3e-11 of it in value and 1.2e-15 in slope
        // (measured); bounds about twice these.
        let mean = 1.0 / 21.0;
        let [f, d1, _] = s.eval(10.0);
        assert!((f - mean).abs() < 1e-10 && d1.abs() < 3e-15, "{f} {d1}");
    }

    /// An interpolating spline of `cos` on 200 uneven knots (steps of 0.1 to 0.4 with a
    /// cluster of 1e-6 mm steps), and its knots.
    fn uneven_cosine() -> (Vec<f64>, SmoothingSpline) {
        let mut x = vec![0.0];
        for i in 1..200 {
            let step = if (50..60).contains(&i) {
                1e-6
            } else {
                0.1 + (i % 7) as f64 * 0.05
            };
            x.push(x[i - 1] + step);
        }
        let y: Vec<f64> = x.iter().map(|x| x.cos()).collect();
        let s = SmoothingSpline::fit(&x, &y, 0.0).unwrap();
        (x, s)
    }

    #[test]
    fn lookup_matches_binary_search_on_uneven_knots() {
        let (x, s) = uneven_cosine();
        let (a, b) = s.domain();
        for k in 0..=5000 {
            let t = a + (b - a) * k as f64 / 5000.0;
            let want = x.partition_point(|&v| v <= t).clamp(1, x.len() - 1) - 1;
            assert_eq!(s.interval(t), want, "t = {t}");
        }
        for &t in &x {
            let want = x.partition_point(|&v| v <= t).clamp(1, x.len() - 1) - 1;
            assert_eq!(s.interval(t), want, "knot {t}");
        }
    }

    /// The walk of a scan gives `eval`'s bits at every point: increasing (every knot, and
    /// 20 points per interval on uneven knots with a cluster of 1e-6 mm steps), stepping
    /// back (the lookup), both ends and NaN.
    #[test]
    fn walk_is_eval_to_the_bit() {
        let (x, s) = uneven_cosine();
        let (a, b) = s.domain();
        let n = 20 * x.len();
        let mut ts: Vec<f64> = (0..=n).map(|k| a + (b - a) * k as f64 / n as f64).collect();
        ts.extend(&x);
        ts.sort_by(f64::total_cmp);
        // Increasing, then the same points again from the end of the walk (every one a step
        // back to the lookup or within the last interval), then in a scrambled order.
        let scrambled = (0..ts.len()).map(|k| ts[(k * 7919) % ts.len()]);
        let order: Vec<f64> = ts
            .iter()
            .copied()
            .chain(ts.iter().copied().rev())
            .chain(scrambled)
            .collect();
        let mut walk = s.walk_from_start();
        for &t in &order {
            let (got, want) = (walk.eval(t), s.eval(t));
            assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "t = {t}");
            // The evaluation inside the domain, likewise.
            assert_eq!(s.eval_inside(t).map(f64::to_bits), want.map(f64::to_bits));
        }
        assert!(s.eval_inside(f64::NAN)[0].is_nan());
        assert!(walk.eval(f64::NAN)[0].is_nan());
        // The walk goes on from the lookup after NaN.
        assert_eq!(walk.eval(b).map(f64::to_bits), s.eval(b).map(f64::to_bits));
        // A walk's value and slope, likewise (the same order of points).
        let mut walk = s.walk_from_start();
        for &t in &order {
            let want = s.eval(t);
            assert_eq!(
                walk.eval_slope(t).map(f64::to_bits),
                [want[0], want[1]].map(f64::to_bits)
            );
        }
    }

    #[test]
    fn rejects_bad_input() {
        let x = [0.0, 1.0, 1.0];
        assert_eq!(
            SmoothingSpline::fit(&x, &[0.0; 3], 0.0).unwrap_err(),
            SplineError::NonIncreasing { index: 2 }
        );
        assert!(matches!(
            SmoothingSpline::fit(&[0.0, 1.0], &[0.0, f64::NAN], 0.0),
            Err(SplineError::NonFinite { index: 1 })
        ));
        assert!(matches!(
            SmoothingSpline::fit(&[0.0, 1.0], &[0.0, 1.0], -1.0),
            Err(SplineError::InvalidLambda { .. })
        ));
        assert!(matches!(
            SmoothingSpline::fit(&[0.0], &[0.0], 0.0),
            Err(SplineError::TooFewPoints { found: 1 })
        ));
        assert!(matches!(
            SmoothingSpline::fit(&[0.0, 1.0], &[0.0], 0.0),
            Err(SplineError::LengthMismatch { x: 2, y: 1 })
        ));
    }

    #[test]
    fn nan_evaluation_does_not_panic() {
        let s = SmoothingSpline::fit(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.0], 0.0).unwrap();
        assert!(s.eval(f64::NAN)[0].is_nan());
        assert!(s.eval(f64::INFINITY)[0].is_infinite());
    }
}
