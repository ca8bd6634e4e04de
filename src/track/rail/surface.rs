//! The placed rail's surface table: quintic Hermite pieces of `Z(Y)` (see the parent
//! module's docs for what is tabulated and what falls back to the inversion).

use super::{PlacedRail, RailPoint, ScanEval};
use crate::profile::ProfileScan;
use crate::profile::bounds::BOUND_PAD;
use std::sync::OnceLock;

/// Step of the piecewise-quintic table of the placed rail surface (mm). Each piece is the
/// quintic Hermite interpolant of the exact `Z`, `Z'`, `Z''` at its ends. Against the exact
/// inversion of UIC60 at 1:40 (`surface_table_matches_the_exact_inversion`) it errs by at most
/// 8.5e-13 mm in `Z`, 1.5e-10 in the slope and 1.5e-8 relative in `Z''`, all on the R13
/// corners at slopes 1.5 to [`SURFACE_TABLE_MAX_SLOPE`], where the derivatives of `Z(Y)` are
/// largest; on the crown and shoulder it is exact to rounding.
pub(crate) const SURFACE_TABLE_STEP_MM: f64 = 0.02;
/// Pieces steeper than this (`|dZ/dY|` at an end, about 72 degrees) are not tabulated: the
/// derivatives of `Z(Y)` grow without bound towards a vertical tangent. There, and on pieces
/// that hold a section joint of an analytic rail (where `Z''` jumps) or more than one knot
/// of a sampled rail, [`PlacedRail::at`] inverts the profile by Newton's method instead.
///
/// A piece of a sampled rail that holds one spline knot is tabulated as two quintics, one
/// on each side of the knot: within a spline piece the surface is as smooth as an analytic
/// arc (a rotated cubic), and `Z'''`, which jumps at the knot, is never interpolated across.
pub(crate) const SURFACE_TABLE_MAX_SLOPE: f64 = 3.0;

/// A knot closer than this to an end of a table piece (in units of the piece, `t`) does not
/// split it: `Z'''` jumps only on a sliver of `1e-6 h`, where the quintic of the piece errs
/// by `|jump of Z'''| (1e-6 h)^3`, far below rounding.
const KNOT_AT_END_T: f64 = 1e-6;
/// Shortest part of a split piece (in units of `t`) that is tabulated; the rail is inverted
/// on a shorter one. The interpolant's `Z''` takes the rounding `delta` of its end values
/// (about 1e-13 mm: the translation into the side frame) as `delta / (len h)^2`: 5e-9 1/mm
/// at a quarter piece, 1e-6 at 1/60 (as sampled UIC60 gives without this bound).
const MIN_SPLIT_T: f64 = 0.25;

/// Quintic pieces of `Z(Y)`: monomial coefficients in `t = (Y - Y_i) / h` on `[0, 1]`; NaN
/// for pieces that are not tabulated, and `[NaN, k, ..]` for a piece split at a spline knot,
/// its two quintics in [`PlacedRail`]'s `splits[k]`.
#[derive(Debug, Clone, Default)]
pub(super) struct SurfaceTable {
    y0: f64,
    inv_step: f64,
    pieces: Vec<[f64; 6]>,
    /// Bounds of the surface per [`SURFACE_BIN_MM`], built on first use (by the certificate
    /// of the gap's global minimum, not by the placement).
    bins: OnceLock<Bins>,
    /// The profile's section joints (its own coordinate), for the bounds.
    joints: Vec<f64>,
    /// The largest value jump of the profile at a joint (mm).
    value_jump: f64,
}

/// The bounds of the surface per [`SURFACE_BIN_MM`] bin in a sparse table (`levels[k][i]`:
/// the union over bins `i..i + 2^k`, `levels[0]` the bins), for the bounds over any run of
/// bins in two lookups. Two overlapping runs count the joints of their overlap twice in
/// `jump`: an upper bound still.
#[derive(Debug, Clone)]
struct Bins {
    /// Each level above the bins made on first use.
    levels: crate::track::sparse::LazyLevels<SurfaceBounds>,
}

