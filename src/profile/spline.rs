//! Placeholder until the smoothing spline lands: same API, piecewise-linear.

/// Placeholder.
#[derive(Debug, Clone)]
pub struct SmoothingSpline {
    x: Vec<f64>,
    y: Vec<f64>,
}

/// Placeholder.
#[derive(Debug)]
pub struct SplineError;

impl SmoothingSpline {
    /// Placeholder.
    pub fn fit(x: &[f64], y: &[f64], _lambda: f64) -> Result<Self, SplineError> {
        Ok(Self {
            x: x.to_vec(),
            y: y.to_vec(),
        })
    }
    /// Placeholder.
    pub fn domain(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }
    /// Placeholder.
    pub fn eval(&self, _x: f64) -> [f64; 3] {
        [self.y[0], 0.0, 0.0]
    }
}
