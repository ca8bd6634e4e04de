//! Creep forces: what a contact patch transmits tangentially, from the wheelset's motion.
//!
//! Stage entry: [`forces`], one patch at a time: the creepages from the motion
//! ([`creepage`]), the normal force from the patch's share of the wheel's vertical load
//! ([`normal`]), the Hertz ellipse for that normal force ([`crate::hertz::ellipse`]), and the
//! tangential forces by one of three models behind one interface (`tangential::solve`):
//!
//! * [`Method::Linear`]: Kalker's linear theory (Kalker 1990, Appendix E; Johnson 1985,
//!   §8.4), the limit of small creepage, with Kalker's coefficients ([`coefficients`]);
//! * [`Method::Fastsim`] (default): Kalker's simplified theory, FASTSIM (Kalker 1982), with
//!   the parabolic or elliptic traction bound and three flexibilities blended as CONTACT
//!   blends them ([`fastsim`]);
//! * [`Method::Polach`]: Polach's closed form (Polach 1999), with his spin extension
//!   ([`polach`]).
//!
//! # Units
//!
//! Millimetres, newtons, MPa (N/mm²), radians, seconds. Creepages ξ, η dimensionless, the
//! spin φ in 1/mm; forces in N, the spin moment in N mm.
//!
//! # Frames and signs
//!
//! **Forces are those of the wheel on the rail**, in the patch's contact frame, and the
//! creepages are the velocity of the rail relative to the wheel over the rolling speed
//! (Kalker's and CONTACT's convention): a positive creepage gives a negative force, the
//! linear theory reads `Fx = -G c² C11 ξ`. The contact frame is the track frame (x forward,
//! y left, z up) turned about x by the patch's contact angle δ: `t_x` along the rail, `t_y`
//! in the tangent plane, `n` the normal out of the rail into the wheel (see [`creepage`]).
//! `Fy` is along `t_y`, `Mz` about `n`. The normal force `FN` presses the rail along `-n`;
//! the vertical load the patch carries is `FZ = FN cos δ - Fy sin δ` ([`normal`]). CONTACT's
//! frame is this one turned by π about x: its `FX`, `FN` equal ours, its `FS`, `MN`, `CETA`,
//! `CPHI` are the negatives of our `Fy`, `Mz`, `η`, `φ`.
//!
//! # References
//!
//! * J.J. Kalker (1990), Three-dimensional elastic bodies in rolling contact, Kluwer:
//!   §1.2 (creepages), Appendix E (linear theory, Table E.3), Ch. 3 (simplified theory);
//!   cited by section: equation numbers were not checked against the book.
//! * J.J. Kalker (1982), A fast algorithm for the simplified theory of rolling contact,
//!   Vehicle System Dynamics 11, 1-13 (FASTSIM).
//! * O. Polach (1999), A fast wheel-rail forces calculation computer code, Vehicle System
//!   Dynamics 33 (Suppl.), 728-739; O. Polach (2005), Creep forces in simulations of
//!   traction vehicles running on adhesion limit, Wear 258, 992-1000 (§2 restates the
//!   method with spin as used here; that paper's reduction factors for large creepage are
//!   not used).
//! * E.A.H. Vollebregt, CONTACT (github.com/eve70a/CONTACT): its FASTSIM with three
//!   flexibilities and their blending (`simpflex` in `src/m_hertz.f90`).
//! * K.L. Johnson (1985), Contact Mechanics, Cambridge University Press, Ch. 8.

pub mod coefficients;
pub mod command;
pub mod creepage;
pub mod fastsim;
pub mod linear;
pub mod normal;
pub mod polach;
pub mod sweep;
pub mod tangential;

use crate::hertz::{self, Contact, HertzError, NotHertzianReason};
use crate::message::Number;
use coefficients::POISSON_RANGE;
use creepage::{ContactPoint, Creepages, Motion};
use std::f64::consts::FRAC_PI_2;
use std::fmt;
use tangential::{EllipticPatch, Tangential};

/// The tangential model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Method {
    /// Kalker's FASTSIM (module [`fastsim`]).
    #[default]
    Fastsim,
    /// Kalker's linear theory (module [`linear`]): no saturation.
    Linear,
    /// Polach's method with spin (module [`polach`]).
    Polach,
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Method::Fastsim => "fastsim",
            Method::Linear => "linear",
            Method::Polach => "polach",
        })
    }
}