/// Width of the bins of [`PlacedRail::binned_bounds`] (mm): the coarse step of the wheel,
/// so that a coarse cell of the gap covers one or two bins.
pub(crate) const SURFACE_BIN_MM: f64 = 0.25;

/// Bounds of the placed rail surface `Z(Y)` over an interval of `Y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SurfaceBounds {
    /// Range of `dZ/dY`.
    pub slope: (f64, f64),
    /// Range of `d2Z/dY2` (1/mm).
    pub d2: (f64, f64),
    /// An upper bound of `Z` (mm).
    pub z_max: f64,
    /// What the section joints inside add to the deviation of `Z` from a curve with the
    /// bounds above (mm): per joint its value jump plus its slope jump times the interval's
    /// width (UIC60: 2.6e-7 mm and 3e-8 at the crown/shoulder joints, from the drawing's
    /// rounded arc centres).
    pub jump: f64,
}

impl SurfaceBounds {
    /// No bound at all.
    pub(crate) const UNBOUNDED: SurfaceBounds = SurfaceBounds {
        slope: (f64::NEG_INFINITY, f64::INFINITY),
        d2: (f64::NEG_INFINITY, f64::INFINITY),
        z_max: f64::INFINITY,
        jump: f64::INFINITY,
    };

    /// The union of two bounds (of adjacent intervals).
    pub(crate) fn union(self, o: SurfaceBounds) -> SurfaceBounds {
        SurfaceBounds {
            slope: (self.slope.0.min(o.slope.0), self.slope.1.max(o.slope.1)),
            d2: (self.d2.0.min(o.d2.0), self.d2.1.max(o.d2.1)),
            z_max: self.z_max.max(o.z_max),
            jump: self.jump + o.jump,
        }
    }
}

/// A table piece split at a spline knot: `t_knot` in `(0, 1)`, the quintic of `[0, t_knot]`
/// in `t` and that of `[t_knot, 1]` in `t - t_knot`; NaN for a part shorter than
/// [`MIN_SPLIT_T`].
#[derive(Debug, Clone, Copy)]
pub(super) struct Split {
    t_knot: f64,
    below: [f64; 6],
    above: [f64; 6],
}

/// The monomial coefficients in `x` (0 to 1 over the piece) of the quintic Hermite
/// interpolant on a piece `len` table steps `h` long between the surface points `a` (at
/// `x = 0`) and `b`.
fn hermite_in_x(a: RailPoint, b: RailPoint, h: f64, len: f64) -> [f64; 6] {
    // Values, len h * slopes and (len h)^2 * second derivatives in x.
    let (p0, p1) = (a.z, b.z);
    let (m0, m1) = (h * a.slope * len, h * b.slope * len);
    let (s0, s1) = (h * h * a.d2 * len * len, h * h * b.d2 * len * len);
    let dp = p1 - p0;
    [
        p0,
        m0,
        0.5 * s0,
        10.0 * dp - 6.0 * m0 - 4.0 * m1 - 1.5 * s0 + 0.5 * s1,
        -15.0 * dp + 8.0 * m0 + 7.0 * m1 + 1.5 * s0 - s1,
        6.0 * dp - 3.0 * m0 - 3.0 * m1 - 0.5 * s0 + 0.5 * s1,
    ]
}

/// The monomial coefficients in `g` (units of the table step `h`) of the quintic Hermite
/// interpolant of a whole piece, from `a` (at `g = 0`) to `b` (at `g = 1`): `x` is `g`
/// (no division by 1 per coefficient).
fn quintic_piece(a: RailPoint, b: RailPoint, h: f64) -> [f64; 6] {
    hermite_in_x(a, b, h, 1.0)
}

/// The monomial coefficients in `g` of the quintic Hermite interpolant on the part `0 <= g
/// <= len` of a piece split at a knot, from `a` (at `g = 0`) to `b`.
fn quintic_part(a: RailPoint, b: RailPoint, h: f64, len: f64) -> [f64; 6] {
    let mut scale = 1.0;
    hermite_in_x(a, b, h, len).map(|ck| {
        let v = ck / scale;
        scale *= len;
        v
    })
}

