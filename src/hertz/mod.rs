//! The Hertz contact ellipse (paper Eqs. 9-20; Johnson 1985, section 4.2).
//!
//! Stage entry: [`ellipse`], from the relative curvatures `A` (rolling) and `B` (lateral), the
//! normal load and the effective modulus, to the semi-axes, pressures and approach.
//! [`relative_curvatures`] builds `A`, `B` from the principal curvatures of wheel and rail
//! (paper Eqs. 12-13) and [`effective_modulus`] the modulus `E*` (paper Eq. 10).
//!
//! # Units
//!
//! Millimetres, newtons, megapascals (N/mm²), radians; curvatures in 1/mm, convex positive.
//!
//! # Methods
//!
//! * [`EllipseMethod::Exact`] (default): `K` and `E` by the arithmetic-geometric mean from `(1, b/a)`,
//!   the shape equation in cancellation-free form, Newton in `ln(b/a)` from Greenwood's start
//!   corrected by a fitted polynomial (one Newton step for `A/B ≥ 7e-13`).
//!   Relative error at most 1.5e-15 for `a`, `b`, `p0` and the approach against 50-digit
//!   mpmath references (`tests/data/hertz_reference.csv`, `scripts/hertz_reference.py`) over
//!   `A/B ∈ [1e-9, 1]` (the tests demand 1e-12); finite and monotonic down to `A/B = 1e-300`.
//! * [`EllipseMethod::Paper`]: the paper's truncated series and fixed-point iteration as stated
//!   (`paper.rs`), kept to measure it.
//!
//! # Accuracy of the paper's method
//!
//! Produced by `cargo test --test hertz -- --nocapture paper_error_table` (relative error of
//! the paper's `b/a` against the exact one, its fixed-point iterations and stop reason; the
//! paper's thresholds 10⁻³ for the series terms and for `|Δe|`, start `e = 0.5`):
//!
//! ```text
//!      A/B   b/a exact     err b/a       err a      err p0  iter         stop
//!     1e-6    0.000346    +5.01e-1    -2.33e-1    +1.33e-1     2 converged
//!     1e-5    0.001185    +3.86e-1    -1.91e-1    +1.03e-1     2 converged
//!     1e-4    0.004125    +2.66e-1    -1.39e-1    +6.50e-2     2 converged
//!     1e-3    0.014734    +1.63e-1    -7.52e-2    +5.27e-3     2 converged
//!     0.01    0.054984    +4.97e-2    -2.31e-2    -1.71e-3     3 converged
//!     0.05    0.144328    +1.84e-2    -8.19e-3    -1.81e-3     4 converged
//!      0.1    0.222250    +1.29e-2    -5.44e-3    -1.91e-3     4 converged
//!      0.2    0.345999    +7.03e-3    -3.24e-3    -5.15e-4     5 converged
//!      0.5    0.630596    +2.83e-3    -1.28e-3    -2.71e-4     5 converged
//!      0.8    0.861803    +1.43e-3    -6.67e-4    -9.62e-5     2 converged
//!      0.9    0.932173    +4.57e-4    -2.45e-4    +3.44e-5     5 converged
//!     0.99    0.993322    +2.97e-5    -2.12e-5    +1.27e-5     6 converged
//!    0.999    0.999333    -5.04e-4    -1.67e-4    +8.38e-4     5 left_domain
//!        1    1.000000    -5.13e-4   +4.62e-14    +5.13e-4     5 left_domain
//! ```
//!
//! (`err` = paper / exact - 1; `a` is the major semi-axis here.) The errors come mostly from
//! the `K` series near `e = 1` (-17 % at `e = 0.9999`, see `accuracy::series_error`): for
//! elongated contacts the fixed point jumps from `e = 0.5` to within 10⁻³ of its limit in two
//! updates, so the loose `|Δe|` stop is not the limiting factor there. Near the circle the
//! truncated series make the update leave `0 < e < 1` and the result is flagged
//! [`Stop::LeftDomain`], although `b/a` is then within 10⁻³. The exact method is also the
//! faster one, at every `A/B` from 1e-3 to 1 (`cargo bench --bench hertz` times both per
//! solve): the arithmetic-geometric mean converges quadratically, where the paper's fixed
//! point sums its series again at every update, with more terms as `e` nears 1.
//!
//! # References
//!
//! * A. Onat, P. Voltr, M. Lata (2014), Nonlinear wheel/rail contact geometry characteristics &
//!   determination of Hertzian contact, Scientific Papers of the University of Pardubice,
//!   Series B 19: Eqs. 9-20.
//! * K. L. Johnson (1985), Contact Mechanics, Cambridge University Press: §4.1 (relative
//!   curvatures), §4.2 (Hertz theory of the elliptic contact). Cited by section: the equation
//!   numbers were not checked against the book.
//! * J. A. Greenwood (1997), Analysis of elliptical Hertzian contacts, Tribology
//!   International 30(3), 235-237: the start `b/a ≈ (A/B)^(2/3)`.
//! * B. C. Carlson (1995), Numerical computation of real or complex elliptic integrals,
//!   Numerical Algorithms 10, 13-26: `R_D`, for the cancellation-free ratio.

