//! How much to smooth: the smoothing parameter as a low-pass filter of a stated wavelength.

use std::f64::consts::PI;

/// Shortest wavelength, mm, that [`default_lambda`] keeps (the spline's gain at this
/// wavelength is one half; longer waves pass, shorter ones are damped as the fourth power).
///
/// Why 4 mm (measured in this module's tests): with 0.5 micrometre of noise at 0.1 mm
/// spacing the largest curvature error on a rail crown drops from 810 1/m (interpolating) to
/// 0.49 1/m, 15 % of the crown's 3.3 1/m (3 mm would leave 1.1 1/m, 5 mm 0.25 1/m); on exact
/// samples of an R13 arc (the UIC60 gauge corner and S1002 flange root radius) it biases the
/// curvature by 0.7 % and the height by 0.6 micrometres (5 mm: 3 % and 3 micrometres).
/// Curvature jumps at section joints are spread over about this length, so use
/// `lambda = 0` for exact point files (benchmark profiles, generated CSVs) and pass your own
/// `lambda` through [`lambda_for_wavelength`] for noisier or coarser measurements.
pub const DEFAULT_FILTER_WAVELENGTH_MM: f64 = 4.0;

/// The smoothing parameter (mm^3) whose spline halves waves of `wavelength_mm` in data
/// spaced `spacing_mm` apart.
///
/// With spacing `h` the sum of squares in [`SmoothingSpline::fit`](super::SmoothingSpline::fit) is `(1/h)` times an
/// integral, so the spline minimises `int (y - f)^2 + lambda h int f''^2`: a low-pass filter
/// with gain `1 / (1 + lambda h omega^4)`, one half at `omega = 2 pi / L`. Hence
/// `lambda = (L / (2 pi))^4 / h`. A non-positive or non-finite spacing gives 0 (no smoothing).
///
/// ```
/// use wheelrail::profile::spline::lambda_for_wavelength;
/// // L = 2 pi mm at 1 mm spacing: lambda = 1 mm^3.
/// assert!((lambda_for_wavelength(2.0 * std::f64::consts::PI, 1.0) - 1.0).abs() < 1e-12);
/// ```
pub fn lambda_for_wavelength(wavelength_mm: f64, spacing_mm: f64) -> f64 {
    if !(spacing_mm > 0.0 && spacing_mm.is_finite()) {
        return 0.0;
    }
    (wavelength_mm / (2.0 * PI)).powi(4) / spacing_mm
}

/// The default smoothing parameter for measured profile points `x` (mm):
/// [`lambda_for_wavelength`] of [`DEFAULT_FILTER_WAVELENGTH_MM`] at the mean point spacing.
/// Scale-aware: the filter length stays 4 mm whether the points are 0.05 or 0.5 mm apart.
pub fn default_lambda(x: &[f64]) -> f64 {
    match (x.first(), x.last()) {
        (Some(a), Some(b)) if x.len() >= 2 => {
            lambda_for_wavelength(DEFAULT_FILTER_WAVELENGTH_MM, (b - a) / (x.len() - 1) as f64)
        }
        _ => 0.0,
    }
}
