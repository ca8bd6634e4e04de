//! Placing the wheels and rails of a wheelset on the track (standard gauge: 1435 mm between
//! the gauge points 14 mm below the top of rail, 1360 mm between the wheels' inner faces, the
//! taping lines 70 mm outside them; the crate docs state the frames and signs).
//!
//! Each side is described in its *side frame*: `Y` = |y| in the track frame (mm, growing
//! towards the field side) and `Z` = z (mm, up). The left side maps to the track frame as
//! `y = Y`, the right side as `y = -Y`.
//!
//! * A rail is rotated by its inclination towards the track centre, then translated so that
//!   its highest point is at `Z = 0` and its gauge point (the most gauge-side point of the head
//!   within [`TrackLayout::gauge_point_depth_mm`] below the top) is at `Y = gauge / 2`.
//! * A wheel is fixed to the wheelset: its taping line is at `Y = flange_back / 2 + 70 mm`
//!   from the wheelset centre and its rolling circle there has the nominal radius `r0`.

use crate::profile::{Profile, ProfileKind};
use std::fmt;
use std::sync::Arc;

mod heights;
mod layout;
mod rail;
mod sparse;
mod wheel;

pub(crate) use heights::{HEIGHT_TABLE_STEP_MM, HeightTable};
pub(crate) use layout::{
    GAUGE_POINT_DEPTH_MM, STANDARD_FLANGE_BACK_MM, STANDARD_GAUGE_MM,
    TAPING_LINE_FROM_INNER_FACE_MM,
};
pub use layout::{Inclination, LayoutError, TrackLayout};
pub(crate) use rail::{MAX_RAIL_SLOPE, SurfaceBounds};
pub use rail::{PlacedRail, RailPoint};
pub(crate) use wheel::{NOMINAL_RADIUS_RANGE_MM, check_nominal_radius};
pub use wheel::{PlacedWheel, WheelPoint};
pub(crate) use wheel::{WheelCell, WheelCells};

/// Why a rail could not be placed.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum PlacementError {
    /// The profile has no point within the gauge-point depth below its top.
    NoGaugePoint {
        /// The profile's name.
        profile: String,
    },
    /// A wheel profile was given where a rail was expected, or the reverse.
    WrongKind {
        /// The profile's name.
        profile: String,
        /// What was expected.
        expected: ProfileKind,
    },
    /// A nominal wheel radius outside `NOMINAL_RADIUS_RANGE_MM` (or not finite).
    NominalRadius {
        /// The radius, mm.
        radius_mm: f64,
    },
    /// A side was placed for another layout than the placement's.
    LayoutMismatch {
        /// The side.
        side: Side,
    },
    /// A wheel lies nowhere above its rail with the wheelset centred: it cannot touch it in
    /// any sweep of a few centimetres (a unit mistake or a wrong profile, not a result).
    NoOverlap {
        /// The side.
        side: Side,
        /// The wheel profile's name.
        wheel: String,
        /// The rail profile's name.
        rail: String,
    },
}

impl fmt::Display for PlacementError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlacementError::NoGaugePoint { profile } => write!(
                f,
                "rail profile {profile}: no point of the head lies within the gauge-point depth below its top"
            ),
            PlacementError::WrongKind { profile, expected } => {
                write!(f, "profile {profile} is not a {expected} profile")
            }
            PlacementError::NominalRadius { radius_mm } => write!(
                f,
                "{} mm is not a railway wheel radius; expected {} to {} mm",
                crate::message::Number(*radius_mm),
                NOMINAL_RADIUS_RANGE_MM.0,
                NOMINAL_RADIUS_RANGE_MM.1
            ),
            PlacementError::LayoutMismatch { side } => write!(
                f,
                "the {} wheel and rail were placed for another track layout",
                side.name()
            ),
            PlacementError::NoOverlap { side, wheel, rail } => write!(
                f,
                "the {} wheel and rail do not overlap laterally with the wheelset centred (wheel {wheel}, rail {rail}): check the profiles' lateral origins and units",
                side.name()
            ),
        }
    }
}