pub mod accuracy;
mod elliptic;
mod exact;
pub(crate) mod paper;
mod sweep;

pub use accuracy::HertzAccuracy;
pub use sweep::{
    ContactSource, Contacts, HertzPosition, HertzSettings, HertzSweep, NormalLoad, SideHertz, sweep,
};

use std::f64::consts::PI;
use std::fmt;

/// Why the shape solve stopped (shared with [`crate::rigid`]).
pub use crate::Stop;

/// An isotropic linear-elastic material.
///
/// # Units
///
/// `young_mpa` in MPa (N/mm²); `poisson` dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    pub(crate) young_mpa: f64,
    pub(crate) poisson: f64,
}

impl Material {
    /// A checked material.
    ///
    /// # Units
    ///
    /// `young_mpa` in MPa (N/mm²); `poisson` dimensionless.
    ///
    /// # Errors
    ///
    /// [`HertzError::NonFinite`] if either value is NaN or infinite,
    /// [`HertzError::NonPositiveModulus`] if `young_mpa <= 0`,
    /// [`HertzError::PoissonOutOfRange`] unless `-1 < poisson < 0.5` (the range where the
    /// strain energy is positive definite; 0.5 itself makes the Hertz compliance term vanish
    /// only for an incompressible body, which the crate does not model).
    ///
    /// # Example
    ///
    /// ```
    /// use wheelrail::hertz::{HertzError, Material};
    /// let steel = Material::new(210_000.0, 0.3)?;
    /// assert!(matches!(Material::new(210_000.0, 0.5), Err(HertzError::PoissonOutOfRange { .. })));
    /// # Ok::<(), HertzError>(())
    /// ```
    pub fn new(young_mpa: f64, poisson: f64) -> Result<Material, HertzError> {
        finite("young_mpa", young_mpa)?;
        finite("poisson", poisson)?;
        if young_mpa <= 0.0 {
            return Err(HertzError::NonPositiveModulus {
                value_mpa: young_mpa,
            });
        }
        if !(poisson > -1.0 && poisson < 0.5) {
            return Err(HertzError::PoissonOutOfRange { poisson });
        }
        Ok(Material { young_mpa, poisson })
    }

    /// Young's modulus (MPa), positive and finite.
    pub fn young_mpa(&self) -> f64 {
        self.young_mpa
    }

    /// Poisson's ratio, in `(-1, 0.5)`.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }
}

/// The effective (contact) modulus `E*` of two bodies, paper Eq. 10 (Johnson 1985, §4.2):
/// `1/E* = (1 - ν₁²)/E₁ + (1 - ν₂²)/E₂`.
///
/// # Units
///
/// MPa.
///
/// # Example
///
/// ```
/// use wheelrail::hertz::{Material, effective_modulus};
/// let steel = Material::new(210_000.0, 0.3)?;
/// // E / (2 (1 - ν²)) = 210000 / 1.82
/// assert!((effective_modulus(&steel, &steel) - 115_384.615_384_615_4).abs() < 1e-9);
/// # Ok::<(), wheelrail::hertz::HertzError>(())
/// ```
pub fn effective_modulus(m1: &Material, m2: &Material) -> f64 {
    let compliance = (1.0 - m1.poisson * m1.poisson) / m1.young_mpa
        + (1.0 - m2.poisson * m2.poisson) / m2.young_mpa;
    1.0 / compliance
}

