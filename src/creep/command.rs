//! The tangential problem of one elliptic patch from plain numbers, checked against the
//! plausible ranges of `wheelrail creep`: what the command line (`wheelrail creep` of the
//! crate `wheelrail-cli`) and the Python binding's `creep_forces` share, so that both accept
//! the same values and refuse the others with the same words.
//!
//! Units: semi-axes in mm, the normal force in N, the spin creepage in 1/mm, the shear
//! modulus in GPa (converted once to MPa); forces of the wheel on the rail in the patch's
//! contact frame (x rolling, y lateral, z the normal out of the rail).

use super::creepage::Creepages;
use super::tangential::{self, EllipticPatch, Tangential};
use super::{Bound, CreepError, Method, Settings};
use crate::message::Number;
use std::fmt;

/// One patch's inputs, as `wheelrail creep` takes them (its options, in [`RANGES`]' order).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchInputs {
    /// Semi-axis of the contact ellipse in the rolling direction, mm.
    pub a_mm: f64,
    /// Lateral semi-axis, mm.
    pub b_mm: f64,
    /// Normal force, N.
    pub normal_force_n: f64,
    /// Longitudinal creepage ξ.
    pub xi: f64,
    /// Lateral creepage η.
    pub eta: f64,
    /// Spin creepage φ, 1/mm.
    pub phi_per_mm: f64,
    /// Coefficient of friction.
    pub mu: f64,
    /// Shear modulus of both bodies, GPa.
    pub shear_modulus_gpa: f64,
    /// Poisson's ratio of both bodies.
    pub poisson: f64,
    /// Tangential model.
    pub method: Method,
    /// FASTSIM's traction bound (FASTSIM only).
    pub bound: Bound,
}

impl PatchInputs {
    /// The values checked against [`RANGES`], in its order.
    fn values(&self) -> [f64; 9] {
        [
            self.a_mm,
            self.b_mm,
            self.normal_force_n,
            self.xi,
            self.eta,
            self.phi_per_mm,
            self.mu,
            self.shear_modulus_gpa,
            self.poisson,
        ]
    }
}

/// The plausible range of one command-line value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// The option, as typed.
    pub key: &'static str,
    /// Smallest value accepted.
    pub min: f64,
    /// Largest value accepted.
    pub max: f64,
    /// Why values beyond are implausible (or meaningless).
    pub why: &'static str,
}

impl Range {
    /// Why `value` given as `key` (the option, or a binding's argument name) is refused:
    /// `KEY VALUE: expected MIN to MAX (WHY)`.
    pub fn refusal(&self, key: &str, value: f64) -> String {
        format!(
            "{key} {}: expected {} to {} ({})",
            Number(value),
            Number(self.min),
            Number(self.max),
            self.why
        )
    }
}

/// The plausible ranges of `wheelrail creep`'s values, each with its reason. All in one place.
pub const RANGES: [Range; 9] = [
    Range {
        key: "--a-mm",
        min: 0.01,
        max: 50.0,
        why: "mm; wheel-rail contact ellipses have semi-axes of 1 to 20 mm",
    },
    Range {
        key: "--b-mm",
        min: 0.01,
        max: 50.0,
        why: "mm; wheel-rail contact ellipses have semi-axes of 1 to 20 mm",
    },
    Range {
        key: "--normal-force-n",
        min: 1.0,
        max: 1e6,
        why: "N; wheel loads reach 200 kN, flange forces twice that",
    },
    Range {
        key: "--xi",
        min: -1.0,
        max: 1.0,
        why: "beyond ±1 the wheel slides faster than it rolls",
    },
    Range {
        key: "--eta",
        min: -1.0,
        max: 1.0,
        why: "beyond ±1 the wheel slides sideways faster than it rolls",
    },
    Range {
        key: "--phi-per-mm",
        min: -0.1,
        max: 0.1,
        why: "1/mm; the spin of a wheel is sin(contact angle) / radius, below 0.01 for radii above 100 mm",
    },
    Range {
        key: "--mu",
        min: 0.01,
        max: 1.0,
        why: "dry steel on steel is 0.3 to 0.6, lubricated 0.05 to 0.2",
    },
    Range {
        key: "--shear-modulus-gpa",
        min: 1.0,
        max: 1000.0,
        why: "GPa; steel is 80 to 82",
    },
    Range {
        key: "--poisson",
        min: 0.0,
        max: 0.5,
        why: "the range of Kalker's table of creep coefficients",
    },
];

/// A value outside its [`Range`], or input the creep model refuses.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum CommandError {
    /// `value` of `range.key` is outside the range (or not finite).
    Implausible {
        /// The range it failed.
        range: Range,
        /// The value given.
        value: f64,
    },
    /// The model refused the input (should not happen after the ranges).
    Creep(CreepError),
}

impl fmt::Display for CommandError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CommandError::Implausible { range, value } => {
                f.write_str(&range.refusal(range.key, *value))
            }
            CommandError::Creep(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for CommandError {}

impl From<CreepError> for CommandError {
    fn from(e: CreepError) -> Self {
        CommandError::Creep(e)
    }
}

/// MPa per GPa: the one unit conversion of a patch's inputs.
const MPA_PER_GPA: f64 = 1e3;

/// Solves the patch described by `inputs`.
///
/// # Errors
///
/// [`CommandError::Implausible`] for a value outside its [`RANGES`] entry (NaN and
/// infinities included), naming the option.
pub fn solve(inputs: &PatchInputs) -> Result<Tangential, CommandError> {
    for (range, value) in RANGES.iter().zip(inputs.values()) {
        if !(range.min..=range.max).contains(&value) {
            return Err(CommandError::Implausible {
                range: *range,
                value,
            });
        }
    }
    let settings = Settings::new(
        inputs.method,
        inputs.mu,
        inputs.shear_modulus_gpa * MPA_PER_GPA,
        inputs.poisson,
    )?
    .with_bound(inputs.bound);
    let patch = EllipticPatch::new(inputs.a_mm, inputs.b_mm, inputs.normal_force_n)?;
    let creepages = Creepages {
        xi: inputs.xi,
        eta: inputs.eta,
        phi_per_mm: inputs.phi_per_mm,
    };
    Ok(tangential::solve(&patch, &creepages, &settings))
}

/// Why a model's spin moment is NaN, in words, or `None` where it gives one (FASTSIM).
pub fn missing_spin_moment(method: Method) -> Option<&'static str> {
    match method {
        Method::Fastsim => None,
        Method::Linear => Some(
            "mz_Nmm is NaN: linear theory's spin moment needs Kalker's C33, which the committed table (Kalker 1990, Table E.3 as in CONTACT) does not hold; use the method fastsim",
        ),
        Method::Polach => {
            Some("mz_Nmm is NaN: Polach's method gives no spin moment; use the method fastsim")
        }
    }
}
