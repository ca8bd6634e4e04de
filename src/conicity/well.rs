//! The Klingel wavelength and the regression of a Δr function in closed form: `S = ∫ Δr dy`
//! as quadratic pieces on both sides of the equilibrium ([`Well`]), the integral of
//! `1 / sqrt(h - S)` piece by piece, and the level `h` of an amplitude.

use super::{ConicityPoint, ConicityStatus, DeltaR};
use std::f64::consts::PI;

/// One piece of a branch of `S`, in the branch coordinate `t >= 0` (distance from the
/// equilibrium band): `S(t0 + τ) = s0 + g0 τ + hm τ²` for `τ ∈ [0, len]`.
#[derive(Debug, Clone, Copy)]
struct Piece {
    t0: f64,
    len: f64,
    s0: f64,
    /// `dS/dt` at the start of the piece.
    g0: f64,
    /// Half the second derivative of `S` on the piece.
    hm: f64,
    /// The largest `S` over this piece and all before it.
    running_max: f64,
    /// `sqrt(|hm|)`, the scale of the closed forms.
    k: f64,
    /// `1 / k`.
    inv_k: f64,
    /// `S` at the end of the piece.
    s1: f64,
}

impl Piece {
    fn s_at(&self, tau: f64) -> f64 {
        self.s0 + tau * (self.g0 + self.hm * tau)
    }

    /// `dS/dt` at `τ`.
    fn slope(&self, tau: f64) -> f64 {
        self.g0 + 2.0 * self.hm * tau
    }

    fn s_end(&self) -> f64 {
        self.s1
    }

    /// The first `τ` in the piece where `S = h`, for `S(0) < h <= max S` on the piece.
    fn reach(&self, h: f64) -> f64 {
        let c = h - self.s0;
        if c <= 0.0 {
            return 0.0;
        }
        let tau = if self.hm == 0.0 {
            c / self.g0
        } else {
            let disc = (self.g0 * self.g0 + 4.0 * self.hm * c).max(0.0).sqrt();
            if self.g0 >= 0.0 {
                2.0 * c / (self.g0 + disc)
            } else {
                (disc - self.g0) / (2.0 * self.hm)
            }
        };
        tau.clamp(0.0, self.len)
    }

    #[inline(always)]
    /// `∫ dτ / sqrt(h - S)` over `[0, len]` in closed form, given `r0 = sqrt(h - S(0))` and
    /// `r1 = sqrt(h - S(len))` (either may be 0: the integrable end singularity is exact).
    fn integral(&self, len: f64, r0: f64, r1: f64) -> f64 {
        if len <= 0.0 {
            // A turning point at the piece's start (the level touches S there): the
            // closed forms below would divide 0 by 0.
            return 0.0;
        }
        let (g0, hm) = (self.g0, self.hm);
        let g1 = g0 + 2.0 * hm * len;
        let k = self.k;
        if hm > 0.0 {
            // h - S = c + b τ + a τ² with a = -hm < 0: an arcsine, written as one atan2 of
            // the end values (no cancellation, exact at a turning point).
            let num = (2.0 * k * (g1 * r0 - g0 * r1)).abs();
            let den = 4.0 * hm * r0 * r1 + g0 * g1;
            atan2_positive(num, den) * self.inv_k
        } else if hm < 0.0 {
            // a > 0: a logarithm, as ln1p of the end values' relative change.
            if g0 + g1 >= 0.0 {
                (2.0 * k * (r0 - r1 + k * len) / (2.0 * k * r1 + g1)).ln_1p() / k
            } else {
                (2.0 * k * (r1 - r0 + k * len) / (2.0 * k * r0 - g0)).ln_1p() / k
            }
        } else if r0 + r1 > 0.0 {
            2.0 * len / (r0 + r1)
        } else {
            f64::INFINITY
        }
    }
}