/// Principal curvatures of wheel (body 1) and rail (body 2) at the contact point.
///
/// # Units
///
/// 1/mm, **positive where the surface is convex** (bulging towards the other body), negative
/// where concave (the S1002 flange root, a worn rail's gauge corner seen from the wheel), zero
/// for a straight generator (the rail in the rolling direction on straight track).
///
/// # Frame
///
/// "Rolling" is the body's principal direction closest to the track's x (running) direction,
/// "lateral" the one perpendicular to it in the contact tangent plane. The angle between the
/// rolling directions of the two bodies is the `psi_rad` of [`relative_curvatures`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalCurvatures {
    /// Wheel, rolling direction: `cos(γ)/r` for rolling radius `r` and contact angle `γ`.
    pub wheel_rolling: f64,
    /// Wheel, lateral: curvature of the wheel profile curve at the contact point.
    pub wheel_lateral: f64,
    /// Rail, rolling direction: 0 on straight track.
    pub rail_rolling: f64,
    /// Rail, lateral: curvature of the rail profile curve at the contact point.
    pub rail_lateral: f64,
}

/// The relative curvatures `(A, B)` of two bodies, paper Eqs. 12-13 (Johnson 1985, §4.1)
/// for a general angle `psi_rad` between their principal directions.
///
/// `A + B = ½ (k₁ₓ + k₁ᵧ + k₂ₓ + k₂ᵧ)` (Eq. 12) and
/// `|B - A| = ½ sqrt((k₁ₓ - k₁ᵧ)² + (k₂ₓ - k₂ᵧ)² + 2 (k₁ₓ - k₁ᵧ)(k₂ₓ - k₂ᵧ) cos 2ψ)` (Eq. 13).
/// `2A`, `2B` are the eigenvalues of the sum of the two curvature tensors; the paper's
/// convention `B ≥ A` is **not** used. Instead:
///
/// * `A` belongs to the principal direction of the relative curvature that lies within 45° of
///   the wheel's rolling direction, `B` to the one within 45° of the wheel's lateral direction
///   (the Jacobi rotation of smallest angle). At exactly 45° (equal diagonal terms) the tie goes
///   to `A = ` the larger one. The contact ellipse's `a` (see [`Ellipse::a_mm`]) lies along the
///   direction of `A`.
/// * For `psi_rad = 0` this is exactly `A = (k₁ₓ + k₂ₓ)/2`, `B = (k₁ᵧ + k₂ᵧ)/2`.
///
/// `psi_rad` is the angle from the wheel's rolling direction to the rail's, about the
/// common normal; only `cos 2ψ`, `sin 2ψ` enter, so its sign and a turn of π do not matter to
/// `A`, `B`.
///
/// # Units
///
/// Curvatures in 1/mm (convex positive), `psi_rad` in rad; returns 1/mm.
///
/// # Example
///
/// ```
/// use wheelrail::hertz::{PrincipalCurvatures, relative_curvatures};
/// // Wheel r = 460 mm with a flat tread on a rail crown of 300 mm, straight track.
/// let k = PrincipalCurvatures {
///     wheel_rolling: 1.0 / 460.0,
///     wheel_lateral: 0.0,
///     rail_rolling: 0.0,
///     rail_lateral: 1.0 / 300.0,
/// };
/// let (a, b) = relative_curvatures(&k, 0.0);
/// assert!((a - 0.5 / 460.0).abs() < 1e-18 && (b - 0.5 / 300.0).abs() < 1e-18);
/// ```
pub fn relative_curvatures(k: &PrincipalCurvatures, psi_rad: f64) -> (f64, f64) {
    let (sin, cos) = psi_rad.sin_cos();
    // Sum of the two curvature tensors in the wheel's principal frame (x rolling, y lateral);
    // the rail's tensor is rotated by psi.
    let txx = k.wheel_rolling + k.rail_rolling * cos * cos + k.rail_lateral * sin * sin;
    let tyy = k.wheel_lateral + k.rail_rolling * sin * sin + k.rail_lateral * cos * cos;
    let txy = (k.rail_rolling - k.rail_lateral) * sin * cos;
    if txy == 0.0 {
        return (0.5 * txx, 0.5 * tyy);
    }
    // Jacobi rotation of smallest angle (|angle| <= 45°), Numerical Recipes §11.1: the tangent
    // t of the angle that diagonalises the tensor, without cancellation.
    let theta = (tyy - txx) / (2.0 * txy);
    let t = if theta.abs() > 1e150 {
        // theta² would overflow; t -> 1/(2 theta).
        0.5 / theta
    } else {
        let t = 1.0 / (theta.abs() + (theta * theta + 1.0).sqrt());
        if theta < 0.0 { -t } else { t }
    };
    (0.5 * (txx - t * txy), 0.5 * (tyy + t * txy))
}

