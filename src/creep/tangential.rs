//! The tangential problem of one elliptic patch with a known normal force: one interface,
//! `solve`, for the three models ([`super::Method`]).
//!
//! # Signs
//!
//! Forces of the wheel on the rail in the contact frame, creepages of the rail relative to
//! the wheel ([`super`] module docs): `Fx = -G c² C11 ξ` at small creepage for every model.

use super::coefficients::{self, Coefficients};
use super::creepage::Creepages;
use super::error::{check_normal_force, check_semi_axes};
use super::{CreepError, Method, Settings};

/// An elliptic contact patch and its normal force, checked by [`EllipticPatch::new`].
///
/// # Units
///
/// mm, N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticPatch {
    a_mm: f64,
    b_mm: f64,
    normal_force_n: f64,
}

impl EllipticPatch {
    /// A patch with semi-axes `a_mm` (rolling direction) and `b_mm` (lateral) pressed by
    /// `normal_force_n`.
    ///
    /// # Units
    ///
    /// mm, N.
    ///
    /// # Errors
    ///
    /// [`CreepError::SemiAxes`] unless both semi-axes are positive and finite,
    /// [`CreepError::NormalForce`] unless the force is.
    pub fn new(a_mm: f64, b_mm: f64, normal_force_n: f64) -> Result<EllipticPatch, CreepError> {
        check_semi_axes(a_mm, b_mm)?;
        check_normal_force(normal_force_n)?;
        Ok(EllipticPatch {
            a_mm,
            b_mm,
            normal_force_n,
        })
    }

    /// Semi-axis along the rolling direction, mm.
    pub fn a_mm(&self) -> f64 {
        self.a_mm
    }
    /// Lateral semi-axis, mm.
    pub fn b_mm(&self) -> f64 {
        self.b_mm
    }
    /// Normal force, N.
    pub fn normal_force_n(&self) -> f64 {
        self.normal_force_n
    }
    /// `c = √(ab)`, the radius of the circle of the same area, mm.
    pub fn c_mm(&self) -> f64 {
        (self.a_mm * self.b_mm).sqrt()
    }
}

/// The solution of the tangential problem on one patch.
///
/// # Units
///
/// N, N mm; forces of the wheel on the rail in the contact frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tangential {
    /// Longitudinal force `Fx` (along the rail), N.
    pub fx_n: f64,
    /// Lateral force `Fy` (in the tangent plane), N.
    pub fy_n: f64,
    /// Spin moment `Mz` about the normal, N mm; NaN for the models that give none (linear
    /// theory without Kalker's `C33`, which the committed table lacks; Polach's method).
    pub mz_nmm: f64,
    /// Share of the patch's area in adhesion (1 for linear theory, which assumes it).
    pub adhesion_fraction: f64,
    /// Kalker's coefficients of the patch's ellipse.
    pub coefficients: Coefficients,
}

impl Tangential {
    /// All numbers NaN: a patch that could not be solved.
    pub fn nan() -> Tangential {
        Tangential {
            fx_n: f64::NAN,
            fy_n: f64::NAN,
            mz_nmm: f64::NAN,
            adhesion_fraction: f64::NAN,
            coefficients: Coefficients {
                c11: f64::NAN,
                c22: f64::NAN,
                c23: f64::NAN,
            },
        }
    }
}

/// The tangential forces on `patch` for `creepages`, by `settings.method()` with its
/// friction and material.
///
/// # Units
///
/// As on [`EllipticPatch`], [`Creepages`], [`Tangential`].
///
/// # Example
///
/// ```
/// use wheelrail::creep::creepage::Creepages;
/// use wheelrail::creep::tangential::{EllipticPatch, solve};
/// use wheelrail::creep::{Method, Settings};
/// // Pure longitudinal creepage far beyond saturation: |Fx| -> μ FN for every bounded model.
/// let patch = EllipticPatch::new(6.0, 4.0, 50_000.0)?;
/// let c = Creepages { xi: 0.5, eta: 0.0, phi_per_mm: 0.0 };
/// for method in [Method::Fastsim, Method::Polach] {
///     let s = Settings::new(method, 0.3, 82_000.0, 0.28)?;
///     let t = solve(&patch, &c, &s);
///     assert!((t.fx_n / -15_000.0 - 1.0).abs() < 1e-3, "{method}: {}", t.fx_n);
/// }
/// # Ok::<(), wheelrail::creep::CreepError>(())
/// ```
pub fn solve(patch: &EllipticPatch, creepages: &Creepages, settings: &Settings) -> Tangential {
    let coefficients = coefficients::kalker(patch.a_mm / patch.b_mm, settings.poisson());
    match settings.method() {
        Method::Linear => super::linear::solve(patch, creepages, &coefficients, settings),
        Method::Fastsim => super::fastsim::solve(patch, creepages, &coefficients, settings),
        Method::Polach => super::polach::solve(patch, creepages, &coefficients, settings),
    }
}
