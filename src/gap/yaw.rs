//! The yaw of the wheelset: the wheel as the rail sees it.
//!
//! A wheel is a surface of revolution about the axle and a rail a profile extruded along
//! the track (x). The vertical gap at a lateral position of the rail is therefore the
//! height of the wheel's *lower outline seen along x* above it: the lowest the wheel's
//! surface comes over that lateral position, at whatever x. Without yaw that outline is
//! the profile in the plane of the axle. A yawed wheel's outline is made of the points
//! where the surface's normal has no x component (the "contact locus" or trace line),
//! which lie ahead of or behind the axle; with that outline in place of the profile, the
//! searches of the unyawed wheelset apply unchanged.
//!
//! # The outline in closed form
//!
//! In the side frame (`Y` along the axle towards the field side, `Z` up, `x` forward) a
//! yaw `psi` about the wheelset's vertical axis turns the axle to `a = (-sin psi, cos psi,
//! 0)`. The circle of profile point `s` has its centre `Yw a` (`Yw` = taping line + `s`)
//! and radius `r = r0 + F(s)`; with `e1 = (cos psi, sin psi, 0)`, `e2 = (0, 0, -1)` its
//! points are `P = Yw a + r (cos alpha e1 + sin alpha e2)`, the surface normal there is
//! along `u - r' a` (`u` the radial unit vector, `r' = dr/dYw = F'(s)`), and its x
//! component vanishes where `cos alpha = -F' tan psi`. The point near the bottom, with
//! `q = F'(s)`, `t = tan psi` and `w = sqrt(1 - q^2 t^2)`:
//!
//! * lateral `Y = Yw cos psi - r q t sin psi`, height `Z = -r w` (relative to the axle);
//! * lead `-r q t` along the wheelset's own forward axis `e1` from the axle, so that its
//!   position along the track is `x = -Yw sin psi + lead cos psi`;
//! * slope of the outline `dZ/dY = -q / (cos psi w)` (the contact angle in the plane across
//!   the track), `dY/ds = D = cos psi - t sin psi (q^2 + r F'')` and
//!   `d2Z/dY2 = -F'' / (cos psi w^3 D)`.
//!
//! Only `F`, `F'` and `F''` enter: the outline, its slope and its curvature are exact to
//! rounding (no iteration, no series). They need `|q t| < 1` (the circle has such a point)
//! and `D > 0` (the outline does not fold back); [`MAX_SLOPE_TAN`] and [`MIN_DY_DS`] keep a
//! margin from both, which only the near-vertical flange back of a measured wheel can reach
//! (S1002's steepest slope, 10, reaches `q t = 0.3` at 30 mrad).
//!
//! Roll is a rotation about x, which leaves the direction the rail sees the wheel along
//! unchanged: the outline of the rolled, yawed wheel is the yawed outline rolled. So roll
//! and shift apply to outline points exactly as to profile points ([`super::SidePose`]),
//! with yaw taken about the wheelset's own vertical axis after roll (the roll-yaw-pitch
//! order of CONTACT's Euler angles).
//!
//! # The small-angle form
//!
//! [`YawModel::SmallAngle`] keeps the profile as the outline (`Y = Yw`, `Z = -r`) and takes
//! only the first-order lead `-r q psi`: what a linearised contact table assumes. Its error
//! grows with `psi^2` (the outline rises by `r q^2 t^2 / 2`: 0.75 mm on a flange of slope
//! 2.3 at 24 mrad); the README's yaw section gives it over 0 to 30 mrad.

use crate::profile::bounds::DerivativeBounds;
use crate::track::{MAX_RAIL_SLOPE, WheelCell, WheelPoint};

/// The largest `|F' tan psi|` for which a wheel point takes part (a circle whose slope is
/// steeper than `1 / tan psi` has no point the rail sees; 0.9 keeps `w >= 0.44`).
pub const MAX_SLOPE_TAN: f64 = 0.9;
/// The smallest `dY/ds` for which a wheel point takes part: where the outline turns back on
/// itself the rail sees only its lower sheet (never on a wheel's tread or flange).
pub const MIN_DY_DS: f64 = 0.1;

