//! A rail placed in its side frame: rotated by its inclination, its top at `Z = 0` and its
//! gauge point at `Y = gauge / 2`, with the tables that make its surface cheap to read.

use super::heights::{HEIGHT_TABLE_STEP_MM, HeightTable};
use super::{Inclination, PlacementError, TrackLayout, convex_from_second_derivative};
use crate::profile::{Profile, ProfileKind};
use nalgebra::{Isometry2, Point2, Translation2, UnitComplex, Vector2};

/// Sampling step used to find the top and the gauge point before refining them (mm).
/// Fine enough that no local extremum of a rail head (radii >= 5 mm) is stepped over.
const PLACEMENT_SCAN_STEP_MM: f64 = 0.01;
/// Placed rail slopes steeper than this (|dZ/dY|, about 88.9 degrees) are no longer treated
/// as part of the running surface: a vertical or undercut face cannot be written as Z(Y).
pub const MAX_RAIL_SLOPE: f64 = 50.0;

/// A point of a placed rail, in the side frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailPoint {
    /// Height `Z` (mm).
    pub z: f64,
    /// `dZ/dY`: tangent of the rail's contact angle in the side frame.
    pub slope: f64,
    /// `d2Z/dY2` (1/mm).
    pub d2: f64,
}

impl RailPoint {
    /// Convex-positive curvature (1/mm).
    #[inline]
    pub fn curvature(&self) -> f64 {
        convex_from_second_derivative(self.slope, self.d2)
    }
}

/// A rail rotated by its inclination and translated into the side frame.
#[derive(Debug, Clone)]
pub struct PlacedRail {
    profile: Profile,
    /// The rail's frame in the side frame: `(Y, Z) = frame (u, v)`, the rotation by the
    /// inclination (counter-clockwise tilts the head towards the track centre) followed by
    /// the translation that puts the top at `Z = 0` and the gauge point at `Y = gauge / 2`.
    /// The hot loops (the inversion) read its rotation's cosine and sine directly.
    frame: Isometry2<f64>,
    /// Profile coordinates `(u_lo, u_hi)` of the running-surface part (see [`MAX_RAIL_SLOPE`]).
    surface: (f64, f64),
    /// Side-frame `Y` of the ends of `surface`.
    y_range: (f64, f64),
    gauge_point: [f64; 2],
    top: [f64; 2],
    /// Start guesses for [`PlacedRail::at`]: `(u, du/dY)` at `Y = y_range.0 + i h`, with
    /// `h` = `INVERSE_TABLE_STEP_MM` (at most); cubic Hermite interpolation between them.
    inverse: Vec<[f64; 2]>,
    /// `1 / h` of `inverse`.
    inverse_scale: f64,
    /// `h` of `inverse` (kept: a division less per lookup).
    inverse_step: f64,
    /// Heights every [`HEIGHT_TABLE_STEP_MM`], built once with the placement.
    heights: HeightTable,
    /// The surface `Z(Y)` by quintic pieces (see [`SURFACE_TABLE_STEP_MM`]).
    surface_table: SurfaceTable,
    /// The pieces of `surface_table` split at a knot of a sampled rail (last: read only
    /// there, off the hot fields).
    splits: Vec<Split>,
}

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
struct SurfaceTable {
    y0: f64,
    inv_step: f64,
    pieces: Vec<[f64; 6]>,
}

/// A table piece split at a spline knot: `t_knot` in `(0, 1)`, the quintic of `[0, t_knot]`
/// in `t` and that of `[t_knot, 1]` in `t - t_knot`; NaN for a part shorter than
/// [`MIN_SPLIT_T`].
#[derive(Debug, Clone, Copy)]
struct Split {
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
    let z = c[0] + f * (c[1] + f * (c[2] + f * (c[3] + f * (c[4] + f * c[5]))));
    let dz = c[1] + f * (2.0 * c[2] + f * (3.0 * c[3] + f * (4.0 * c[4] + f * 5.0 * c[5])));
    let d2 = 2.0 * c[2] + f * (6.0 * c[3] + f * (12.0 * c[4] + f * 20.0 * c[5]));
    RailPoint {
        z,
        slope: dz * inv_step,
        d2: d2 * inv_step * inv_step,
    }
}