/// The surface from the quintic `c` at `g` (in units of the step; `inv_step` = `1 / h`).
#[inline]
fn quintic_point(c: &[f64; 6], f: f64, inv_step: f64) -> RailPoint {
    let [z, slope, d2] = quintic(*c, f, inv_step);
    RailPoint { z, slope, d2 }
}

/// `[Z, dZ/dY, d2Z/dY2]` from the quintic `c` at `f` (`inv_step` = `1 / h`), for `f64` or
/// for SIMD lanes of `f64`: the same operations in the same order, so each lane rounds
/// exactly as the scalar evaluation (no fused multiply-add).
#[inline(always)]
fn quintic<T>(c: [T; 6], f: T, inv_step: T) -> [T; 3]
where
    T: Copy + From<f64> + std::ops::Add<Output = T> + std::ops::Mul<Output = T>,
{
    let k = T::from;
    let z = quintic_z(c, f);
    let dz =
        c[1] + f * (k(2.0) * c[2] + f * (k(3.0) * c[3] + f * (k(4.0) * c[4] + f * k(5.0) * c[5])));
    let d2 = k(2.0) * c[2] + f * (k(6.0) * c[3] + f * (k(12.0) * c[4] + f * k(20.0) * c[5]));
    [z, dz * inv_step, d2 * inv_step * inv_step]
}

/// The height `Z` from the quintic `c` at `f`: the `z` of [`quintic_point`], by the same
/// operations.
#[inline(always)]
fn quintic_z<T>(c: [T; 6], f: T) -> T
where
    T: Copy + std::ops::Add<Output = T> + std::ops::Mul<Output = T>,
{
    c[0] + f * (c[1] + f * (c[2] + f * (c[3] + f * (c[4] + f * c[5]))))
}

impl PlacedRail {
    /// The height `Z` at `y`, the `z` of [`PlacedRail::at`] to the bit without its slope
    /// and curvature (a sixth of its work on a tabulated piece): what the height table is
    /// filled with; `None` outside [`PlacedRail::y_range`]. For a scan at increasing `y`,
    /// the profile is evaluated by `scan` (of this rail's profile) where the rail is
    /// inverted; any `y` is allowed.
    #[inline]
    pub(in crate::track) fn height_from(&self, scan: &mut ProfileScan, y: f64) -> Option<f64> {
        let (y_lo, y_hi) = self.y_range();
        if !(y_lo..=y_hi).contains(&y) {
            return None;
        }
        Some(match self.plain_piece(y) {
            Some((c, f)) => quintic_z(*c, f),
            None => self.untabulated_height(scan, y),
        })
    }

    /// The `z` of [`PlacedRail::untabulated_at`] to the bit, the profile evaluated from
    /// `scan` where the rail is inverted.
    #[inline(never)]
    fn untabulated_height(&self, scan: &mut ProfileScan, y: f64) -> f64 {
        match self.split_part(y) {
            Some((c, g)) => quintic_z(*c, g),
            None => {
                let eval = |u| scan.eval(u);
                self.invert_with(y, self.guess(y), eval).1.z
            }
        }
    }

    /// The plain quintic piece of the table at `y` (inside `y_range`) and `y`'s place `f`
    /// in it (units of the step), `None` where `y` has no plain piece (steep, at a joint,
    /// split at a knot).
    #[inline]
    fn plain_piece(&self, y: f64) -> Option<(&[f64; 6], f64)> {
        let table = &self.surface_table;
        let t = (y - table.y0) * table.inv_step;
        // `t >= 0` inside y_range (`y0` is its start); through i32 as in `guess`.
        let i = t as i32 as usize;
        let c = table.pieces.get(i)?;
        (!c[0].is_nan()).then_some((c, t - i as f64))
    }