/// How the yaw moves the wheel's outline.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum YawModel {
    /// The outline of the yawed surface of revolution, in closed form (module docs).
    #[default]
    Exact,
    /// The profile as the outline and the first-order lead: the linearised form, kept to
    /// measure its error.
    SmallAngle,
}

impl YawModel {
    /// Name in scene files and tables.
    pub fn name(self) -> &'static str {
        match self {
            YawModel::Exact => "exact",
            YawModel::SmallAngle => "small_angle",
        }
    }

    /// The model of a scene-file name.
    pub fn from_name(name: &str) -> Option<YawModel> {
        match name {
            "exact" => Some(YawModel::Exact),
            "small_angle" => Some(YawModel::SmallAngle),
            _ => None,
        }
    }
}

/// The yaw of the wheelset as one side sees it, in its side frame: `psi = sign * yaw` of
/// the wheelset (the right side's frame is the left's mirror image, which turns a yaw about
/// z into its opposite), with its trigonometry.
///
/// # Frames and signs
///
/// The wheelset's yaw is a right-hand rotation about the track's z (up): positive yaw turns
/// the wheelset's forward axis to the left (+y), moving the left wheel back (-x) and the
/// right wheel forward.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Yaw {
    psi: f64,
    cos: f64,
    sin: f64,
    tan: f64,
    model: YawModel,
}

impl Yaw {
    /// No yaw.
    pub const NONE: Yaw = Yaw {
        psi: 0.0,
        cos: 1.0,
        sin: 0.0,
        tan: 0.0,
        model: YawModel::Exact,
    };

    /// The side's view of a wheelset yaw `yaw_rad` on the side with `sign` (+1 left, -1
    /// right).
    pub fn new(sign: f64, yaw_rad: f64, model: YawModel) -> Yaw {
        let psi = Yaw::side_psi(sign, yaw_rad);
        let (sin, cos) = psi.sin_cos();
        Yaw {
            psi,
            cos,
            sin,
            tan: sin / cos,
            model,
        }
    }

    /// The side's yaw (rad).
    pub fn psi(&self) -> f64 {
        self.psi
    }

    /// `sign * yaw_rad`, with no yaw always `+0` (a pose and the side's yaw compare by
    /// their bits).
    #[inline]
    pub(crate) fn side_psi(sign: f64, yaw_rad: f64) -> f64 {
        sign * yaw_rad + 0.0
    }

    /// The model.
    pub fn model(&self) -> YawModel {
        self.model
    }

    /// Whether the outline is the profile (no yaw, or the small-angle form).
    #[inline]
    pub fn keeps_profile(&self) -> bool {
        self.psi == 0.0 || self.model == YawModel::SmallAngle
    }

    /// The point of the outline on the circle of the wheel point `p` (the profile point at
    /// no yaw): `None` where that circle has no point the rail sees within the margins
    /// ([`MAX_SLOPE_TAN`], [`MIN_DY_DS`]). `p` itself where the outline is the profile.
    #[inline]
    pub fn outline(&self, p: WheelPoint) -> Option<WheelPoint> {
        if self.keeps_profile() {
            return Some(p);
        }
        // q = F', z = -r, d2 = -F''.
        let q = -p.slope;
        let qt = q * self.tan;
        let w2 = 1.0 - qt * qt;
        let ts = self.tan * self.sin;
        let dy_ds = self.cos - ts * (q * q + p.z * p.d2);
        if qt.abs() > MAX_SLOPE_TAN || dy_ds < MIN_DY_DS {
            return None;
        }
        let w = w2.sqrt();
        let cw = self.cos * w;
        let (y, z) = self.outline_yz(p.y, p.z, q);
        Some(WheelPoint {
            y,
            z,
            slope: p.slope / cw,
            d2: p.d2 / (cw * w2 * dy_ds),
            dy_ds,
        })
    }