/// FASTSIM's traction bound `μ p(x, y)`: the shape of the pressure it assumes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Bound {
    /// `p = 2 FN/(π a b) · (1 - x²/a² - y²/b²)`: Kalker's choice for FASTSIM, which makes
    /// its force-creepage curves closest to the exact theory's (Kalker 1990, §3.3).
    #[default]
    Parabolic,
    /// `p = 3 FN/(2 π a b) · √(1 - x²/a² - y²/b²)`: Hertz's pressure.
    Elliptic,
}

impl fmt::Display for Bound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Bound::Parabolic => "parabolic",
            Bound::Elliptic => "elliptic",
        })
    }
}

/// FASTSIM's flexibilities `L1`, `L2`, `L3` (the compliance of the simplified theory for ξ,
/// η, φ; module [`fastsim`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Flexibility {
    /// CONTACT's blend: the three flexibilities at small creepage, shifting to one
    /// combined flexibility as the creepage grows to 3 times the creepage that saturates
    /// linear theory (`fastsim::flexibilities`).
    #[default]
    Blended,
    /// Kalker's three flexibilities, unchanged at any creepage.
    Three,
}

/// How FASTSIM turns a slipping traction from one cell to the next (module [`fastsim`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Scheme {
    /// The step's tangential part over the bound at mid-step: second order in the cell
    /// length, to the same limit as Kalker's.
    #[default]
    Midpoint,
    /// Kalker's: the traction plus the step, scaled back onto the bound (Kalker 1982, as in
    /// CONTACT): first order in the cell length where spin turns the traction.
    Kalker,
}

/// FASTSIM's discretisation: `strips` across the ellipse (lateral), `elements` along each
/// strip (rolling direction), each strip divided evenly.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Grid {
    /// Strips across the patch (lateral).
    pub strips: u32,
    /// Elements along each strip (rolling direction).
    pub elements: u32,
}

/// The default FASTSIM grid, chosen by run time against error (`fastsim::study`, record in
/// `docs/`): see [`fastsim`].
pub const DEFAULT_GRID: Grid = Grid {
    strips: 32,
    elements: 32,
};

/// The number of strips and elements a grid may have: at least 1, at most 4000 (16 million
/// cells, a tenth of a second; the study's converged reference uses 1000 × 1000).
pub(crate) const GRID_RANGE: (u32, u32) = (1, 4000);

/// Coefficients of friction accepted: above 0 (no friction transmits nothing, which needs
/// no model) up to 1 (dry steel on steel is 0.3 to 0.6; more is no wheel-rail contact).
pub(crate) const FRICTION_RANGE: (f64, f64) = (0.0, 1.0);

/// Default coefficient of friction: dry rail, CONTACT's examples and the Manchester benchmark.
pub(crate) const DEFAULT_FRICTION: f64 = 0.3;
/// Default shear modulus, MPa: CONTACT's steel (82 GPa).
pub(crate) const DEFAULT_SHEAR_MODULUS_MPA: f64 = 82_000.0;
/// Default Poisson's ratio: CONTACT's steel.
pub(crate) const DEFAULT_POISSON: f64 = 0.28;
/// Default relative tolerance of the normal-force solve on the vertical load: `|FN cos δ -
/// Fy sin δ - FZ| ≤ 1e-10 FZ` (0.1 mN on a 100 kN wheel), far below what the models resolve.
pub(crate) const DEFAULT_NORMAL_TOLERANCE: f64 = 1e-10;
/// Default cap on the evaluations of the tangential model in the normal-force solve; the
/// solve takes 3 to 6 with FASTSIM or Polach, up to 11 with linear theory (see [`normal`]).
pub(crate) const DEFAULT_NORMAL_MAX_ITERATIONS: u32 = 60;

