//! The Hertz contact ellipse (placeholder, being written).
