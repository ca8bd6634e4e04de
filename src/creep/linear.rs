//! Kalker's linear theory of rolling contact: the limit of vanishing creepage, in which the
//! whole patch adheres (Kalker 1990, Appendix E with Table E.3; Johnson 1985, §8.4 with
//! Table 8.1; cited by section and table: the equation numbers were not checked against the
//! books).
//!
//! With `c = √(ab)`, `G` the shear modulus and the forces of the wheel on the rail:
//!
//! ```text
//! Fx = -G c² C11 ξ
//! Fy = -G c² C22 η - G c³ C23 φ
//! ```
//!
//! The forces grow without bound: this is the slope every saturating model must start
//! with (tests `small_creepage_tends_to_linear_theory` in `tests/creep_theory.rs`). The spin moment
//! `Mz = G c³ C23 η - G c⁴ C33 φ` needs `C33`, which the committed copy of Table E.3 does not
//! hold: `mz_nmm` is NaN rather than a number without a source.

use super::Settings;
use super::coefficients::Coefficients;
use super::creepage::Creepages;
use super::tangential::{EllipticPatch, Tangential};

/// Linear theory on `patch` (module docs); adhesion fraction 1 by assumption.
pub(super) fn solve(
    patch: &EllipticPatch,
    creepages: &Creepages,
    coefficients: &Coefficients,
    settings: &Settings,
) -> Tangential {
    let g = settings.shear_modulus_mpa();
    let c = patch.c_mm();
    let gc2 = g * c * c;
    Tangential {
        fx_n: -gc2 * coefficients.c11 * creepages.xi,
        fy_n: -gc2
            * (coefficients.c22 * creepages.eta + c * coefficients.c23 * creepages.phi_per_mm),
        mz_nmm: f64::NAN,
        adhesion_fraction: 1.0,
        coefficients: *coefficients,
    }
}