/// The settings of the creep stage, checked by their constructors (the default is FASTSIM,
/// parabolic bound, blended flexibilities, a grid of 32 × 32, μ = 0.3, steel with
/// G = 82 GPa and ν = 0.28).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    method: Method,
    bound: Bound,
    flexibility: Flexibility,
    scheme: Scheme,
    grid: Grid,
    friction: f64,
    shear_modulus_mpa: f64,
    poisson: f64,
    normal_tolerance: f64,
    normal_max_iterations: u32,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            method: Method::default(),
            bound: Bound::default(),
            flexibility: Flexibility::default(),
            scheme: Scheme::default(),
            grid: DEFAULT_GRID,
            friction: DEFAULT_FRICTION,
            shear_modulus_mpa: DEFAULT_SHEAR_MODULUS_MPA,
            poisson: DEFAULT_POISSON,
            normal_tolerance: DEFAULT_NORMAL_TOLERANCE,
            normal_max_iterations: DEFAULT_NORMAL_MAX_ITERATIONS,
        }
    }
}

impl Settings {
    /// Settings with a method, a coefficient of friction and the material of both bodies
    /// (Kalker's theory takes them elastically alike); the rest as [`Settings::default`].
    ///
    /// # Units
    ///
    /// `shear_modulus_mpa` in MPa; `friction`, `poisson` dimensionless.
    ///
    /// # Errors
    ///
    /// [`CreepError::Friction`] outside (0, 1] (`FRICTION_RANGE`),
    /// [`CreepError::ShearModulus`] unless positive and finite, [`CreepError::Poisson`]
    /// outside [0, 0.5] (`POISSON_RANGE`: the columns of Kalker's table).
    ///
    /// # Example
    ///
    /// ```
    /// use wheelrail::creep::{CreepError, Method, Settings};
    /// let s = Settings::new(Method::Polach, 0.4, 80_000.0, 0.3)?;
    /// assert_eq!(s.method(), Method::Polach);
    /// assert!(matches!(Settings::new(Method::Linear, 0.3, 80e3, 0.6), Err(CreepError::Poisson { .. })));
    /// # Ok::<(), CreepError>(())
    /// ```
    pub fn new(
        method: Method,
        friction: f64,
        shear_modulus_mpa: f64,
        poisson: f64,
    ) -> Result<Settings, CreepError> {
        if !(friction > FRICTION_RANGE.0 && friction <= FRICTION_RANGE.1) {
            return Err(CreepError::Friction { friction });
        }
        if !(shear_modulus_mpa > 0.0 && shear_modulus_mpa.is_finite()) {
            return Err(CreepError::ShearModulus { shear_modulus_mpa });
        }
        if !(POISSON_RANGE.0..=POISSON_RANGE.1).contains(&poisson) {
            return Err(CreepError::Poisson { poisson });
        }
        Ok(Settings {
            method,
            friction,
            shear_modulus_mpa,
            poisson,
            ..Settings::default()
        })
    }

    /// The same settings with another tangential model.
    pub fn with_method(self, method: Method) -> Settings {
        Settings { method, ..self }
    }

    /// The same settings with another traction bound (FASTSIM only).
    pub fn with_bound(self, bound: Bound) -> Settings {
        Settings { bound, ..self }
    }

    /// The same settings with another treatment of the flexibilities (FASTSIM only).
    pub fn with_flexibility(self, flexibility: Flexibility) -> Settings {
        Settings {
            flexibility,
            ..self
        }
    }

    /// The same settings with another FASTSIM scheme.
    pub fn with_scheme(self, scheme: Scheme) -> Settings {
        Settings { scheme, ..self }
    }

    /// The same settings with another FASTSIM grid.
    ///
    /// # Errors
    ///
    /// [`CreepError::Grid`] unless both counts lie in 1 to 4000 (`GRID_RANGE`).
    pub fn with_grid(self, grid: Grid) -> Result<Settings, CreepError> {
        let ok = |n: u32| (GRID_RANGE.0..=GRID_RANGE.1).contains(&n);
        if !(ok(grid.strips) && ok(grid.elements)) {
            return Err(CreepError::Grid { grid });
        }
        Ok(Settings { grid, ..self })
    }

    /// The same settings with another tolerance and iteration cap of the normal-force solve.
    ///
    /// # Errors
    ///
    /// [`CreepError::NormalSolve`] unless `1e-15 ≤ tolerance ≤ 1e-2` and
    /// `1 ≤ max_iterations ≤ 1000`.
    pub fn with_normal_solve(
        self,
        tolerance: f64,
        max_iterations: u32,
    ) -> Result<Settings, CreepError> {
        if !((1e-15..=1e-2).contains(&tolerance) && (1..=1000).contains(&max_iterations)) {
            return Err(CreepError::NormalSolve {
                tolerance,
                max_iterations,
            });
        }
        Ok(Settings {
            normal_tolerance: tolerance,
            normal_max_iterations: max_iterations,
            ..self
        })
    }

