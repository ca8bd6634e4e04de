//! Measured wheels and rails as a maintenance engineer judges them: a wheel's flange
//! dimensions against their limits, a rail's wear against its nominal profile.
//!
//! * [`flange_dimensions`]: Sh, Sd and qR of a wheel profile (EN 15313, UIC 510-2; the
//!   definitions and their sources in [`dimensions`]);
//! * [`Limits`]: the in-service limits of those dimensions for standard-gauge wheels, by
//!   wheel diameter, with a scene's overrides, and the limits a wheel breaks ([`limits`]);
//! * [`rail_wear`]: the vertical wear on the centre line and the gauge-face wear at the
//!   gauge-point depth of a rail against its nominal profile ([`wear`]);
//! * all of it for the four profiles of a placement, which a run computes with its profiles
//!   for the report's table ([`pipeline::Results`](crate::pipeline::Results)'s
//!   `maintenance`) and a fleet summarises per row.
//!
//! A broken limit is a result, not an error: it is reported, and a run or a fleet exits as
//! it would without it.

pub mod dimensions;
pub mod limits;
pub mod wear;

pub use dimensions::{DimensionError, FlangeDimensions, flange_dimensions};
pub use limits::{Breach, LimitOverrides, Limits};
pub use wear::{RailWear, WearError, rail_wear};

use crate::profile::Profile;
use crate::track::{Inclination, Placement};

/// One wheel's flange dimensions, its limits and the limits it breaks.
#[derive(Debug, Clone, PartialEq)]
pub struct WheelAssessment {
    /// Sh, Sd, qR, or why they cannot be measured.
    pub dimensions: Result<FlangeDimensions, DimensionError>,
    /// The limits that apply (by the wheel's nominal diameter, with the scene's overrides).
    pub limits: Limits,
    /// The limits broken (empty when within limits or undefined).
    pub breaches: Vec<Breach>,
}

impl WheelAssessment {
    /// `ok`, the broken limits (`Sd 33.06 > 33 mm; ...`) or why the dimensions are
    /// undefined.
    pub fn status(&self) -> String {
        match &self.dimensions {
            Err(e) => format!("flange dimensions undefined: {e}"),
            Ok(_) if self.breaches.is_empty() => "ok".into(),
            Ok(_) => self
                .breaches
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("; "),
        }
    }
}

/// The nominal rails a placement's rails are measured against, with the inclination in
/// their data (the scene's `rail.profile_inclination`, shared by every rail of a scene).
#[derive(Debug, Clone)]
pub(crate) struct NominalRails {
    /// Left and right nominal rail profiles.
    pub profiles: [Profile; 2],
    /// The inclination in the data of the nominal and the measured rails.
    pub profile_inclination: Inclination,
}

/// The maintenance view of a placement's profiles.
#[derive(Debug, Clone, PartialEq)]
pub struct Assessment {
    /// Left and right wheels.
    pub wheels: [WheelAssessment; 2],
    /// Left and right rails against their nominal profiles; `None` when no nominal rail
    /// was given (a report without `rail.nominal_profile`, a fleet of wheels).
    pub rails: Option<[Result<RailWear, WearError>; 2]>,
}

/// The flange dimensions of `placement`'s wheels against the standard's limits for their
/// nominal diameters with `overrides`, and the wear of its rails against `nominal` (when
/// given) at the track's gauge-point depth.
pub(crate) fn assess(
    placement: &Placement,
    overrides: &LimitOverrides,
    nominal: Option<&NominalRails>,
) -> Assessment {
    let wheel = |w: &crate::track::PlacedWheel| {
        let dimensions = flange_dimensions(w.profile());
        let limits = Limits::with_overrides(2.0 * w.nominal_radius_mm(), overrides);
        let breaches = dimensions
            .as_ref()
            .map(|d| limits.breaches(d))
            .unwrap_or_default();
        WheelAssessment {
            dimensions,
            limits,
            breaches,
        }
    };
    let depth = placement.layout.gauge_point_depth_mm;
    let rails = nominal.map(|n| {
        let wear = |rail: &crate::track::PlacedRail, nominal: &Profile| {
            rail_wear(rail.profile(), nominal, n.profile_inclination, depth)
        };
        [
            wear(&placement.left.rail, &n.profiles[0]),
            wear(&placement.right.rail, &n.profiles[1]),
        ]
    });
    let left = wheel(&placement.left.wheel);
    // A mirror-symmetric wheelset's two wheels are equal: the same numbers, measured once.
    let right = if placement.is_mirror_symmetric() {
        left.clone()
    } else {
        wheel(&placement.right.wheel)
    };
    Assessment {
        wheels: [left, right],
        rails,
    }
}
