//! The crate's top-level error: every failure of the numerics, each naming the file, line or
//! scene key it comes from. It sits above the stages in the module graph: it wraps each
//! public error type (a `From` for every one, so that `?` mixes them), and no module below
//! it returns it. Writing files, tables and charts fail in the crates that do them
//! (`wheelrail-report`, `wheelrail-cli`), with errors of their own that wrap this one.

use std::fmt;

/// Any error of wheelrail's numerics. The command line prints it and exits with code 2.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// A profile file could not be read or is not a valid profile.
    Profile(crate::profile::read::ReadError),
    /// A spline could not be fitted to a profile's points.
    Spline(crate::profile::SplineError),
    /// A scene file could not be read or is invalid.
    Scene(crate::scene::SceneError),
    /// A track layout or an inclination out of its range.
    Layout(crate::track::LayoutError),
    /// A wheel or rail could not be placed.
    Placement(crate::track::PlacementError),
    /// Shifts that are no sweep.
    Sweep(crate::sweep::SweepError),
    /// Settings of the roll solver out of their range.
    RollSettings(crate::rigid::RollSettingsError),
    /// Settings of the quasi-elastic search out of their range.
    QuasiElasticSettings(crate::quasi_elastic::QuasiElasticSettingsError),
    /// A Hertz input out of its range (a material, curvatures, a load).
    Hertz(crate::hertz::HertzError),
    /// Equivalent-conicity amplitudes that are not accepted.
    ConicitySettings(crate::conicity::ConicitySettingsError),
    /// A Δr function that cannot be used.
    DeltaR(crate::conicity::DeltaRError),
    /// A Δr table whose text cannot be read.
    DeltaRCsv(crate::conicity::DeltaRCsvError),
    /// Creep-force inputs out of their range, or a patch the creep forces cannot be found for.
    Creep(crate::creep::CreepError),
    /// Fleet inputs that cannot be used (a pairs file, a shard, no items).
    Fleet(crate::fleet::FleetError),
    /// Why a fleet's item failed (its row's status).
    Row(crate::fleet::RowError),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Profile(e) => write!(f, "{e}"),
            Error::Spline(e) => write!(f, "{e}"),
            Error::Scene(e) => write!(f, "{e}"),
            Error::Layout(e) => write!(f, "{e}"),
            Error::Placement(e) => write!(f, "{e}"),
            Error::Sweep(e) => write!(f, "{e}"),
            Error::RollSettings(e) => write!(f, "{e}"),
            Error::QuasiElasticSettings(e) => write!(f, "{e}"),
            Error::Hertz(e) => write!(f, "{e}"),
            Error::ConicitySettings(e) => write!(f, "{e}"),
            Error::DeltaR(e) => write!(f, "{e}"),
            Error::DeltaRCsv(e) => write!(f, "{e}"),
            Error::Creep(e) => write!(f, "creep stage: {e}"),
            Error::Fleet(e) => write!(f, "{e}"),
            Error::Row(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {}

/// `From` for each wrapped error type, so that `?` converts it.
macro_rules! from {
    ($($variant:ident($type:ty)),* $(,)?) => {
        $(impl From<$type> for Error {
            fn from(e: $type) -> Self {
                Error::$variant(e)
            }
        })*
    };
}

from! {
    Profile(crate::profile::read::ReadError),
    Spline(crate::profile::SplineError),
    Scene(crate::scene::SceneError),
    Layout(crate::track::LayoutError),
    Placement(crate::track::PlacementError),
    Sweep(crate::sweep::SweepError),
    RollSettings(crate::rigid::RollSettingsError),
    QuasiElasticSettings(crate::quasi_elastic::QuasiElasticSettingsError),
    Hertz(crate::hertz::HertzError),
    ConicitySettings(crate::conicity::ConicitySettingsError),
    DeltaR(crate::conicity::DeltaRError),
    DeltaRCsv(crate::conicity::DeltaRCsvError),
    Creep(crate::creep::CreepError),
    Fleet(crate::fleet::FleetError),
    Row(crate::fleet::RowError),
}
