//! A rail placed in its side frame: rotated by its inclination, its top at `Z = 0` and its
//! gauge point at `Y = gauge / 2`, with the tables that make its surface cheap to read.
//!
//! Run time is spent evaluating the gap between a wheel point and the rail under it, so the
//! placement builds these tables once per rail: [`PlacedRail::at`] reads quintic Hermite
//! pieces of `Z(Y)` every [`SURFACE_TABLE_STEP_MM`] built from exact values and
//! derivatives; on a sampled rail a piece that holds one spline knot is two quintics split
//! at the knot (the third derivative jumps there). Pieces that are steep (slope above
//! [`SURFACE_TABLE_MAX_SLOPE`]), hold a section joint of an analytic rail or two knots, and
//! split parts shorter than a quarter piece (their `Z''` would take the rounding of the end
//! values over a tiny length) fall back to [`PlacedRail::exact_at`], Newton's inversion of
//! the profile from a cubic table of `u(Y)`, out of line so that the tabulated lookup stays
//! short. Unit tests bound the difference of the two over the whole head, for the analytic
//! and the sampled UIC60 (`surface_table_matches_the_exact_inversion`,
//! `sampled_surface_table_matches_the_exact_inversion`).

use super::heights::{HEIGHT_TABLE_STEP_MM, HeightTable};
use super::{Inclination, PlacementError, TrackLayout, convex_from_second_derivative};
use crate::profile::{Profile, ProfileKind, ProfileScan};
use nalgebra::{Isometry2, Point2, Translation2, UnitComplex, Vector2};

mod surface;

pub(crate) use surface::SurfaceBounds;
use surface::{Split, SurfaceTable};

/// Sampling step used to find the top and the gauge point before refining them (mm).
/// Fine enough that no local extremum of a rail head (radii >= 5 mm) is stepped over.
const PLACEMENT_SCAN_STEP_MM: f64 = 0.01;
/// Placed rail slopes steeper than this (|dZ/dY|, about 88.9 degrees) are no longer treated
/// as part of the running surface: a vertical or undercut face cannot be written as Z(Y).
pub(crate) const MAX_RAIL_SLOPE: f64 = 50.0;

/// A point of a placed rail in the side frame, as [`PlacedRail::at`] gives it and
/// [`crate::gap::GapPoint`] carries it.
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

/// How the placement evaluates the rail profile at increasing `u` (its scan and tables):
/// [`Profile::eval`] to the bit, from a [`ProfileScan`] that walks a sampled profile's
/// spline forward ([`Walked`]) or by `eval` itself ([`Direct`]).
trait ScanEval: Copy {
    /// A scan of `profile` at increasing `u`.
    fn scan(self, profile: &Profile) -> ProfileScan<'_>;
}

/// [`ScanEval`] by [`Profile::scan`] (a sampled rail's spline steps forward from its last
/// piece).
#[derive(Debug, Clone, Copy)]
struct Walked;

impl ScanEval for Walked {
    #[inline]
    fn scan(self, profile: &Profile) -> ProfileScan<'_> {
        profile.scan()
    }
}

/// [`ScanEval`] by [`Profile::eval`] at every point (built-in rails, and the reference of
/// the tests).
#[derive(Debug, Clone, Copy)]
struct Direct;

impl ScanEval for Direct {
    #[inline]
    fn scan(self, profile: &Profile) -> ProfileScan<'_> {
        ProfileScan::Eval(profile)
    }
}

/// The rail profile sampled every [`PLACEMENT_SCAN_STEP_MM`] for its placement.
struct Scan {
    /// The profile coordinates of the samples: `lo + (hi - lo) i / n`.
    domain: (f64, f64),
    n: usize,
    /// Every sample's rotated point `[Y, Z]`, from one evaluation each.
    points: Vec<[f64; 2]>,
    /// Whether the rotated tangent at each sample is steep or turns back (see
    /// [`Scan::running_surface`]).
    steep: Vec<bool>,
}

