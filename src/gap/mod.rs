//! The vertical gap between one wheel and its rail for a wheelset pose, its minima, and the
//! derivative of the minimum gap with respect to the roll (envelope theorem).
//!
//! Per side the pose is seen in the side frame as a shift `delta = sign * y_ws` and a roll
//! `phi = sign * roll`. A wheel point `(Yw, Zw)` relative to the axle maps to
//! `Y = delta + cos(phi) Yw - sin(phi) Zw`, `z = h + sin(phi) Yw + cos(phi) Zw` (rotation about
//! the axle, paper Sect. 3; the lateral motion caused by roll is kept). The gap is
//! `d(s) = z(s) - Zrail(Y(s))`; without the axle height `h` it is `g(s) = d(s) - h`.
//!
//! The layer both contact searches ([`crate::rigid`], [`crate::quasi_elastic`]) stand on:
//! the pose and the gap at a wheel point (here), the coarse scans for basins (`scan.rs`) and
//! low regions (`low.rs`) with their block bounds over boxes of poses (`pose_box.rs`),
//! exact minima in a basin (`minimum.rs`), the paper's tabulated profiles (`tabulated.rs`),
//! the wheel a yaw shows the rail (`yaw.rs`, `outline.rs`); and the [`ContactPoint`] both
//! searches report (`contact.rs`). The rigid search's minimum is certified global at the
//! solution (`certify.rs`, on the bounds of `bound.rs`): no point of the gap lies lower by
//! more than a stated tolerance.
//!
//! Public here: the pose of a side ([`SidePose`]), the gap at one wheel point
//! ([`SideGap::new`], [`SideGap::at`], giving a [`GapPoint`]), for checks of a search from
//! outside (the reference tests' brute-force minima), and the [`ContactPoint`] the searches
//! report. The scans, minima, tolerances and the certificate are the searches' own.
//!
//! # Units and frames
//!
//! Millimetres and radians, in the side frame of the crate docs (`sign` +1 for the left
//! side, -1 for the right).

mod bound;
mod certify;
mod contact;
mod hollow;
mod low;
mod minimum;
mod outline;
mod pose_box;
mod scan;
mod tabulated;
#[cfg(test)]
pub(crate) mod tests;
pub(crate) mod yaw;

use crate::track::{PlacedRail, PlacedWheel, RailPoint, SidePair, WheelPoint};
use scan::SCAN_BLOCK;
use tabulated::Tables;

pub use contact::ContactPoint;
pub(crate) use pose_box::PoseBox;
pub(crate) use scan::Scanned;
pub(crate) use yaw::{Yaw, YawModel};

/// Step of the coarse scan of the wheel that finds the basins of the gap (mm). Refinement
/// then finds each minimum exactly; see [`COARSE_MARGIN_MM`].
pub(crate) const COARSE_STEP_MM: f64 = 0.25;
/// Coarse minima within this margin of the lowest coarse minimum are all refined. It bounds
/// the error of the coarse values (kappa h^2 / 2 = 0.006 mm for a relative curvature of
/// 1/5 mm^-1 at 0.25 mm) with a safety factor of 8.
pub(crate) const COARSE_MARGIN_MM: f64 = 0.05;
/// Two minima closer than this in the wheel coordinate are one basin (mm).
pub(crate) const SAME_BASIN_MM: f64 = 0.5;

/// The pose of one side: shift and roll as seen in the side frame.
///
/// Plain numbers rather than a `nalgebra::Isometry2` (used for the rail's frame in
/// `track::rail`): the gap is evaluated millions of times per sweep and only needs the
/// lateral position and height of a wheel point, `delta + cos s - sin z` and its height,
/// with the axle height solved separately; a general 2-D transform would carry what this
/// loop does not use.
///
/// The yaw is not applied here: it changes which points of the wheel the rail sees (its
/// outline), which the side's [`SideGap`] holds for one yaw at a time (no yaw unless the
/// searches set one); `yaw` names that yaw, so that a pose of another yaw is never mistaken
/// for this one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SidePose {
    /// `sign * y_ws` (mm).
    pub delta: f64,
    /// `cos(sign * roll)`.
    pub cos: f64,
    /// `sin(sign * roll)`.
    pub sin: f64,
    /// `sign * yaw` (rad): the side's yaw.
    pub yaw: f64,
}