    /// Lead of the point the rail sees on the circle of the profile point `p` (no yaw):
    /// its distance ahead of the axle along the wheelset's own forward axis (mm),
    /// `-r F' tan psi` (`-r F' psi` in the small-angle form).
    #[inline]
    pub fn lead(&self, p: &WheelPoint) -> f64 {
        let t = match self.model {
            YawModel::Exact => self.tan,
            YawModel::SmallAngle => self.psi,
        };
        // -r F' t with r = -z and F' = -slope.
        -(p.z * p.slope) * t
    }

    /// Longitudinal position along the track (x forward) of the point the rail sees on the
    /// circle of the profile point `p`, relative to the wheelset centre (mm).
    #[inline]
    pub fn x(&self, p: &WheelPoint) -> f64 {
        self.x_of(p.y, self.lead(p))
    }

    /// Longitudinal position along the track of a point `lead` ahead of the axle on the
    /// circle centred `yw` along the axle from the wheelset centre (mm): the rotation of
    /// `(lead, yw)` by the yaw (linear in both, so it holds for averages too).
    #[inline]
    pub fn x_of(&self, yw: f64, lead: f64) -> f64 {
        match self.model {
            YawModel::Exact => -yw * self.sin + lead * self.cos,
            YawModel::SmallAngle => -yw * self.psi + lead,
        }
    }

    /// The profile point (no yaw) whose circle holds the outline point `o`: the inverse of
    /// [`Yaw::outline`], to rounding (`w = 1 / sqrt(1 + (dZ/dY sin psi)^2)` from the
    /// outline's slope, then the closed forms solved for the profile's).
    #[inline]
    pub fn profile_point(&self, o: &WheelPoint) -> WheelPoint {
        if self.keeps_profile() {
            return *o;
        }
        let so = o.slope * self.sin;
        let w2 = 1.0 / (1.0 + so * so);
        let w = w2.sqrt();
        let slope = o.slope * self.cos * w;
        let z = o.z / w;
        let y = (o.y + self.tan * self.sin * z * slope) / self.cos;
        WheelPoint {
            y,
            z,
            slope,
            d2: o.d2 * self.cos * w * w2 * o.dy_ds,
            dy_ds: 1.0,
        }
    }

    /// Bounds of the outline over a cell of the profile, from the profile's bounds `c` there
    /// (no yaw) and the cell's length `h` (mm): `d` the ranges of the outline's `-dZ/dY` and
    /// `-d2Z/dY2` (as a profile's `F'` and `F''`), `z` its heights, `jump` what its joints
    /// add; `None` where a point of the cell may lie outside the margins.
    ///
    /// Interval arithmetic over the closed forms (module docs): `q / (cos w)` grows with `q`;
    /// the others are products and quotients of the ranges of `q^2`, `r`, `F''` and `w`. A
    /// jump of `F` or `F'` at a joint inside moves the outline vertically by at most `1 / w`
    /// of it and sideways by `t sin (r |jump F'| + |q| |jump F|)`; sideways motion raises
    /// a gap by at most the rail's steepest running slope ([`MAX_RAIL_SLOPE`]) times it.
    pub(crate) fn outline_cell(&self, c: WheelCell, h: f64) -> Option<WheelCell> {
        if self.keeps_profile() {
            return Some(c);
        }
        let k = Steepness::of(&c);
        if !self.admits(&k) {
            return None;
        }
        let t = self.tan.abs();
        let ts = self.tan * self.sin;
        let (q_lo, q_hi) = c.d.d1;
        let (f2_lo, f2_hi) = c.d.d2;
        let (w_lo, w_hi) = self.w_range(&k);
        let dy_ds = self.dy_ds_range(&k);
        let slope = |q: f64| q / (self.cos * (1.0 - (q * t).powi(2)).sqrt());
        let den = (
            self.cos * w_lo.powi(3) * dy_ds.0,
            self.cos * w_hi.powi(3) * dy_ds.1,
        );
        let quotient = |v: f64| [v / den.0, v / den.1];
        let [a, b] = quotient(f2_lo);
        let [e, f] = quotient(f2_hi);
        let d = DerivativeBounds {
            d1: (slope(q_lo), slope(q_hi)),
            d2: (a.min(b), e.max(f)),
        }
        .padded();
        let jump = if c.jump > 0.0 {
            let sideways = ts * (-c.z.0 / h.max(f64::MIN_POSITIVE) + k.q_abs.1) * c.jump;
            c.jump / w_lo + MAX_RAIL_SLOPE * sideways
        } else {
            0.0
        };
        Some(WheelCell {
            d,
            z: self.outline_z(&c, &k),
            jump,
        })
    }