impl Scan {
    /// The scan of `profile`, evaluated by `eval` (see [`ScanEval`]). Out of line: called
    /// once, and its cost stays visible in a profile.
    #[inline(never)]
    fn of(profile: &Profile, rotation: UnitComplex<f64>, eval: impl ScanEval) -> Scan {
        let (lo, hi) = profile.domain();
        let n = ((hi - lo) / PLACEMENT_SCAN_STEP_MM).ceil() as usize;
        // One plain loop: the samples increase, so the profile is evaluated by a scan
        // (the same values as
        // `eval`), without the second derivative; `i as f64` is counted in floating point
        // (exact below 2^53), not converted from the index each time.
        let (width, count) = (hi - lo, n as f64);
        // Filled in place (no capacity tested per sample).
        let mut points = vec![[0.0; 2]; n + 1];
        let mut steep = vec![false; n + 1];
        let mut scan = eval.scan(profile);
        let mut i = 0.0;
        for (point, steep) in points.iter_mut().zip(&mut steep) {
            let u = lo + width * i / count;
            i += 1.0;
            let [v, d1] = scan.eval_slope(u);
            let p = rotation * Point2::new(u, v);
            let t = rotation * Vector2::new(1.0, d1);
            *point = [p.x, p.y];
            *steep = t.x <= 0.0 || t.y.abs() > MAX_RAIL_SLOPE * t.x;
        }
        Scan {
            domain: (lo, hi),
            n,
            points,
            steep,
        }
    }

    /// The profile coordinate of sample `i`.
    fn u(&self, i: usize) -> f64 {
        let (lo, hi) = self.domain;
        lo + (hi - lo) * i as f64 / self.n as f64
    }

    /// The running surface `(u_lo, u_hi)`: the connected stretch around the top sample
    /// `i_top` where Y(u) increases and the placed slope stays below [`MAX_RAIL_SLOPE`].
    fn running_surface(&self, i_top: usize) -> (f64, f64) {
        let mut i_lo = i_top;
        while i_lo > 0 && !self.steep[i_lo - 1] {
            i_lo -= 1;
        }
        let mut i_hi = i_top;
        while i_hi + 1 < self.points.len() && !self.steep[i_hi + 1] {
            i_hi += 1;
        }
        (self.u(i_lo), self.u(i_hi))
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
        // The scan and the tables evaluate the profile at increasing `u`: a sampled one
        // walked forward, a built-in one as everywhere (one dispatch here, not per point).
        if profile.is_sampled() {
            PlacedRail::place_with(profile, profile_inclination, layout, Walked)
        } else {
            PlacedRail::place_with(profile, profile_inclination, layout, Direct)
        }
    }

    /// [`PlacedRail::place`] for a rail profile evaluated by `eval` in its scan and tables.
    fn place_with(
        profile: Profile,
        profile_inclination: Inclination,
        layout: &TrackLayout,
        eval: impl ScanEval,
    ) -> Result<PlacedRail, PlacementError> {
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
        let scan = Scan::of(&rail.profile, rotation, eval);
        let (i_top, top) = rail.find_top(&scan);
        let floor = top[1] - layout.gauge_point_depth_mm;
        let gp = rail.find_gauge_point(&scan, floor)?;
        rail.frame.translation = Translation2::new(0.5 * layout.gauge_mm - gp[0], -top[1]);
        rail.gauge_point = rail.to_side(gp);
        rail.top = rail.to_side(top);
        rail.surface = scan.running_surface(i_top);
        // Freed before the tables are built, which reuse its memory.
        drop(scan);
        rail.y_range = (
            rail.point_of(rail.surface.0)[0],
            rail.point_of(rail.surface.1)[0],
        );
        rail.tabulate_inverse(eval);
        // The heights are read from the surface table, which is built first.
        rail.tabulate_surface(eval);
        rail.heights = HeightTable::new(&rail, HEIGHT_TABLE_STEP_MM);
        Ok(rail)
    }

