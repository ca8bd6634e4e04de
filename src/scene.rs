//! Scene files (placeholder, being written).

/// Error in a scene file.
#[derive(Debug)]
pub struct SceneError;

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("scene error")
    }
}