    /// The tangential model.
    pub fn method(&self) -> Method {
        self.method
    }
    /// FASTSIM's traction bound.
    pub fn bound(&self) -> Bound {
        self.bound
    }
    /// FASTSIM's flexibilities.
    pub fn flexibility(&self) -> Flexibility {
        self.flexibility
    }
    /// FASTSIM's scheme for slipping tractions.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }
    /// FASTSIM's grid.
    pub fn grid(&self) -> Grid {
        self.grid
    }
    /// Coefficient of friction μ.
    pub fn friction(&self) -> f64 {
        self.friction
    }
    /// Shear modulus G of both bodies, MPa.
    pub fn shear_modulus_mpa(&self) -> f64 {
        self.shear_modulus_mpa
    }
    /// Poisson's ratio ν of both bodies.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }
    /// The effective modulus of Hertz theory for two bodies of this material,
    /// `E* = E / (2 (1 - ν²)) = G / (1 - ν)` (MPa; paper Eq. 10 with `E = 2 G (1 + ν)`).
    pub fn effective_modulus_mpa(&self) -> f64 {
        self.shear_modulus_mpa / (1.0 - self.poisson)
    }
    /// Relative tolerance of the normal-force solve on the vertical load.
    pub fn normal_tolerance(&self) -> f64 {
        self.normal_tolerance
    }
    /// Cap on the tangential evaluations of the normal-force solve.
    pub fn normal_max_iterations(&self) -> u32 {
        self.normal_max_iterations
    }
}

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

/// Invalid input to the creep stage; each variant names the quantity, so that a caller (a
/// scene, the command line) can name its key.
#[derive(Debug, Clone, PartialEq)]
pub enum CreepError {
    /// A value that must be finite is NaN or infinite.
    NonFinite {
        /// Name of the input.
        quantity: &'static str,
        /// Its value.
        value: f64,
    },
    /// The forward speed is not positive.
    NonPositiveSpeed {
        /// mm/s.
        speed_mm_s: f64,
    },
    /// The rolling speed (the mean speed of the two bodies' material through the patch) is
    /// not positive: the wheel does not roll forwards.
    NoRolling {
        /// mm/s.
        rolling_speed_mm_s: f64,
    },
    /// The rolling radius is not positive, or the lead is not shorter than it.
    BadRollingRadius {
        /// mm.
        rolling_radius_mm: f64,
        /// mm.
        lead_mm: f64,
    },
    /// A contact angle outside `(-π/2, π/2)`.
    ContactAngle {
        /// rad.
        contact_angle_rad: f64,
    },
    /// A coefficient of friction outside (0, 1] (`FRICTION_RANGE`).
    Friction {
        /// μ.
        friction: f64,
    },
    /// A shear modulus that is not positive and finite.
    ShearModulus {
        /// MPa.
        shear_modulus_mpa: f64,
    },
    /// A Poisson's ratio outside [0, 0.5] (`POISSON_RANGE`).
    Poisson {
        /// ν.
        poisson: f64,
    },
    /// A FASTSIM grid outside 1 to 4000 strips or elements (`GRID_RANGE`).
    Grid {
        /// The grid asked for.
        grid: Grid,
    },
    /// Semi-axes that are not positive and finite.
    SemiAxes {
        /// mm.
        a_mm: f64,
        /// mm.
        b_mm: f64,
    },
    /// A normal force that is not positive and finite.
    NormalForce {
        /// N.
        normal_force_n: f64,
    },
    /// A vertical load that is not positive and finite.
    VerticalLoad {
        /// N.
        vertical_load_n: f64,
    },
    /// Normal-solve settings out of range (see [`Settings::with_normal_solve`]).
    NormalSolve {
        /// Relative tolerance.
        tolerance: f64,
        /// Iteration cap.
        max_iterations: u32,
    },
    /// The Hertz stage refused the input.
    Hertz(HertzError),
    /// A list of pitch rates without one rate per position of the sweep.
    PitchRates {
        /// Rates given.
        given: usize,
        /// Positions of the sweep.
        positions: usize,
    },
}