/// How [`ellipse`] evaluates the elliptic integrals and the shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum EllipseMethod {
    /// AGM for `K`, `E`, cancellation-free shape equation, Newton in `ln(b/a)`: machine
    /// precision.
    #[default]
    Exact,
    /// The paper's truncated series and fixed-point iteration with its thresholds (module
    /// `hertz::paper`); errors of per cent level.
    Paper,
}

impl fmt::Display for EllipseMethod {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            EllipseMethod::Exact => "exact",
            EllipseMethod::Paper => "paper",
        })
    }
}

/// Why a contact is not Hertzian: the gap between the bodies is not a positive-definite
/// quadratic form, so there is no elliptic contact patch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NotHertzianReason {
    /// `A + B <= 0`: the surfaces are conformal or concave overall (the bodies nest).
    Conformal,
    /// `A <= 0` with `A + B > 0`: no closure in the rolling direction (a line contact at
    /// `A = 0`, a saddle-shaped gap below).
    NonPositiveRolling,
    /// `B <= 0` with `A + B > 0`: no closure in the lateral direction (conformal lateral
    /// profiles, e.g. a flange root on a gauge corner).
    NonPositiveLateral,
}

impl fmt::Display for NotHertzianReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            NotHertzianReason::Conformal => "conformal: A + B <= 0",
            NotHertzianReason::NonPositiveRolling => "not Hertzian: A <= 0 (rolling direction)",
            NotHertzianReason::NonPositiveLateral => "not Hertzian: B <= 0 (lateral direction)",
        })
    }
}

/// The Hertz contact ellipse and pressure.
///
/// # Frame
///
/// `a_mm` is the semi-axis along the direction of `A` (rolling, x), `b_mm` along `B`
/// (lateral), whichever is longer.
///
/// # Units
///
/// mm, MPa; `eccentricity` dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    /// Semi-axis along the rolling direction (the direction of `A`), mm.
    pub a_mm: f64,
    /// Semi-axis along the lateral direction (the direction of `B`), mm.
    pub b_mm: f64,
    /// Maximum pressure `p0 = 3 P / (2 π a b)` (paper Eq. 11), MPa.
    pub p0_mpa: f64,
    /// Mean pressure `P / (π a b) = 2 p0 / 3`, MPa.
    pub mean_pressure_mpa: f64,
    /// Approach of distant points `δ = 3 P K / (2 π a_major E*)` (Johnson 1985, §4.2,
    /// with the major semi-axis), mm. Sphere on plane: `δ = a²/R`.
    pub approach_mm: f64,
    /// Eccentricity of the ellipse, `sqrt(1 - (minor/major)²)` (paper Eq. 9).
    pub eccentricity: f64,
    /// Iterations of the shape solve (Newton steps or fixed-point updates; 0 for the circle).
    pub iterations: u32,
    /// Why the shape solve stopped.
    pub stop: Stop,
    /// The method that produced these numbers.
    pub method: EllipseMethod,
}

/// Outcome of [`ellipse`]: the contact is Hertzian, or the reason it is not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// An elliptic Hertz contact.
    Hertzian(Ellipse),
    /// No elliptic contact patch exists for these curvatures.
    NotHertzian(NotHertzianReason),
}

