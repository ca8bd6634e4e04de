//! The parameters engineers judge a wheel/rail pair by, from its rigid sweep: the equivalent
//! conicity function by both methods, `tan γe` at 2, 3 and 4 mm, Polach's nonlinearity
//! parameter, where flange contact begins, the contact-point jumps, Δr and the contact angle
//! difference at ±3 mm.

use super::well::Well;
use super::{
    ConicityMethod, DeltaR, EquivalentConicity, equivalent_conicity, supported_default_amplitudes,
};
use crate::rigid::{self, JumpKind, RigidPosition, RigidSweep, contact_angle};
use crate::track::{Placement, Side};
use std::borrow::Cow;

pub(crate) use crate::rigid::FLANGE_CONTACT_GAMMA_RAD;

/// The lateral shift at which Δr and the contact angle difference are reported (mm).
pub(crate) const REPORT_SHIFT_MM: f64 = 3.0;

/// The largest amplitude of EN 15302's reference results (mm): Annex F tabulates `tan γe`
/// from 1.0 to 7.5 mm. [`assess_on`] makes the Δr function reach every amplitude up to it
/// (or up to the largest the settings ask for).
pub(crate) const STANDARD_MAX_AMPLITUDE_MM: f64 = 7.5;

/// How many times [`assess_on`] widens a sweep that does not reach far enough: each
/// widening reaches what the last Δr function showed missing, and a motion's turning point
/// moves little once the flange is reached, so two suffice on the EN 15302 cases; the cap
/// only bounds a Δr that never turns (a wheel that climbs its rail).
const MAX_WIDENINGS: usize = 6;

/// The farthest shift [`assess_on`] asks for (mm): twice the lateral clearance of a
/// standard-gauge wheelset (about 7 mm per side before the flange), far beyond where any
/// flange contact turns the kinematic motion.
pub(crate) const WIDEST_SHIFT_MM: f64 = 20.0;

/// The amplitudes bounding Polach's nonlinearity parameter (mm).
pub(crate) const NONLINEARITY_AMPLITUDES_MM: [f64; 2] = [2.0, 4.0];

/// The largest amplitude of the equivalent conicity accepted (mm): the motion must stay on
/// the rail heads, and a scene's `[sweep]` is limited to ±100 mm.
pub(crate) const MAX_AMPLITUDE_MM: f64 = 100.0;

/// The largest number of amplitudes accepted: as many as a sweep has positions at most.
const MAX_AMPLITUDES: usize = crate::sweep::MAX_POSITIONS;

/// ConicitySettings of the `equivalent_conicity` stage (`[conicity]` in a scene), checked by
/// [`ConicitySettings::with_amplitudes_mm`]. The default: Klingel's method at 0.5 to 10 mm in
/// 0.1 mm steps, clipped to what the sweep supports.
#[derive(Debug, Clone, PartialEq)]
pub struct ConicitySettings {
    pub(crate) method: ConicityMethod,
    pub(crate) amplitudes_mm: Option<Vec<f64>>,
}

impl Default for ConicitySettings {
    fn default() -> Self {
        ConicitySettings {
            method: ConicityMethod::Klingel,
            amplitudes_mm: None,
        }
    }
}

/// Why equivalent-conicity amplitudes are not accepted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ConicitySettingsError {
    /// No amplitudes, or more than 100001.
    Count {
        /// How many were given.
        count: usize,
    },
    /// An amplitude that is not a number above 0 and at most 100 mm.
    OutOfRange {
        /// Its index (from 0).
        index: usize,
        /// The amplitude, mm.
        amplitude_mm: f64,
    },
    /// An amplitude not above the one before it.
    NotIncreasing {
        /// The amplitude, mm.
        amplitude_mm: f64,
        /// The one before it, mm.
        previous_mm: f64,
    },
}