/// The rail profile sampled every [`PLACEMENT_SCAN_STEP_MM`] for its placement.
struct Scan {
    /// Profile coordinates of the samples.
    us: Vec<f64>,
    /// Every sample's rotated point and tangent `[Y, Z, dY/du, dZ/du]`, from one evaluation
    /// each.
    samples: Vec<[f64; 4]>,
}

impl Scan {
    fn of(profile: &Profile, rotation: UnitComplex<f64>) -> Scan {
        let (lo, hi) = profile.domain();
        let n = ((hi - lo) / PLACEMENT_SCAN_STEP_MM).ceil() as usize;
        let us: Vec<f64> = (0..=n)
            .map(|i| lo + (hi - lo) * i as f64 / n as f64)
            .collect();
        let samples = us
            .iter()
            .map(|&u| {
                let [v, d1, _] = profile.eval(u);
                let p = rotation * Point2::new(u, v);
                let t = rotation * Vector2::new(1.0, d1);
                [p.x, p.y, t.x, t.y]
            })
            .collect();
        Scan { us, samples }
    }

    /// The running surface `(u_lo, u_hi)`: the connected stretch around the top sample
    /// `i_top` where Y(u) increases and the placed slope stays below [`MAX_RAIL_SLOPE`].
    fn running_surface(&self, i_top: usize) -> (f64, f64) {
        let steep = |i: usize| {
            let [_, _, ty, tz] = self.samples[i];
            ty <= 0.0 || tz.abs() > MAX_RAIL_SLOPE * ty
        };
        let mut i_lo = i_top;
        while i_lo > 0 && !steep(i_lo - 1) {
            i_lo -= 1;
        }
        let mut i_hi = i_top;
        while i_hi + 1 < self.us.len() && !steep(i_hi + 1) {
            i_hi += 1;
        }
        (self.us[i_lo], self.us[i_hi])
    }
}

impl PlacedRail {
    /// Places `profile` (upright, or already inclined by `profile_inclination`) for a track
    /// with `layout`, on the side frame's positive Y.
    ///
    /// # Errors
    /// [`PlacementError`] when the profile is not a rail or has no gauge point.
    pub fn place(
        profile: Profile,
        profile_inclination: Inclination,
        layout: &TrackLayout,
    ) -> Result<PlacedRail, PlacementError> {
        if profile.kind() != ProfileKind::Rail {
            return Err(PlacementError::WrongKind {
                profile: profile.name().to_string(),
                expected: ProfileKind::Rail,
            });
        }
        // Counter-clockwise in (Y field-side, Z up) tilts the head towards the track centre;
        // the translation follows from the rotated head below.
        let rotation = UnitComplex::new(layout.inclination.0 - profile_inclination.0);
        let mut rail = PlacedRail {
            profile,
            frame: Isometry2::from_parts(Translation2::identity(), rotation),
            surface: (0.0, 0.0),
            y_range: (0.0, 0.0),
            gauge_point: [0.0, 0.0],
            top: [0.0, 0.0],
            inverse: Vec::new(),
            inverse_scale: 0.0,
            inverse_step: 0.0,
            heights: HeightTable::default(),
            surface_table: SurfaceTable::default(),
            splits: Vec::new(),
        };
        let scan = Scan::of(&rail.profile, rotation);
        let (i_top, top) = rail.find_top(&scan);
        let floor = top[1] - layout.gauge_point_depth_mm;
        let gp = rail.find_gauge_point(&scan, floor)?;
        rail.frame.translation = Translation2::new(0.5 * layout.gauge_mm - gp[0], -top[1]);
        rail.gauge_point = rail.to_side(gp);
        rail.top = rail.to_side(top);
        rail.surface = scan.running_surface(i_top);
        rail.y_range = (
            rail.point_of(rail.surface.0)[0],
            rail.point_of(rail.surface.1)[0],
        );
        rail.tabulate_inverse();
        // The heights are read from the surface table, which is built first.
        rail.tabulate_surface();
        rail.heights = HeightTable::new(&rail, HEIGHT_TABLE_STEP_MM);
        Ok(rail)
    }