impl Contact {
    /// The ellipse, if the contact is Hertzian.
    pub fn ellipse(&self) -> Option<&Ellipse> {
        match self {
            Contact::Hertzian(e) => Some(e),
            Contact::NotHertzian(_) => None,
        }
    }
}

/// Invalid input to the Hertz stage.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum HertzError {
    /// A value that must be finite is NaN or infinite.
    NonFinite {
        /// Name of the input.
        quantity: &'static str,
        /// Its value.
        value: f64,
    },
    /// The normal load is zero or negative (no contact is not a load case).
    NonPositiveLoad {
        /// The load, N.
        load_n: f64,
    },
    /// A modulus (Young's or effective) is zero or negative.
    NonPositiveModulus {
        /// The modulus, MPa.
        value_mpa: f64,
    },
    /// Poisson's ratio outside `(-1, 0.5)`.
    PoissonOutOfRange {
        /// The ratio.
        poisson: f64,
    },
    /// A principal radius of curvature of exactly zero (an edge: infinite curvature).
    ZeroRadius {
        /// Name of the radius.
        quantity: &'static str,
    },
    /// The inputs are valid but the result overflows an f64 (e.g. a semi-axis above 1e308 mm).
    NonFiniteResult,
}

impl fmt::Display for HertzError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HertzError::NonFinite { quantity, value } => {
                write!(f, "{quantity} must be finite, got {value}")
            }
            HertzError::NonPositiveLoad { load_n } => {
                write!(f, "the normal load must be positive, got {load_n} N")
            }
            HertzError::NonPositiveModulus { value_mpa } => {
                write!(f, "the modulus must be positive, got {value_mpa} MPa")
            }
            HertzError::PoissonOutOfRange { poisson } => {
                write!(f, "Poisson's ratio must lie in (-1, 0.5), got {poisson}")
            }
            HertzError::ZeroRadius { quantity } => {
                write!(
                    f,
                    "{quantity} is zero (an edge); use inf for a flat direction"
                )
            }
            HertzError::NonFiniteResult => {
                f.write_str("the Hertz solution overflows (inputs too extreme for f64)")
            }
        }
    }
}

impl std::error::Error for HertzError {}

fn finite(quantity: &'static str, value: f64) -> Result<(), HertzError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(HertzError::NonFinite { quantity, value })
    }
}