/// `S` on both sides of the equilibrium band, as pieces in the branch coordinates.
#[derive(Debug)]
pub(super) struct Well {
    /// The band where Δr = 0 (mm; equal ends for a crossing point).
    band: (f64, f64),
    /// Towards larger `y`: `t = y - band.1`.
    right: Vec<Piece>,
    /// Towards smaller `y`: `t = band.0 - y`.
    left: Vec<Piece>,
    /// The right branch's pieces as arrays for the interior sum.
    right_lanes: Lanes,
    /// The left branch's pieces as arrays for the interior sum.
    left_lanes: Lanes,
}

/// A branch's pieces as arrays, for the interior sum of [`Well::branch_integral`], which
/// the compiler vectorises: `S` at each piece's end, the length and `-hm len²`.
#[derive(Debug)]
struct Lanes {
    s_end: Vec<f64>,
    len: Vec<f64>,
    curv: Vec<f64>,
}

impl Lanes {
    pub(super) fn new(pieces: &[Piece]) -> Lanes {
        Lanes {
            s_end: pieces.iter().map(|p| p.s1).collect(),
            len: pieces.iter().map(|p| p.len).collect(),
            curv: pieces.iter().map(|p| -p.hm * p.len * p.len).collect(),
        }
    }
}

/// Buffers of [`Well::branch_integral`], reused over the amplitudes: `sqrt(h - S)` at the
/// knots, the series value of each piece and its argument `W`.
#[derive(Debug, Default)]
struct Scratch {
    root: Vec<f64>,
    value: Vec<f64>,
    w: Vec<f64>,
}

/// `|W|` below which [`piece_series`] is used: its remainder is below `|W|⁹ / 19 < 1e-18`.
const SERIES_LIMIT: f64 = 1.0 / 64.0;

/// Whether [`piece_series`] applies at `w` (false for a NaN `w`: both ends at `S = h`).
#[inline(always)]
fn in_series_domain(w: f64) -> bool {
    w.abs() < SERIES_LIMIT
}

/// `∫ dτ / sqrt(h - S)` over a piece of length `len` from `r0 + r1` (the end values of
/// `sqrt(h - S)`) and `curv = -hm len²`, for `|W| < SERIES_LIMIT`.
///
/// With `x = k len / (r0 + r1)` and `k = sqrt(|hm|)`, the closed forms of
/// [`Piece::integral`] reduce to `(2/k) atan x` (`hm > 0`) and `(2/k) atanh x` (`hm < 0`);
/// both are `2 len / (r0 + r1) · F(W)` with `W = -hm len² / (r0 + r1)²` and
/// `F(W) = Σ Wⁿ / (2n + 1)`, summed here to `n = 8`. No square root of `hm`, no branch on
/// its sign: the loop over the interior pieces vectorises.
#[inline(always)]
fn piece_series(len: f64, curv: f64, r_sum: f64) -> (f64, f64) {
    let t = 1.0 / r_sum;
    let u = len * t;
    let w = curv * t * t;
    let w2 = w * w;
    let w4 = w2 * w2;
    let a = (1.0 + w * (1.0 / 3.0)) + w2 * (1.0 / 5.0 + w * (1.0 / 7.0));
    let b = (1.0 / 9.0 + w * (1.0 / 11.0)) + w2 * (1.0 / 13.0 + w * (1.0 / 15.0));
    let f = a + w4 * (b + w4 * (1.0 / 17.0));
    (2.0 * u * f, w)
}