impl std::error::Error for PlacementError {}

/// Convex-positive curvature of a rail-like graph `Z(Y)` (convex where `Z'' < 0`).
#[inline]
fn convex_from_second_derivative(slope: f64, d2: f64) -> f64 {
    let t = 1.0 + slope * slope;
    -d2 / (t * t.sqrt())
}

/// Left or right side of the track.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// y > 0.
    Left,
    /// y < 0.
    Right,
}

impl Side {
    /// +1 for the left side, -1 for the right: track `y = sign * Y`.
    pub fn sign(self) -> f64 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }

    /// `"left"` or `"right"`, the CSV column prefix.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }
}

/// One side of the track: a wheel and the rail under it.
///
/// The placed rail is shared, not copied: both sides of a track with one rail profile, the
/// pairs of a fleet and the scenes of a run with a `crate::cache::PlacementCache` hold the
/// same tables (cloning a side pair clones the wheel and counts one more user of the rail).
#[derive(Debug, Clone)]
pub struct SidePair {
    /// The wheel, fixed to the wheelset.
    pub(crate) wheel: PlacedWheel,
    /// The placed rail.
    pub(crate) rail: Arc<PlacedRail>,
}

/// Both sides of a wheelset on its track.
///
/// Whether the wheelset is [mirror-symmetric](Placement::is_mirror_symmetric) is decided
/// once, by content, when the placement is made: sweeps symmetric about the centre then
/// solve their half from the middle on and mirror the rest (see
/// [`Placement::without_mirroring`] for the switch that solves every position).
#[derive(Debug, Clone)]
pub struct Placement {
    /// The layout the sides were placed with.
    pub(crate) layout: TrackLayout,
    /// Left side (y > 0).
    pub(crate) left: SidePair,
    /// Right side (y < 0).
    pub(crate) right: SidePair,
    /// Whether the right side is the left one mirrored (see [`Placement::new`]).
    mirror_symmetric: bool,
    /// Whether sweeps use the mirror symmetry (true unless switched off).
    mirroring: bool,
}

impl SidePair {
    /// A wheel of `nominal_radius_mm` on a rail given upright or already inclined by
    /// `rail_profile_inclination`, placed for `layout`.
    ///
    /// # Errors
    /// [`PlacementError`] when a profile is of the wrong kind or the rail has no gauge point.
    pub fn place(
        wheel: Profile,
        nominal_radius_mm: f64,
        rail: Profile,
        rail_profile_inclination: Inclination,
        layout: &TrackLayout,
    ) -> Result<SidePair, PlacementError> {
        Ok(SidePair {
            wheel: PlacedWheel::place(wheel, nominal_radius_mm, layout)?,
            rail: Arc::new(PlacedRail::place(rail, rail_profile_inclination, layout)?),
        })
    }

    /// A placed wheel on a placed rail, owned or shared (`Arc<PlacedRail>`): for a caller
    /// that places a rail once and puts many wheels on it (a fleet, both sides of a track).
    /// [`Placement::new`] checks that both were placed for its layout.
    pub fn new(wheel: PlacedWheel, rail: impl Into<Arc<PlacedRail>>) -> SidePair {
        SidePair {
            wheel,
            rail: rail.into(),
        }
    }

    /// The wheel, fixed to the wheelset.
    pub fn wheel(&self) -> &PlacedWheel {
        &self.wheel
    }

    /// The placed rail.
    pub fn rail(&self) -> &PlacedRail {
        &self.rail
    }

    /// The placed rail, shared: to put it under another wheel without copying its tables.
    pub fn shared_rail(&self) -> &Arc<PlacedRail> {
        &self.rail
    }

    /// Whether the wheel lies above some part of its rail with the wheelset centred.
    fn overlaps(&self) -> bool {
        let (s_lo, s_hi) = self.wheel.profile().domain();
        let (y_lo, y_hi) = self.rail.y_range();
        let taping = self.wheel.taping_line_mm();
        taping + s_hi >= y_lo && taping + s_lo <= y_hi
    }
}