/// The Hertz contact ellipse for relative curvatures `A` (rolling) and `B` (lateral), normal
/// load `P` and effective modulus `E*` (paper Eqs. 9-20; Johnson 1985, §4.2).
///
/// With the smaller relative curvature `A'` and the larger `B'`, the axis ratio
/// `g = minor/major` solves `A'/B' = (K - E)/((1/g²) E - K)` (paper Eq. 14), the major
/// semi-axis (along `A'`) is `a³ = 3 P (K - E)/(2 π E* e² A')` (paper Eq. 20), the minor one
/// `g a`, then `p0 = 3 P/(2 π a b)` (paper Eq. 11) and `δ = 3 P K/(2 π a E*)`. The result is
/// swapped back so that [`Ellipse::a_mm`] lies along `A` and [`Ellipse::b_mm`] along `B`.
///
/// # Units
///
/// `a_per_mm`, `b_per_mm` in 1/mm (see [`relative_curvatures`]), `load_n` in N,
/// `e_star_mpa` in MPa; the ellipse in mm and MPa.
///
/// # Errors
///
/// [`HertzError::NonFinite`] for a NaN or infinite input, [`HertzError::NonPositiveLoad`],
/// [`HertzError::NonPositiveModulus`] for `e_star_mpa <= 0`, [`HertzError::NonFiniteResult`]
/// if the semi-axes overflow. Non-positive curvatures are not errors: they give
/// [`Contact::NotHertzian`].
///
/// # Example
///
/// ```
/// use wheelrail::hertz::{Contact, EllipseMethod, ellipse};
/// // Steel sphere R = 10 mm on a steel plane, P = 100 N, E* = 115384.6 MPa:
/// // a = (3 P R / (4 E*))^(1/3) = 0.186 626 mm (Johnson 1985, §4.2).
/// let e_star = 210_000.0 / (2.0 * (1.0 - 0.09));
/// let Contact::Hertzian(c) = ellipse(0.05, 0.05, 100.0, e_star, EllipseMethod::Exact)? else {
///     panic!("convex bodies are Hertzian");
/// };
/// let a = (3.0 * 100.0 * 10.0 / (4.0 * e_star)).cbrt();
/// assert!((c.a_mm / a - 1.0).abs() < 1e-14 && (c.b_mm / a - 1.0).abs() < 1e-14);
/// assert!((c.approach_mm / (a * a / 10.0) - 1.0).abs() < 1e-14);
/// # Ok::<(), wheelrail::hertz::HertzError>(())
/// ```
pub fn ellipse(
    a_per_mm: f64,
    b_per_mm: f64,
    load_n: f64,
    e_star_mpa: f64,
    method: EllipseMethod,
) -> Result<Contact, HertzError> {
    finite("A", a_per_mm)?;
    finite("B", b_per_mm)?;
    finite("load", load_n)?;
    finite("effective modulus", e_star_mpa)?;
    if load_n <= 0.0 {
        return Err(HertzError::NonPositiveLoad { load_n });
    }
    if e_star_mpa <= 0.0 {
        return Err(HertzError::NonPositiveModulus {
            value_mpa: e_star_mpa,
        });
    }
    // Halves avoid overflow of A + B near f64::MAX.
    if 0.5 * a_per_mm + 0.5 * b_per_mm <= 0.0 {
        return Ok(Contact::NotHertzian(NotHertzianReason::Conformal));
    }
    if a_per_mm <= 0.0 {
        return Ok(Contact::NotHertzian(NotHertzianReason::NonPositiveRolling));
    }
    if b_per_mm <= 0.0 {
        return Ok(Contact::NotHertzian(NotHertzianReason::NonPositiveLateral));
    }
    let rolling_is_major = a_per_mm <= b_per_mm;
    let (small, large) = if rolling_is_major {
        (a_per_mm, b_per_mm)
    } else {
        (b_per_mm, a_per_mm)
    };
    // Major semi-axis from a³ = 3 P D / (2 π E* A') with D = (K - E)/e².
    let (g, eccentricity, k, d, iterations, stop) = match method {
        EllipseMethod::Exact => {
            let ratio = small / large;
            let ln_ratio = if ratio >= f64::MIN_POSITIVE {
                ratio.ln()
            } else {
                small.ln() - large.ln()
            };
            let s = exact::shape(ratio, ln_ratio);
            let e = ((1.0 - s.g) * (1.0 + s.g)).sqrt();
            (s.g, e, s.k, s.d, s.iterations, s.stop)
        }
        EllipseMethod::Paper => {
            let s = paper::eccentricity(small / large, &paper::PaperSettings::default());
            let e = s.eccentricity;
            let e_sq = e * e;
            // (1 - e)(1 + e), not 1 - e²: e is within 1e-7 of 1 for A/B = 1e-6.
            let g = ((1.0 - e) * (1.0 + e)).sqrt();
            let d = (s.k - s.e_integral) / e_sq;
            (g, s.eccentricity, s.k, d, s.iterations, s.stop)
        }
    };
    let major = (3.0 * load_n * d / (2.0 * PI * e_star_mpa * small)).cbrt();
    let minor = g * major;
    let p0 = 3.0 * load_n / (2.0 * PI * major * minor);
    let approach = 3.0 * load_n * k / (2.0 * PI * major * e_star_mpa);
    if !(major.is_finite() && minor > 0.0 && p0.is_finite() && approach.is_finite()) {
        return Err(HertzError::NonFiniteResult);
    }
    let (a_mm, b_mm) = if rolling_is_major {
        (major, minor)
    } else {
        (minor, major)
    };
    Ok(Contact::Hertzian(Ellipse {
        a_mm,
        b_mm,
        p0_mpa: p0,
        mean_pressure_mpa: p0 * (2.0 / 3.0),
        approach_mm: approach,
        eccentricity,
        iterations,
        stop,
        method,
    }))
}
