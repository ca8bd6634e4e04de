//! The placed rail's surface table: quintic Hermite pieces of `Z(Y)` (see the parent
//! module's docs for what is tabulated and what falls back to the inversion).

use super::{PlacedRail, RailPoint};

/// Step of the piecewise-quintic table of the placed rail surface (mm). Each piece is the
/// quintic Hermite interpolant of the exact `Z`, `Z'`, `Z''` at its ends. Against the exact
/// inversion of UIC60 at 1:40 (`surface_table_matches_the_exact_inversion`) it errs by at most
/// 8.5e-13 mm in `Z`, 1.5e-10 in the slope and 1.5e-8 relative in `Z''`, all on the R13
/// corners at slopes 1.5 to [`SURFACE_TABLE_MAX_SLOPE`], where the derivatives of `Z(Y)` are
/// largest; on the crown and shoulder it is exact to rounding.
pub const SURFACE_TABLE_STEP_MM: f64 = 0.02;
/// Pieces steeper than this (`|dZ/dY|` at an end, about 72 degrees) are not tabulated: the
/// derivatives of `Z(Y)` grow without bound towards a vertical tangent. There, and on pieces
/// that hold a section joint of an analytic rail (where `Z''` jumps) or more than one knot
/// of a sampled rail, [`PlacedRail::at`] inverts the profile by Newton's method instead.
///
/// A piece of a sampled rail that holds one spline knot is tabulated as two quintics, one
/// on each side of the knot: within a spline piece the surface is as smooth as an analytic
/// arc (a rotated cubic), and `Z'''`, which jumps at the knot, is never interpolated across.
pub const SURFACE_TABLE_MAX_SLOPE: f64 = 3.0;

/// A knot closer than this to an end of a table piece (in units of the piece, `t`) does not
/// split it: `Z'''` jumps only on a sliver of `1e-6 h`, where the quintic of the piece errs
/// by `|jump of Z'''| (1e-6 h)^3`, far below rounding.
const KNOT_AT_END_T: f64 = 1e-6;
/// Shortest part of a split piece (in units of `t`) that is tabulated; the rail is inverted
/// on a shorter one. The interpolant's `Z''` takes the rounding `delta` of its end values
/// (about 1e-13 mm: the translation into the side frame) as `delta / (len h)^2`: 5e-9 1/mm
/// at a quarter piece, 1e-6 at 1/60 (measured on sampled UIC60 before this bound).
const MIN_SPLIT_T: f64 = 0.25;

/// Quintic pieces of `Z(Y)`: monomial coefficients in `t = (Y - Y_i) / h` on `[0, 1]`; NaN
/// for pieces that are not tabulated, and `[NaN, k, ..]` for a piece split at a spline knot,
/// its two quintics in [`PlacedRail`]'s `splits[k]`.
#[derive(Debug, Clone, Default)]
pub(super) struct SurfaceTable {
    y0: f64,
    inv_step: f64,
    pieces: Vec<[f64; 6]>,
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

/// The monomial coefficients in `g` of the quintic Hermite interpolant on `0 <= g <= len`
/// (`len` in units of the table step `h`) of the surface points `a` (at `g = 0`) and `b`.
fn quintic_piece(a: RailPoint, b: RailPoint, h: f64, len: f64) -> [f64; 6] {
    // Values, len h * slopes and (len h)^2 * second derivatives in x = g / len.
    let (p0, p1) = (a.z, b.z);
    let (m0, m1) = (h * a.slope * len, h * b.slope * len);
    let (s0, s1) = (h * h * a.d2 * len * len, h * h * b.d2 * len * len);
    let dp = p1 - p0;
    let c = [
        p0,
        m0,
        0.5 * s0,
        10.0 * dp - 6.0 * m0 - 4.0 * m1 - 1.5 * s0 + 0.5 * s1,
        -15.0 * dp + 8.0 * m0 + 7.0 * m1 + 1.5 * s0 - s1,
        6.0 * dp - 3.0 * m0 - 3.0 * m1 - 0.5 * s0 + 0.5 * s1,
    ];
    // Exact for len = 1 (divisions by 1).
    let mut scale = 1.0;
    c.map(|ck| {
        let v = ck / scale;
        scale *= len;
        v
    })
}

/// The surface from the quintic `c` at `g` (in units of the step; `inv_step` = `1 / h`).
#[inline]
fn quintic_point(c: &[f64; 6], f: f64, inv_step: f64) -> RailPoint {
    let z = quintic_z(c, f);
    let dz = c[1] + f * (2.0 * c[2] + f * (3.0 * c[3] + f * (4.0 * c[4] + f * 5.0 * c[5])));
    let d2 = 2.0 * c[2] + f * (6.0 * c[3] + f * (12.0 * c[4] + f * 20.0 * c[5]));
    RailPoint {
        z,
        slope: dz * inv_step,
        d2: d2 * inv_step * inv_step,
    }
}

/// The height `Z` from the quintic `c` at `f`: the `z` of [`quintic_point`], by the same
/// operations.
#[inline]
fn quintic_z(c: &[f64; 6], f: f64) -> f64 {
    c[0] + f * (c[1] + f * (c[2] + f * (c[3] + f * (c[4] + f * c[5]))))
}

impl PlacedRail {
    /// The height `Z` at `y`, the `z` of [`PlacedRail::at`] to the bit without its slope
    /// and curvature (a sixth of its work on a tabulated piece): what the height table is
    /// filled with. `None` outside [`PlacedRail::y_range`].
    #[inline]
    pub(in crate::track) fn height_at(&self, y: f64) -> Option<f64> {
        let (y_lo, y_hi) = self.y_range();
        if !(y_lo..=y_hi).contains(&y) {
            return None;
        }
        let table = &self.surface_table;
        let t = (y - table.y0) * table.inv_step;
        let i = t as i32 as usize;
        Some(match table.pieces.get(i) {
            Some(c) if !c[0].is_nan() => quintic_z(c, t - i as f64),
            _ => self.untabulated_at(y).z,
        })
    }

