//! The numerical settings of the default roll solver, carried by [`Solver::Default`].

#[cfg(doc)]
use super::Solver;
use crate::message::Number;
use std::fmt;

/// Tolerances and caps of the default roll solver (safeguarded Newton on
/// `F(theta) = m_L - m_R`, see [`crate::rigid`]), checked by [`RollSettings::new`].
/// [`Default`] gives the project's values; each accessor states why.
///
/// The solver reads them by reference, once per position: the hot loop holds plain numbers.
///
/// # Example
/// ```
/// use wheelrail::{pipeline, rigid, scene::Scene};
/// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// // A looser residual than the default's 1e-11 mm.
/// let loose = rigid::RollSettings::default().with_residual_tol_mm(1e-6).unwrap();
/// let sweep = rigid::search(&placement, &wheelrail::sweep::Sweep::from_slice(&[3.0]).unwrap(), rigid::Solver::Default(loose));
/// assert_eq!(sweep.positions()[0].stop, rigid::Stop::Converged);
/// assert!(sweep.positions()[0].residual <= 1e-6);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollSettings {
    pub(super) residual_tol_mm: f64,
    pub(super) collapsed_residual_mm: f64,
    pub(super) max_iter: usize,
    pub(super) bracket_collapse_rad: f64,
    pub(super) rescan_roll_rad: f64,
    pub(super) same_minimum_mm: f64,
}

/// Why roll-solver settings are not accepted.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum RollSettingsError {
    /// A tolerance that is not a finite number above 0 (the setting's name and value).
    NotPositive {
        /// The setting, as its accessor is named.
        setting: &'static str,
        /// Its value.
        value: f64,
    },
    /// An iteration cap of 0.
    NoIteration,
}

impl fmt::Display for RollSettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            RollSettingsError::NotPositive { setting, value } => {
                write!(
                    f,
                    "{setting} = {} must be a finite number above 0",
                    Number(value)
                )
            }
            RollSettingsError::NoIteration => f.write_str("max_iter must be at least 1"),
        }
    }
}

impl std::error::Error for RollSettingsError {}

impl RollSettings {
    /// The settings, each explained at its accessor.
    ///
    /// # Errors
    /// [`RollSettingsError`]: a tolerance not above 0 (or not finite), an iteration cap of
    /// 0.
    pub fn new(
        residual_tol_mm: f64,
        collapsed_residual_mm: f64,
        max_iter: usize,
        bracket_collapse_rad: f64,
        rescan_roll_rad: f64,
        same_minimum_mm: f64,
    ) -> Result<RollSettings, RollSettingsError> {
        for (setting, value) in [
            ("residual_tol_mm", residual_tol_mm),
            ("collapsed_residual_mm", collapsed_residual_mm),
            ("bracket_collapse_rad", bracket_collapse_rad),
            ("rescan_roll_rad", rescan_roll_rad),
            ("same_minimum_mm", same_minimum_mm),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(RollSettingsError::NotPositive { setting, value });
            }
        }
        if max_iter == 0 {
            return Err(RollSettingsError::NoIteration);
        }
        Ok(RollSettings {
            residual_tol_mm,
            collapsed_residual_mm,
            max_iter,
            bracket_collapse_rad,
            rescan_roll_rad,
            same_minimum_mm,
        })
    }

    /// These settings with the residual `residual_tol_mm` (mm).
    ///
    /// # Errors
    /// As [`RollSettings::new`].
    pub fn with_residual_tol_mm(
        self,
        residual_tol_mm: f64,
    ) -> Result<RollSettings, RollSettingsError> {
        let s = self;
        let collapsed = s.collapsed_residual_mm;
        RollSettings::new(
            residual_tol_mm,
            collapsed,
            s.max_iter,
            s.bracket_collapse_rad,
            s.rescan_roll_rad,
            s.same_minimum_mm,
        )
    }

    /// These settings with the iteration cap `max_iter`.
    ///
    /// # Errors
    /// As [`RollSettings::new`].
    pub fn with_max_iter(self, max_iter: usize) -> Result<RollSettings, RollSettingsError> {
        let s = self;
        let residual = s.residual_tol_mm;
        RollSettings::new(
            residual,
            s.collapsed_residual_mm,
            max_iter,
            s.bracket_collapse_rad,
            s.rescan_roll_rad,
            s.same_minimum_mm,
        )
    }

    /// Residual `|m_L - m_R|` at which the solver stops (mm). Default 1e-11: the rigid
    /// search promises 1e-9 mm (its agreement with a brute-force search, `tests/rigid.rs`);
    /// Newton reaches 1e-12 in one more step, so the margin costs nothing.
    pub fn residual_tol_mm(&self) -> f64 {
        self.residual_tol_mm
    }

    /// Residual accepted when the bracket on the roll has collapsed to the last bit (mm).
    /// Default 1e-9: the promise of the default solver, 100 times the normal
    /// tolerance (rounding of the gaps, about 1e-13 mm each at |g| ~ 450 mm, can keep
    /// `|F|` just above `residual_tol_mm` at the best double). Below `residual_tol_mm` it
    /// accepts nothing more.
    pub fn collapsed_residual_mm(&self) -> f64 {
        self.collapsed_residual_mm
    }

    /// Iteration cap per position. Default 60: 3-6 iterations are typical, flange onset up
    /// to ~15.
    pub fn max_iter(&self) -> usize {
        self.max_iter
    }

    /// A bracket on the roll narrower than this, relative to `max(|theta|, 1)`, has
    /// collapsed (rad). Default 1e-15: a few ulps of a roll of order 1e-3..1.
    pub fn bracket_collapse_rad(&self) -> f64 {
        self.bracket_collapse_rad
    }

    /// Roll change after which the basins of the gap are scanned again (rad). Default 5e-4:
    /// wheel points move by about r0 * 5e-4 = 0.25 mm, one coarse step of the scan;
    /// smaller moves are followed by the basins themselves. Large-roll wheelsets (very
    /// unequal radii) need it.
    pub fn rescan_roll_rad(&self) -> f64 {
        self.rescan_roll_rad
    }

    /// Two basins whose minima lie this close have slid onto the same minimum; one is
    /// dropped (mm). Default 1e-6: far above the local tolerance (1e-11 mm), far below any
    /// distance between two distinct minima of a profile (joints are millimetres apart).
    pub fn same_minimum_mm(&self) -> f64 {
        self.same_minimum_mm
    }
}

impl Default for RollSettings {
    fn default() -> RollSettings {
        RollSettings {
            residual_tol_mm: 1e-11,
            collapsed_residual_mm: 1e-9,
            max_iter: 60,
            bracket_collapse_rad: 1e-15,
            rescan_roll_rad: 5e-4,
            same_minimum_mm: 1e-6,
        }
    }
}