    /// Top of the rail in the rotated profile frame: the maximum of Z(u), refined by
    /// bisection on dZ/du (concave near the top); with the index of the highest sample.
    fn find_top(&self, scan: &Scan) -> (usize, [f64; 2]) {
        let (us, samples) = (&scan.us, &scan.samples);
        let i_top = (0..us.len())
            .max_by(|&a, &b| samples[a][1].total_cmp(&samples[b][1]))
            .unwrap_or(0);
        let u_top = refine_extremum(
            |u| self.rotated_tangent(u)[1],
            us[i_top.saturating_sub(1)],
            us[(i_top + 1).min(us.len() - 1)],
        );
        (i_top, self.rotated(u_top))
    }

    /// Gauge point in the rotated profile frame: the most gauge-side (smallest Y) point with
    /// Z >= `floor` (the top less the gauge point depth).
    fn find_gauge_point(&self, scan: &Scan, floor: f64) -> Result<[f64; 2], PlacementError> {
        let (us, samples) = (&scan.us, &scan.samples);
        let mut best: Option<(usize, f64)> = None;
        for (i, p) in samples.iter().enumerate() {
            if p[1] >= floor && best.is_none_or(|(_, y)| p[0] < y) {
                best = Some((i, p[0]));
            }
        }
        let Some((i_gp, _)) = best else {
            return Err(PlacementError::NoGaugePoint {
                profile: self.profile.name().to_string(),
            });
        };
        let below = |i: usize| samples[i][1] < floor;
        let u_gp = if i_gp > 0 && below(i_gp - 1) {
            // The depth line cuts the head between two samples: bisect Z(u) = floor.
            bisect(|u| self.rotated(u)[1] - floor, us[i_gp - 1], us[i_gp])
        } else if i_gp + 1 < us.len() && below(i_gp + 1) {
            bisect(|u| self.rotated(u)[1] - floor, us[i_gp + 1], us[i_gp])
        } else {
            refine_extremum(
                |u| self.rotated_tangent(u)[0],
                us[i_gp.saturating_sub(1)],
                us[(i_gp + 1).min(us.len() - 1)],
            )
        };
        Ok(self.rotated(u_gp))
    }

    /// The profile this rail was placed from.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The gauge point `(Y, Z)` in the side frame: `Y = gauge / 2` by construction.
    pub fn gauge_point(&self) -> [f64; 2] {
        self.gauge_point
    }

    /// The highest point `(Y, Z)` of the placed head: `Z = 0` by construction.
    pub fn top(&self) -> [f64; 2] {
        self.top
    }

    /// The side-frame interval `(Y_lo, Y_hi)` on which [`PlacedRail::at`] answers.
    #[inline]
    pub fn y_range(&self) -> (f64, f64) {
        self.y_range
    }

    /// The rail's heights tabulated every [`HEIGHT_TABLE_STEP_MM`] (coarse scans).
    #[inline]
    pub fn heights(&self) -> &HeightTable {
        &self.heights
    }

    /// The placed point `(Y, Z)` of the profile coordinate `u`.
    #[inline]
    pub fn point_of(&self, u: f64) -> [f64; 2] {
        self.to_side(self.rotated(u))
    }

    /// The placed rail surface at the profile coordinate `u`: its point, slope `dZ/dY` and
    /// curvature, with the section on the field side of `u` at a joint (as the profile's
    /// own evaluation), whatever the slope (steep flanks included).
    pub fn surface_at(&self, u: f64) -> RailPoint {
        let [v, d1, d2] = self.profile.eval(u);
        let t = self.frame.rotation * Vector2::new(1.0, d1);
        let (ty, tz) = (t.x, t.y);
        let p = self.frame * Point2::new(u, v);
        RailPoint {
            z: p.y,
            slope: tz / ty,
            d2: d2 / (ty * ty * ty),
        }
    }