    /// Whether the outline of every point of a cell of steepness `k` exists within the
    /// margins ([`MAX_SLOPE_TAN`], [`MIN_DY_DS`]): what [`Yaw::outline_cell`] decides.
    #[inline]
    pub(crate) fn admits(&self, k: &Steepness) -> bool {
        k.q_abs.1 * self.tan.abs() <= MAX_SLOPE_TAN
            && self.cos - self.tan * self.sin * k.sum.1 >= MIN_DY_DS
    }

    /// The range of the outline's heights over a cell with bounds `c` and steepness `k` (no
    /// yaw), which it [admits](Yaw::admits): `Z w`, `w = sqrt(1 - F'^2 tan^2 psi)` over the
    /// cell's range of `|F'|`, padded for rounding.
    #[inline]
    pub(crate) fn outline_z(&self, c: &WheelCell, k: &Steepness) -> (f64, f64) {
        let (w_lo, w_hi) = self.w_range(k);
        let pad = 1e-12 * -c.z.0;
        (c.z.0 * w_hi - pad, c.z.1 * w_lo + pad)
    }

    /// The range of the outline's `dY/ds` over a cell of steepness `k`.
    #[inline]
    pub(crate) fn dy_ds_range(&self, k: &Steepness) -> (f64, f64) {
        let ts = self.tan * self.sin;
        (self.cos - ts * k.sum.1, self.cos - ts * k.sum.0)
    }

    /// The range of `w` over a cell of steepness `k`.
    #[inline]
    fn w_range(&self, k: &Steepness) -> (f64, f64) {
        let t = self.tan.abs();
        (
            (1.0 - (k.q_abs.1 * t).powi(2)).sqrt(),
            (1.0 - (k.q_abs.0 * t).powi(2)).sqrt(),
        )
    }

    /// The outline's lateral position and height of profile points `(yw, z, q = F')`, as
    /// [`Yaw::outline`] computes them, operation for operation (in SIMD lanes or not).
    #[inline(always)]
    pub(crate) fn outline_yz<T: Lane>(&self, yw: T, z: T, q: T) -> (T, T) {
        let qt = q * T::from(self.tan);
        let w = (T::from(1.0) - qt * qt).sqrt();
        let ts = T::from(self.tan * self.sin);
        (yw * T::from(self.cos) + ts * z * q, z * w)
    }
}

/// What decides a cell's outline and bounds its slope terms, from the cell's bounds (no
/// yaw): the range of `|F'|` and of `F'^2 + r F''` (`r = -Z`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Steepness {
    q_abs: (f64, f64),
    sum: (f64, f64),
}

impl Steepness {
    /// The largest `|F'|`.
    pub(crate) fn q_abs_max(&self) -> f64 {
        self.q_abs.1
    }

    /// The steepness of a cell with bounds `c`.
    pub(crate) fn of(c: &WheelCell) -> Steepness {
        let (q_lo, q_hi) = c.d.d1;
        let q_abs_max = q_lo.abs().max(q_hi.abs());
        let q_abs_min = if q_lo <= 0.0 && q_hi >= 0.0 {
            0.0
        } else {
            q_lo.abs().min(q_hi.abs())
        };
        let r_f2 = product((-c.z.1, -c.z.0), c.d.d2);
        Steepness {
            q_abs: (q_abs_min, q_abs_max),
            sum: (
                q_abs_min * q_abs_min + r_f2.0,
                q_abs_max * q_abs_max + r_f2.1,
            ),
        }
    }
}