impl SidePose {
    /// The pose of the side with `sign` (+1 left, -1 right) for a wheelset shift and roll,
    /// without yaw.
    pub fn new(sign: f64, y_ws: f64, roll: f64) -> SidePose {
        let (sin, cos) = (sign * roll).sin_cos();
        SidePose {
            delta: sign * y_ws,
            cos,
            sin,
            yaw: 0.0,
        }
    }

    /// The pose of the side with `sign` for a wheelset shift, roll and yaw (rad).
    pub fn yawed(sign: f64, y_ws: f64, roll: f64, yaw_rad: f64) -> SidePose {
        SidePose {
            yaw: Yaw::side_psi(sign, yaw_rad),
            ..SidePose::new(sign, y_ws, roll)
        }
    }

    /// Side-frame lateral position and height above the axle of a wheel point.
    #[inline]
    pub fn apply(&self, yw: f64, zw: f64) -> [f64; 2] {
        self.apply_to(yw, zw)
    }

    /// [`SidePose::apply`] for SIMD lanes of `f64` (or `f64`, which `apply` is): the same
    /// operations in the same order, so each lane rounds exactly as the scalar form (no
    /// fused multiply-add).
    #[inline(always)]
    pub(crate) fn apply_to<T>(&self, yw: T, zw: T) -> [T; 2]
    where
        T: Copy
            + From<f64>
            + std::ops::Add<Output = T>
            + std::ops::Sub<Output = T>
            + std::ops::Mul<Output = T>,
    {
        let (cos, sin) = (T::from(self.cos), T::from(self.sin));
        [
            T::from(self.delta) + cos * yw - sin * zw,
            sin * yw + cos * zw,
        ]
    }
}

/// The gap at one wheel point, with everything the contact quantities need.
///
/// Its derivatives are taken along the wheel point's lateral coordinate `Yw` (relative to
/// the wheelset centre, before roll): `Yw = s +` taping line without yaw, the outline's
/// lateral coordinate with yaw (`wheel.dy_ds` per mm of `s`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GapPoint {
    /// Wheel profile coordinate (mm).
    pub s: f64,
    /// `g(s) = z - h - Zrail`: the gap without the axle height (mm).
    pub g: f64,
    /// `dg/dYw` (`dg/ds` without yaw).
    pub dg: f64,
    /// `d2g/dYw2` (1/mm).
    pub ddg: f64,
    /// Side-frame lateral position of the wheel point (mm).
    pub y: f64,
    /// Height of the wheel point above the axle (mm, negative).
    pub z_rel: f64,
    /// The wheel point (no roll): the outline's point on the circle of `s` with yaw.
    pub wheel: WheelPoint,
    /// The rail under it.
    pub rail: RailPoint,
}

impl GapPoint {
    /// Derivative of the gap at this point with respect to the side roll `phi`, the point
    /// held fixed: `(Y - delta) + Zrail'(Y) * z_rel`. At a unique minimiser it is the
    /// derivative of the minimum gap (envelope theorem).
    #[inline]
    pub fn dg_dphi(&self, pose: &SidePose) -> f64 {
        (self.y - pose.delta) + self.rail.slope * self.z_rel
    }
}