    /// The surface at `y` (inside `y_range`) from its quintic piece, `None` where `y` has no
    /// tabulated piece.
    #[inline]
    pub(super) fn tabulated_at(&self, y: f64) -> Option<RailPoint> {
        let table = &self.surface_table;
        let t = (y - table.y0) * table.inv_step;
        // `t >= 0` inside y_range (`y0` is its start); through i32 as in `guess`.
        let i = t as i32 as usize;
        let c = table.pieces.get(i)?;
        if c[0].is_nan() {
            return None;
        }
        let f = t - i as f64;
        Some(quintic_point(c, f, table.inv_step))
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
        (!c[0].is_nan()).then(|| quintic_point(c, g, table.inv_step))
    }

    /// Fills the quintic table of the surface from exact inversions every
    /// [`SURFACE_TABLE_STEP_MM`]; pieces that are steep, hold a joint of an analytic rail or
    /// several knots of a sampled one are left out (NaN), pieces that hold one knot are split
    /// there (see [`SURFACE_TABLE_MAX_SLOPE`]).
    pub(super) fn tabulate_surface(&mut self) {
        let (y_lo, y_hi) = self.y_range;
        let n = ((y_hi - y_lo) / SURFACE_TABLE_STEP_MM).floor() as usize;
        let h = SURFACE_TABLE_STEP_MM;
        let joints: Vec<f64> = self
            .profile
            .joints()
            .into_iter()
            .map(|u| self.point_of(u)[0])
            .collect();
        // A sampled rail's knots `(Y, u)` (its joints are among them); an analytic rail has
        // none.
        let mut knots: Vec<(f64, f64)> = if self.profile.is_sampled() {
            self.profile
                .breaks()
                .into_iter()
                .map(|u| (self.point_of(u)[0], u))
                .collect()
        } else {
            Vec::new()
        };
        knots.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut next_knot = 0;
        let node = |i: usize| {
            let y = y_lo + h * i as f64;
            self.invert(y, self.guess(y)).1
        };
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
        let mut b = node(0);
        for i in 0..n {
            let a = b;
            b = node(i + 1);
            let piece = {
                let (ya, yb) = (y_lo + h * i as f64, y_lo + h * (i + 1) as f64);
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
                        (None, _) => quintic_piece(a, b, h, 1.0),
                        (Some((t_knot, u)), None) => self.split_piece(a, b, t_knot, u, &mut splits),
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
        };
        self.splits = splits;
    }

    /// The piece from nodes `a` to `b` split at the knot `u` of a sampled rail, at `t_knot`
    /// of the piece: its two quintics pushed onto `splits`, and the marker `[NaN, k, ..]`
    /// that points to them (NaN where the knot is steep).
    fn split_piece(
        &self,
        a: RailPoint,
        b: RailPoint,
        t_knot: f64,
        u: f64,
        splits: &mut Vec<Split>,
    ) -> [f64; 6] {
        let h = SURFACE_TABLE_STEP_MM;
        let k = self.surface_at(u);
        if !(k.slope.abs() <= SURFACE_TABLE_MAX_SLOPE && k.z.is_finite()) {
            return [f64::NAN; 6];
        }
        let part = |p, q, len| {
            if len >= MIN_SPLIT_T {
                quintic_piece(p, q, h, len)
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
