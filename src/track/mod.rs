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

mod heights;
mod rail;
mod wheel;

pub use heights::{HEIGHT_TABLE_STEP_MM, HeightTable};
pub use rail::{
    MAX_RAIL_SLOPE, PlacedRail, RailPoint, SURFACE_TABLE_MAX_SLOPE, SURFACE_TABLE_STEP_MM,
};
pub use wheel::{PlacedWheel, WheelPoint};

/// Distance from the inner face of a wheel to its taping line (EN 13715), mm.
pub const TAPING_LINE_FROM_INNER_FACE_MM: f64 = 70.0;

/// A rail inclination towards the track centre, as an angle in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inclination(pub f64);

impl Inclination {
    /// Parses `"1:40"`, `"1:20"`, `"vertical"` (or `"0"`), or an angle in radians (`"0.025"`).
    ///
    /// # Errors
    /// A message saying what was expected when the text is none of these or the angle is not
    /// in `[0, 0.2]` rad (an inclination outward or above about 11 degrees is not a track).
    ///
    /// # Example
    /// ```
    /// use wheelrail::track::Inclination;
    /// let i = Inclination::parse("1:40").unwrap();
    /// assert!((i.0 - 0.0249948).abs() < 1e-7);
    /// ```
    pub fn parse(text: &str) -> Result<Inclination, String> {
        let t = text.trim();
        let angle = if t.eq_ignore_ascii_case("vertical") || t.eq_ignore_ascii_case("upright") {
            0.0
        } else if let Some((one, n)) = t.split_once(':') {
            let one: f64 = one.trim().parse().map_err(|_| expected(text))?;
            let n: f64 = n.trim().parse().map_err(|_| expected(text))?;
            if !(one > 0.0 && n > 0.0 && one.is_finite() && n.is_finite()) {
                return Err(expected(text));
            }
            (one / n).atan()
        } else {
            t.parse::<f64>().map_err(|_| expected(text))?
        };
        if !(0.0..=0.2).contains(&angle) {
            return Err(format!(
                "inclination {text:?} is {angle} rad; expected 0 to 0.2 rad towards the track centre"
            ));
        }
        Ok(Inclination(angle))
    }
}

fn expected(text: &str) -> String {
    format!(
        "inclination {text:?} not understood; expected \"1:40\", \"1:20\", \"1:30\", \"vertical\" or an angle in radians"
    )
}

/// Dimensions of the track and wheelset layout (all mm).
#[derive(Debug, Clone, PartialEq)]
pub struct TrackLayout {
    /// Track gauge between the gauge points.
    pub gauge_mm: f64,
    /// Depth below the top of rail at which the gauge is measured (14 mm).
    pub gauge_point_depth_mm: f64,
    /// Rail inclination towards the track centre.
    pub inclination: Inclination,
    /// Distance between the inner faces of the wheels (flange-back, 1360 mm).
    pub flange_back_mm: f64,
}

/// Standard gauge (mm): 1435.
pub const STANDARD_GAUGE_MM: f64 = 1435.0;
/// Depth below the top of rail at which the gauge is measured (mm, EN 13848-1): 14.
pub const GAUGE_POINT_DEPTH_MM: f64 = 14.0;
/// Distance between the inner faces of a standard wheelset's wheels (mm): 1360.
pub const STANDARD_FLANGE_BACK_MM: f64 = 1360.0;

impl TrackLayout {
    /// Standard gauge (1435 mm, measured 14 mm below the top of rail) and a standard
    /// wheelset (1360 mm between the wheels' inner faces), rails inclined by `inclination`.
    ///
    /// # Example
    /// ```
    /// use wheelrail::track::{Inclination, TrackLayout};
    /// let layout = TrackLayout::standard(Inclination::parse("1:40").unwrap());
    /// assert_eq!(layout.gauge_mm, 1435.0);
    /// assert_eq!(layout.taping_line_mm(), 750.0);
    /// ```
    pub fn standard(inclination: Inclination) -> TrackLayout {
        TrackLayout {
            gauge_mm: STANDARD_GAUGE_MM,
            gauge_point_depth_mm: GAUGE_POINT_DEPTH_MM,
            inclination,
            flange_back_mm: STANDARD_FLANGE_BACK_MM,
        }
    }

    /// Lateral position of the taping lines from the wheelset centre, `Y` in the side frame.
    pub fn taping_line_mm(&self) -> f64 {
        0.5 * self.flange_back_mm + TAPING_LINE_FROM_INNER_FACE_MM
    }
}

/// Why a rail could not be placed.
#[derive(Debug, Clone, PartialEq)]
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
#[derive(Debug, Clone)]
pub struct SidePair {
    /// The wheel, fixed to the wheelset.
    pub wheel: PlacedWheel,
    /// The placed rail.
    pub rail: PlacedRail,
}

/// Both sides of a wheelset on its track.
#[derive(Debug, Clone)]
pub struct Placement {
    /// The layout the sides were placed with.
    pub layout: TrackLayout,
    /// Left side (y > 0).
    pub left: SidePair,
    /// Right side (y < 0).
    pub right: SidePair,
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
            rail: PlacedRail::place(rail, rail_profile_inclination, layout)?,
        })
    }
}

impl Placement {
    /// A wheelset whose two wheels have the same profile and radius on two rails of the same
    /// profile (each side in its mirrored side frame): the usual case, placed once.
    ///
    /// `rail_profile_inclination` is the inclination the rail profile data already has
    /// (upright: `Inclination(0.0)`); the layout's inclination is the track's.
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
    ///     Profile::s1002(), 460.0, Profile::uic60e1(), Inclination(0.0), layout,
    /// ).unwrap();
    /// assert_eq!(placement.left.wheel.nominal_radius_mm(), 460.0);
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
        Ok(Placement {
            layout,
            right: left.clone(),
            left,
        })
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

    #[test]
    fn inclination_parsing() {
        assert!(Inclination::parse("vertical").unwrap().0.abs() < 1e-15);
        assert!((Inclination::parse("1:20").unwrap().0 - 0.05f64.atan()).abs() < 1e-15);
        assert!((Inclination::parse("0.025").unwrap().0 - 0.025).abs() < 1e-15);
        assert!(Inclination::parse("1:0").is_err());
        assert!(Inclination::parse("steep").is_err());
        assert!(Inclination::parse("-0.1").is_err());
    }
}
