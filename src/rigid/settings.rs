//! The numerical settings of the default roll solver, carried by [`Solver::Default`].

#[cfg(doc)]
use super::Solver;

/// Tolerances and caps of the default roll solver (safeguarded Newton on
/// `F(theta) = m_L - m_R`, see [`crate::rigid`]). [`Default`] gives the project's values;
/// each field states why.
///
/// The solver reads them by reference, once per position: the hot loop holds plain numbers.
///
/// # Example
/// ```
/// use wheelrail::{pipeline, rigid, scene::Scene};
/// let scene = Scene::from_toml("", "inline", std::path::Path::new(".")).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// // A looser residual than the default's 1e-11 mm.
/// let loose = rigid::RollSettings { residual_tol_mm: 1e-6, ..Default::default() };
/// let sweep = rigid::search(&placement, &wheelrail::sweep::Sweep::from_slice(&[3.0]).unwrap(), rigid::Solver::Default(loose));
/// assert_eq!(sweep.positions()[0].stop, rigid::Stop::Converged);
/// assert!(sweep.positions()[0].residual <= 1e-6);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollSettings {
    /// Residual `|m_L - m_R|` at which the solver stops (mm). Default 1e-11: the rigid
    /// search promises 1e-9 mm (its agreement with a brute-force search, `tests/rigid.rs`);
    /// Newton reaches 1e-12 in one more step, so the margin costs nothing.
    pub residual_tol_mm: f64,
    /// Residual accepted when the bracket on the roll has collapsed to the last bit (mm).
    /// Default 1e-9: the promise of the default solver, 100 times the normal
    /// tolerance (rounding of the gaps, about 1e-13 mm each at |g| ~ 450 mm, can keep
    /// `|F|` just above `residual_tol_mm` at the best double).
    pub collapsed_residual_mm: f64,
    /// Iteration cap per position. Default 60: 3-6 iterations are typical, flange onset up
    /// to ~15.
    pub max_iter: usize,
    /// A bracket on the roll narrower than this, relative to `max(|theta|, 1)`, has
    /// collapsed (rad). Default 1e-15: a few ulps of a roll of order 1e-3..1.
    pub bracket_collapse_rad: f64,
    /// Roll change after which the basins of the gap are scanned again (rad). Default 5e-4:
    /// wheel points move by about r0 * 5e-4 = 0.25 mm, one coarse step
    /// ([`crate::gap::COARSE_STEP_MM`]); smaller moves are followed by the basins
    /// themselves. Large-roll wheelsets (very unequal radii) need it.
    pub rescan_roll_rad: f64,
    /// Two basins whose minima lie this close have slid onto the same minimum; one is
    /// dropped (mm). Default 1e-6: far above the local tolerance (1e-11 mm), far below any
    /// distance between two distinct minima of a profile (joints are millimetres apart).
    pub same_minimum_mm: f64,
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
