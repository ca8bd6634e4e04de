//! The report's error: a failure of the numerics a report runs, or of a table or chart it
//! makes, each saying what failed.

use crate::{ChartError, TableError};
use std::fmt;

/// Any error of a report.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// The numerics failed (a profile, a scene, a stage's input).
    Numerics(wheelrail::Error),
    /// A table whose columns do not fit together.
    Table(TableError),
    /// A chart that cannot be rendered (its name and why).
    Chart(String, ChartError),
    /// A figure asked for a stage result the pipeline did not compute (the results of
    /// another scene).
    MissingStage {
        /// The figure.
        figure: &'static str,
        /// The stage it draws.
        stage: &'static str,
    },
    /// A thread pool could not be started (a study timed on one thread).
    ThreadPool(rayon::ThreadPoolBuildError),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Numerics(e) => write!(f, "{e}"),
            Error::Table(e) => write!(f, "internal error building a table: {e}"),
            Error::Chart(name, e) => write!(f, "figure {name}: {e}"),
            Error::MissingStage { figure, stage } => {
                write!(f, "figure {figure} needs stage {stage} which did not run")
            }
            Error::ThreadPool(e) => write!(f, "cannot start the threads: {e}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Numerics(e) => Some(e),
            Error::Table(e) => Some(e),
            Error::Chart(_, e) => Some(e),
            Error::ThreadPool(e) => Some(e),
            Error::MissingStage { .. } => None,
        }
    }
}

impl From<wheelrail::Error> for Error {
    fn from(e: wheelrail::Error) -> Self {
        Error::Numerics(e)
    }
}

impl From<rayon::ThreadPoolBuildError> for Error {
    fn from(e: rayon::ThreadPoolBuildError) -> Self {
        Error::ThreadPool(e)
    }
}

impl From<TableError> for Error {
    fn from(e: TableError) -> Self {
        Error::Table(e)
    }
}

/// `From` for the numerics' error types, through [`wheelrail::Error`], so that `?` converts
/// them.
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
    wheelrail::hertz::HertzError,
    wheelrail::conicity::DeltaRError,
    wheelrail::conicity::DeltaRCsvError,
    wheelrail::creep::CreepError,
    wheelrail::fleet::FleetError,
}