impl std::fmt::Display for ConicitySettingsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            ConicitySettingsError::Count { count } => {
                write!(
                    f,
                    "expected 1 to {MAX_AMPLITUDES} amplitudes, found {count}"
                )
            }
            ConicitySettingsError::OutOfRange {
                index,
                amplitude_mm,
            } => write!(
                f,
                "amplitude {amplitude_mm} (item {}) must be a number above 0 and at most {MAX_AMPLITUDE_MM} mm",
                index + 1
            ),
            ConicitySettingsError::NotIncreasing {
                amplitude_mm,
                previous_mm,
            } => write!(
                f,
                "amplitudes must increase: {amplitude_mm} follows {previous_mm}"
            ),
        }
    }
}

impl std::error::Error for ConicitySettingsError {}

impl ConicitySettings {
    /// The pair's parameters by `method` (both methods are always tabulated), at the
    /// default amplitudes.
    pub fn new(method: ConicityMethod) -> ConicitySettings {
        ConicitySettings {
            method,
            amplitudes_mm: None,
        }
    }

    /// These settings at the amplitudes `amplitudes_mm` (mm): 1 to 100001 of them,
    /// increasing, each above 0 and at most 100 mm.
    ///
    /// # Errors
    /// [`ConicitySettingsError`] naming the first amplitude that is not accepted.
    pub fn with_amplitudes_mm(
        self,
        amplitudes_mm: Vec<f64>,
    ) -> Result<ConicitySettings, ConicitySettingsError> {
        let a = &amplitudes_mm;
        if a.is_empty() || a.len() > MAX_AMPLITUDES {
            return Err(ConicitySettingsError::Count { count: a.len() });
        }
        for (index, &v) in a.iter().enumerate() {
            if !(v.is_finite() && v > 0.0 && v <= MAX_AMPLITUDE_MM) {
                return Err(ConicitySettingsError::OutOfRange {
                    index,
                    amplitude_mm: v,
                });
            }
            if index > 0 && v <= a[index - 1] {
                return Err(ConicitySettingsError::NotIncreasing {
                    amplitude_mm: v,
                    previous_mm: a[index - 1],
                });
            }
        }
        Ok(ConicitySettings {
            amplitudes_mm: Some(amplitudes_mm),
            ..self
        })
    }

    /// The method of the pair's parameters.
    pub fn method(&self) -> ConicityMethod {
        self.method
    }

    /// The amplitudes (mm, increasing); `None`: the default ones, clipped to the sweep.
    pub fn amplitudes_mm(&self) -> Option<&[f64]> {
        self.amplitudes_mm.as_deref()
    }
}

/// The parameters of a wheel/rail pair (see [`Parameters::rows`] for their definitions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameters {
    /// The method of the `tan γe` values.
    pub method: ConicityMethod,
    /// `tan γe` at ŷ = 2 mm.
    pub tan_gamma_e_2mm: f64,
    /// `tan γe` at ŷ = 3 mm.
    pub tan_gamma_e_3mm: f64,
    /// `tan γe` at ŷ = 4 mm.
    pub tan_gamma_e_4mm: f64,
    /// Polach's nonlinearity parameter (1/mm).
    pub nonlinearity_per_mm: f64,
    /// Equilibrium position of the wheelset, where Δr = 0 (mm).
    pub equilibrium_mm: f64,
    /// Shift where the left wheel's flange contact begins (mm, > 0; NaN beyond the sweep).
    pub flange_contact_left_mm: f64,
    /// Shift where the right wheel's flange contact begins (mm, < 0; NaN beyond the sweep).
    pub flange_contact_right_mm: f64,
    /// Number of contact-point jumps over the sweep (both wheels), sampling artefacts left
    /// out.
    pub contact_point_jumps: usize,
    /// Number of sampling artefacts over the sweep (both wheels): hops of a sampled
    /// profile's contact point across hollows of the gap shallower than
    /// `rigid::ARTEFACT_HOLLOW_MM`.
    pub sampling_artefacts: usize,
    /// Δr at y_ws = +3 mm (mm).
    pub delta_r_at_plus_3mm_mm: f64,
    /// Δr at y_ws = -3 mm (mm).
    pub delta_r_at_minus_3mm_mm: f64,
    /// Contact angle difference `γ_left - γ_right` at y_ws = +3 mm (rad).
    pub contact_angle_difference_at_plus_3mm_rad: f64,
    /// Contact angle difference `γ_left - γ_right` at y_ws = -3 mm (rad).
    pub contact_angle_difference_at_minus_3mm_rad: f64,
}