impl Placement {
    /// A wheelset on its track from its two sides, each placed for `layout`.
    ///
    /// The wheelset is mirror-symmetric when its right side has the left side's content to
    /// the bit: the same wheel profile data at the same radius, the same rail profile data
    /// placed the same way (the layout, one for both sides, is mirror-symmetric: one gauge,
    /// inclination and flange-back distance). Profiles are compared by their data, not by
    /// their names, so equal sides built any way (one side cloned, or both placed from
    /// equal files) make equal placements, with bit-identical results. Two equal wheels
    /// then share their cell bounds (built once, on first use).
    ///
    /// # Errors
    /// [`PlacementError::LayoutMismatch`] when a side was placed for another layout (its
    /// taping line or gauge point is elsewhere), [`PlacementError::NoOverlap`] when a wheel
    /// lies nowhere above its rail with the wheelset centred.
    ///
    /// # Example
    /// ```
    /// use wheelrail::profile::Profile;
    /// use wheelrail::track::{Inclination, Placement, SidePair, TrackLayout};
    /// let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
    /// let side = || {
    ///     SidePair::place(Profile::s1002(), 460.0, Profile::uic60e1(), Inclination::VERTICAL, &layout)
    /// };
    /// let placement = Placement::new(layout.clone(), side().unwrap(), side().unwrap()).unwrap();
    /// assert_eq!(placement.right().wheel().nominal_radius_mm(), 460.0);
    /// ```
    pub fn new(
        layout: TrackLayout,
        left: SidePair,
        right: SidePair,
    ) -> Result<Placement, PlacementError> {
        for (side, pair) in [(Side::Left, &left), (Side::Right, &right)] {
            let gauge_point_y = pair.rail.gauge_point()[0];
            // The same arithmetic on the same layout gives the same numbers: any difference
            // is another layout, not rounding.
            let off = |a: f64, b: f64| (a - b).abs() > 1e-9 * a.abs().max(1.0);
            if off(pair.wheel.taping_line_mm(), layout.taping_line_mm())
                || off(gauge_point_y, 0.5 * layout.gauge_mm)
            {
                return Err(PlacementError::LayoutMismatch { side });
            }
            if !pair.overlaps() {
                return Err(PlacementError::NoOverlap {
                    side,
                    wheel: pair.wheel.profile().name().to_string(),
                    rail: pair.rail.profile().name().to_string(),
                });
            }
        }
        let mirror_symmetric = left.wheel.same_as(&right.wheel) && left.rail.same_as(&right.rail);
        let mut right = right;
        if mirror_symmetric {
            right.wheel.share_cells_with(&left.wheel);
        }
        Ok(Placement {
            layout,
            left,
            right,
            mirror_symmetric,
            mirroring: true,
        })
    }

    /// The layout the sides were placed with.
    pub fn layout(&self) -> &TrackLayout {
        &self.layout
    }

    /// The left side (y > 0).
    pub fn left(&self) -> &SidePair {
        &self.left
    }

    /// The right side (y < 0).
    pub fn right(&self) -> &SidePair {
        &self.right
    }

    /// A wheelset whose two wheels have the same profile and radius on two rails of the same
    /// profile (each side in its mirrored side frame): the usual case, placed once (the
    /// right side shares the left's rail) and [mirror-symmetric](Self::is_mirror_symmetric).
    ///
    /// `rail_profile_inclination` is the inclination the rail profile data already has
    /// (upright: `Inclination::VERTICAL`); the layout's inclination is the track's.
    ///
    /// # Errors
    /// [`PlacementError`] as [`SidePair::place`].
    ///
    /// # Example
    /// ```
    /// use wheelrail::profile::Profile;
    /// use wheelrail::track::{Inclination, Placement, TrackLayout};
    /// let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
    /// let placement = Placement::symmetric(
    ///     Profile::s1002(), 460.0, Profile::uic60e1(), Inclination::VERTICAL, layout,
    /// ).unwrap();
    /// assert_eq!(placement.left().wheel().nominal_radius_mm(), 460.0);
    /// ```
    pub fn symmetric(
        wheel: Profile,
        nominal_radius_mm: f64,
        rail: Profile,
        rail_profile_inclination: Inclination,
        layout: TrackLayout,
    ) -> Result<Placement, PlacementError> {
        let left = SidePair::place(
            wheel,
            nominal_radius_mm,
            rail,
            rail_profile_inclination,
            &layout,
        )?;
        let right = left.clone();
        Placement::new(layout, left, right)
    }

