//! One contact patch: what the contact search reports of it ([`Patch`]), and the stage
//! entry [`forces`], its normal force, ellipse and tangential forces from the wheelset's
//! motion ([`PatchForces`], [`Status`]).

use super::CreepError;
use super::creepage::{self, ContactPoint, Creepages, Motion};
use super::error::{check_normal_force, check_semi_axes, finite};
use super::normal;
use super::settings::Settings;
use super::tangential::{self, EllipticPatch, Tangential};
use crate::hertz::{self, Contact, NotHertzianReason};

/// The shape of a patch: its curvatures (the ellipse follows the normal force) or its
/// semi-axes at a known normal force (an equivalent ellipse; they scale as `FN^(1/3)`, as
/// a Hertz ellipse of fixed curvatures does).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Relative curvatures `A` (rolling) and `B` (lateral), 1/mm (paper Eqs. 12-13,
    /// [`crate::hertz::relative_curvatures`]).
    Curvatures {
        /// `A`, 1/mm.
        a_per_mm: f64,
        /// `B`, 1/mm.
        b_per_mm: f64,
    },
    /// Semi-axes `a` (rolling), `b` (lateral) at the normal force `at_normal_force_n`.
    SemiAxes {
        /// `a`, mm.
        a_mm: f64,
        /// `b`, mm.
        b_mm: f64,
        /// The normal force they belong to, N.
        at_normal_force_n: f64,
    },
}

/// One contact patch as the contact search reports it: its shape, where it touches the
/// wheel (lead, lateral position, rolling radius, contact angle), and the vertical load it
/// carries.
///
/// # Units
///
/// mm, rad, N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Patch {
    /// The ellipse's curvatures or semi-axes.
    pub shape: Shape,
    /// The contact point and contact angle (frames in [`creepage`]).
    pub point: ContactPoint,
    /// The vertical load the patch carries (its share of the wheel's), N, positive.
    pub vertical_load_n: f64,
}

/// Why a patch's forces are what they are.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Status {
    /// The normal force balances the vertical load within the tolerance after `iterations`
    /// evaluations of the tangential model.
    Converged {
        /// Evaluations of the tangential model.
        iterations: u32,
    },
    /// The normal-force solve hit its cap; the numbers are the last iterate's.
    IterationCap,
    /// No normal force balances the vertical load: the tangential force's vertical part
    /// pulls the wheel down faster than the normal force lifts it (`μ tan|δ| ≥ 1` with the
    /// friction against the load: Nadal's limit). Numbers are NaN.
    NoEquilibrium,
    /// The curvatures give no Hertz ellipse; numbers are NaN.
    NotHertzian(NotHertzianReason),
}

impl Status {
    /// The status as an identifier for CSV columns (`converged`, `iteration_cap`,
    /// `no_equilibrium`, `not_hertzian`).
    pub fn as_str(&self) -> &'static str {
        match self {
            Status::Converged { .. } => "converged",
            Status::IterationCap => "iteration_cap",
            Status::NoEquilibrium => "no_equilibrium",
            Status::NotHertzian(_) => "not_hertzian",
        }
    }
}

/// What [`forces`] finds on one patch.
///
/// # Units
///
/// N, N mm, mm; creepages as [`Creepages`]. Forces on the rail in the contact frame (module
/// docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchForces {
    /// The creepages from the motion.
    pub creepages: Creepages,
    /// Normal force `FN`, N.
    pub normal_force_n: f64,
    /// Semi-axis along the rolling direction at `FN`, mm.
    pub a_mm: f64,
    /// Lateral semi-axis at `FN`, mm.
    pub b_mm: f64,
    /// The tangential forces, spin moment, adhesion fraction and Kalker's coefficients.
    pub tangential: Tangential,
    /// How the normal-force solve ended.
    pub status: Status,
}