/// One row of the parameter table.
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterRow {
    /// Machine name (`parameters.csv`, fleet columns).
    pub name: &'static str,
    /// Value (NaN where undefined).
    pub value: f64,
    /// Unit (`1` for dimensionless, `count`).
    pub unit: &'static str,
    /// Definition in words, with its source.
    pub definition: String,
    /// Why the value can be NaN (the `status` of a NaN row of `parameters.csv`).
    pub undefined: &'static str,
}

impl ParameterRow {
    /// `ok` for a finite value, else `undefined: ` and the reason.
    pub fn status(&self) -> String {
        if self.value.is_finite() {
            "ok".to_string()
        } else {
            format!("undefined: {}", self.undefined)
        }
    }
}

impl Parameters {
    /// The amplitude at which acceptance rules quote the equivalent conicity (mm):
    /// [`Parameters::tan_gamma_e_3mm`]'s.
    pub const REFERENCE_AMPLITUDE_MM: f64 = 3.0;

    /// Every parameter undefined (NaN, no jumps): the row of a pair that could not be
    /// assessed.
    pub fn undefined(method: ConicityMethod) -> Parameters {
        Parameters {
            method,
            tan_gamma_e_2mm: f64::NAN,
            tan_gamma_e_3mm: f64::NAN,
            tan_gamma_e_4mm: f64::NAN,
            nonlinearity_per_mm: f64::NAN,
            equilibrium_mm: f64::NAN,
            flange_contact_left_mm: f64::NAN,
            flange_contact_right_mm: f64::NAN,
            contact_point_jumps: 0,
            sampling_artefacts: 0,
            delta_r_at_plus_3mm_mm: f64::NAN,
            delta_r_at_minus_3mm_mm: f64::NAN,
            contact_angle_difference_at_plus_3mm_rad: f64::NAN,
            contact_angle_difference_at_minus_3mm_rad: f64::NAN,
        }
    }

