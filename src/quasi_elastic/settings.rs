//! The quasi-elastic search's settings, with their defaults and the ranges
//! [`QuasiElasticSettings::new`] accepts, each with its reason.

use crate::message::Number;
use std::fmt;

/// Default regularisation parameter (mm): the paper's 1e-5 m.
pub(crate) const DEFAULT_EPSILON_MM: f64 = 0.01;
/// Integrals stop where `(d - d_min) / eps` exceeds this. For a quadratic gap the weight left
/// out is `erfc(sqrt(25)) = 1.6e-12` of the total, and the integration regions are 18 %
/// shorter than at 37. On the paper scene the default's error in a and b (2.3e-8 against
/// the tradeoff study's reference) is the panels'; cut-offs of 15 and 37 give 4e-7 and
/// 5e-8 (`wheelrail tradeoff`).
pub(crate) const DEFAULT_CUTOFF: f64 = 25.0;
/// Default panel length of the Gauss-Legendre quadrature in weight widths `sqrt(eps / d'')`.
/// On the paper scene, against panels of half a width (`wheelrail tradeoff`): a and b err by
/// 2.3e-8 relative at 3 widths, 1.3e-8 at 2 (17 % slower), 2.9e-7 at 4 (8 % faster).
pub(crate) const DEFAULT_PANEL_WIDTHS: f64 = 3.0;
/// Largest step of the trapezoid variant in the wheel coordinate (mm).
pub(crate) const DEFAULT_MAX_STEP_MM: f64 = 0.05;
/// The values of eps accepted (mm): from 1e-6 mm (below it the weight is narrower than the
/// spacing of doubles around a contact point) to 1 mm (far beyond any elastic approach; the
/// paper uses 0.01 to 0.05 mm).
pub(crate) const EPSILON_RANGE_MM: (f64, f64) = (1e-6, 1.0);
/// The cut-offs accepted, in units of eps: at least 1 (the weight is cut within one width:
/// the average would no longer be the paper's) and at most 700 (`exp(-700)` is near the
/// smallest double; a larger cut-off cuts nothing and only widens the regions integrated).
pub(crate) const CUTOFF_RANGE: (f64, f64) = (1.0, 700.0);
/// The Gauss-Legendre panel lengths accepted, in weight widths: from 0.05 (the tradeoff
/// study's reference uses 0.5; 0.05 already takes seconds per sweep) to 8 (8 nodes over 8
/// widths no longer resolve the weight; 4 widths already err by 3e-7 in a and b on the
/// paper scene).
pub(crate) const PANEL_WIDTHS_RANGE: (f64, f64) = (0.05, 8.0);
/// The starting steps of the trapezoid quadrature accepted (mm): from 1e-4 mm (its nodes
/// cover low regions millimetres wide: 1e-6 mm would take half a minute per position) to
/// 10 mm (the step is halved until it resolves the weight, so a longer start only adds
/// halvings; 10 mm is wider than any low region of a contact).
pub(crate) const TRAPEZOID_STEP_RANGE_MM: (f64, f64) = (1e-4, 10.0);

/// Why quasi-elastic settings are not accepted; each variant names the setting, so that a
/// caller (the scene file) can name the key it came from.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum QuasiElasticSettingsError {
    /// eps outside `EPSILON_RANGE_MM` (or not finite).
    Epsilon {
        /// eps, mm.
        epsilon_mm: f64,
    },
    /// A cut-off outside `CUTOFF_RANGE` (or not finite).
    Cutoff {
        /// The cut-off, in units of eps.
        cutoff: f64,
    },
    /// A Gauss-Legendre panel length outside `PANEL_WIDTHS_RANGE` (or not finite).
    PanelWidths {
        /// The panel length, in weight widths.
        panel_widths: f64,
    },
    /// A trapezoid step outside `TRAPEZOID_STEP_RANGE_MM` (or not finite).
    MaxStep {
        /// The step, mm.
        max_step_mm: f64,
    },
}