    /// The rail surface above the side-frame lateral position `y` (mm), or `None` outside
    /// [`PlacedRail::y_range`].
    ///
    /// From the quintic table of the surface where it holds (see [`SURFACE_TABLE_STEP_MM`]
    /// for its errors), otherwise as [`PlacedRail::exact_at`].
    #[inline]
    pub fn at(&self, y: f64) -> Option<RailPoint> {
        let (y_lo, y_hi) = self.y_range();
        if !(y_lo..=y_hi).contains(&y) {
            return None;
        }
        Some(
            self.tabulated_at(y)
                .unwrap_or_else(|| self.untabulated_at(y)),
        )
    }

    /// The rail surface above `y` by inverting the profile, `Y(u) = y`, by Newton's method
    /// from a tabulated inverse (one step to 1e-15 mm on the arcs, two where the head turns
    /// steep: see `INVERSE_TABLE_STEP_MM`); `None` outside [`PlacedRail::y_range`].
    pub fn exact_at(&self, y: f64) -> Option<RailPoint> {
        let (y_lo, y_hi) = self.y_range();
        if !(y_lo..=y_hi).contains(&y) {
            return None;
        }
        Some(self.invert(y, self.guess(y)).1)
    }

    /// The rail profile's own coordinate `u` of the surface point above `y` (exact
    /// inversion), or `None` outside [`PlacedRail::y_range`].
    pub fn profile_coordinate(&self, y: f64) -> Option<f64> {
        let (y_lo, y_hi) = self.y_range();
        (y_lo..=y_hi)
            .contains(&y)
            .then(|| self.invert(y, self.guess(y)).0)
    }

