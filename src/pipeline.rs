//! The stage graph (placeholder, being written).