    /// Whether the right side is the left one mirrored: the same wheel profile data and
    /// radius, the same rail profile data placed the same way (decided by
    /// [`Placement::new`]). Each side is computed in its own mirrored side frame, so the
    /// right wheel at a shift `-y` and roll `-theta` is then the left wheel at `y` and
    /// `theta`, operation for operation: a sweep symmetric about the centre needs only
    /// its half.
    pub fn is_mirror_symmetric(&self) -> bool {
        self.mirror_symmetric
    }

    /// Whether sweeps on this placement solve half of a symmetric sweep and mirror the
    /// rest: [mirror-symmetric](Self::is_mirror_symmetric) and not
    /// [switched off](Self::without_mirroring).
    pub fn mirrors(&self) -> bool {
        self.mirror_symmetric && self.mirroring
    }

    /// This placement with the mirror switched off: every position of a sweep is solved,
    /// symmetric or not (to check the mirrored half against solved positions, or to
    /// measure the work of a wheelset whose two wheels differ). The same numbers otherwise.
    ///
    /// # Example
    /// ```
    /// use wheelrail::profile::Profile;
    /// use wheelrail::track::{Inclination, Placement, TrackLayout};
    /// let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
    /// let placement = Placement::symmetric(
    ///     Profile::s1002(), 460.0, Profile::uic60e1(), Inclination::VERTICAL, layout,
    /// ).unwrap();
    /// assert!(placement.mirrors());
    /// let every_position = placement.without_mirroring();
    /// assert!(every_position.is_mirror_symmetric() && !every_position.mirrors());
    /// ```
    pub fn without_mirroring(self) -> Placement {
        Placement {
            mirroring: false,
            ..self
        }
    }

    /// The side pair of `side`.
    pub fn side(&self, side: Side) -> &SidePair {
        match side {
            Side::Left => &self.left,
            Side::Right => &self.right,
        }
    }

    /// Vertical offset that brings each wheel of the centred, unrolled wheelset down onto
    /// its rail: the smallest gap between wheel and rail with the axle at height `r0`
    /// (scanned every 0.01 mm). Used to draw the profiles in contact; the contact search
    /// solves the real position.
    pub fn resting_gap(&self, side: Side) -> f64 {
        let pair = self.side(side);
        let r0 = pair.wheel.nominal_radius_mm();
        let (lo, hi) = pair.wheel.profile().domain();
        let n = ((hi - lo) / 0.01).ceil() as usize;
        (0..=n)
            .filter_map(|i| {
                let p = pair.wheel.at(lo + (hi - lo) * i as f64 / n as f64);
                pair.rail.at(p.y).map(|r| r0 + p.z - r.z)
            })
            .fold(f64::INFINITY, f64::min)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two equal wheels placed separately are recognised by their content, and share their
    /// cell bounds from then on (built once for both).
    #[test]
    fn equal_sides_placed_separately_are_mirror_symmetric() {
        let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
        let side = || {
            let (wheel, rail) = (Profile::s1002(), Profile::uic60e1());
            SidePair::place(wheel, 460.0, rail, Inclination::VERTICAL, &layout).unwrap()
        };
        let (left, right) = (side(), side());
        assert!(!left.wheel.shares_cells_with(&right.wheel));
        let placement = Placement::new(layout.clone(), left, right).unwrap();
        assert!(placement.is_mirror_symmetric());
        assert!(
            placement
                .right
                .wheel
                .shares_cells_with(&placement.left.wheel)
        );
    }
}