    /// The surface at `y` (inside `y_range`) from its quintic piece, `None` where `y` has no
    /// tabulated piece.
    #[inline]
    fn tabulated_at(&self, y: f64) -> Option<RailPoint> {
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
    fn untabulated_at(&self, y: f64) -> RailPoint {
        self.split_at(y)
            .unwrap_or_else(|| self.invert(y, self.guess(y)).1)
    }

    /// The surface at `y` (inside `y_range`) from the part of a piece split at a knot, `None`
    /// where `y` is in no such part.
    fn split_at(&self, y: f64) -> Option<RailPoint> {
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
    fn tabulate_surface(&mut self) {
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
        let nodes: Vec<RailPoint> = (0..=n)
            .map(|i| {
                let y = y_lo + h * i as f64;
                self.invert(y, self.guess(y)).1
            })
            .collect();
        let steep = |p: &RailPoint| !(p.slope.abs() <= SURFACE_TABLE_MAX_SLOPE && p.z.is_finite());
        let mut splits = Vec::new();
        let pieces: Vec<[f64; 6]> = nodes
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let (a, b) = (w[0], w[1]);
                let (ya, yb) = (y_lo + h * i as f64, y_lo + h * (i + 1) as f64);
                let holds_joint = joints.iter().any(|&j| (ya..=yb).contains(&j));
                if holds_joint || steep(&a) || steep(&b) {
                    return [f64::NAN; 6];
                }
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
                    (Some((t_knot, u)), None) => {
                        let k = self.surface_at(u);
                        if steep(&k) {
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
                    (Some(_), Some(_)) => [f64::NAN; 6],
                }
            })
            .collect();
        self.surface_table = SurfaceTable {
            y0: y_lo,
            inv_step: 1.0 / h,
            pieces,
        };
        self.splits = splits;
    }

    /// The start of the inversion at `y` (inside `y_range`): cubic Hermite interpolation of
    /// the table of exact inverses.
    #[inline]
    fn guess(&self, y: f64) -> f64 {
        let last = self.inverse.len() - 2;
        let t = (y - self.y_range.0) * self.inverse_scale;
        // `t >= 0` inside y_range, and the clamp keeps the last interval. Through i32 (the
        // table is short): one conversion each way, where usize costs a dozen instructions.
        let ti = (t as i32).min(last as i32);
        let f = t - f64::from(ti);
        let i = ti as usize;
        let h = self.inverse_step;
        let ([u0, m0], [u1, m1]) = (self.inverse[i], self.inverse[i + 1]);
        let g = 1.0 - f;
        // Hermite basis in Horner-friendly form.
        u0 * g * g * (1.0 + 2.0 * f) + u1 * f * f * (3.0 - 2.0 * f) + h * f * g * (m0 * g - m1 * f)
    }

    /// The profile coordinate `u` and the rail point at `y`, by Newton's method on `Y(u) = y`
    /// from `u`.
    #[inline]
    fn invert(&self, y: f64, u: f64) -> (f64, RailPoint) {
        let target = y - self.frame.translation.x;
        let (cos, sin) = self.cos_sin();
        let (lo, hi) = self.surface;
        let mut u = u.clamp(lo, hi);
        let mut value = self.profile.eval(u);
        for _ in 0..MAX_NEWTON_STEPS {
            let yu = cos * u - sin * value[0];
            let dyu = cos - sin * value[1];
            let step = (yu - target) / dyu;
            let next = u - step;
            if step.abs() < TAYLOR_FINISH_MM && (lo..=hi).contains(&next) {
                // The start was already this close: the profile at the root follows from
                // its value and derivatives at the start (see TAYLOR_FINISH_MM).
                let [v, d1, d2] = value;
                let d = -step;
                value = [v + d * (d1 + 0.5 * d * d2), d1 + d * d2, d2];
                u = next;
                break;
            }
            u = next.clamp(lo, hi);
            value = self.profile.eval(u);
            if step.abs() < INVERSE_TOL_MM {
                break;
            }
        }
        let [v, d1, d2] = value;
        let ty = cos - sin * d1;
        let tz = sin + cos * d1;
        // For the rotated curve (Y(u), Z(u)): Z'' = (Y'Z'' - Z'Y'')/Y'^3 = v''/Y'^3.
        (
            u,
            RailPoint {
                z: sin * u + cos * v + self.frame.translation.y,
                slope: tz / ty,
                d2: d2 / (ty * ty * ty),
            },
        )
    }

    /// Fills the table of start guesses: exact inverses (from the linearised inverse, as
    /// many Newton steps as needed) every `INVERSE_TABLE_STEP_MM` or less.
    fn tabulate_inverse(&mut self) {
        let (y_lo, y_hi) = self.y_range;
        let n = ((y_hi - y_lo) / INVERSE_TABLE_STEP_MM).ceil().max(1.0) as usize;
        let h = (y_hi - y_lo) / n as f64;
        // Each entry starts from the tangent of the one before (from the linearised inverse
        // at the first).
        let (cos, sin) = self.cos_sin();
        let mut guess = (y_lo - self.frame.translation.x) / cos;
        self.inverse = (0..=n)
            .map(|i| {
                let y = if i == n { y_hi } else { y_lo + h * i as f64 };
                let (u, _) = self.invert(y, guess);
                let d1 = self.profile.eval(u)[1];
                let du_dy = 1.0 / (cos - sin * d1);
                guess = u + h * du_dy;
                [u, du_dy]
            })
            .collect();
        self.inverse_scale = 1.0 / h;
        self.inverse_step = h;
    }

    /// The cosine and sine of the inclination (the rotation's complex number, no trigonometry).
    #[inline]
    fn cos_sin(&self) -> (f64, f64) {
        (self.frame.rotation.re, self.frame.rotation.im)
    }

    /// The profile point at `u`, rotated (not yet translated).
    #[inline]
    fn rotated(&self, u: f64) -> [f64; 2] {
        let v = self.profile.eval(u)[0];
        let p = self.frame.rotation * Point2::new(u, v);
        [p.x, p.y]
    }

    /// The profile's tangent `(1, v')` at `u`, rotated.
    #[inline]
    fn rotated_tangent(&self, u: f64) -> [f64; 2] {
        let d1 = self.profile.eval(u)[1];
        let t = self.frame.rotation * Vector2::new(1.0, d1);
        [t.x, t.y]
    }

    /// A rotated point translated into the side frame.
    #[inline]
    fn to_side(&self, p: [f64; 2]) -> [f64; 2] {
        let q = Point2::new(p[0], p[1]) + self.frame.translation.vector;
        [q.x, q.y]
    }
}

/// Newton steps allowed when inverting the rotated rail; 1-2 are used from the table, 3-4
/// from the linearised inverse that fills it.
const MAX_NEWTON_STEPS: usize = 8;
/// Spacing of the table of start guesses of the rail inversion (mm). Away from the joints
/// of the head, Hermite interpolation of `u(Y)` errs by far less than [`INVERSE_TOL_MM`], so
/// the first Newton step already meets the tolerance (2 profile evaluations instead of 4
/// from the linearised inverse); next to a joint, where `u''` jumps, and on the steep gauge
/// corner a second step follows. The answer is the converged root either way.
const INVERSE_TABLE_STEP_MM: f64 = 0.05;
/// A first Newton step shorter than this (mm) ends the inversion without evaluating the
/// profile again: the root's value and slope follow from a second-order Taylor expansion
/// about the start, erring by |v'''| d^3 / 6 and |v'''| d^2 / 2, and its second derivative
/// is the start's, erring by |v'''| d <= 4e-11 1/mm (|v'''| <= 4 1/mm^2 on the R13 corner
/// of UIC60 up to the 70-degree flank). Newton's own error after the step is below 1e-23 mm.
/// From the table (see `INVERSE_TABLE_STEP_MM`) most lookups end here, with one profile
/// evaluation instead of two.
const TAYLOR_FINISH_MM: f64 = 1e-11;
/// Step size after which the inversion of the rotated rail has converged (mm). Newton
/// converges quadratically with a constant |Y''/2Y'| <= sin(angle) * kappa / 2 < 1e-2 1/mm,
/// so after a step of 1e-7 mm the error is below 1e-16 mm.
const INVERSE_TOL_MM: f64 = 1e-7;

/// Bisection for a sign change of `f` between `a` and `b` (60 halvings: below 1e-15 mm for
/// any bracket shorter than 1 m).
fn bisect(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (mut a, mut b) = (a, b);
    let fa = f(a);
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Zero of a derivative `df` between `a` and `b` if it changes sign there, else the end
/// with the smaller |df|.
fn refine_extremum(df: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    if (df(a) > 0.0) != (df(b) > 0.0) {
        bisect(df, a, b)
    } else if df(a).abs() < df(b).abs() {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper_layout() -> TrackLayout {
        TrackLayout::standard(Inclination::parse("1:40").unwrap())
    }

    #[test]
    fn uic60_at_1_in_40_has_its_top_43_03_mm_field_side_of_the_gauge_point() {
        let rail =
            PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &paper_layout()).unwrap();
        // Gauge point exactly at half the gauge (bisection to 1e-15).
        assert!((rail.gauge_point()[0] - 717.5).abs() < 1e-9);
        assert!((rail.gauge_point()[1] + 14.0).abs() < 1e-9);
        assert!(rail.top()[1].abs() < 1e-12);
        // Reference value (the project's reference notes on the standard-gauge layout,
        // outside this repository): 43.03 mm (2 decimals), so 760.53 from the track centre.
        let offset = rail.top()[0] - rail.gauge_point()[0];
        assert!((offset - 43.03).abs() < 0.005, "{offset}");
    }

    #[test]
    fn top_offsets_for_other_inclinations() {
        // Same reference notes: upright 35.98 mm, 1:20 46.5 mm (as many decimals as given).
        for (incl, expected, tol) in [("vertical", 35.98, 0.005), ("1:20", 46.5, 0.05)] {
            let layout = TrackLayout {
                inclination: Inclination::parse(incl).unwrap(),
                ..paper_layout()
            };
            let rail =
                PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &layout).unwrap();
            let offset = rail.top()[0] - rail.gauge_point()[0];
            assert!((offset - expected).abs() < tol, "{incl}: {offset}");
        }
    }

    #[test]
    fn rail_inverse_is_exact() {
        let rail =
            PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &paper_layout()).unwrap();
        let (lo, hi) = rail.profile().domain();
        for i in 0..=200 {
            let u = lo + (hi - lo) * f64::from(i) / 200.0;
            let p = rail.point_of(u);
            if let Some(r) = rail.at(p[0]) {
                assert!((r.z - p[1]).abs() < 1e-10, "u = {u}");
            }
        }
    }