/// A number or SIMD lanes of numbers, for the outline's closed forms.
pub(crate) trait Lane:
    Copy
    + From<f64>
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
{
    /// The square root (correctly rounded, lane by lane).
    fn sqrt(self) -> Self;
}

impl Lane for f64 {
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
}

impl Lane for wide::f64x4 {
    #[inline(always)]
    fn sqrt(self) -> wide::f64x4 {
        wide::f64x4::sqrt(self)
    }
}

/// The range of `a b` for `a`, `b` in their ranges.
fn product(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let p = [a.0 * b.0, a.0 * b.1, a.1 * b.0, a.1 * b.1];
    (
        p.iter().copied().fold(f64::INFINITY, f64::min),
        p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::Profile;
    use crate::track::{Inclination, PlacedWheel, TrackLayout};

    fn s1002() -> PlacedWheel {
        let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
        PlacedWheel::place(Profile::s1002(), 460.0, &layout).unwrap()
    }

    /// The lowest point of the yawed wheel's surface over the lateral position `y` (side
    /// frame, relative to the axle), by brute force over the surface: for each angle of a
    /// fine grid about the bottom, the circle through `y` found by bisection on the profile
    /// coordinate, then the lowest of those refined by golden section in the angle. Its
    /// height, the profile coordinate and the x of the point.
    fn brute_lowest(wheel: &PlacedWheel, psi: f64, y: f64) -> (f64, f64, f64) {
        let (sn, cs) = psi.sin_cos();
        let (lo, hi) = wheel.profile().domain();
        // Point of the circle at s and angle beta from the bottom (beta > 0 towards -e1).
        let point = |s: f64, beta: f64| {
            let p = wheel.at(s);
            let r = -p.z;
            // P = Yw a + r (-sin beta e1 + cos beta e2).
            let px = -p.y * sn - r * beta.sin() * cs;
            let py = p.y * cs - r * beta.sin() * sn;
            let pz = -r * beta.cos();
            [px, py, pz]
        };
        // At a fixed angle, P_y grows with s (nearly dP_y/ds = cos psi): bisection.
        let at_angle = |beta: f64| -> Option<(f64, f64, f64)> {
            let (mut a, mut b) = (lo, hi);
            if point(a, beta)[1] > y || point(b, beta)[1] < y {
                return None;
            }
            for _ in 0..200 {
                let m = 0.5 * (a + b);
                if point(m, beta)[1] < y {
                    a = m;
                } else {
                    b = m;
                }
            }
            let s = 0.5 * (a + b);
            let p = point(s, beta);
            Some((p[2], s, p[0]))
        };
        let height = |beta: f64| at_angle(beta).map_or(f64::INFINITY, |v| v.0);
        let grid: Vec<f64> = (-400..=400).map(|k| 0.5 * f64::from(k) / 400.0).collect();
        let best = grid
            .iter()
            .copied()
            .min_by(|a, b| height(*a).total_cmp(&height(*b)))
            .unwrap();
        let (mut a, mut b) = (best - 0.5 / 400.0, best + 0.5 / 400.0);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..100 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if height(c) < height(d) {
                b = d;
            } else {
                a = c;
            }
        }
        // The height is flat in the angle to its rounding (1e-11 mm over 2e-7 rad): the
        // vertex of the parabola through three heights 1e-5 rad apart places the angle to
        // about 1e-9 rad.
        let (b0, h) = (0.5 * (a + b), 1e-5);
        let (zm, z0, zp) = (height(b0 - h), height(b0), height(b0 + h));
        let vertex = b0 + 0.5 * h * (zm - zp) / (zm - 2.0 * z0 + zp);
        at_angle(vertex).unwrap()
    }

    /// The closed-form outline is the lowest point of the yawed surface over its lateral
    /// position, found by brute force over the surface (module docs): height to 1e-9 mm,
    /// profile coordinate and x to 1e-5 mm (the brute force finds the angle of a minimum
    /// flat in it to about 1e-9 rad, r times that in x); on the
    /// S1002 tread, flange root and flange, at yaws up to 50 mrad either way.
    #[test]
    fn the_outline_is_the_lowest_point_of_the_surface() {
        let wheel = s1002();
        for psi in [-0.05, -0.024, 0.005, 0.03] {
            let yaw = Yaw::new(1.0, psi, YawModel::Exact);
            for s in [-33.0, -28.0, -20.0, -10.0, 0.0, 12.0, 30.0] {
                let p = yaw.outline(wheel.at(s)).unwrap();
                let (z, s_brute, x_brute) = brute_lowest(&wheel, psi, p.y);
                assert!((z - p.z).abs() < 1e-9, "psi {psi} s {s}: {} vs {z}", p.z);
                assert!((s - s_brute).abs() < 1e-5, "psi {psi} s {s}: {s_brute}");
                let x = yaw.x(&wheel.at(s));
                assert!(
                    (x - x_brute).abs() < 1e-5,
                    "psi {psi} s {s}: x {x} vs {x_brute}"
                );
            }
        }
    }

    /// The outline's slope, `dY/ds` and second derivative are its derivatives: central
    /// differences of the outline's own points agree to their truncation (1e-7 relative).
    #[test]
    fn the_outline_derivatives_are_its_differences() {
        let wheel = s1002();
        let yaw = Yaw::new(-1.0, 0.03, YawModel::Exact);
        let h = 1e-4;
        for k in 0..60 {
            let s = -34.0 + 1.1 * f64::from(k);
            let at = |s: f64| yaw.outline(wheel.at(s)).unwrap();
            let (m, p, c) = (at(s - h), at(s + h), at(s));
            let dy = (p.y - m.y) / (2.0 * h);
            let slope = (p.z - m.z) / (p.y - m.y);
            assert!(
                (dy - c.dy_ds).abs() < 1e-7,
                "s {s}: dy/ds {dy} vs {}",
                c.dy_ds
            );
            assert!(
                (slope - c.slope).abs() < 1e-7 * c.slope.abs().max(1.0),
                "s {s}: slope {slope} vs {}",
                c.slope
            );
            let d2 = (p.slope - m.slope) / (p.y - m.y);
            assert!(
                (d2 - c.d2).abs() < 1e-5 * c.d2.abs().max(1e-3),
                "s {s}: d2 {d2} vs {}",
                c.d2
            );
        }
    }

    /// The profile point recovered from its outline point is the profile point, to rounding
    /// (1e-12 relative), on S1002 at yaws up to 50 mrad.
    #[test]
    fn the_profile_point_of_an_outline_point_is_the_profile_point() {
        let wheel = s1002();
        for psi in [-0.05, 0.01, 0.03] {
            let yaw = Yaw::new(1.0, psi, YawModel::Exact);
            for k in 0..100 {
                let p = wheel.at(-60.0 + 1.1 * f64::from(k));
                let Some(o) = yaw.outline(p) else { continue };
                let back = yaw.profile_point(&o);
                for (a, b) in [
                    (back.y, p.y),
                    (back.z, p.z),
                    (back.slope, p.slope),
                    (back.d2, p.d2),
                ] {
                    assert!(
                        (a - b).abs() <= 1e-12 * b.abs().max(1.0),
                        "psi {psi}: {back:?} vs {p:?}"
                    );
                }
            }
        }
    }

    /// Without yaw, and in the small-angle form, the outline is the profile point itself.
    #[test]
    fn no_yaw_keeps_the_profile() {
        let wheel = s1002();
        for yaw in [Yaw::NONE, Yaw::new(1.0, 0.02, YawModel::SmallAngle)] {
            let p = wheel.at(-12.0);
            assert_eq!(yaw.outline(p), Some(p));
        }
        assert_eq!(Yaw::NONE.lead(&wheel.at(-30.0)).abs().to_bits(), 0);
    }

    /// The lead is `r tan(gamma) tan(psi)` (gamma the unyawed contact angle, the tangent
    /// of the profile's slope), and the outline's contact angle `tan(gamma) / (cos psi w)`:
    /// on the flange (tan gamma 2.3 near s = -30) at 24 mrad 1.0018 times the profile's.
    #[test]
    fn lead_and_angle_on_the_flange() {
        let wheel = s1002();
        let p = wheel.at(-30.0);
        let yaw = Yaw::new(1.0, 0.024, YawModel::Exact);
        let r = -p.z;
        assert!((yaw.lead(&p) - r * p.slope * 0.024f64.tan()).abs() < 1e-12);
        let o = yaw.outline(p).unwrap();
        let w = (1.0 - (p.slope * 0.024f64.tan()).powi(2)).sqrt();
        assert!((o.slope - p.slope / (0.024f64.cos() * w)).abs() < 1e-15);
    }

    /// The cell bounds hold every outline point of dense samples of the cell, on S1002 cells
    /// of 0.25 mm and 2 mm at yaws up to 40 mrad.
    #[test]
    fn outline_cells_hold_their_points() {
        let wheel = s1002();
        let (lo, hi) = wheel.profile().domain();
        let joints = wheel.profile().joints();
        for psi in [-0.04, 0.01, 0.03] {
            let yaw = Yaw::new(1.0, psi, YawModel::Exact);
            for h in [0.25, 2.0] {
                let mut a = lo;
                while a + h <= hi {
                    let b = a + h;
                    let Some(c) = yaw.outline_cell(wheel.cell(a, b, &joints), h) else {
                        a += 0.7 * h;
                        continue;
                    };
                    for k in 0..=100 {
                        let s = a + h * f64::from(k) / 100.0;
                        let Some(p) = yaw.outline(wheel.at(s)) else {
                            continue;
                        };
                        assert!(
                            c.z.0 <= p.z && p.z <= c.z.1,
                            "psi {psi} [{a}, {b}] z {}",
                            p.z
                        );
                        assert!(
                            c.d.d1.0 <= -p.slope && -p.slope <= c.d.d1.1,
                            "psi {psi} [{a}, {b}] slope {}: {:?}",
                            -p.slope,
                            c.d.d1
                        );
                        assert!(
                            c.d.d2.0 <= -p.d2 && -p.d2 <= c.d.d2.1,
                            "psi {psi} [{a}, {b}] d2 {}: {:?}",
                            -p.d2,
                            c.d.d2
                        );
                    }
                    a += 0.7 * h;
                }
            }
        }
    }

    /// The radius of the arc wheel's profile, mm.
    const ARC_RADIUS_MM: f64 = 100.0;
    /// The nominal radius of the arc wheel, mm.
    const ARC_NOMINAL_RADIUS_MM: f64 = 460.0;
    /// The slope of the plane rail's head (falling 1:10 towards the field side).
    const PLANE_SLOPE: f64 = -0.1;

    /// A wheel whose profile is a circular arc of [`ARC_RADIUS_MM`] about the taping line (a
    /// torus) on a rail whose head is a plane of slope [`PLANE_SLOPE`], both as point
    /// profiles (the arc sampled every 0.1 mm), on a track without inclination.
    fn arc_wheel_on_a_plane() -> crate::track::SidePair {
        use crate::profile::ProfileKind;
        use crate::profile::read::PointProfile;
        use crate::track::{PlacedRail, SidePair};
        let radius = ARC_RADIUS_MM;
        let arc: Vec<[f64; 2]> = (-400..=400)
            .map(|k| {
                let s = 0.1 * f64::from(k);
                [s, (radius * radius - s * s).sqrt() - radius]
            })
            .collect();
        let plane: Vec<[f64; 2]> = (0..=600)
            .map(|k| [0.1 * f64::from(k), -0.01 * f64::from(k)])
            .collect();
        let wheel = PointProfile::from_points(ProfileKind::Wheel, "arc R100", arc).unwrap();
        let rail = PointProfile::from_points(ProfileKind::Rail, "plane 1:10", plane).unwrap();
        let layout = TrackLayout::standard(Inclination::VERTICAL);
        SidePair::new(
            PlacedWheel::place(
                Profile::from_points(wheel, 0.0).unwrap(),
                ARC_NOMINAL_RADIUS_MM,
                &layout,
            )
            .unwrap(),
            PlacedRail::place(
                Profile::from_points(rail, 0.0).unwrap(),
                Inclination::VERTICAL,
                &layout,
            )
            .unwrap(),
        )
    }

    /// The closed-form contact of [`arc_wheel_on_a_plane`] at roll `phi` (track frame) and
    /// yaw `psi`: the profile coordinate `s`, the rolling radius `r` there and the lead.
    /// The rail's normal is fixed, so the point of contact follows from the tangent plane
    /// alone: the rolled outline's slope `atan(m) + phi` equals the plane's,
    /// `m = -q / (cos psi w)` gives the profile slope
    /// `q = -M cos psi / sqrt(1 + M^2 sin^2 psi)` (`M = tan(atan(Z') - phi)`), and the arc
    /// the point `s = -q R / sqrt(1 + q^2)`, its radius, and the lead `-r q tan psi`.
    fn arc_on_plane_contact(phi: f64, psi: f64) -> (f64, f64, f64) {
        let radius = ARC_RADIUS_MM;
        let m = (PLANE_SLOPE.atan() - phi).tan();
        let (sn, cs) = psi.sin_cos();
        let q = -m * cs / (1.0 + m * m * sn * sn).sqrt();
        let s = -q * radius / (1.0 + q * q).sqrt();
        let r = ARC_NOMINAL_RADIUS_MM + (radius * radius - s * s).sqrt() - radius;
        (s, r, -r * q * psi.tan())
    }

    /// The arc wheel on the plane rail ([`arc_wheel_on_a_plane`]): the gap's minimum lands
    /// on the closed-form contact ([`arc_on_plane_contact`]) to the arc's sampling (1e-9 mm
    /// in `s`), with its lead (close to `r tan(delta) psi`), at shifts, rolls and yaws up to
    /// 30 mrad either way.
    #[test]
    fn an_arc_wheel_on_a_plane_touches_where_the_tangent_planes_agree() {
        use crate::gap::{PoseBox, Scanned, SideGap, SidePose};
        let pair = arc_wheel_on_a_plane();
        let mut checked = 0;
        for sign in [1.0, -1.0] {
            for psi in [0.01, 0.03, -0.02] {
                let mut side = SideGap::new(&pair, sign);
                let yaw = Yaw::new(sign, psi, YawModel::Exact);
                side.set_yaw(yaw);
                for y_ws in [-4.0, 0.0, 3.0] {
                    for roll in [0.0, 2e-3, -1e-3] {
                        let pose = SidePose::yawed(sign, y_ws, roll, psi);
                        let mut basins = Vec::new();
                        side.basins(
                            &pose,
                            &mut PoseBox::default(),
                            &mut Scanned::default(),
                            &mut basins,
                        );
                        let p = basins
                            .iter()
                            .filter_map(|&b| side.minimum(b, None, &pose))
                            .min_by(|a, b| a.g.total_cmp(&b.g))
                            .unwrap();
                        let phi = sign * roll;
                        let (s_exact, r, lead) = arc_on_plane_contact(phi, yaw.psi());
                        let at = format!("sign {sign} psi {psi} y {y_ws} roll {roll}");
                        assert!((p.s - s_exact).abs() < 1e-9, "{at}: s {} vs {s_exact}", p.s);
                        let base = side.wheel().at(p.s);
                        assert!(
                            (yaw.lead(&base) - lead).abs() < 1e-9,
                            "{at}: lead {} vs {lead}",
                            yaw.lead(&base)
                        );
                        // The contact angle in the track frame is the plane's.
                        assert!(
                            (p.wheel.slope.atan() + phi - PLANE_SLOPE.atan()).abs() < 1e-10,
                            "{at}"
                        );
                        // Within a few per mille of the small-angle estimate r tan(delta) psi.
                        let estimate = r * (PLANE_SLOPE.atan() - phi).tan().abs() * yaw.psi();
                        assert!(
                            (lead.abs() - estimate.abs()).abs() <= 2e-3 * estimate.abs(),
                            "{at}"
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 54);
    }
}