    /// The surface at `y` (inside `y_range`) from its quintic piece, `None` where `y` has no
    /// tabulated piece.
    #[inline]
    pub(super) fn tabulated_at(&self, y: f64) -> Option<RailPoint> {
        let (c, f) = self.plain_piece(y)?;
        Some(quintic_point(c, f, self.surface_table.inv_step))
    }

    /// [`PlacedRail::at`] of four lateral positions, to the bit: the quintics of the plain
    /// pieces in SIMD lanes (each lane's piece looked up on its own, [`quintic`] in the
    /// lanes), the other lanes (outside `y_range`, untabulated) one by one by `at`.
    #[inline]
    pub(crate) fn at_x4(&self, y: [f64; 4]) -> [Option<RailPoint>; 4] {
        let (y_lo, y_hi) = self.y_range();
        let piece = |y: f64| {
            (y_lo..=y_hi)
                .contains(&y)
                .then(|| self.plain_piece(y))
                .flatten()
        };
        let pieces = y.map(piece);
        // Lanes without a plain piece compute a dummy quintic, replaced below.
        let (c, f) = (
            pieces.map(|p| p.map_or([0.0; 6], |(c, _)| *c)),
            pieces.map(|p| p.map_or(0.0, |(_, f)| f)),
        );
        let coefficient = |k: usize| wide::f64x4::from([c[0][k], c[1][k], c[2][k], c[3][k]]);
        let inv_step = wide::f64x4::splat(self.surface_table.inv_step);
        let [z, slope, d2] =
            quintic(std::array::from_fn(coefficient), f.into(), inv_step).map(|v| v.to_array());
        std::array::from_fn(|l| match pieces[l] {
            Some(_) => Some(RailPoint {
                z: z[l],
                slope: slope[l],
                d2: d2[l],
            }),
            None => self.at(y[l]),
        })
    }

    /// The surface at `y` (inside `y_range`) where [`PlacedRail::tabulated_at`] has no
    /// plain quintic: from the split piece of a sampled rail's knot, else by inversion. Out
    /// of line, so that the tabulated lookup stays as short as it was before the splits.
    #[inline(never)]
    pub(super) fn untabulated_at(&self, y: f64) -> RailPoint {
        self.split_at(y)
            .unwrap_or_else(|| self.invert(y, self.guess(y)).1)
    }

    /// The surface at `y` (inside `y_range`) from the part of a piece split at a knot, `None`
    /// where `y` is in no such part.
    pub(super) fn split_at(&self, y: f64) -> Option<RailPoint> {
        let (c, g) = self.split_part(y)?;
        Some(quintic_point(c, g, self.surface_table.inv_step))
    }

    /// The quintic of the part of a piece split at a knot that holds `y` (inside
    /// `y_range`) and `y`'s place in it, `None` where `y` is in no such part.
    #[inline]
    fn split_part(&self, y: f64) -> Option<(&[f64; 6], f64)> {
        let table = &self.surface_table;
        let t = (y - table.y0) * table.inv_step;
        let i = t as i32 as usize;
        // `[NaN, k, ..]` marks a piece split at a knot, `splits[k]`.
        let c = table.pieces.get(i).filter(|c| c[1].is_finite())?;
        let split = self.splits.get(c[1] as usize)?;
        let f = t - i as f64;
        let (c, g) = if f <= split.t_knot {
            (&split.below, f)
        } else {
            (&split.above, f - split.t_knot)
        };
        (!c[0].is_nan()).then_some((c, g))
    }