impl fmt::Display for QuasiElasticSettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            QuasiElasticSettingsError::Epsilon { epsilon_mm } => write!(
                f,
                "{} mm is not a regularisation parameter: expected {} to {} mm (paper: 0.01 to 0.05 mm)",
                Number(epsilon_mm),
                EPSILON_RANGE_MM.0,
                EPSILON_RANGE_MM.1
            ),
            QuasiElasticSettingsError::Cutoff { cutoff } => write!(
                f,
                "{} eps is not a useful cut-off of the weight exp(-gap/eps) (exp(-700) is near the smallest double); expected {} to {} eps",
                Number(cutoff),
                CUTOFF_RANGE.0,
                CUTOFF_RANGE.1
            ),
            QuasiElasticSettingsError::PanelWidths { panel_widths } => write!(
                f,
                "{} is outside {} to {} weight widths: shorter panels would take minutes, longer ones no longer resolve the weight",
                Number(panel_widths),
                PANEL_WIDTHS_RANGE.0,
                PANEL_WIDTHS_RANGE.1
            ),
            QuasiElasticSettingsError::MaxStep { max_step_mm } => write!(
                f,
                "{} mm is outside {} to {} mm: shorter steps would not finish, a longer start only adds halvings",
                Number(max_step_mm),
                TRAPEZOID_STEP_RANGE_MM.0,
                TRAPEZOID_STEP_RANGE_MM.1
            ),
        }
    }
}

impl std::error::Error for QuasiElasticSettingsError {}

/// `v` if it is within `[lo, hi]` (NaN is not).
fn within(v: f64, (lo, hi): (f64, f64)) -> bool {
    (lo..=hi).contains(&v)
}

/// How the weighted integrals are evaluated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Quadrature {
    /// 8-point Gauss-Legendre panels on each smooth piece of the integrand: the pieces end
    /// at the wheel's and the rail's section joints (where curvatures jump) and at the
    /// barriers between patches. Default.
    GaussLegendre {
        /// Panel length in weight widths `sqrt(eps / d'')` (`DEFAULT_PANEL_WIDTHS`).
        panel_widths: f64,
    },
    /// Trapezoid sums on a fixed grid in `s`, the step halved from `max_step_mm` until it
    /// resolves the weight's width (the paper's kind of quadrature on tabulated data): only
    /// first order where a curvature jumps inside the patch.
    Trapezoid {
        /// Largest step (mm).
        max_step_mm: f64,
    },
}

impl Quadrature {
    /// Name used in scene files and tables.
    pub fn name(self) -> String {
        match self {
            Quadrature::GaussLegendre { panel_widths } => {
                format!("gauss_legendre {panel_widths} widths")
            }
            Quadrature::Trapezoid { max_step_mm } => format!("trapezoid {max_step_mm} mm"),
        }
    }
}

/// QuasiElasticSettings of the quasi-elastic search, checked by [`QuasiElasticSettings::new`] (the default is the
/// paper's eps with this crate's quadrature: see the constants).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuasiElasticSettings {
    /// Regularisation parameter `eps` (mm).
    pub(crate) epsilon_mm: f64,
    /// Cut-off of the weight, in units of `eps`.
    pub(crate) cutoff: f64,
    /// Quadrature.
    pub(crate) quadrature: Quadrature,
}

impl Default for QuasiElasticSettings {
    fn default() -> QuasiElasticSettings {
        QuasiElasticSettings {
            epsilon_mm: DEFAULT_EPSILON_MM,
            cutoff: DEFAULT_CUTOFF,
            quadrature: Quadrature::GaussLegendre {
                panel_widths: DEFAULT_PANEL_WIDTHS,
            },
        }
    }
}

impl QuasiElasticSettings {
    /// The values of eps accepted (mm): from 1e-6 mm (below it the weight is narrower than
    /// the spacing of doubles around a contact point) to 1 mm (far beyond any elastic
    /// approach; the paper uses 0.01 to 0.05 mm).
    pub const EPSILON_RANGE_MM: (f64, f64) = EPSILON_RANGE_MM;
    /// The cut-offs accepted, in units of eps (see [`QuasiElasticSettings::new`]).
    pub const CUTOFF_RANGE: (f64, f64) = CUTOFF_RANGE;
    /// The Gauss-Legendre panel lengths accepted, in weight widths.
    pub const PANEL_WIDTHS_RANGE: (f64, f64) = PANEL_WIDTHS_RANGE;
    /// The starting steps of the trapezoid quadrature accepted (mm).
    pub const TRAPEZOID_STEP_RANGE_MM: (f64, f64) = TRAPEZOID_STEP_RANGE_MM;

