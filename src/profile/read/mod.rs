//! Profile file readers (placeholder, being written).

/// Error reading a profile file.
#[derive(Debug)]
pub struct ReadError;

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("profile read error")
    }
}