    /// Fills the quintic table of the surface from exact inversions every
    /// [`SURFACE_TABLE_STEP_MM`]; pieces that are steep, hold a joint of an analytic rail or
    /// several knots of a sampled one are left out (NaN), pieces that hold one knot are split
    /// there (see [`SURFACE_TABLE_MAX_SLOPE`]).
    #[inline(never)] // called once: its cost stays visible in a profile
    pub(super) fn tabulate_surface(&mut self, eval: impl ScanEval) {
        let (y_lo, y_hi) = self.y_range;
        let n = ((y_hi - y_lo) / SURFACE_TABLE_STEP_MM).floor() as usize;
        let h = SURFACE_TABLE_STEP_MM;
        let joints: Vec<f64> = self
            .profile
            .joints()
            .into_iter()
            .map(|u| self.point_of(u)[0])
            .collect();
        let knots = self.knots_by_y(eval);
        let mut next_knot = 0;
        // The nodes increase in `y`, so in `u`: the profile by a scan (the same bits).
        let mut scan = eval.scan(&self.profile);
        // The node at `y`; the nodes' `y_lo + h i` each made once, for the node and for the
        // ends of its pieces.
        let mut node = |y: f64| {
            let eval = |u| scan.eval(u);
            self.invert_with(y, self.guess(y), eval).1
        };
        // The knots that split pieces increase too: a scan of their own.
        let mut knot_scan = eval.scan(&self.profile);
        let steep = |p: &RailPoint| !(p.slope.abs() <= SURFACE_TABLE_MAX_SLOPE && p.z.is_finite());
        // A piece holds at most one split, at a knot of its own inside it: the knots on the
        // surface bound the splits.
        let on_surface = knots
            .iter()
            .filter(|k| (y_lo..=y_hi).contains(&k.0))
            .count();
        let mut splits = Vec::with_capacity(on_surface);
        // The nodes are made as the pieces need them, each once: no table of them is kept.
        let mut pieces: Vec<[f64; 6]> = Vec::with_capacity(n);
        let node_y = |i: usize| y_lo + h * i as f64;
        let mut yb = node_y(0);
        let mut b = node(yb);
        for i in 0..n {
            let (a, ya) = (b, yb);
            yb = node_y(i + 1);
            b = node(yb);
            let piece = {
                let holds_joint = joints.iter().any(|&j| (ya..=yb).contains(&j));
                if holds_joint || steep(&a) || steep(&b) {
                    [f64::NAN; 6]
                } else {
                    // Knots strictly inside the piece (see KNOT_AT_END_T); the pieces come in
                    // increasing Y, so the first knot not below the piece is carried along.
                    while next_knot < knots.len() && knots[next_knot].0 < ya {
                        next_knot += 1;
                    }
                    let mut inside = knots[next_knot..]
                        .iter()
                        .take_while(|k| k.0 <= yb)
                        .map(|&(y, u)| ((y - ya) / h, u))
                        .filter(|&(t, _)| t > KNOT_AT_END_T && t < 1.0 - KNOT_AT_END_T);
                    match (inside.next(), inside.next()) {
                        (None, _) => quintic_piece(a, b, h),
                        (Some((t_knot, u)), None) => {
                            let k = self.surface_from(u, knot_scan.eval(u));
                            self.split_piece(a, b, t_knot, k, &mut splits)
                        }
                        (Some(_), Some(_)) => [f64::NAN; 6],
                    }
                }
            };
            pieces.push(piece);
        }
        self.surface_table = SurfaceTable {
            y0: y_lo,
            inv_step: 1.0 / h,
            pieces,
            bins: OnceLock::new(),
            joints: self.profile.joints(),
            value_jump: crate::track::wheel::value_jump(&self.profile),
        };
        self.splits = splits;
    }

    /// A sampled rail's knots `(Y, u)` by increasing `Y` (its joints are among them); an
    /// analytic rail has none. The knots increase: their heights by a scan (the value
    /// only).
    fn knots_by_y(&self, eval: impl ScanEval) -> Vec<(f64, f64)> {
        if !self.profile.is_sampled() {
            return Vec::new();
        }
        let mut scan = eval.scan(&self.profile);
        let mut knots: Vec<(f64, f64)> = self
            .profile
            .breaks()
            .into_iter()
            .map(|u| {
                let [v, _] = scan.eval_slope(u);
                (self.to_side(self.rotated_point(u, v))[0], u)
            })
            .collect();
        knots.sort_by(|a, b| a.0.total_cmp(&b.0));
        knots
    }

