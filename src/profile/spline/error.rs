//! Why a spline could not be fitted.

use std::fmt;

/// Why a spline could not be fitted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SplineError {
    /// Fewer than two points.
    TooFewPoints {
        /// Points given.
        found: usize,
    },
    /// `x` and `y` differ in length.
    LengthMismatch {
        /// Length of `x`.
        x: usize,
        /// Length of `y`.
        y: usize,
    },
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// Index of the point.
        index: usize,
    },
    /// `x[index]` is not larger than `x[index - 1]`.
    NonIncreasing {
        /// Index of the point.
        index: usize,
    },
    /// `lambda` is negative or not finite.
    InvalidLambda {
        /// The value given.
        lambda: f64,
    },
    /// The banded solve broke down (a pivot that should be positive was not), which only
    /// extreme spacing ratios combined with extreme `lambda` can cause.
    NumericalBreakdown {
        /// Index of the interior knot where it happened.
        index: usize,
    },
}

impl fmt::Display for SplineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SplineError::TooFewPoints { found } => {
                write!(f, "a spline needs at least 2 points, got {found}")
            }
            SplineError::LengthMismatch { x, y } => {
                write!(f, "x has {x} values but y has {y}")
            }
            SplineError::NonFinite { index } => {
                write!(f, "point {index} is NaN or infinite")
            }
            SplineError::NonIncreasing { index } => write!(
                f,
                "x must increase strictly, but x[{index}] <= x[{}]",
                index.saturating_sub(1)
            ),
            SplineError::InvalidLambda { lambda } => {
                write!(f, "smoothing parameter {lambda} must be finite and >= 0")
            }
            SplineError::NumericalBreakdown { index } => {
                write!(f, "the spline system broke down at knot {index}")
            }
        }
    }
}

impl std::error::Error for SplineError {}
