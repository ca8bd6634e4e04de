//! Boxes of poses ([`PoseBox`]): lower bounds of every block's coarse gaps made once for a
//! box of shifts, rolls and (where the yaw moves the outline) yaws about a pose, which the
//! scans (`scan.rs`) and the certificate (`certify.rs`) of the poses inside it read instead
//! of bounding each block at its own pose.

use super::{SideGap, SidePose};

/// Half the width in `delta` of the box of poses a [`PoseBox`] holds (mm): ten positions of
/// a sweep at 0.1 mm steps on either side of the pose it was made at. A wider box is made
/// less often but bounds more loosely, so that more blocks are bounded at their pose
/// instead; a narrower one is made again more often. 1 mm does the least work of the
/// paper sweep between 0.5 and 2 mm (with [`POSE_BOX_SIN`] at 1e-3 times this).
pub(crate) const POSE_BOX_DELTA_MM: f64 = 1.0;
/// Half the width in `sin(phi)` of the box of poses a [`PoseBox`] holds: a roll change of
/// 1e-3 rad moves a wheel point by at most 1e-3 times its distance from the reference point
/// (half the profile's width, about 70 mm) vertically relative to it, and by 1e-3 x 500 mm
/// laterally (the common motion of the whole wheel is taken out, see [`PoseBox`]).
pub(crate) const POSE_BOX_SIN: f64 = 1e-3;
/// Half the width in yaw of the box of poses a [`PoseBox`] holds where the yaw moves the
/// wheel's outline (rad): four positions of a sweep at 0.1 mm steps whose yaw grows 2.4
/// mrad per mm (the Manchester benchmark's). The outline of a flange moves 0.1 mm
/// vertically per mrad at 20 mrad (less on the tread), which loosens the bounds of the
/// blocks near the contact only, and those are evaluated anyway.
pub(crate) const POSE_BOX_YAW_RAD: f64 = 1e-3;

/// Lower bounds of every block's coarse gaps that hold for a whole box of poses:
/// `|delta - delta0| <=` [`POSE_BOX_DELTA_MM`] and `|sin phi - sin phi0| <=`
/// [`POSE_BOX_SIN`] about the pose `(delta0, phi0)` they were made at. A scan at a pose
/// inside the box reads them instead of bounding each block at its pose, and bounds at its
/// pose only the blocks these do not already skip.
///
/// The bound, by interval arithmetic over the box (`s = sin phi`, `c = cos phi`, both in
/// their intervals over the box; a block's `Yw` and `Zw` in theirs): the coarse gap of a
/// wheel point is `g = s Yw + c Zw - Zr(Y)` with `Y = delta + c Yw - s Zw`, so
/// `g - (s Yc + c Zc) = s (Yw - Yc) + c (Zw - Zc) - Zr(Y)` is at least the lowest the
/// first two terms reach over the box minus the highest table height over the lateral span
/// `Y` can cover in the box. `(Yc, Zc)` is one wheel point, the same for all blocks: the
/// motion `s Yc + c Zc` that the roll gives the whole wheel (0.75 mm per mrad at the
/// tread's 750 mm lever arm) is added back at the scanned pose, so that only the motion of
/// a block relative to that point (`|Yw - Yc|`, at most half the profile's width) loosens
/// the bound. The unit test
/// `pose_box_bounds_are_below_every_sample_of_their_block_in_the_box` checks the bound on
/// the corners of boxes along the paper sweep.
///
/// With a yaw that moves the wheel's outline, the box also spans yaws within
/// [`POSE_BOX_YAW_RAD`] of its own, so that a sweep whose yaw changes with the shift keeps
/// its boxes from position to position: each block's extents are widened by how far its
/// outline can move over those yaws ([`SideGap::outline_motion`], where the part of the wheel
/// that takes part is the same at both ends of the range; otherwise the box holds its own
/// yaw only), `(Yc, Zc)` is kept with the box, and the certificate's cushions, which read
/// the outline's bounds at one yaw, are made again when the yaw changes.
#[derive(Debug, Clone, Default)]
pub(crate) struct PoseBox {
    /// `(delta0, sin phi0, psi0)`, `None` until made.
    centre: Option<(f64, f64, f64)>,
    /// How far from `psi0` the side's yaw may be (rad): 0 where the outline is the profile.
    pub(super) yaw_half: f64,
    /// `(Yc, Zc)`, the point whose motion with the roll the bounds take out.
    pub(super) reference: [f64; 2],
    /// The bits of the side's yaw the `cushions` were made at.
    pub(super) cushion_yaw: u64,
    /// Per block, how far its outline may move over the box's yaws (a buffer reused).
    motions: Vec<(f64, f64)>,
    /// Per block, the lower bound of `g - (s Yc + c Zc)` over the box.
    pub(super) bounds: Vec<f64>,
    /// Per block, the same for every point of its cells against the exact rail (the
    /// certificate's, `certify.rs`).
    pub(super) certified: Vec<f64>,
    /// Per block, the lateral span its cells can cover in the box.
    pub(super) spans: Vec<[f64; 2]>,
    /// Per block, the certificate's cushion over the box (`certify.rs`), NaN until asked.
    pub(super) cushions: Vec<f64>,
    /// The ranges of `cos phi` and `sin phi` over the box.
    pub(super) trig: [(f64, f64); 2],
}