    /// The parameters as named rows with units and definitions, in report order.
    pub fn rows(&self) -> Vec<ParameterRow> {
        let m = match self.method {
            ConicityMethod::Klingel => {
                "EN 15302 Annex B, Klingel wavelength of the kinematic motion"
            }
            ConicityMethod::Regression => "EN 15302 Annex C, regression of delta_r over the motion",
        };
        let tan = |i: usize, a: &str| ParameterRow {
            name: ["tan_gamma_e_2mm", "tan_gamma_e_3mm", "tan_gamma_e_4mm"][i],
            value: [
                self.tan_gamma_e_2mm,
                self.tan_gamma_e_3mm,
                self.tan_gamma_e_4mm,
            ][i],
            unit: "1",
            definition: format!("equivalent conicity at amplitude {a} mm ({m})"),
            undefined: "the motion of this amplitude leaves the swept delta_r or has no period (see the status in equivalent_conicity.csv)",
        };
        vec![
            tan(0, "2"),
            tan(1, "3"),
            tan(2, "4"),
            ParameterRow {
                name: "nonlinearity_parameter_per_mm",
                value: self.nonlinearity_per_mm,
                unit: "1/mm",
                definition: "Polach's nonlinearity parameter NP = (tan_gamma_e(4 mm) - tan_gamma_e(2 mm)) / (4 mm - 2 mm), the slope of the equivalent conicity function (O. Polach, Vehicle System Dynamics 48 (2010) Suppl., 19-36); < 0 for a function falling with amplitude, typical of worn, conformal pairs".into(),
                undefined: "tan_gamma_e at 2 or 4 mm is undefined",
            },
            ParameterRow {
                name: "equilibrium_y_mm",
                value: self.equilibrium_mm,
                unit: "mm",
                definition: "wheelset shift where delta_r = 0 (stable crossing nearest 0; the middle of a band of delta_r = 0); the kinematic motion oscillates about it".into(),
                undefined: "delta_r has no stable zero crossing within the sweep",
            },
            ParameterRow {
                name: "flange_contact_left_y_mm",
                value: self.flange_contact_left_mm,
                unit: "mm",
                definition: format!("smallest shift y_ws > 0 at which the left wheel's contact angle exceeds {FLANGE_CONTACT_GAMMA_RAD} rad (linear between sweep positions; at a contact-point jump, its middle); NaN if not within the sweep"),
                undefined: "no flange contact of the left wheel within the sweep",
            },
            ParameterRow {
                name: "flange_contact_right_y_mm",
                value: self.flange_contact_right_mm,
                unit: "mm",
                definition: format!("the same for the right wheel, y_ws < 0 (contact angle above {FLANGE_CONTACT_GAMMA_RAD} rad)"),
                undefined: "no flange contact of the right wheel within the sweep",
            },
            ParameterRow {
                name: "contact_point_jumps",
                value: self.contact_point_jumps as f64,
                unit: "count",
                definition: "contact-point jumps of either wheel over the sweep (rigid_jumps.csv, kind jump, located to 1e-4 mm)".into(),
                undefined: "never (a count)",
            },
            ParameterRow {
                name: "sampling_artefacts",
                value: self.sampling_artefacts as f64,
                unit: "count",
                definition: format!("hops of a sampled profile's contact point between two minima of the gap that a hollow shallower than {} mm separates, counted apart from the jumps (rigid_jumps.csv, kind artefact; continuous in delta_r and the charts)", rigid::ARTEFACT_HOLLOW_MM),
                undefined: "never (a count)",
            },
            ParameterRow {
                name: "delta_r_at_plus_3mm_mm",
                value: self.delta_r_at_plus_3mm_mm,
                unit: "mm",
                definition: "rolling radius difference r_left - r_right at y_ws = +3 mm".into(),
                undefined: "y_ws = +3 mm is outside the sweep or did not converge",
            },
            ParameterRow {
                name: "delta_r_at_minus_3mm_mm",
                value: self.delta_r_at_minus_3mm_mm,
                unit: "mm",
                definition: "rolling radius difference r_left - r_right at y_ws = -3 mm".into(),
                undefined: "y_ws = -3 mm is outside the sweep or did not converge",
            },
            ParameterRow {
                name: "contact_angle_difference_at_plus_3mm_rad",
                value: self.contact_angle_difference_at_plus_3mm_rad,
                unit: "rad",
                definition: "gamma_left - gamma_right at y_ws = +3 mm (track frame, roll included, mirrored per side)".into(),
                undefined: "y_ws = +3 mm is outside the sweep or did not converge",
            },
            ParameterRow {
                name: "contact_angle_difference_at_minus_3mm_rad",
                value: self.contact_angle_difference_at_minus_3mm_rad,
                unit: "rad",
                definition: "gamma_left - gamma_right at y_ws = -3 mm".into(),
                undefined: "y_ws = -3 mm is outside the sweep or did not converge",
            },
        ]
    }
}

/// The equivalent conicity of a pair and its parameters (the `equivalent_conicity` stage).
#[derive(Debug, Clone)]
pub struct PairConicity {
    /// The Δr function of the rigid sweep (`r_left - r_right`, mm, over `y_ws` in mm): NaN
    /// where a position did not converge or a wheel has no contact, each contact-point jump a
    /// discontinuity in the middle of its refined interval (values from its ends); a
    /// sampling artefact ([`JumpKind::Artefact`]) is no discontinuity.
    pub delta_r: DeltaR,
    /// The equivalent conicity by the Klingel method (EN 15302 Annex B).
    pub klingel: EquivalentConicity,
    /// The equivalent conicity by regression (EN 15302 Annex C), at the same amplitudes.
    pub regression: EquivalentConicity,
    /// The pair's parameters, by the settings' method.
    pub parameters: Parameters,
}

impl PairConicity {
    /// The result of `method`.
    pub fn by(&self, method: ConicityMethod) -> &EquivalentConicity {
        match method {
            ConicityMethod::Klingel => &self.klingel,
            ConicityMethod::Regression => &self.regression,
        }
    }
}