impl Well {
    pub(super) fn new(delta_r: &DeltaR) -> Option<Well> {
        let band = delta_r.equilibrium()?;
        let (y, d) = (&delta_r.y, &delta_r.dr);
        let n = y.len();
        // Right branch, t = y - band.1, dS/dt = Δr: from the value just right of the band
        // (0 at a crossing inside a piece; at a knot, the last point there holds the value
        // from the right) through every later point.
        let start = y.partition_point(|&v| v <= band.1);
        let mut right = Vec::new();
        if start > 0 && start < n {
            let g = if y[start - 1] >= band.1 {
                d[start - 1]
            } else {
                0.0
            };
            let pts: Vec<(f64, f64)> = std::iter::once((0.0, g))
                .chain((start..n).map(|k| (y[k] - band.1, d[k])))
                .collect();
            right = branch(&pts);
        }
        // Left branch, mirrored: t = band.0 - y, dS/dt = -Δr(y); at a knot the first point
        // there holds the value from the left.
        let stop = y.partition_point(|&v| v < band.0);
        let mut left = Vec::new();
        if stop > 0 && stop < n {
            let g = if y[stop] <= band.0 { -d[stop] } else { 0.0 };
            let pts: Vec<(f64, f64)> = std::iter::once((0.0, g))
                .chain((0..stop).rev().map(|k| (band.0 - y[k], -d[k])))
                .collect();
            left = branch(&pts);
        }
        Some(Well {
            band,
            right_lanes: Lanes::new(&right),
            left_lanes: Lanes::new(&left),
            right,
            left,
        })
    }

    pub(super) fn equilibrium(&self) -> f64 {
        0.5 * (self.band.0 + self.band.1)
    }

    pub(super) fn band_width(&self) -> f64 {
        self.band.1 - self.band.0
    }

    /// The first `t` of a branch where `S = h`, on piece `p`.
    fn turning(pieces: &[Piece], p: usize, h: f64) -> f64 {
        pieces[p].t0 + pieces[p].reach(h)
    }

