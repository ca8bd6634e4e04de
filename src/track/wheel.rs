//! A wheel fixed to the wheelset, in its side frame.

use super::{PlacementError, TrackLayout, convex_from_second_derivative};
use crate::profile::{Profile, ProfileKind};

/// A wheel fixed to the wheelset, in the side frame relative to the wheelset centre.
#[derive(Debug, Clone)]
pub struct PlacedWheel {
    profile: Profile,
    taping_line_mm: f64,
    nominal_radius_mm: f64,
}

/// A point of a placed wheel relative to the wheelset centre (side frame, no roll).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelPoint {
    /// Lateral `Y` from the wheelset centre (mm).
    pub y: f64,
    /// Vertical `Z` from the axle (mm): `-(r0 + F(s))`.
    pub z: f64,
    /// `dZ/dY` (= `-dF/ds`): tangent of the wheel's contact angle without roll.
    pub slope: f64,
    /// `d2Z/dY2` (= `-d2F/ds2`, 1/mm).
    pub d2: f64,
}

impl WheelPoint {
    /// Convex-positive curvature (1/mm): the wheel surface is convex towards the rail where
    /// `F'' < 0`, i.e. where `Z'' > 0`.
    #[inline]
    pub fn curvature(&self) -> f64 {
        -convex_from_second_derivative(self.slope, self.d2)
    }
}

/// The nominal wheel radii accepted (mm): from small trolley wheels to the largest
/// locomotive wheels, with margin.
pub const NOMINAL_RADIUS_RANGE_MM: (f64, f64) = (100.0, 1000.0);

/// `nominal_radius_mm` if it is within [`NOMINAL_RADIUS_RANGE_MM`].
///
/// # Errors
/// [`PlacementError::NominalRadius`] otherwise (and for a non-finite radius).
pub fn check_nominal_radius(nominal_radius_mm: f64) -> Result<f64, PlacementError> {
    let (lo, hi) = NOMINAL_RADIUS_RANGE_MM;
    if (lo..=hi).contains(&nominal_radius_mm) {
        Ok(nominal_radius_mm)
    } else {
        Err(PlacementError::NominalRadius {
            radius_mm: nominal_radius_mm,
        })
    }
}

impl PlacedWheel {
    /// Fixes `profile` to the wheelset with its taping line at `layout.taping_line_mm()`
    /// and its rolling circle there of radius `nominal_radius_mm`.
    ///
    /// # Errors
    /// [`PlacementError::WrongKind`] when the profile is not a wheel,
    /// [`PlacementError::NominalRadius`] when the radius is outside
    /// [`NOMINAL_RADIUS_RANGE_MM`].
    pub fn place(
        profile: Profile,
        nominal_radius_mm: f64,
        layout: &TrackLayout,
    ) -> Result<PlacedWheel, PlacementError> {
        let nominal_radius_mm = check_nominal_radius(nominal_radius_mm)?;
        if profile.kind() != ProfileKind::Wheel {
            return Err(PlacementError::WrongKind {
                profile: profile.name().to_string(),
                expected: ProfileKind::Wheel,
            });
        }
        Ok(PlacedWheel {
            profile,
            taping_line_mm: layout.taping_line_mm(),
            nominal_radius_mm,
        })
    }

    /// The wheel profile.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// Nominal rolling radius r0 at the taping line (mm).
    pub fn nominal_radius_mm(&self) -> f64 {
        self.nominal_radius_mm
    }

    /// Lateral position of the taping line from the wheelset centre (mm).
    pub fn taping_line_mm(&self) -> f64 {
        self.taping_line_mm
    }

    /// The wheel point at profile coordinate `s` (mm), relative to the wheelset centre.
    #[inline]
    pub fn at(&self, s: f64) -> WheelPoint {
        let [f, d1, d2] = self.profile.eval(s);
        WheelPoint {
            y: self.taping_line_mm + s,
            z: -(self.nominal_radius_mm + f),
            slope: -d1,
            d2: -d2,
        }
    }
}