/// The Δr function of a rigid sweep: `r_left - r_right` at every converged position, NaN
/// where a position did not converge or a wheel has no contact, and each contact-point
/// jump as a discontinuity in the middle of its refined interval (values from its ends).
/// A sampling artefact ([`JumpKind::Artefact`]) is no discontinuity: Δr is linear between
/// the sweep positions around it, as where the contact point moves continuously.
fn delta_r_of(sweep: &RigidSweep) -> DeltaR {
    let mut points: Vec<(f64, f64)> = sweep
        .positions()
        .iter()
        .map(|p| (p.y_ws, p.delta_r()))
        .collect();
    for j in sweep.jumps().iter().filter(|j| j.kind == JumpKind::Jump) {
        let mid = 0.5 * (j.y_from + j.y_to);
        // Drop sweep positions inside the refined interval (none on a sweep coarser than
        // 1e-4 mm), then insert the discontinuity.
        points.retain(|&(y, _)| y <= j.y_from || y >= j.y_to);
        let at = points.partition_point(|&(y, _)| y < mid);
        points.insert(at, (mid, j.delta_r_to));
        points.insert(at, (mid, j.delta_r_from));
    }
    let (y, dr): (Vec<f64>, Vec<f64>) = points.into_iter().unzip();
    DeltaR::with_jumps(y, dr).unwrap_or_else(|_| {
        // Two jumps in one refined interval would repeat a y three times: keep the sweep
        // positions only (the jumps' effect is then that of linear interpolation).
        let (y, dr) = sweep
            .positions()
            .iter()
            .map(|p| (p.y_ws, p.delta_r()))
            .unzip();
        // A rigid sweep's shifts are a `Sweep`'s: finite and strictly increasing.
        DeltaR::with_jumps(y, dr).expect("a sweep's shifts increase strictly")
    })
}

/// The equivalent conicity and parameters of the pair swept by `sweep`: its Δr function
/// (jumps as steps: [`PairConicity::delta_r`]), tan γe by both methods at the settings'
/// amplitudes (mm), and the [`Parameters`] (tan γe at 2, 3 and 4 mm, nonlinearity, flange-contact
/// shifts, jumps). Amplitudes the sweep cannot support give NaN with their status, not an
/// error.
///
/// # Example
/// ```
/// use wheelrail::{conicity, pipeline, rigid, scene::Scene};
/// let scene = Scene::from_toml("[sweep]\nfrom_mm = -10.0\nto_mm = 10.0\nstep_mm = 0.1", "doc", ".".as_ref()).unwrap();
/// let sweep = rigid::search(&pipeline::place(&scene).unwrap(), scene.sweep(), rigid::Solver::default());
/// let pair = conicity::assess(&sweep, &conicity::ConicitySettings::default());
/// let tan_gamma_e_3mm = pair.parameters.tan_gamma_e_3mm;
/// assert!(tan_gamma_e_3mm > 0.1 && tan_gamma_e_3mm < 0.3); // S1002 on UIC60 1:40
/// ```
pub fn assess(sweep: &RigidSweep, settings: &ConicitySettings) -> PairConicity {
    assess_delta_r(sweep, delta_r_of(sweep), settings)
}

/// [`assess`] with the Δr function reaching every amplitude the settings need: the rigid
/// search on `placement` (the one `sweep` was solved on) is asked for the shifts beyond
/// the sweep that the motions of those amplitudes reach (`rigid::extend`, each end
/// continued outwards), so that an off-centre pair (wheels of different radii, EN 15302
/// cases E5 to E8) gets every amplitude up to 7.5 mm (`STANDARD_MAX_AMPLITUDE_MM`, or the largest
/// of `settings.amplitudes_mm`) without a wider sweep in the scene. Only the shifts the
/// motions need are solved, as far as 20 mm (`WIDEST_SHIFT_MM`). The parameters that describe the
/// sweep (flange contact, jumps) are `sweep`'s own; `tan γe` and Δr at ±3 mm come from the
/// widened Δr function. Where `sweep` already reaches far enough, this is [`assess`].
///
/// # Example
/// ```
/// use wheelrail::{conicity, pipeline, rigid, scene::Scene};
/// let scene = Scene::from_toml("[sweep]\nfrom_mm = -4.0\nto_mm = 4.0\nstep_mm = 0.1", "doc", ".".as_ref()).unwrap();
/// let placement = pipeline::place(&scene).unwrap();
/// let sweep = rigid::search(&placement, scene.sweep(), rigid::Solver::default());
/// let pair = conicity::assess_on(&placement, &sweep, &conicity::ConicitySettings::default());
/// // The sweep ends at 4 mm; the motion of 7.5 mm is computed all the same.
/// assert!(pair.klingel.at(7.5).unwrap().is_finite());
/// ```
pub fn assess_on(
    placement: &Placement,
    sweep: &RigidSweep,
    settings: &ConicitySettings,
) -> PairConicity {
    let widened = widened(placement, sweep, settings);
    assess_delta_r(sweep, delta_r_of(&widened), settings)
}

