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

/// A number in a message as a user would write it: the shortest text that reads back as the
/// same `f64`, in scientific notation when it is very large or very small (`1e308`, not 309
/// digits; `1e-300`, not 300 zeros).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Number(pub f64);

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let magnitude = self.0.abs();
        if magnitude == 0.0 || !magnitude.is_finite() || (1e-4..1e16).contains(&magnitude) {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Number;

    #[test]
    fn numbers_read_as_written() {
        for (x, text) in [
            (1e308, "1e308"),
            (-1e-300, "-1e-300"),
            (70.0, "70"),
            (0.3, "0.3"),
            (1.5e-5, "1.5e-5"),
            (f64::INFINITY, "inf"),
            (0.0, "0"),
        ] {
            assert_eq!(Number(x).to_string(), text);
            assert_eq!(
                Number(x).to_string().parse::<f64>().unwrap().to_bits(),
                x.to_bits()
            );
        }
    }
}
