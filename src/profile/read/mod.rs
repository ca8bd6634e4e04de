//! Placeholder until the readers land.
use super::ProfileKind;

/// Placeholder.
#[derive(Debug)]
pub struct ReadError;

impl ReadError {
    /// Placeholder.
    pub fn spline(_path: &str, _e: super::spline::SplineError) -> Self {
        ReadError
    }
}

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("profile read error")
    }
}

/// Placeholder.
pub struct PointProfile {
    /// Placeholder.
    pub kind: ProfileKind,
    /// Placeholder.
    pub points: Vec<[f64; 2]>,
    /// Placeholder.
    pub source: ProfileSource,
}

/// Placeholder.
pub struct ProfileSource {
    /// Placeholder.
    pub path: String,
    /// Placeholder.
    pub sha256: String,
}

/// Placeholder.
pub fn read_profile(
    _path: &std::path::Path,
    _kind: ProfileKind,
) -> Result<PointProfile, ReadError> {
    Err(ReadError)
}