/// The pair's equivalent conicity function by the settings' method only, and its
/// parameters: what [`assess_on`] gives for that method (on the same widened sweep), without
/// the other method's function, which a fleet's summary does not need. The same functions
/// compute both: the values are [`assess_on`]'s to the last digit.
pub(crate) fn assess_by_method_on(
    placement: &Placement,
    sweep: &RigidSweep,
    settings: &ConicitySettings,
) -> (EquivalentConicity, Parameters) {
    let widened = widened(placement, sweep, settings);
    let delta_r = delta_r_of(&widened);
    let amplitudes = amplitudes(settings, &delta_r);
    (
        equivalent_conicity(&delta_r, &amplitudes, settings.method),
        parameters(sweep, &delta_r, settings),
    )
}

/// The largest amplitude the settings need (mm).
fn wanted_amplitude(settings: &ConicitySettings) -> f64 {
    settings
        .amplitudes_mm
        .as_deref()
        .map_or(STANDARD_MAX_AMPLITUDE_MM, |a| {
            a.iter()
                .copied()
                .filter(|a| a.is_finite())
                .fold(0.0, f64::max)
        })
}

/// `sweep`, widened by the rigid search on `placement` until its Δr function supports the
/// largest amplitude the settings need by both methods (see [`assess_on`]).
fn widened<'s>(
    placement: &Placement,
    sweep: &'s RigidSweep,
    settings: &ConicitySettings,
) -> Cow<'s, RigidSweep> {
    let wanted = wanted_amplitude(settings);
    let mut current = Cow::Borrowed(sweep);
    for _ in 0..MAX_WIDENINGS {
        let Some((from, to)) = reach_needed(&current, wanted) else {
            break;
        };
        let (from, to) = (from.max(-WIDEST_SHIFT_MM), to.min(WIDEST_SHIFT_MM));
        let wider = rigid::extend(placement, &current, from, to);
        if wider.positions().len() == current.positions().len() {
            break;
        }
        current = Cow::Owned(wider);
    }
    current
}

/// The shifts `(from, to)` the Δr function of `sweep` must reach for the amplitude `a`
/// by both methods, or `None` when it reaches them (or has no equilibrium, or ends at a
/// position that did not converge, which more positions cannot mend).
///
/// The regression needs `y_eq ± a`. The Klingel motion needs the level of its turning
/// points on both sides; where the Δr function ends first on one side, that side is taken
/// further by twice the amplitude missing (the turning point moves by about as much as the
/// amplitude, more on the side that rises slower), at least 0.5 mm.
fn reach_needed(sweep: &RigidSweep, a: f64) -> Option<(f64, f64)> {
    let positions = sweep.positions();
    let (first, last) = (positions.first()?, positions.last()?);
    if !(first.delta_r().is_finite() && last.delta_r().is_finite()) {
        return None;
    }
    let delta_r = delta_r_of(sweep);
    let well = Well::new(&delta_r)?;
    let eq = well.equilibrium();
    let (mut from, mut to) = ((eq - a).min(first.y_ws), (eq + a).max(last.y_ws));
    let max = well.klingel_max_amplitude();
    if max < a * (1.0 - 1e-12) {
        let more = (2.0 * (a - max)).max(0.5);
        let [below, above] = well.limiting_branches();
        if above {
            to = to.max(last.y_ws + more);
        }
        if below {
            from = from.min(first.y_ws - more);
        }
    }
    let needed = from < first.y_ws || to > last.y_ws;
    needed.then_some((from, to))
}

