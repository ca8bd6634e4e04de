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
#[path = "yaw_tests.rs"]
mod tests;