/// The forces of one patch: creepages from `motion`, the normal force from the patch's
/// vertical load with the tangential force's vertical part (`FZ = FN cos δ - Fy sin δ`,
/// solved as [`normal`] states), the Hertz ellipse at that normal force, and the tangential
/// forces by `settings.method()`.
///
/// # Units
///
/// As on [`Patch`], [`Motion`] and [`PatchForces`].
///
/// # Errors
///
/// The [`CreepError`] of `creepage::creepages` for the motion and point, and
/// [`CreepError::VerticalLoad`] unless the load is positive and finite,
/// [`CreepError::SemiAxes`] or [`CreepError::NormalForce`] for a bad [`Shape::SemiAxes`],
/// [`CreepError::NonFinite`] for non-finite curvatures. A shape that is not Hertzian, and a
/// load no normal force balances, are results ([`Status`]), not errors.
///
/// # Example
///
/// ```
/// use wheelrail::creep::creepage::{ContactPoint, Motion};
/// use wheelrail::creep::{Patch, Settings, Shape, Status, forces};
/// // A tread contact, 10 kN, on a free-rolling wheelset 1 mm larger in radius than the mean.
/// let patch = Patch {
///     shape: Shape::Curvatures { a_per_mm: 1.0 / 920.0, b_per_mm: 1.0 / 600.0 },
///     point: ContactPoint {
///         lead_mm: 0.0,
///         lateral_mm: 750.0,
///         rolling_radius_mm: 461.0,
///         contact_angle_rad: 0.03,
///     },
///     vertical_load_n: 10_000.0,
/// };
/// let f = forces(&patch, &Motion::free_rolling(20_000.0, 460.0), &Settings::default())?;
/// assert!(matches!(f.status, Status::Converged { .. }));
/// // ξ > 0 (this wheel runs on the larger radius): the force on the rail is backwards.
/// assert!(f.creepages.xi > 0.0 && f.tangential.fx_n < 0.0);
/// // FN cos δ - Fy sin δ = FZ.
/// let fz = f.normal_force_n * 0.03_f64.cos() - f.tangential.fy_n * 0.03_f64.sin();
/// assert!((fz - 10_000.0).abs() < 1e-5);
/// # Ok::<(), wheelrail::creep::CreepError>(())
/// ```
pub fn forces(
    patch: &Patch,
    motion: &Motion,
    settings: &Settings,
) -> Result<PatchForces, CreepError> {
    let creepages = creepage::creepages(motion, &patch.point)?;
    let fz = patch.vertical_load_n;
    if !(fz > 0.0 && fz.is_finite()) {
        return Err(CreepError::VerticalLoad {
            vertical_load_n: fz,
        });
    }
    match patch.shape {
        Shape::Curvatures { a_per_mm, b_per_mm } => {
            finite("A", a_per_mm)?;
            finite("B", b_per_mm)?;
        }
        Shape::SemiAxes {
            a_mm,
            b_mm,
            at_normal_force_n,
        } => {
            check_semi_axes(a_mm, b_mm)?;
            check_normal_force(at_normal_force_n)?;
        }
    }
    // The last evaluation, kept: a converged solve returns the normal force it tried last.
    let mut last: Option<(f64, Evaluation)> = None;
    let outcome = normal::solve(
        fz,
        patch.point.contact_angle_rad,
        settings.normal_tolerance(),
        settings.normal_max_iterations(),
        |normal_force_n| {
            let e = evaluate(&patch.shape, normal_force_n, &creepages, settings)?;
            last = Some((normal_force_n, e));
            Ok(match e {
                Evaluation::Solved(_, t) => Ok(t.fy_n),
                Evaluation::NotHertzian(reason) => Err(reason),
            })
        },
    )?;
    let failed = |status| PatchForces {
        creepages,
        normal_force_n: f64::NAN,
        a_mm: f64::NAN,
        b_mm: f64::NAN,
        tangential: Tangential::nan(),
        status,
    };
    let (status, normal_force_n) = match outcome {
        normal::Outcome::Converged {
            normal_force_n,
            iterations,
        } => (Status::Converged { iterations }, normal_force_n),
        normal::Outcome::IterationCap { normal_force_n } => (Status::IterationCap, normal_force_n),
        normal::Outcome::NoEquilibrium => return Ok(failed(Status::NoEquilibrium)),
        normal::Outcome::NotHertzian(reason) => return Ok(failed(Status::NotHertzian(reason))),
    };
    // After an iteration cap the best point need not be the last one: evaluate there.
    let at_solution = match last {
        Some((x, e)) if x.to_bits() == normal_force_n.to_bits() => e,
        _ => evaluate(&patch.shape, normal_force_n, &creepages, settings)?,
    };
    Ok(match at_solution {
        Evaluation::Solved(p, tangential) => PatchForces {
            creepages,
            normal_force_n,
            a_mm: p.a_mm(),
            b_mm: p.b_mm(),
            tangential,
            status,
        },
        Evaluation::NotHertzian(reason) => failed(Status::NotHertzian(reason)),
    })
}

/// The tangential solution of a patch shape at one normal force, or why there is none.
#[derive(Debug, Clone, Copy)]
enum Evaluation {
    Solved(EllipticPatch, Tangential),
    NotHertzian(NotHertzianReason),
}

/// The ellipse of `shape` at `normal_force_n` (Hertz for curvatures, scaled semi-axes
/// otherwise) and its tangential solution.
fn evaluate(
    shape: &Shape,
    normal_force_n: f64,
    creepages: &Creepages,
    settings: &Settings,
) -> Result<Evaluation, CreepError> {
    let (a_mm, b_mm) = match *shape {
        Shape::Curvatures { a_per_mm, b_per_mm } => {
            let e_star = settings.effective_modulus_mpa();
            match hertz::ellipse(
                a_per_mm,
                b_per_mm,
                normal_force_n,
                e_star,
                hertz::EllipseMethod::Exact,
            )
            .map_err(CreepError::Hertz)?
            {
                Contact::Hertzian(e) => (e.a_mm, e.b_mm),
                Contact::NotHertzian(reason) => return Ok(Evaluation::NotHertzian(reason)),
            }
        }
        Shape::SemiAxes {
            a_mm,
            b_mm,
            at_normal_force_n,
        } => {
            let scale = (normal_force_n / at_normal_force_n).cbrt();
            (a_mm * scale, b_mm * scale)
        }
    };
    let patch = EllipticPatch::new(a_mm, b_mm, normal_force_n)?;
    let t = tangential::solve(&patch, creepages, settings);
    Ok(Evaluation::Solved(patch, t))
}
