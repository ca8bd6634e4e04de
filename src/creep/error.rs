//! The error of the creep stage, one variant per refused input, and the checks that raise
//! it.

use super::coefficients::POISSON_RANGE;
use super::settings::{FRICTION_RANGE, GRID_RANGE, Grid};
use crate::hertz::HertzError;
use crate::message::Number;
use std::f64::consts::FRAC_PI_2;
use std::fmt;

/// Invalid input to the creep stage; each variant names the quantity, so that a caller (a
/// scene, the command line) can name its key.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum CreepError {
    /// A value that must be finite is NaN or infinite.
    NonFinite {
        /// Name of the input.
        quantity: &'static str,
        /// Its value.
        value: f64,
    },
    /// The forward speed is not positive.
    NonPositiveSpeed {
        /// mm/s.
        speed_mm_s: f64,
    },
    /// The rolling speed (the mean speed of the two bodies' material through the patch) is
    /// not positive: the wheel does not roll forwards.
    NoRolling {
        /// mm/s.
        rolling_speed_mm_s: f64,
    },
    /// The rolling radius is not positive, or the lead is not shorter than it.
    BadRollingRadius {
        /// mm.
        rolling_radius_mm: f64,
        /// mm.
        lead_mm: f64,
    },
    /// A contact angle outside `(-π/2, π/2)`.
    ContactAngle {
        /// rad.
        contact_angle_rad: f64,
    },
    /// A coefficient of friction outside (0, 1] (`FRICTION_RANGE`).
    Friction {
        /// μ.
        friction: f64,
    },
    /// A shear modulus that is not positive and finite.
    ShearModulus {
        /// MPa.
        shear_modulus_mpa: f64,
    },
    /// A Poisson's ratio outside [0, 0.5] (`POISSON_RANGE`).
    Poisson {
        /// ν.
        poisson: f64,
    },
    /// A FASTSIM grid outside 1 to 4000 strips or elements (`GRID_RANGE`).
    Grid {
        /// The grid asked for.
        grid: Grid,
    },
    /// Semi-axes that are not positive and finite.
    SemiAxes {
        /// mm.
        a_mm: f64,
        /// mm.
        b_mm: f64,
    },
    /// A normal force that is not positive and finite.
    NormalForce {
        /// N.
        normal_force_n: f64,
    },
    /// A vertical load that is not positive and finite.
    VerticalLoad {
        /// N.
        vertical_load_n: f64,
    },
    /// Normal-solve settings out of range (see
    /// [`Settings::with_normal_solve`](super::Settings::with_normal_solve)).
    NormalSolve {
        /// Relative tolerance.
        tolerance: f64,
        /// Iteration cap.
        max_iterations: u32,
    },
    /// The Hertz stage refused the input.
    Hertz(HertzError),
    /// A list of pitch rates without one rate per position of the sweep.
    PitchRates {
        /// Rates given.
        given: usize,
        /// Positions of the sweep.
        positions: usize,
    },
}

impl fmt::Display for CreepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CreepError::NonFinite { quantity, value } => {
                write!(f, "{quantity} = {value}: expected a finite number")
            }
            CreepError::NonPositiveSpeed { speed_mm_s } => write!(
                f,
                "speed {} mm/s: expected a positive forward speed (the creepages are divided by it)",
                Number(*speed_mm_s)
            ),
            CreepError::NoRolling { rolling_speed_mm_s } => write!(
                f,
                "rolling speed {} mm/s: the wheel turns backwards faster than it runs forwards; expected a rolling wheel",
                Number(*rolling_speed_mm_s)
            ),
            CreepError::BadRollingRadius {
                rolling_radius_mm,
                lead_mm,
            } => write!(
                f,
                "rolling radius {} mm with lead {} mm: expected a positive radius longer than the lead",
                Number(*rolling_radius_mm),
                Number(*lead_mm)
            ),
            CreepError::ContactAngle { contact_angle_rad } => write!(
                f,
                "contact angle {} rad: expected -pi/2 < angle < pi/2",
                Number(*contact_angle_rad)
            ),
            CreepError::Friction { friction } => write!(
                f,
                "coefficient of friction {}: expected above {} up to {}",
                Number(*friction),
                FRICTION_RANGE.0,
                FRICTION_RANGE.1
            ),
            CreepError::ShearModulus { shear_modulus_mpa } => write!(
                f,
                "shear modulus {} MPa: expected a positive number",
                Number(*shear_modulus_mpa)
            ),
            CreepError::Poisson { poisson } => write!(
                f,
                "Poisson's ratio {}: expected {} to {} (the range of Kalker's table)",
                Number(*poisson),
                POISSON_RANGE.0,
                POISSON_RANGE.1
            ),
            CreepError::Grid { grid } => write!(
                f,
                "FASTSIM grid {} x {}: expected {} to {} strips and elements",
                grid.strips, grid.elements, GRID_RANGE.0, GRID_RANGE.1
            ),
            CreepError::SemiAxes { a_mm, b_mm } => write!(
                f,
                "semi-axes a = {} mm, b = {} mm: expected positive lengths",
                Number(*a_mm),
                Number(*b_mm)
            ),
            CreepError::NormalForce { normal_force_n } => write!(
                f,
                "normal force {} N: expected a positive force",
                Number(*normal_force_n)
            ),
            CreepError::VerticalLoad { vertical_load_n } => write!(
                f,
                "vertical load {} N: expected a positive load",
                Number(*vertical_load_n)
            ),
            CreepError::NormalSolve {
                tolerance,
                max_iterations,
            } => write!(
                f,
                "normal-force solve with tolerance {} and {max_iterations} iterations: expected 1e-15 to 1e-2 and 1 to 1000",
                Number(*tolerance)
            ),
            CreepError::Hertz(e) => write!(f, "{e}"),
            CreepError::PitchRates { given, positions } => write!(
                f,
                "{given} pitch rates for a sweep of {positions} positions: expected one rate per position"
            ),
        }
    }
}

impl std::error::Error for CreepError {}

/// `Ok` if `value` is finite.
pub(super) fn finite(quantity: &'static str, value: f64) -> Result<(), CreepError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(CreepError::NonFinite { quantity, value })
    }
}

/// `Ok` if `|δ| < π/2` (a normal in the track's horizontal plane carries no vertical load).
pub(super) fn check_contact_angle(contact_angle_rad: f64) -> Result<(), CreepError> {
    if contact_angle_rad.abs() < FRAC_PI_2 {
        Ok(())
    } else {
        Err(CreepError::ContactAngle { contact_angle_rad })
    }
}

/// `Ok` if both semi-axes are positive and finite.
pub(super) fn check_semi_axes(a_mm: f64, b_mm: f64) -> Result<(), CreepError> {
    if a_mm > 0.0 && b_mm > 0.0 && a_mm.is_finite() && b_mm.is_finite() {
        Ok(())
    } else {
        Err(CreepError::SemiAxes { a_mm, b_mm })
    }
}

/// `Ok` if the normal force is positive and finite.
pub(super) fn check_normal_force(normal_force_n: f64) -> Result<(), CreepError> {
    if normal_force_n > 0.0 && normal_force_n.is_finite() {
        Ok(())
    } else {
        Err(CreepError::NormalForce { normal_force_n })
    }
}