    /// Regularisation parameter `eps_mm`, the weight cut off at `cutoff` × eps, and the
    /// quadrature.
    ///
    /// # Errors
    /// [`QuasiElasticSettingsError`] naming the first value outside its range (see the constants of
    /// this module), checked in the order of the arguments.
    ///
    /// # Example
    /// ```
    /// use wheelrail::quasi_elastic::{Quadrature, QuasiElasticSettings};
    /// let paper_eps = QuasiElasticSettings::new(0.01, 25.0, Quadrature::GaussLegendre { panel_widths: 3.0 });
    /// assert_eq!(paper_eps.unwrap(), QuasiElasticSettings::default());
    /// assert!(QuasiElasticSettings::new(-0.01, 25.0, Quadrature::default()).is_err());
    /// ```
    pub fn new(
        epsilon_mm: f64,
        cutoff: f64,
        quadrature: Quadrature,
    ) -> Result<QuasiElasticSettings, QuasiElasticSettingsError> {
        if !within(epsilon_mm, EPSILON_RANGE_MM) {
            return Err(QuasiElasticSettingsError::Epsilon { epsilon_mm });
        }
        if !within(cutoff, CUTOFF_RANGE) {
            return Err(QuasiElasticSettingsError::Cutoff { cutoff });
        }
        match quadrature {
            Quadrature::GaussLegendre { panel_widths }
                if !within(panel_widths, PANEL_WIDTHS_RANGE) =>
            {
                return Err(QuasiElasticSettingsError::PanelWidths { panel_widths });
            }
            Quadrature::Trapezoid { max_step_mm }
                if !within(max_step_mm, TRAPEZOID_STEP_RANGE_MM) =>
            {
                return Err(QuasiElasticSettingsError::MaxStep { max_step_mm });
            }
            _ => {}
        }
        Ok(QuasiElasticSettings {
            epsilon_mm,
            cutoff,
            quadrature,
        })
    }

    /// These settings with eps = `epsilon_mm`.
    ///
    /// # Errors
    /// [`QuasiElasticSettingsError::Epsilon`] as [`QuasiElasticSettings::new`].
    pub fn with_epsilon(
        self,
        epsilon_mm: f64,
    ) -> Result<QuasiElasticSettings, QuasiElasticSettingsError> {
        QuasiElasticSettings::new(epsilon_mm, self.cutoff, self.quadrature)
    }

    /// These settings with the weight cut off at `cutoff` × eps.
    ///
    /// # Errors
    /// [`QuasiElasticSettingsError::Cutoff`] as [`QuasiElasticSettings::new`].
    pub fn with_cutoff(
        self,
        cutoff: f64,
    ) -> Result<QuasiElasticSettings, QuasiElasticSettingsError> {
        QuasiElasticSettings::new(self.epsilon_mm, cutoff, self.quadrature)
    }

    /// These settings with `quadrature`.
    ///
    /// # Errors
    /// [`QuasiElasticSettingsError::PanelWidths`] or [`QuasiElasticSettingsError::MaxStep`] as [`QuasiElasticSettings::new`].
    pub fn with_quadrature(
        self,
        quadrature: Quadrature,
    ) -> Result<QuasiElasticSettings, QuasiElasticSettingsError> {
        QuasiElasticSettings::new(self.epsilon_mm, self.cutoff, quadrature)
    }

    /// Regularisation parameter eps, mm.
    pub fn epsilon_mm(&self) -> f64 {
        self.epsilon_mm
    }

    /// Cut-off of the weight, in units of eps.
    pub fn cutoff(&self) -> f64 {
        self.cutoff
    }

    /// The quadrature.
    pub fn quadrature(&self) -> Quadrature {
        self.quadrature
    }
}

impl Default for Quadrature {
    /// Gauss-Legendre panels of `DEFAULT_PANEL_WIDTHS` weight widths.
    fn default() -> Quadrature {
        Quadrature::GaussLegendre {
            panel_widths: DEFAULT_PANEL_WIDTHS,
        }
    }
}