    /// Every 1e-3 mm over `rail`: the quintic pieces against Newton's inversion; the number
    /// of points tabulated, of points, and the largest differences in `Z`, the slope and
    /// `Z''` (relative).
    fn table_against_inversion(rail: &PlacedRail) -> (usize, usize, [f64; 3]) {
        let (lo, hi) = rail.y_range();
        let (mut tabulated, mut worst) = (0, [0.0f64; 3]);
        let n = ((hi - lo) / 1e-3) as usize;
        for i in 0..=n {
            let y = lo + (hi - lo) * i as f64 / n as f64;
            let table = rail.tabulated_at(y).or_else(|| rail.split_at(y));
            let (Some(t), Some(e)) = (table, rail.exact_at(y)) else {
                continue;
            };
            tabulated += 1;
            for (w, d) in worst.iter_mut().zip([
                t.z - e.z,
                t.slope - e.slope,
                (t.d2 - e.d2) / (1.0 + e.d2.abs()),
            ]) {
                *w = w.max(d.abs());
            }
        }
        (tabulated, n, worst)
    }

    #[test]
    fn sampled_surface_table_matches_the_exact_inversion() {
        // UIC60 sampled every 0.25 mm (joints included) and fitted by an interpolating spline,
        // as the tradeoff study's sampled setting: the pieces that hold a knot are split there.
        let points = Profile::uic60e1()
            .sample(0.25)
            .iter()
            .map(|r| [r[0], r[1]])
            .collect();
        let points =
            crate::profile::read::PointProfile::from_points(ProfileKind::Rail, "sampled", points)
                .unwrap();
        let profile = Profile::from_points(points, 0.0).unwrap();
        let rail = PlacedRail::place(profile, Inclination::VERTICAL, &paper_layout()).unwrap();
        let splits = rail.splits.len();
        let (tabulated, n, worst) = table_against_inversion(&rail);
        println!(
            "tabulated {tabulated} of {n} ({splits} split pieces); max |dz| {:.1e}, |dslope| {:.1e}, |dZ''| rel {:.1e}",
            worst[0], worst[1], worst[2]
        );
        // One piece in 12.5 holds a knot (0.25 mm / 0.02 mm); as much of the head as on the
        // analytic rail is tabulated.
        assert!(splits > 200, "{splits}");
        assert!(tabulated > n * 3 / 4, "{tabulated} of {n}");
        // Measured: 2.0e-13 mm, 5.1e-11 and 7.8e-9 (the analytic rail: 8.5e-13, 1.5e-10,
        // 1.5e-8); the analytic rail's limits.
        assert!(worst[0] < 4e-12, "z {:e}", worst[0]);
        assert!(worst[1] < 6e-10, "slope {:e}", worst[1]);
        assert!(worst[2] < 6e-8, "second derivative {:e}", worst[2]);
    }

    #[test]
    fn surface_table_matches_the_exact_inversion() {
        // Every 1e-3 mm over the placed UIC60 at 1:40: the quintic pieces against Newton's
        // inversion of the analytic head.
        let rail =
            PlacedRail::place(Profile::uic60e1(), Inclination::VERTICAL, &paper_layout()).unwrap();
        let (tabulated, n, worst) = table_against_inversion(&rail);
        println!(
            "tabulated {tabulated} of {n}; max |dz| {:.1e}, |dslope| {:.1e}, |dZ''| rel {:.1e}",
            worst[0], worst[1], worst[2]
        );
        // Most of the head is tabulated (the steep gauge face and the pieces at joints not).
        assert!(tabulated > n * 3 / 4, "{tabulated} of {n}");
        // Measured: 8.5e-13 mm, 1.5e-10 and 1.5e-8, all on the R13 corners at slopes 1.5 to
        // 3, where the derivatives of Z(Y) are largest; limits 4 times that.
        assert!(worst[0] < 4e-12, "z {:e}", worst[0]);
        assert!(worst[1] < 6e-10, "slope {:e}", worst[1]);
        assert!(worst[2] < 6e-8, "second derivative {:e}", worst[2]);
    }
}
