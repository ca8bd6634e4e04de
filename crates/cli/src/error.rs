//! The program's error: what a command can meet, each naming the file, line, key or
//! argument it comes from. The program prints it and exits with code 2.

use std::fmt;
use std::path::PathBuf;

/// Any error of the command line.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// The numerics failed (a profile, a scene, a stage's input).
    Numerics(wheelrail::Error),
    /// A report's table or chart failed.
    Report(wheelrail_report::Error),
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
    /// A thread pool could not be started.
    ThreadPool(rayon::ThreadPoolBuildError),
    /// Command-line arguments that cannot run: what was given and what was expected.
    Usage(String),
    /// Arguments of `wheelrail hertz` outside what a wheel and rail can be.
    HertzArgs(crate::hertz::RunError),
    /// Arguments of `wheelrail creep` outside what a contact patch can be.
    CreepArgs(wheelrail::creep::command::CommandError),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Numerics(e) => write!(f, "{e}"),
            Error::Report(e) => write!(f, "{e}"),
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Output { path, problem } => write!(f, "{}: {problem}", path.display()),
            Error::WorkBudget { scene, estimate } => write!(
                f,
                "{scene}: {estimate}: refused; coarsen those keys, or run with --allow-long"
            ),
            Error::ThreadPool(e) => write!(f, "cannot start the threads: {e}"),
            Error::Usage(message) => f.write_str(message),
            Error::HertzArgs(e) => write!(f, "{e}"),
            Error::CreepArgs(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Numerics(e) => Some(e),
            Error::Report(e) => Some(e),
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
    Numerics(wheelrail::Error),
    Report(wheelrail_report::Error),
    ThreadPool(rayon::ThreadPoolBuildError),
    HertzArgs(crate::hertz::RunError),
    CreepArgs(wheelrail::creep::command::CommandError),
}

/// `From` for the numerics' error types, through [`wheelrail::Error`].
macro_rules! from_numerics {
    ($($type:ty),* $(,)?) => {
        $(impl From<$type> for Error {
            fn from(e: $type) -> Self {
                Error::Numerics(e.into())
            }
        })*
    };
}

from_numerics! {
    wheelrail::profile::read::ReadError,
    wheelrail::profile::SplineError,
    wheelrail::scene::SceneError,
    wheelrail::track::LayoutError,
    wheelrail::track::PlacementError,
    wheelrail::sweep::SweepError,
    wheelrail::rigid::RollSettingsError,
    wheelrail::quasi_elastic::QuasiElasticSettingsError,
    wheelrail::hertz::HertzError,
    wheelrail::conicity::ConicitySettingsError,
    wheelrail::conicity::DeltaRError,
    wheelrail::conicity::DeltaRCsvError,
    wheelrail::creep::CreepError,
    wheelrail::fleet::FleetError,
    wheelrail::fleet::RowError,
}

impl From<wheelrail_report::TableError> for Error {
    fn from(e: wheelrail_report::TableError) -> Self {
        Error::Report(e.into())
    }
}