/// One side's geometry prepared for repeated gap evaluations: the placed pair and the coarse
/// wheel samples (the coarse scans read the rail's
/// `HeightTable`). Built once per sweep.
#[derive(Debug, Clone)]
pub struct SideGap<'a> {
    /// The wheel and rail of the side.
    pub pair: &'a SidePair,
    /// The rail of `pair`, behind its `Arc` once here rather than at every evaluation.
    rail: &'a PlacedRail,
    /// +1 left, -1 right.
    pub sign: f64,
    coarse: Vec<[f64; 3]>,
    /// Per block of [`SCAN_BLOCK`] coarse samples: `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]`.
    blocks: Vec<[f64; 4]>,
    /// Per block of [`SCAN_BLOCK`] coarse cells (from its first sample up to the next
    /// block's first): the same ranges over the whole wheel between, from the
    /// [`PlacedWheel::cells`] bounds, so that a bound from them holds for every point of the
    /// wheel there (the scan for basins and the certificate read them).
    cert_blocks: Vec<[f64; 4]>,
    /// The extents of `blocks` over the groups of the low-region scan (`low.rs`).
    group_extents: Vec<[f64; 4]>,
    tabulated: Option<Tables>,
    /// Where the wheel takes part: the profile's domain (beyond it the profile is clamped,
    /// and a point there would be a phantom of the wheel's end displaced sideways), with
    /// yaw the part of it whose outline the rail sees (`outline.rs`).
    domain: (f64, f64),
    /// The yaw whose outline `coarse`, `blocks`, `cert_blocks`, `group_extents`, the
    /// tables and `domain` hold ([`SideGap::set_yaw`]).
    yaw: Yaw,
    /// What the outline of a yaw is made from (`outline.rs`), made on the first yaw.
    outline_base: std::sync::Arc<std::sync::OnceLock<outline::OutlineBase>>,
    /// With a yaw that moves the outline: per block, the widest lateral extent of one of
    /// its coarse cells (mm), and the largest step of the outline at a section joint,
    /// vertical plus the rail's steepest slope times sideways (mm).
    outline_widths: Vec<f64>,
    outline_jump: f64,
    /// With a yaw that moves the outline: the first and last coarse sample that take part.
    outline_samples: (usize, usize),
    /// Whether the side's yaw changes from pose to pose (a sweep whose yaw grows with the
    /// shift): its boxes of poses then span yaws ([`SideGap::set_yaw_varies`]).
    yaw_varies: bool,
    /// Section joints of the wheel profile (where its value may jump).
    joints: Vec<f64>,
    /// Side-frame lateral positions of the rail profile's breaks
    /// ([`crate::profile::Profile::breaks`]) and of the ends of its running surface, increasing.
    rail_break_ys: Vec<f64>,
    /// The wheel profile's breaks and the ends of its domain, increasing.
    wheel_breaks: Vec<f64>,
}