    /// The piece from nodes `a` to `b` split at the knot `k` (its surface point) of a
    /// sampled rail, at `t_knot` of the piece: its two quintics pushed onto `splits`, and
    /// the marker `[NaN, k, ..]` that points to them (NaN where the knot is steep).
    fn split_piece(
        &self,
        a: RailPoint,
        b: RailPoint,
        t_knot: f64,
        k: RailPoint,
        splits: &mut Vec<Split>,
    ) -> [f64; 6] {
        let h = SURFACE_TABLE_STEP_MM;
        if !(k.slope.abs() <= SURFACE_TABLE_MAX_SLOPE && k.z.is_finite()) {
            return [f64::NAN; 6];
        }
        let part = |p, q, len| {
            if len >= MIN_SPLIT_T {
                quintic_part(p, q, h, len)
            } else {
                [f64::NAN; 6]
            }
        };
        splits.push(Split {
            t_knot,
            below: part(a, k, t_knot),
            above: part(k, b, 1.0 - t_knot),
        });
        let mut marker = [f64::NAN; 6];
        marker[1] = (splits.len() - 1) as f64;
        marker
    }
}

impl PlacedRail {
    /// Rigorous bounds of the exact surface over `[y_lo, y_hi]` clipped to
    /// [`PlacedRail::y_range`], `None` where that is empty: the profile coordinates of the
    /// ends by inversion, the profile's [`derivative_bounds`](crate::profile::Profile::derivative_bounds)
    /// between them, rotated. With the tangent `(ty, tz) = (cos - sin v', sin + cos v')`,
    /// `dZ/dY = tz / ty` increases with `v'`, and `d2Z/dY2 = v'' / ty^3`; `Z` lies below
    /// both lines through the end heights with the extreme slopes.
    pub(crate) fn surface_bounds(&self, y_lo: f64, y_hi: f64) -> Option<SurfaceBounds> {
        let (lo, hi) = self.y_range;
        let (y_lo, y_hi) = (y_lo.max(lo), y_hi.min(hi));
        // Also rejects NaN.
        if y_lo
            .partial_cmp(&y_hi)
            .is_none_or(|o| o == std::cmp::Ordering::Greater)
        {
            return None;
        }
        let (u_lo, a) = self.invert(y_lo, self.guess(y_lo));
        let (u_hi, b) = self.invert(y_hi, self.guess(y_hi));
        let d = self
            .profile
            .derivative_bounds(u_lo.min(u_hi), u_lo.max(u_hi));
        let (cos, sin) = self.cos_sin();
        let ty = |d1: f64| cos - sin * d1;
        let (ty_a, ty_b) = (ty(d.d1.0), ty(d.d1.1));
        let (ty_min, ty_max) = (ty_a.min(ty_b), ty_a.max(ty_b));
        let unbounded = (f64::NEG_INFINITY, f64::INFINITY);
        let (slope, d2) = if ty_min > 0.0 {
            let z1 = |d1: f64| (sin + cos * d1) / ty(d1);
            let over = |v: f64| {
                [
                    v / (ty_min * ty_min * ty_min),
                    v / (ty_max * ty_max * ty_max),
                ]
            };
            let [p, q] = over(d.d2.0);
            let [r, t] = over(d.d2.1);
            let pad = |(lo, hi): (f64, f64)| {
                let w = BOUND_PAD * lo.abs().max(hi.abs());
                (lo - w, hi + w)
            };
            (
                pad((z1(d.d1.0), z1(d.d1.1))),
                pad((p.min(q).min(r).min(t), p.max(q).max(r).max(t))),
            )
        } else {
            (unbounded, unbounded)
        };
        // Z <= z_a + s1 (y - y_lo) and Z <= z_b - s0 (y_hi - y): the lower of the two lines.
        let w = y_hi - y_lo;
        let (s0, s1) = slope;
        let z_max = if s1 <= 0.0 {
            a.z
        } else if s0 >= 0.0 {
            b.z
        } else {
            let t = ((b.z - a.z - s0 * w) / (s1 - s0)).clamp(0.0, w);
            a.z + s1 * t
        };
        let jump = self
            .surface_table
            .joints
            .iter()
            .copied()
            .filter(|&u| (u_lo..=u_hi).contains(&u))
            .map(|u| {
                let (p, q) = (self.profile.eval(u), self.profile.eval(u - 1e-12));
                // dZ/dY changes by dv' / ty^2 for a change dv' of the profile's slope.
                (p[0] - q[0]).abs() + (p[1] - q[1]).abs() / (ty_min * ty_min).max(1e-300) * w
            })
            .sum::<f64>();
        Some(SurfaceBounds {
            slope,
            d2,
            z_max: z_max + jump + BOUND_PAD * z_max.abs().max(1.0),
            jump,
        })
    }

