//! Cubic smoothing splines for sampled profiles (placeholder, being written).