/// `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]` of the coarse samples of each block of [`SCAN_BLOCK`].
fn sample_blocks(coarse: &[[f64; 3]], out: &mut Vec<[f64; 4]>) {
    out.clear();
    out.extend(coarse.chunks(SCAN_BLOCK).map(|c| {
        // Plain compares: heights are finite or +inf, never NaN (as f64::min and max).
        let (mut z_lo, mut z_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in c {
            if p[2] < z_lo {
                z_lo = p[2];
            }
            if p[2] > z_hi {
                z_hi = p[2];
            }
        }
        [c[0][1], c[c.len() - 1][1], z_lo, z_hi]
    }));
}

/// `values` and `extra` sorted increasing, as `sort_by(f64::total_cmp)` sorts them (numbers
/// equal under `total_cmp` have the same bits, so there is one such order). A profile's
/// breaks come in order (the rail's may come decreasing in the side frame): those are
/// checked, turned where they decrease and `extra` inserted, instead of a merge sort of the
/// whole (a sampled profile's spline has a break at each of its knots); any other order is
/// sorted.
fn sorted_with(mut values: Vec<f64>, extra: [f64; 2]) -> Vec<f64> {
    // A plain `<` between neighbours first (breaks differ): numbers in increasing order
    // are in `total_cmp`'s order too; the slower `total_cmp` decides only where that fails.
    let le = |a: &f64, b: &f64| a.total_cmp(b).is_le();
    let increasing = |v: &[f64]| v.windows(2).all(|w| w[0] < w[1]) || v.is_sorted_by(le);
    if !increasing(&values) && values.windows(2).all(|w| w[0] > w[1]) {
        values.reverse();
    }
    if !increasing(&values) {
        values.extend(extra);
        values.sort_by(f64::total_cmp);
        return values;
    }
    for x in extra {
        let at = values.partition_point(|v| v.total_cmp(&x).is_lt());
        values.insert(at, x);
    }
    values
}

/// A bracket `[lo, hi]` in `s` around a coarse minimum, to be refined.
pub(crate) type Basin = (f64, f64);
impl<'a> SideGap<'a> {
    /// Both sides of a placement, left (+1) then right (-1): the order of every per-side
    /// array of the searches.
    ///
    /// A [mirror-symmetric](crate::track::Placement::is_mirror_symmetric) placement's right
    /// side has the left side's wheel and rail to the bit: its coarse samples, breaks and
    /// block bounds, which are made from those alone, are the left side's, copied rather
    /// than made again.
    pub fn both(placement: &'a crate::track::Placement) -> [SideGap<'a>; 2] {
        let left = SideGap::new(&placement.left, 1.0);
        let right = if placement.is_mirror_symmetric() {
            SideGap {
                pair: &placement.right,
                rail: placement.right.rail(),
                sign: -1.0,
                outline_base: Default::default(),
                ..left.clone()
            }
        } else {
            SideGap::new(&placement.right, -1.0)
        };
        [left, right]
    }

    /// Prepares the side with `sign` (+1 left, -1 right).
    pub fn new(pair: &'a SidePair, sign: f64) -> SideGap<'a> {
        let (lo, hi) = pair.wheel.profile().domain();
        let n = ((hi - lo) / COARSE_STEP_MM).ceil() as usize;
        let coarse: Vec<[f64; 3]> = (0..=n)
            .map(|i| {
                let s = lo + (hi - lo) * i as f64 / n as f64;
                let p = pair.wheel.at(s);
                [s, p.y, p.z]
            })
            .collect();
        let mut blocks = Vec::new();
        sample_blocks(&coarse, &mut blocks);
        let mut side = SideGap {
            pair,
            rail: pair.rail(),
            sign,
            coarse,
            blocks,
            cert_blocks: Vec::new(),
            group_extents: Vec::new(),
            tabulated: None,
            domain: (lo, hi),
            yaw: Yaw::NONE,
            outline_base: Default::default(),
            outline_widths: Vec::new(),
            outline_jump: 0.0,
            outline_samples: (0, n),
            yaw_varies: false,
            joints: pair.wheel.profile().joints(),
            rail_break_ys: {
                // The ends of the running surface too: beyond them the gap is undefined.
                let (y_lo, y_hi) = pair.rail.y_range();
                let ys: Vec<f64> = pair
                    .rail
                    .profile()
                    .breaks()
                    .into_iter()
                    .map(|u| pair.rail.point_of(u)[0])
                    .collect();
                sorted_with(ys, [y_lo, y_hi])
            },
            wheel_breaks: sorted_with(pair.wheel.profile().breaks(), [lo, hi]),
        };
        let (mut cert_blocks, mut group_extents) = (Vec::new(), Vec::new());
        side.certified_blocks(&mut cert_blocks);
        side.group_extents(&mut group_extents);
        (side.cert_blocks, side.group_extents) = (cert_blocks, group_extents);
        side
    }
    /// Where the wheel profile's second derivative may jump (joints, spline knots) and the
    /// ends of its domain, increasing (mm).
    pub(crate) fn wheel_breaks(&self) -> &[f64] {
        &self.wheel_breaks
    }

    /// Side-frame lateral positions `Y` of the rail profile's breaks (joints, spline knots)
    /// and of the ends of its running surface, increasing (mm).
    pub(crate) fn rail_break_ys(&self) -> &[f64] {
        &self.rail_break_ys
    }

    /// The wheel.
    pub fn wheel(&self) -> &PlacedWheel {
        &self.pair.wheel
    }

    /// Whether `s` lies inside the wheel profile's domain (where [`SideGap::at`] is defined).
    #[inline]
    pub(crate) fn in_domain(&self, s: f64) -> bool {
        (self.domain.0..=self.domain.1).contains(&s)
    }

    /// The gap at `s` for `pose`, or `None` where the wheel point is not above the rail or
    /// `s` lies outside the wheel profile.
    #[inline]
    pub fn at(&self, s: f64, pose: &SidePose) -> Option<GapPoint> {
        if !self.in_domain(s) {
            return None;
        }
        self.at_wheel_point(s, self.pair.wheel.at(s), pose)
    }

    /// [`SideGap::at`] where the caller knows whether the side is [`yawed`](SideGap::yawed)
    /// (`YAWED`), for loops that decide it once: without yaw the profile's point itself, no
    /// outline and no test.
    #[inline(always)]
    pub(crate) fn at_as<const YAWED: bool>(&self, s: f64, pose: &SidePose) -> Option<GapPoint> {
        debug_assert_eq!(YAWED, self.yawed());
        if !self.in_domain(s) {
            return None;
        }
        count!(ExactGap, 1);
        let wheel = self.pair.wheel.at(s);
        let wheel = if YAWED {
            self.yaw.outline(wheel)?
        } else {
            wheel
        };
        let yz = pose.apply(wheel.y, wheel.z);
        let rail = self.rail.at(yz[0])?;
        Some(Self::gap_point(s, wheel, pose, yz, rail))
    }

    /// [`SideGap::at`] with the wheel point at `s` given (`wheel = self.wheel().at(s)`,
    /// evaluated by the caller, e.g. in SIMD lanes); `s` must lie inside the wheel's domain.
    #[inline]
    pub(crate) fn at_wheel_point(
        &self,
        s: f64,
        wheel: WheelPoint,
        pose: &SidePose,
    ) -> Option<GapPoint> {
        count!(ExactGap, 1);
        let wheel = self.outline(wheel)?;
        let yz = pose.apply(wheel.y, wheel.z);
        let rail = self.rail.at(yz[0])?;
        Some(Self::gap_point(s, wheel, pose, yz, rail))
    }

    /// [`SideGap::at`] of four points with their wheel points given (`wheel[i] =
    /// self.wheel().at(s[i])`, e.g. from [`PlacedWheel::at_x4`]), to the bit: the rail
    /// looked up for the four at once ([`PlacedRail::at_x4`], SIMD lanes); `visit(i, gap)`
    /// for each point `i` (in order) where `at` is `Some(gap)`. A visitor rather than an
    /// array of four options: the gap points are built in place, not moved through one.
    #[inline]
    pub(crate) fn each_x4(
        &self,
        s: [f64; 4],
        wheel: [WheelPoint; 4],
        pose: &SidePose,
        mut visit: impl FnMut(usize, GapPoint),
    ) {
        if !self.yaw.keeps_profile() {
            // The outline point by point: no lanes for the yawed wheel.
            for i in 0..4 {
                if self.in_domain(s[i])
                    && let Some(p) = self.at_wheel_point(s[i], wheel[i], pose)
                {
                    visit(i, p);
                }
            }
            return;
        }
        let yz = wheel.map(|w| pose.apply(w.y, w.z));
        let rail = self.rail.at_x4(yz.map(|p| p[0]));
        for i in 0..4 {
            if !self.in_domain(s[i]) {
                continue;
            }
            count!(ExactGap, 1);
            if let Some(rail) = rail[i] {
                visit(i, Self::gap_point(s[i], wheel[i], pose, yz[i], rail));
            }
        }
    }

    /// The gap point at `s` from its wheel point, the wheel point `[y, z_rel]` placed by
    /// `pose`, and the rail point below it.
    #[inline(always)]
    fn gap_point(
        s: f64,
        wheel: WheelPoint,
        pose: &SidePose,
        [y, z_rel]: [f64; 2],
        rail: RailPoint,
    ) -> GapPoint {
        // Derivatives along Yw: wheel.slope = dZw/dYw (-F' without yaw), wheel.d2 =
        // d2Zw/dYw2 (-F'').
        let f1 = -wheel.slope;
        let f2 = -wheel.d2;
        let dy = pose.cos + pose.sin * f1;
        let dz = pose.sin - pose.cos * f1;
        let ddy = pose.sin * f2;
        let ddz = -pose.cos * f2;
        let rail_dd = rail.d2;
        GapPoint {
            s,
            g: z_rel - rail.z,
            dg: dz - rail.slope * dy,
            ddg: ddz - rail_dd * dy * dy - rail.slope * ddy,
            y,
            z_rel,
            wheel,
            rail,
        }
    }
}