impl PoseBox {
    /// Whether `other` was made at the same pose as this box (compared to the bit), so that,
    /// for the same side, the two are the same box: a box is a function of its side and the
    /// pose it was made at, and the certificate's cushions of one serve the other.
    pub(crate) fn made_at_same_pose(&self, other: &PoseBox) -> bool {
        let bits = |c: Option<(f64, f64, f64)>| c.map(|(d, s, y)| [d, s, y].map(f64::to_bits));
        self.centre.is_some() && bits(self.centre) == bits(other.centre)
    }

    /// Whether `pose` lies in the box (false before the first scan).
    #[inline]
    pub(super) fn holds(&self, pose: &SidePose) -> bool {
        self.centre.is_some_and(|(delta, sin, yaw)| {
            (pose.delta - delta).abs() <= POSE_BOX_DELTA_MM
                && (pose.sin - sin).abs() <= POSE_BOX_SIN
                && (pose.yaw - yaw).abs() <= self.yaw_half
        })
    }
}

/// The range of `a b` for `a` in `[a.0, a.1]` and `b` in `[b.0, b.1]`.
#[inline]
fn product(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let p = [a.0 * b.0, a.0 * b.1, a.1 * b.0, a.1 * b.1];
    (
        p.iter().fold(f64::INFINITY, |m, &v| m.min(v)),
        p.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v)),
    )
}

impl SideGap<'_> {
    /// The wheel point `(Yc, Zc)` whose motion with the roll [`PoseBox`] takes out: the
    /// middle coarse sample.
    #[inline]
    pub(super) fn box_reference(&self) -> [f64; 2] {
        let [_, yw, zw] = self.coarse[self.coarse.len() / 2];
        [yw, zw]
    }

    /// Makes `pose_box` the box about `pose`: every block's bound over it, for the scan (its
    /// samples against the height table) and for the certificate (every point of its cells
    /// against the exact rail, as in [`SideGap::certified_block_bound`]); the certificate's
    /// cushions of the box are computed when first asked for.
    pub(super) fn fill_pose_box(&self, pose: &SidePose, pose_box: &mut PoseBox) {
        let [yc, zc] = self.box_reference();
        // With a yaw, how far each block's outline can move over the box's yaws; where that
        // is not bounded (the part of the wheel that takes part may change), the box holds
        // its own yaw only.
        let mut motions = std::mem::take(&mut pose_box.motions);
        let mut yaw_half = self.box_yaw_half(POSE_BOX_YAW_RAD);
        motions.clear();
        if yaw_half > 0.0 {
            motions.extend((0..self.blocks.len()).map(|b| self.outline_motion(b, yaw_half)));
            if motions.iter().any(|m| !m.0.is_finite() || !m.1.is_finite()) {
                yaw_half = 0.0;
            }
        }
        let widened = |b: usize, [yw_lo, yw_hi, zw_lo, zw_hi]: [f64; 4]| {
            if yaw_half > 0.0 {
                let (my, mz) = motions[b];
                [yw_lo - my, yw_hi + my, zw_lo - mz, zw_hi + mz]
            } else {
                [yw_lo, yw_hi, zw_lo, zw_hi]
            }
        };
        let (d, sin) = (pose.delta, pose.sin);
        let s = (sin - POSE_BOX_SIN, sin + POSE_BOX_SIN);
        // cos phi = sqrt(1 - sin^2) (|phi| < 90 degrees) falls with |sin phi|.
        let cos = |v: f64| (1.0 - v * v).sqrt();
        let c_hi = if s.0 <= 0.0 && s.1 >= 0.0 {
            1.0
        } else {
            cos(s.0).max(cos(s.1))
        };
        let c = (cos(s.0).min(cos(s.1)), c_hi);
        let neg_s = (-s.1, -s.0);
        // The lateral span over the box and the lowest height less the common motion of a
        // block with wheel extents `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]`.
        let extent = |[yw_lo, yw_hi, zw_lo, zw_hi]: [f64; 4]| {
            let cy = product(c, (yw_lo, yw_hi));
            let sz = product(neg_s, (zw_lo, zw_hi));
            let z_lo =
                product(s, (yw_lo - yc, yw_hi - yc)).0 + product(c, (zw_lo - zc, zw_hi - zc)).0;
            [
                d - POSE_BOX_DELTA_MM + cy.0 + sz.0,
                d + POSE_BOX_DELTA_MM + cy.1 + sz.1,
                z_lo,
            ]
        };
        let heights = self.rail.heights();
        pose_box.centre = Some((d, sin, pose.yaw));
        pose_box.yaw_half = yaw_half;
        pose_box.reference = [yc, zc];
        pose_box.cushion_yaw = pose.yaw.to_bits();
        pose_box.trig = [c, s];
        pose_box.bounds.clear();
        pose_box
            .bounds
            .extend(self.blocks.iter().enumerate().map(|(b, &block)| {
                let [y_lo, y_hi, z_lo] = extent(widened(b, block));
                heights
                    .max_over(y_lo, y_hi)
                    .map_or(f64::INFINITY, |rail| z_lo - rail)
            }));
        // As in `certified_block_bound`: a step of the height table wider.
        let w = crate::track::HEIGHT_TABLE_STEP_MM;
        pose_box.certified.clear();
        pose_box.spans.clear();
        for (b, &block) in self.cert_blocks.iter().enumerate() {
            let [y_lo, y_hi, z_lo] = extent(widened(b, block));
            pose_box.spans.push([y_lo, y_hi]);
            pose_box.certified.push(
                self.rail
                    .binned_max_height(y_lo - w, y_hi + w)
                    .map_or(f64::INFINITY, |rail| z_lo - rail),
            );
        }
        pose_box.cushions.clear();
        pose_box.cushions.resize(self.cert_blocks.len(), f64::NAN);
        pose_box.motions = motions;
    }
}