    /// The largest value jump of the rail profile at a section joint (mm; UIC60: 2.6e-7, 0
    /// for a spline).
    pub(crate) fn value_jump_mm(&self) -> f64 {
        self.surface_table.value_jump
    }

    /// Bounds of the surface over `[y_lo, y_hi]` (clipped as in
    /// [`PlacedRail::surface_bounds`]), the union of those of the [`SURFACE_BIN_MM`] bins it
    /// overlaps (its `jump` may count a joint twice): looser, and cheap after the first call.
    pub(crate) fn binned_bounds(&self, y_lo: f64, y_hi: f64) -> Option<SurfaceBounds> {
        let (level, i, j) = self.bins_over(y_lo, y_hi)?;
        Some(level[i].union(level[j]))
    }

    /// An upper bound of the surface's height over `[y_lo, y_hi]` (clipped as in
    /// [`PlacedRail::surface_bounds`]): the `z_max` of
    /// [`binned_bounds`](PlacedRail::binned_bounds).
    pub(crate) fn binned_max_height(&self, y_lo: f64, y_hi: f64) -> Option<f64> {
        let (level, i, j) = self.bins_over(y_lo, y_hi)?;
        Some(level[i].z_max.max(level[j].z_max))
    }

    /// The level of the sparse table and the two runs of it (their first bins `i`, `j`) that
    /// together cover the bins overlapping `[y_lo, y_hi]` clipped to the running surface
    /// (one more where rounding could put an end on the wrong side of a bin edge), `None`
    /// where that is empty.
    #[inline]
    fn bins_over(&self, y_lo: f64, y_hi: f64) -> Option<(&[SurfaceBounds], usize, usize)> {
        let (lo, hi) = self.y_range;
        let bins = self.surface_table.bins.get_or_init(|| self.build_bins());
        let (y_lo, y_hi) = (y_lo.max(lo), y_hi.min(hi));
        // Also rejects NaN.
        if y_lo
            .partial_cmp(&y_hi)
            .is_none_or(|o| o == std::cmp::Ordering::Greater)
        {
            return None;
        }
        let last = bins.levels.level(0).len() - 1;
        let bin =
            |y: f64, widen: f64| (((y - lo) / SURFACE_BIN_MM + widen).max(0.0) as usize).min(last);
        let (i, j) = (bin(y_lo, -1e-9), bin(y_hi, 1e-9));
        let k = crate::track::sparse::level_of(j - i + 1);
        Some((bins.levels.level(k), i, j + 1 - (1 << k)))
    }

    fn build_bins(&self) -> Bins {
        let (lo, hi) = self.y_range;
        let n = ((hi - lo) / SURFACE_BIN_MM).ceil().max(1.0) as usize;
        let bounds: Vec<SurfaceBounds> = (0..n)
            .map(|i| {
                let a = lo + SURFACE_BIN_MM * i as f64;
                let b = if i + 1 == n { hi } else { a + SURFACE_BIN_MM };
                self.surface_bounds(a, b)
                    .unwrap_or(SurfaceBounds::UNBOUNDED)
            })
            .collect();
        Bins {
            levels: crate::track::sparse::LazyLevels::new(bounds, SurfaceBounds::union),
        }
    }
}
