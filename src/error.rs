//! The crate's top-level error: every failure a run can meet, each naming the file, line or
//! scene key it comes from. It sits above the numerics in the module graph: it wraps each
//! public error type (a `From` for every one, so that `?` mixes them), and no module below
//! it returns it.

use std::fmt;
use std::path::PathBuf;

/// Any error of wheelrail. The CLI prints it and exits with code 2.
#[derive(Debug)]
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
    /// A file or folder could not be read or written.
    Io {
        /// The file or folder.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// An output that cannot be written where it is asked for (a file in the way of a
    /// folder, a name that is no file name, a folder another run is writing).
    Output {
        /// The file or folder.
        path: PathBuf,
        /// What is in the way.
        problem: String,
    },
    /// A scene whose estimated work exceeds the budget, refused (see `wheelrail report
    /// --allow-long`).
    WorkBudget {
        /// The scene (or a fleet's template) and what the estimate is about.
        scene: String,
        /// The estimate and the keys that drive it.
        estimate: String,
    },
    /// A figure asked for a stage result the pipeline did not compute (the results of
    /// another scene).
    MissingStage {
        /// The figure.
        figure: &'static str,
        /// The stage it draws.
        stage: &'static str,
    },
    /// A thread pool could not be started.
    ThreadPool(rayon::ThreadPoolBuildError),
    /// Command-line arguments that cannot run: what was given and what was expected.
    #[cfg(feature = "cli")]
    Usage(String),
    /// A table whose columns do not fit together.
    Table(crate::report::TableError),
    /// A chart that cannot be rendered (its name and why).
    #[cfg(feature = "cli")]
    Chart(String, crate::report::ChartError),
    /// Arguments of `wheelrail hertz` outside what a wheel and rail can be.
    #[cfg(feature = "cli")]
    HertzArgs(crate::hertz::cli::RunError),
    /// Arguments of `wheelrail creep` outside what a contact patch can be.
    #[cfg(feature = "cli")]
    CreepArgs(crate::creep::command::CommandError),
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
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Output { path, problem } => write!(f, "{}: {problem}", path.display()),
            Error::WorkBudget { scene, estimate } => write!(
                f,
                "{scene}: {estimate}: refused; coarsen those keys, or run with --allow-long"
            ),
            Error::MissingStage { figure, stage } => {
                write!(f, "figure {figure} needs stage {stage} which did not run")
            }
            Error::ThreadPool(e) => write!(f, "cannot start the threads: {e}"),
            #[cfg(feature = "cli")]
            Error::Usage(message) => f.write_str(message),
            Error::Table(e) => write!(f, "internal error building a table: {e}"),
            #[cfg(feature = "cli")]
            Error::Chart(name, e) => write!(f, "figure {name}: {e}"),
            #[cfg(feature = "cli")]
            Error::HertzArgs(e) => write!(f, "{e}"),
            #[cfg(feature = "cli")]
            Error::CreepArgs(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

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
    ThreadPool(rayon::ThreadPoolBuildError),
}

from! {
    Table(crate::report::TableError),
}

#[cfg(feature = "cli")]
from! {
    HertzArgs(crate::hertz::cli::RunError),
    CreepArgs(crate::creep::command::CommandError),
}