/// The equivalent conicity and the parameters of the pair swept by `sweep` on its Δr
/// function `delta_r` (the sweep's own, or a widened one).
fn assess_delta_r(
    sweep: &RigidSweep,
    delta_r: DeltaR,
    settings: &ConicitySettings,
) -> PairConicity {
    let amplitudes = amplitudes(settings, &delta_r);
    let klingel = equivalent_conicity(&delta_r, &amplitudes, ConicityMethod::Klingel);
    let regression = equivalent_conicity(&delta_r, &amplitudes, ConicityMethod::Regression);
    let parameters = parameters(sweep, &delta_r, settings);
    PairConicity {
        delta_r,
        klingel,
        regression,
        parameters,
    }
}

/// The amplitudes of the settings, or the default ones the Δr function supports.
fn amplitudes(settings: &ConicitySettings, delta_r: &DeltaR) -> Vec<f64> {
    settings
        .amplitudes_mm
        .clone()
        .unwrap_or_else(|| supported_default_amplitudes(delta_r))
}

/// The parameters of the pair swept by `sweep`, whose Δr function is `delta_r`.
fn parameters(sweep: &RigidSweep, delta_r: &DeltaR, settings: &ConicitySettings) -> Parameters {
    let at = equivalent_conicity(delta_r, &[2.0, 3.0, 4.0], settings.method);
    let [t2, t3, t4] = [0, 1, 2].map(|i| at.points[i].tan_gamma_e);
    let [a2, a4] = NONLINEARITY_AMPLITUDES_MM;
    let delta_r_at = |y: f64| delta_r.at(y).unwrap_or(f64::NAN);
    let contact_angle_difference_at = |y: f64| {
        interpolate(sweep, y, |p| {
            contact_angle(p, Side::Left) - contact_angle(p, Side::Right)
        })
    };
    let count = |kind: JumpKind| sweep.jumps().iter().filter(|j| j.kind == kind).count();
    Parameters {
        method: settings.method,
        tan_gamma_e_2mm: t2,
        tan_gamma_e_3mm: t3,
        tan_gamma_e_4mm: t4,
        nonlinearity_per_mm: (t4 - t2) / (a4 - a2),
        equilibrium_mm: at.equilibrium_mm,
        flange_contact_left_mm: sweep.flange_contact_mm(Side::Left),
        flange_contact_right_mm: sweep.flange_contact_mm(Side::Right),
        contact_point_jumps: count(JumpKind::Jump),
        sampling_artefacts: count(JumpKind::Artefact),
        delta_r_at_plus_3mm_mm: delta_r_at(REPORT_SHIFT_MM),
        delta_r_at_minus_3mm_mm: delta_r_at(-REPORT_SHIFT_MM),
        contact_angle_difference_at_plus_3mm_rad: contact_angle_difference_at(REPORT_SHIFT_MM),
        contact_angle_difference_at_minus_3mm_rad: contact_angle_difference_at(-REPORT_SHIFT_MM),
    }
}

/// `f` at shift `y`, linear between the neighbouring positions (the position itself when
/// the sweep holds `y`); NaN outside the sweep.
fn interpolate(sweep: &RigidSweep, y: f64, f: impl Fn(&RigidPosition) -> f64) -> f64 {
    let p = &sweep.positions();
    let i = p.partition_point(|q| q.y_ws < y);
    if let Some(q) = p.get(i)
        && (q.y_ws - y).abs() < 1e-9
    {
        return f(q);
    }
    if i == 0 || i == p.len() {
        return f64::NAN;
    }
    let (a, b) = (&p[i - 1], &p[i]);
    let t = (y - a.y_ws) / (b.y_ws - a.y_ws);
    f(a) + t * (f(b) - f(a))
}

#[cfg(test)]
mod tests;