    /// Top of the rail in the rotated profile frame: the maximum of Z(u), refined by
    /// bisection on dZ/du (concave near the top); with the index of the highest sample.
    fn find_top(&self, scan: &Scan) -> (usize, [f64; 2]) {
        let points = &scan.points;
        let i_top = (0..points.len())
            .max_by(|&a, &b| points[a][1].total_cmp(&points[b][1]))
            .unwrap_or(0);
        let u_top = refine_extremum(
            |u| self.rotated_tangent(u)[1],
            scan.u(i_top.saturating_sub(1)),
            scan.u((i_top + 1).min(points.len() - 1)),
        );
        (i_top, self.rotated(u_top))
    }

    /// Gauge point in the rotated profile frame: the most gauge-side (smallest Y) point with
    /// Z >= `floor` (the top less the gauge point depth).
    fn find_gauge_point(&self, scan: &Scan, floor: f64) -> Result<[f64; 2], PlacementError> {
        let points = &scan.points;
        let mut best: Option<(usize, f64)> = None;
        for (i, p) in points.iter().enumerate() {
            if p[1] >= floor && best.is_none_or(|(_, y)| p[0] < y) {
                best = Some((i, p[0]));
            }
        }
        let Some((i_gp, _)) = best else {
            return Err(PlacementError::NoGaugePoint {
                profile: self.profile.name().to_string(),
            });
        };
        let below = |i: usize| points[i][1] < floor;
        let u_gp = if i_gp > 0 && below(i_gp - 1) {
            // The depth line cuts the head between two samples: bisect Z(u) = floor.
            bisect(
                |u| self.rotated(u)[1] - floor,
                scan.u(i_gp - 1),
                scan.u(i_gp),
            )
        } else if i_gp + 1 < points.len() && below(i_gp + 1) {
            bisect(
                |u| self.rotated(u)[1] - floor,
                scan.u(i_gp + 1),
                scan.u(i_gp),
            )
        } else {
            refine_extremum(
                |u| self.rotated_tangent(u)[0],
                scan.u(i_gp.saturating_sub(1)),
                scan.u((i_gp + 1).min(points.len() - 1)),
            )
        };
        Ok(self.rotated(u_gp))
    }

    /// Whether `other` is this rail to the bit: the same profile data placed by the same
    /// frame onto the same running surface. Everything else of a placed rail (its tables)
    /// is computed from these, so the two answer every lookup alike.
    pub(crate) fn same_as(&self, other: &PlacedRail) -> bool {
        let bits = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits());
        let numbers = |r: &PlacedRail| {
            let (t, c) = (r.frame.translation.vector, r.frame.rotation);
            [
                t.x,
                t.y,
                c.re,
                c.im,
                r.surface.0,
                r.surface.1,
                r.y_range.0,
                r.y_range.1,
                r.gauge_point[0],
                r.gauge_point[1],
                r.top[0],
                r.top[1],
            ]
        };
        self.profile.same_data(&other.profile) && bits(&numbers(self), &numbers(other))
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
    pub(crate) fn heights(&self) -> &HeightTable {
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
        self.surface_from(u, self.profile.eval(u))
    }

    /// Along the increasing profile coordinates `us`: per `u` the side-frame `Y` of
    /// [`PlacedRail::point_of`] and [`PlacedRail::surface_at`], the same numbers from one
    /// walk along the profile, one evaluation a point instead of two looked up (the rail
    /// table of a report evaluates every point of the profile).
    pub fn surface_along(&self, us: &[f64]) -> Vec<(f64, RailPoint)> {
        let mut scan = self.profile.scan();
        us.iter()
            .map(|&u| {
                let value = scan.eval(u);
                let y = self.to_side(self.rotated_point(u, value[0]))[0];
                (y, self.surface_from(u, value))
            })
            .collect()
    }