    /// `∫ dt / sqrt(h - S)` from 0 to the turning point on piece `p`: the pieces before
    /// `p` by [`piece_series`] where it applies (nearly all: `W` is small away from the
    /// turning point) and by [`Piece::integral`] elsewhere, then the part of piece `p`.
    fn branch_integral(
        pieces: &[Piece],
        lanes: &Lanes,
        p: usize,
        h: f64,
        scratch: &mut Scratch,
    ) -> f64 {
        let Scratch { root, value, w } = scratch;
        let need = pieces.len() + 1;
        for buffer in [&mut *root, &mut *value, &mut *w] {
            if buffer.len() < need {
                buffer.resize(need, 0.0);
            }
        }
        let (root, value, w) = (&mut root[..=p], &mut value[..p], &mut w[..p]);
        root[0] = (h - pieces[0].s0).max(0.0).sqrt();
        for (r, &s) in root[1..].iter_mut().zip(&lanes.s_end[..p]) {
            *r = (h - s).max(0.0).sqrt();
        }
        let mut outside = 0usize;
        let ends = root[..p].iter().zip(&root[1..]);
        let data = lanes.len[..p].iter().zip(&lanes.curv[..p]);
        for ((v, wi), ((r0, r1), (&len, &curv))) in
            value.iter_mut().zip(w.iter_mut()).zip(ends.zip(data))
        {
            let (series, arg) = piece_series(len, curv, r0 + r1);
            let inside = in_series_domain(arg);
            *v = if inside { series } else { 0.0 };
            *wi = arg;
            outside += usize::from(!inside);
        }
        // Four partial sums (the additions vectorise), then the pieces outside the series.
        let mut acc = [0.0f64; 4];
        let chunks = value.chunks_exact(4);
        let tail: f64 = chunks.remainder().iter().sum();
        for c in chunks {
            for (a, v) in acc.iter_mut().zip(c) {
                *a += v;
            }
        }
        let mut sum = (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail;
        for (i, wi) in w.iter().enumerate().filter(|_| outside > 0) {
            if !in_series_domain(*wi) {
                sum += pieces[i].integral(pieces[i].len, root[i], root[i + 1]);
            }
        }
        let last = &pieces[p];
        let tau = last.reach(h);
        sum + last.integral(tau, root[p], 0.0)
    }

    /// Which branches end at the lowest level of `S`, `[towards smaller y, towards larger
    /// y]` (both when they end at the same level): the ones that limit the largest Klingel
    /// motion ([`Well::klingel_max_amplitude`]).
    pub(super) fn limiting_branches(&self) -> [bool; 2] {
        let top = |p: &[Piece]| p.last().map_or(0.0, |p| p.running_max);
        let (below, above) = (top(&self.left), top(&self.right));
        [below <= above, above <= below]
    }

    pub(super) fn klingel_max_amplitude(&self) -> f64 {
        let (Some(r), Some(l)) = (self.right.last(), self.left.last()) else {
            return 0.5 * self.band_width();
        };
        let h = r.running_max.min(l.running_max);
        let pr = self.right.partition_point(|p| p.running_max < h);
        let pl = self.left.partition_point(|p| p.running_max < h);
        0.5 * (self.band_width()
            + Well::turning(&self.right, pr, h)
            + Well::turning(&self.left, pl, h))
    }

    /// The Klingel equivalent conicity at each amplitude (any order).
    pub(super) fn klingel(&self, amplitudes: &[f64]) -> Vec<ConicityPoint> {
        let mut order: Vec<usize> = (0..amplitudes.len()).collect();
        order.sort_by(|&a, &b| amplitudes[a].total_cmp(&amplitudes[b]));
        let mut out = vec![
            ConicityPoint {
                amplitude_mm: f64::NAN,
                tan_gamma_e: f64::NAN,
                centre_mm: f64::NAN,
                status: ConicityStatus::BeyondRange,
            };
            amplitudes.len()
        ];
        let (mut pr, mut pl) = (0usize, 0usize);
        let band = self.band_width();
        let mut scratch = Scratch::default();
        for &i in &order {
            let a = amplitudes[i];
            out[i].amplitude_mm = a;
            let target = 2.0 * a - band;
            if a.is_nan() || a <= 0.0 {
                out[i].status = ConicityStatus::BeyondRange;
                continue;
            }
            if target <= 0.0 {
                out[i] = ConicityPoint {
                    amplitude_mm: a,
                    tan_gamma_e: 0.0,
                    centre_mm: self.equilibrium(),
                    status: ConicityStatus::ZeroBand,
                };
                continue;
            }
            // Advance to the pieces holding the turning points of the wanted level.
            let width = |pr: usize, pl: usize, h: f64| {
                Well::turning(&self.right, pr, h) + Well::turning(&self.left, pl, h)
            };
            let width_hi = loop {
                if pr >= self.right.len() || pl >= self.left.len() {
                    break None;
                }
                let hi = self.right[pr].running_max.min(self.left[pl].running_max);
                let w = width(pr, pl, hi);
                if w >= target {
                    break Some(w);
                }
                if self.right[pr].running_max <= hi {
                    pr += 1;
                }
                if self.left[pl].running_max <= hi {
                    pl += 1;
                }
            };
            let Some(width_hi) = width_hi else {
                out[i].status = ConicityStatus::BeyondRange;
                continue;
            };
            let lo = [
                pr.checked_sub(1).map(|k| self.right[k].running_max),
                pl.checked_sub(1).map(|k| self.left[k].running_max),
            ]
            .into_iter()
            .flatten()
            .fold(0.0, f64::max);
            let hi = self.right[pr].running_max.min(self.left[pl].running_max);
            let width_lo = width(pr, pl, lo);
            if width_lo > target * (1.0 + 1e-12) {
                out[i].status = ConicityStatus::NoPeriodicMotion;
                continue;
            }
            // Width and its slope in u = sqrt(h): dt/dh = 1 / S' at each turning point.
            let f = |u: f64| {
                let h = u * u;
                let (right, left) = (&self.right[pr], &self.left[pl]);
                let (tau_r, tau_l) = (right.reach(h), left.reach(h));
                let width = right.t0 + tau_r + left.t0 + tau_l;
                let slope = 2.0 * u * (1.0 / right.slope(tau_r) + 1.0 / left.slope(tau_l));
                (width - target, slope)
            };
            let h = solve_level(f, (lo, width_lo - target), (hi, width_hi - target));
            let (tr, tl) = (
                Well::turning(&self.right, pr, h),
                Well::turning(&self.left, pl, h),
            );
            let integral = band / h.sqrt()
                + Well::branch_integral(&self.right, &self.right_lanes, pr, h, &mut scratch)
                + Well::branch_integral(&self.left, &self.left_lanes, pl, h, &mut scratch);
            let ratio = PI / integral;
            out[i] = ConicityPoint {
                amplitude_mm: a,
                tan_gamma_e: ratio * ratio,
                centre_mm: 0.5 * ((self.band.1 + tr) + (self.band.0 - tl)),
                status: ConicityStatus::Ok,
            };
        }
        out
    }

    pub(super) fn regression_max_amplitude(&self) -> f64 {
        let reach = |p: &[Piece]| p.last().map_or(0.0, |p| p.t0 + p.len);
        let c = self.equilibrium();
        (self.band.1 + reach(&self.right) - c).min(c - (self.band.0 - reach(&self.left)))
    }

    /// The regression equivalent conicity at amplitude `a`: `(1/(π a)) ∫ sin φ Δr(c + a sin
    /// φ) dφ` over `[-π/2, π/2]`, exact on each linear piece.
    pub(super) fn regression(&self, delta_r: &DeltaR, a: f64) -> ConicityPoint {
        let c = self.equilibrium();
        let mut point = ConicityPoint {
            amplitude_mm: a,
            tan_gamma_e: f64::NAN,
            centre_mm: c,
            status: ConicityStatus::BeyondRange,
        };
        if a.is_nan() || a <= 0.0 || a > self.regression_max_amplitude() * (1.0 + 1e-12) + 1e-12 {
            return point;
        }
        if 2.0 * a <= self.band_width() {
            point.tan_gamma_e = 0.0;
            point.status = ConicityStatus::ZeroBand;
            return point;
        }
        let (y, d) = (&delta_r.y, &delta_r.dr);
        let (lo, hi) = (c - a, c + a);
        // Antiderivative pieces: with x = sin φ = (y - c)/a and Δr = A + B x on a piece,
        // ∫ sin φ (A + B sin φ) dφ = -A cos φ + B (φ - sin φ cos φ) / 2.
        // The angle terms of a knot, `(cos φ, φ - sin φ cos φ)`: computed once and shared by
        // the two pieces that meet there.
        let angle = |x: f64| {
            let x = x.clamp(-1.0, 1.0);
            let cos = (1.0 - x * x).max(0.0).sqrt();
            (x, cos, x.asin() - x * cos)
        };
        let prim = |(_, cos, arc): (f64, f64, f64), aa: f64, bb: f64| -aa * cos + 0.5 * bb * arc;
        let mut knot = (f64::NAN, 0.0, 0.0);
        let mut sum = 0.0;
        // The pieces that overlap (lo, hi): from the last point at or below lo.
        let first = y.partition_point(|&v| v <= lo).saturating_sub(1);
        for k in first..y.len().saturating_sub(1) {
            let (y0, y1) = (y[k], y[k + 1]);
            if y0 >= hi {
                break;
            }
            if y1 <= y0 || y1 <= lo {
                continue;
            }
            let m = (d[k + 1] - d[k]) / (y1 - y0);
            // Δr = d0 + m (y - y0) = (d0 + m (c - y0)) + (m a) x.
            let aa = d[k] + m * (c - y0);
            let bb = m * a;
            let x0 = ((y0.max(lo)) - c) / a;
            let x1 = ((y1.min(hi)) - c) / a;
            let start = if knot.0.to_bits() == x0.clamp(-1.0, 1.0).to_bits() {
                knot
            } else {
                angle(x0)
            };
            knot = angle(x1);
            sum += prim(knot, aa, bb) - prim(start, aa, bb);
        }
        point.tan_gamma_e = sum / (PI * a);
        point.status = ConicityStatus::Ok;
        point
    }
}

/// `atan2(y, x)` for `y >= 0`: where `0 <= y < x / 8` (most pieces of a well: the angle a
/// piece spans is small away from the turning points) by the Taylor series of `atan` to
/// `z^17`, whose remainder `z^19 / 19 < 3e-19 z` is below the rounding of the result;
/// elsewhere by the library. Twice as fast as `f64::atan2` on the paper's Δr.
fn atan2_positive(y: f64, x: f64) -> f64 {
    if x > 0.0 && y < 0.125 * x {
        let z = y / x;
        let w = z * z;
        // 1 - w/3 + w²/5 - ... + w⁸/17 by Estrin's scheme (short dependency chains).
        let w2 = w * w;
        let w4 = w2 * w2;
        // Reciprocals as constants: a division by 3.0 would stay a division.
        let a = (1.0 - w * (1.0 / 3.0)) + w2 * (1.0 / 5.0 - w * (1.0 / 7.0));
        let b = (1.0 / 9.0 - w * (1.0 / 11.0)) + w2 * (1.0 / 13.0 - w * (1.0 / 15.0));
        let p = a + w4 * (b + w4 * (1.0 / 17.0));
        z * p
    } else {
        y.atan2(x)
    }
}

/// The pieces of one branch from its points `(t, dS/dt)`, `t` not decreasing from 0 (a
/// repeated `t` is a jump of the slope). Ends at the first unknown value.
fn branch(pts: &[(f64, f64)]) -> Vec<Piece> {
    let mut pieces = Vec::with_capacity(pts.len());
    let mut s = 0.0;
    let mut running_max: f64 = 0.0;
    for w in pts.windows(2) {
        let ((t0, g0), (t1, g1)) = (w[0], w[1]);
        if !(g0.is_finite() && g1.is_finite()) {
            break;
        }
        let len = t1 - t0;
        if len <= 0.0 {
            continue;
        }
        let hm = 0.5 * (g1 - g0) / len;
        let mut piece = Piece {
            t0,
            len,
            s0: s,
            g0,
            hm,
            running_max,
            k: hm.abs().sqrt(),
            inv_k: 1.0 / hm.abs().sqrt(),
            s1: 0.0,
        };
        piece.s1 = piece.s_at(len);
        // The largest S on the piece: at an end, or where dS/dt changes from + to -.
        let mut top = piece.s_end().max(s);
        if g0 > 0.0 && g1 < 0.0 {
            top = top.max(piece.s_at(-g0 / (2.0 * hm)));
        }
        running_max = running_max.max(top);
        s = piece.s_end();
        pieces.push(Piece {
            running_max,
            ..piece
        });
    }
    pieces
}

/// The level `h` in `[lo, hi]` where the width `f(u).0` of the motion reaches its target,
/// given `f` at both ends (`f` gives the width less the target, and its slope, as functions
/// of `u = sqrt(h)`; the turning points are smooth in `u` near the equilibrium, where they
/// grow like `sqrt(h)`). Newton's
/// method safeguarded by the bracket (bisection when a step would leave it or the slope is
/// not finite): quadratic convergence from the regula falsi start (110 evaluations for the
/// 96 default amplitudes on the paper's Δr).
fn solve_level(f: impl Fn(f64) -> (f64, f64), (lo, fa): (f64, f64), (hi, fb): (f64, f64)) -> f64 {
    let (mut ua, mut ub) = (lo.max(0.0).sqrt(), hi.sqrt());
    if fb <= 0.0 {
        return hi;
    }
    if fa >= 0.0 {
        return lo;
    }
    let mut u = (ua * fb - ub * fa) / (fb - fa);
    if !(u > ua && u < ub) {
        u = 0.5 * (ua + ub);
    }
    for _ in 0..200 {
        let (fu, slope) = f(u);
        if fu == 0.0 {
            break;
        }
        if fu < 0.0 {
            ua = u;
        } else {
            ub = u;
        }
        let newton = u - fu / slope;
        let next = if slope.is_finite() && slope > 0.0 && newton > ua && newton < ub {
            newton
        } else {
            0.5 * (ua + ub)
        };
        let done = (next - u).abs() <= 4.0 * f64::EPSILON * u || ub - ua <= 4.0 * f64::EPSILON * ub;
        u = next;
        if done {
            break;
        }
    }
    u * u
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn piece_integral_matches_quadrature() {
        // Against a fine midpoint rule on a piece away from any root, every case of hm
        // (measured at most 1.4e-13 apart: the midpoint rule's error at 200 000 steps).
        for (g0, hm) in [
            (0.3, 0.2),
            (0.3, -0.05),
            (0.3, 0.0),
            (-0.1, 0.4),
            (0.0, 1e-9),
        ] {
            let p = Piece {
                t0: 0.0,
                len: 0.7,
                s0: 0.1,
                g0,
                hm,
                running_max: 0.0,
                k: hm.abs().sqrt(),
                inv_k: 1.0 / hm.abs().sqrt(),
                s1: 0.1 + 0.7 * (g0 + hm * 0.7),
            };
            let h = 2.0;
            let r0 = (h - p.s_at(0.0)).sqrt();
            let r1 = (h - p.s_end()).sqrt();
            let exact = p.integral(p.len, r0, r1);
            let n = 200_000;
            let dt = p.len / f64::from(n);
            let mid: f64 = (0..n)
                .map(|i| dt / (h - p.s_at((f64::from(i) + 0.5) * dt)).sqrt())
                .sum();
            assert!((exact - mid).abs() < 3e-13, "{g0} {hm}: {exact} {mid}");
        }
    }

    #[test]
    fn piece_series_matches_the_closed_forms() {
        // Both signs of hm and hm = 0, over the series' whole domain |W| < 1/64 and end values
        // from equal to very unequal: the series and the atan2 / ln1p forms agree to rounding.
        let (mut worst, mut largest_w, mut tested): (f64, f64, usize) = (0.0, 0.0, 0);
        for hm in [0.3, 1e-6, 0.0, -1e-6, -0.3] {
            for len in [1e-4, 0.1, 0.7] {
                for (r0, r1) in [
                    (1.0, 1.0),
                    (0.2, 1.3),
                    (2.0, 0.05),
                    (0.2, 0.3),
                    (1e-3, 3e-3),
                ] {
                    let p = Piece {
                        t0: 0.0,
                        len,
                        s0: 0.0,
                        g0: 0.0,
                        hm,
                        running_max: 0.0,
                        k: f64::abs(hm).sqrt(),
                        inv_k: 1.0 / f64::abs(hm).sqrt(),
                        s1: 0.0,
                    };
                    // The piece's own g0 must match its end values: h - S(len) = r1² with
                    // h - S(0) = r0², so g0 = (r0² - r1²) / len - hm len.
                    let p = Piece {
                        g0: (r0 * r0 - r1 * r1) / len - hm * len,
                        ..p
                    };
                    let (series, w) = piece_series(len, -hm * len * len, r0 + r1);
                    if w.abs() >= SERIES_LIMIT {
                        continue;
                    }
                    let exact = p.integral(len, r0, r1);
                    worst = worst.max((series - exact).abs() / exact);
                    largest_w = largest_w.max(w.abs());
                    tested += 1;
                }
            }
        }
        assert!(tested >= 50 && largest_w > 0.01, "{tested} {largest_w}");
        // Measured 1.9 ε.
        assert!(worst < 4.0 * f64::EPSILON, "{worst:e}");
    }

    #[test]
    fn short_atan_series_matches_the_library() {
        for i in 0..=2000 {
            let z = 0.125 * f64::from(i) / 2000.0;
            for x in [1e-3, 1.0, 7.5e4] {
                let (a, b) = (atan2_positive(z * x, x), (z * x).atan2(x));
                assert!((a - b).abs() <= 2.0 * f64::EPSILON * b, "{z}: {a} {b}");
            }
        }
    }
}
