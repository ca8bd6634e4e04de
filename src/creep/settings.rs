//! The settings of the creep stage: the tangential model and its options, the material,
//! the friction and the normal-force solve, each checked by its constructor.

use super::CreepError;
use super::coefficients::POISSON_RANGE;
use std::fmt;

/// The tangential model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Method {
    /// Kalker's FASTSIM (module [`fastsim`](super::fastsim)).
    #[default]
    Fastsim,
    /// Kalker's linear theory (module [`linear`](super::linear)): no saturation.
    Linear,
    /// Polach's method with spin (module [`polach`](super::polach)).
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
/// η, φ; module [`fastsim`](super::fastsim)).
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

/// How FASTSIM turns a slipping traction from one cell to the next (module
/// [`fastsim`](super::fastsim)).
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
/// `docs/`): see [`fastsim`](super::fastsim).
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
/// solve takes 3 to 6 with FASTSIM or Polach, up to 11 with linear theory (see [`normal`](super::normal)).
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