impl fmt::Display for CreepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CreepError::NonFinite { quantity, value } => {
                write!(f, "{quantity} = {value}: expected a finite number")
            }
            CreepError::NonPositiveSpeed { speed_mm_s } => write!(
                f,
                "speed {} mm/s: expected a positive forward speed (the creepages are divided by it)",
                Number(*speed_mm_s)
            ),
            CreepError::NoRolling { rolling_speed_mm_s } => write!(
                f,
                "rolling speed {} mm/s: the wheel turns backwards faster than it runs forwards; expected a rolling wheel",
                Number(*rolling_speed_mm_s)
            ),
            CreepError::BadRollingRadius {
                rolling_radius_mm,
                lead_mm,
            } => write!(
                f,
                "rolling radius {} mm with lead {} mm: expected a positive radius longer than the lead",
                Number(*rolling_radius_mm),
                Number(*lead_mm)
            ),
            CreepError::ContactAngle { contact_angle_rad } => write!(
                f,
                "contact angle {} rad: expected -pi/2 < angle < pi/2",
                Number(*contact_angle_rad)
            ),
            CreepError::Friction { friction } => write!(
                f,
                "coefficient of friction {}: expected above {} up to {}",
                Number(*friction),
                FRICTION_RANGE.0,
                FRICTION_RANGE.1
            ),
            CreepError::ShearModulus { shear_modulus_mpa } => write!(
                f,
                "shear modulus {} MPa: expected a positive number",
                Number(*shear_modulus_mpa)
            ),
            CreepError::Poisson { poisson } => write!(
                f,
                "Poisson's ratio {}: expected {} to {} (the range of Kalker's table)",
                Number(*poisson),
                POISSON_RANGE.0,
                POISSON_RANGE.1
            ),
            CreepError::Grid { grid } => write!(
                f,
                "FASTSIM grid {} x {}: expected {} to {} strips and elements",
                grid.strips, grid.elements, GRID_RANGE.0, GRID_RANGE.1
            ),
            CreepError::SemiAxes { a_mm, b_mm } => write!(
                f,
                "semi-axes a = {} mm, b = {} mm: expected positive lengths",
                Number(*a_mm),
                Number(*b_mm)
            ),
            CreepError::NormalForce { normal_force_n } => write!(
                f,
                "normal force {} N: expected a positive force",
                Number(*normal_force_n)
            ),
            CreepError::VerticalLoad { vertical_load_n } => write!(
                f,
                "vertical load {} N: expected a positive load",
                Number(*vertical_load_n)
            ),
            CreepError::NormalSolve {
                tolerance,
                max_iterations,
            } => write!(
                f,
                "normal-force solve with tolerance {} and {max_iterations} iterations: expected 1e-15 to 1e-2 and 1 to 1000",
                Number(*tolerance)
            ),
            CreepError::Hertz(e) => write!(f, "{e}"),
            CreepError::PitchRates { given, positions } => write!(
                f,
                "{given} pitch rates for a sweep of {positions} positions: expected one rate per position"
            ),
        }
    }
}

impl std::error::Error for CreepError {}

/// `Ok` if `value` is finite.
fn finite(quantity: &'static str, value: f64) -> Result<(), CreepError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(CreepError::NonFinite { quantity, value })
    }
}

/// `Ok` if `|δ| < π/2` (a normal in the track's horizontal plane carries no vertical load).
fn check_contact_angle(contact_angle_rad: f64) -> Result<(), CreepError> {
    if contact_angle_rad.abs() < FRAC_PI_2 {
        Ok(())
    } else {
        Err(CreepError::ContactAngle { contact_angle_rad })
    }
}

/// `Ok` if both semi-axes are positive and finite.
fn check_semi_axes(a_mm: f64, b_mm: f64) -> Result<(), CreepError> {
    if a_mm > 0.0 && b_mm > 0.0 && a_mm.is_finite() && b_mm.is_finite() {
        Ok(())
    } else {
        Err(CreepError::SemiAxes { a_mm, b_mm })
    }
}

/// `Ok` if the normal force is positive and finite.
fn check_normal_force(normal_force_n: f64) -> Result<(), CreepError> {
    if normal_force_n > 0.0 && normal_force_n.is_finite() {
        Ok(())
    } else {
        Err(CreepError::NormalForce { normal_force_n })
    }
}