    /// [`PlacedRail::surface_at`] from the profile's `[v, v', v'']` at `u`.
    #[inline]
    fn surface_from(&self, u: f64, [v, d1, d2]: [f64; 3]) -> RailPoint {
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
    /// From the quintic table of the surface where it holds (see `SURFACE_TABLE_STEP_MM`
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

    /// The start of the inversion at `y` (inside `y_range`): cubic Hermite interpolation of
    /// the table of exact inverses.
    #[inline]
    fn guess(&self, y: f64) -> f64 {
        let last = self.inverse.len() - 2;
        let t = (y - self.y_range.0) * self.inverse_scale;
        // `t >= 0` inside y_range, and the clamp keeps the last interval. Through i32 (the
        // table is short): one conversion each way, where a usize conversion adds saturation
        // and sign handling.
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
        self.invert_with(y, u, |u| self.profile.eval(u))
    }

    /// [`PlacedRail::invert`] evaluating the profile by `eval` (`Profile::eval` or the
    /// same bits from a scan, for the tables built at increasing `y`).
    #[inline]
    fn invert_with(&self, y: f64, u: f64, eval: impl FnMut(f64) -> [f64; 3]) -> (f64, RailPoint) {
        let (u, value, _) = self.newton(y, u, eval);
        (u, self.point_from(u, value))
    }

    /// Newton's method on `Y(u) = y` from `u`, the profile evaluated by `eval`: the root
    /// `u`, the profile's `[v, v', v'']` there, and whether those are `eval(u)` itself
    /// (`false`: from the Taylor expansion of `TAYLOR_FINISH_MM`).
    #[inline]
    fn newton(
        &self,
        y: f64,
        u: f64,
        mut eval: impl FnMut(f64) -> [f64; 3],
    ) -> (f64, [f64; 3], bool) {
        let target = y - self.frame.translation.x;
        let (cos, sin) = self.cos_sin();
        let (lo, hi) = self.surface;
        let mut u = u.clamp(lo, hi);
        let mut value = eval(u);
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
                return (next, value, false);
            }
            u = next.clamp(lo, hi);
            value = eval(u);
            if step.abs() < INVERSE_TOL_MM {
                break;
            }
        }
        (u, value, true)
    }

    /// The rail point of the profile coordinate `u` with the profile's `[v, v', v'']` there.
    #[inline]
    fn point_from(&self, u: f64, value: [f64; 3]) -> RailPoint {
        let (cos, sin) = self.cos_sin();
        let [v, d1, d2] = value;
        let ty = cos - sin * d1;
        let tz = sin + cos * d1;
        // For the rotated curve (Y(u), Z(u)): Z'' = (Y'Z'' - Z'Y'')/Y'^3 = v''/Y'^3.
        RailPoint {
            z: sin * u + cos * v + self.frame.translation.y,
            slope: tz / ty,
            d2: d2 / (ty * ty * ty),
        }
    }

    /// Fills the table of start guesses: exact inverses (from the linearised inverse, as
    /// many Newton steps as needed) every `INVERSE_TABLE_STEP_MM` or less.
    #[inline(never)] // called once: its cost stays visible in a profile
    fn tabulate_inverse(&mut self, eval: impl ScanEval) {
        let (y_lo, y_hi) = self.y_range;
        let n = ((y_hi - y_lo) / INVERSE_TABLE_STEP_MM).ceil().max(1.0) as usize;
        let h = (y_hi - y_lo) / n as f64;
        // Each entry starts from the tangent of the one before (from the linearised inverse
        // at the first).
        let (cos, sin) = self.cos_sin();
        let mut guess = (y_lo - self.frame.translation.x) / cos;
        // The entries increase in `y`, so in `u`: the profile by a scan.
        let mut scan = eval.scan(&self.profile);
        let mut eval = |u| scan.eval(u);
        self.inverse = (0..=n)
            .map(|i| {
                let y = if i == n { y_hi } else { y_lo + h * i as f64 };
                // The slope at the root: Newton's own evaluation there where it ended on
                // one (from the tangent of the entry before, most do), else evaluated.
                let (u, value, evaluated) = self.newton(y, guess, &mut eval);
                let d1 = if evaluated { value[1] } else { eval(u)[1] };
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
        self.rotated_point(u, self.profile.eval(u)[0])
    }

    /// The profile point `(u, v)`, rotated (not yet translated).
    #[inline]
    fn rotated_point(&self, u: f64, v: f64) -> [f64; 2] {
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
mod tests;
