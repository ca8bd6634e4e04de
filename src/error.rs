//! The crate's top-level error: every failure a run can meet, each naming the file, line or
//! scene key it comes from.

use std::fmt;

/// Any error of a wheelrail run. The CLI prints it and exits with code 2.
#[derive(Debug)]
pub enum Error {
    /// A profile file could not be read or is not a valid profile.
    Profile(crate::profile::read::ReadError),
    /// A scene file could not be read or is invalid.
    Scene(crate::scene::SceneError),
    /// Writing an output failed.
    Io {
        /// The file or folder being written.
        path: std::path::PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// Any other failure, described in words.
    Other(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Profile(e) => write!(f, "{e}"),
            Error::Scene(e) => write!(f, "{e}"),
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Other(msg) => f.write_str(msg),
        }
    }
}

impl std::error::Error for Error {}

impl From<crate::profile::read::ReadError> for Error {
    fn from(e: crate::profile::read::ReadError) -> Self {
        Error::Profile(e)
    }
}

impl From<crate::scene::SceneError> for Error {
    fn from(e: crate::scene::SceneError) -> Self {
        Error::Scene(e)
    }
}
