//! The scene file as serde reads it: one struct per table, every key optional, unknown keys
//! rejected. [`super::Scene::from_toml`] checks the values.

#![allow(non_snake_case)] // keys carry their units as written: `wheel_load_kN`, `young_GPa`

use serde::Deserialize;

/// The scene file as written: every key optional where a default exists.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    /// Short name, used for the output folder.
    pub name: Option<String>,
    /// Title shown in the report.
    pub title: Option<String>,
    /// `[wheel]`.
    #[serde(default)]
    pub wheel: RawWheel,
    /// `[rail]`.
    #[serde(default)]
    pub rail: RawRail,
    /// `[track]`.
    #[serde(default)]
    pub track: RawTrack,
    /// `[wheelset]`.
    #[serde(default)]
    pub wheelset: RawWheelset,
    /// `[load]`.
    #[serde(default)]
    pub load: RawLoad,
    /// `[material]`.
    #[serde(default)]
    pub material: RawMaterial,
    /// `[sweep]`.
    #[serde(default)]
    pub sweep: RawSweep,
    /// `[outputs]`.
    #[serde(default)]
    pub outputs: RawOutputs,
    /// `[rigid]`.
    #[serde(default)]
    pub rigid: RawRigid,
    /// `[quasi_elastic]`.
    #[serde(default)]
    pub quasi_elastic: RawQuasiElastic,
    /// `[hertz]`.
    #[serde(default)]
    pub hertz: RawHertz,
    /// `[conicity]`.
    #[serde(default)]
    pub conicity: RawConicity,
    /// `[fleet]`.
    #[serde(default)]
    pub fleet: RawFleet,
    /// `[limits]`.
    #[serde(default)]
    pub limits: RawLimits,
    /// `[creep]`: present when the scene asks for creep forces.
    pub creep: Option<RawCreep>,
    /// `[table]`: present when the scene asks for the contact table.
    pub table: Option<RawTable>,
}

/// `[limits]`: maintenance limits of the flange dimensions (mm), each overriding the
/// standard's value for the wheel's diameter ([`crate::maintenance::Limits`]).
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawLimits {
    /// Least flange height Sh.
    pub sh_min_mm: Option<f64>,
    /// Greatest flange height Sh.
    pub sh_max_mm: Option<f64>,
    /// Least flange thickness Sd.
    pub sd_min_mm: Option<f64>,
    /// Greatest flange thickness Sd.
    pub sd_max_mm: Option<f64>,
    /// Least qR.
    pub qr_min_mm: Option<f64>,
}

/// `[creep]`: the creep stage's motion and model.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawCreep {
    /// Forward speed, m/s.
    pub speed_m_s: Option<f64>,
    /// Coefficient of friction.
    pub friction: Option<f64>,
    /// "fastsim" (default), "linear" or "polach".
    pub method: Option<String>,
    /// FASTSIM's traction bound: "parabolic" (default) or "elliptic".
    pub bound: Option<String>,
    /// The contacts: "quasi_elastic" (default: the heaviest patch and the second) or "rigid".
    pub contact: Option<String>,
    /// Lateral velocity of the wheelset, mm/s, positive to the left.
    pub lateral_velocity_mm_s: Option<f64>,
    /// Yaw rate of the wheelset, rad/s.
    pub yaw_rate_rad_s: Option<f64>,
    /// Pitch rate, rad/s (positive rolls forwards): one for every position or one per
    /// position; default free rolling.
    pub pitch_rate_rad_s: Option<OneOrMany>,
}

/// A number, or a list of numbers.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum OneOrMany {
    /// One value for all.
    One(f64),
    /// One value each.
    Many(Vec<f64>),
}

/// `[table]`: the grid of the contact table.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawTable {
    /// First lateral shift, mm.
    pub from_mm: Option<f64>,
    /// Last lateral shift, mm.
    pub to_mm: Option<f64>,
    /// Step of the shift, mm.
    pub step_mm: Option<f64>,
    /// First yaw, mrad.
    pub yaw_from_mrad: Option<f64>,
    /// Last yaw, mrad.
    pub yaw_to_mrad: Option<f64>,
    /// Step of the yaw, mrad.
    pub yaw_step_mrad: Option<f64>,
}

/// `[fleet]`: settings of `wheelrail fleet` when this scene is its template.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawFleet {
    /// The limit of tan γe(3 mm) that the fleet report marks (dimensionless, > 0).
    pub conicity_limit: Option<f64>,
}

/// `[conicity]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawConicity {
    /// "klingel" (EN 15302 Annex B, default) or "regression" (Annex C).
    pub method: Option<String>,
    /// Amplitudes (mm, increasing); default 0.5 to 10 mm in 0.1 mm steps, clipped to what
    /// the sweep supports.
    pub amplitudes_mm: Option<Vec<f64>>,
}

/// `[rigid]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawRigid {
    /// "default" or "paper".
    pub solver: Option<String>,
    /// "solved" (default: the roll that puts both wheels on their rails) or "none" (each
    /// wheel lowered onto its rail, the wheelset level: EN 15302 Annex E's Δr).
    pub roll: Option<String>,
}

/// `[quasi_elastic]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawQuasiElastic {
    /// Regularisation parameter eps (mm).
    pub epsilon_mm: Option<f64>,
    /// Values of eps for the sensitivity figure (mm).
    pub sensitivity_epsilon_mm: Option<Vec<f64>>,
    /// Cut-off of the weight in units of eps.
    pub cutoff: Option<f64>,
    /// "gauss_legendre" (default) or "trapezoid".
    pub quadrature: Option<String>,
    /// Largest step of the trapezoid quadrature (mm).
    pub max_step_mm: Option<f64>,
    /// Panel length of the Gauss-Legendre quadrature, in weight widths.
    pub panel_widths: Option<f64>,
}

/// `[hertz]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawHertz {
    /// "exact" or "paper".
    pub method: Option<String>,
    /// "quasi_elastic" or "rigid".
    pub contact: Option<String>,
    /// "projected" or "vertical".
    pub normal_load: Option<String>,
}

/// `[wheel]`: profile (both sides, or per side) and nominal radius.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawWheel {
    /// Built-in name or a path (relative to the scene file) for both wheels.
    pub profile: Option<String>,
    /// Overrides `profile` for the left wheel.
    pub left_profile: Option<String>,
    /// Overrides `profile` for the right wheel.
    pub right_profile: Option<String>,
    /// Nominal rolling radius at the taping line, both wheels.
    pub nominal_radius_mm: Option<f64>,
    /// Overrides `nominal_radius_mm` for the left wheel.
    pub left_nominal_radius_mm: Option<f64>,
    /// Overrides `nominal_radius_mm` for the right wheel.
    pub right_nominal_radius_mm: Option<f64>,
    /// Filter wavelength of the spline through wheel profiles read from files (0: none).
    pub smoothing_wavelength_mm: Option<f64>,
    /// Drop measured points that step back (MiniProf fold-backs) instead of refusing them.
    pub drop_step_backs: Option<bool>,
}

/// `[rail]`: profile (both sides, or per side) and inclination.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawRail {
    /// Built-in name or a path (relative to the scene file) for both rails.
    pub profile: Option<String>,
    /// Overrides `profile` for the left rail.
    pub left_profile: Option<String>,
    /// Overrides `profile` for the right rail.
    pub right_profile: Option<String>,
    /// Inclination of the rails in the track ("1:40", "1:20", "vertical", radians).
    pub inclination: Option<String>,
    /// Inclination already contained in the profile data (default "vertical": upright).
    pub profile_inclination: Option<String>,
    /// The nominal profile the rails' wear is measured against (built-in name or path).
    pub nominal_profile: Option<String>,
    /// Filter wavelength of the spline through rail profiles read from files (0: none).
    pub smoothing_wavelength_mm: Option<f64>,
    /// Drop measured points that step back (MiniProf fold-backs) instead of refusing them.
    pub drop_step_backs: Option<bool>,
}

/// `[track]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawTrack {
    /// Gauge between the gauge points.
    pub gauge_mm: Option<f64>,
    /// Depth of the gauge points below the top of rail.
    pub gauge_point_depth_mm: Option<f64>,
}

/// `[wheelset]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawWheelset {
    /// Distance between the inner faces of the wheels.
    pub flange_back_mm: Option<f64>,
    /// A fixed yaw of the wheelset, mrad (right-hand about z up).
    pub yaw_mrad: Option<f64>,
    /// The model of the yawed wheel's outline: "exact" or "small_angle".
    pub yaw_model: Option<String>,
}

/// `[load]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)]
pub struct RawLoad {
    /// Vertical load per wheel in kN.
    pub wheel_load_kN: Option<f64>,
}

/// `[material]`: both bodies, or per body.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)]
pub struct RawMaterial {
    /// Young's modulus of both bodies, GPa.
    pub young_GPa: Option<f64>,
    /// Poisson's ratio of both bodies.
    pub poisson: Option<f64>,
    /// Overrides `young_GPa` for the wheel.
    pub wheel_young_GPa: Option<f64>,
    /// Overrides `young_GPa` for the rail.
    pub rail_young_GPa: Option<f64>,
    /// Overrides `poisson` for the wheel.
    pub wheel_poisson: Option<f64>,
    /// Overrides `poisson` for the rail.
    pub rail_poisson: Option<f64>,
}

/// `[sweep]`: lateral positions of the wheelset.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawSweep {
    /// First lateral shift.
    pub from_mm: Option<f64>,
    /// Last lateral shift (included when the step divides the range).
    pub to_mm: Option<f64>,
    /// Step between lateral shifts.
    pub step_mm: Option<f64>,
    /// Yaw growing with the shift, mrad per mm (added to `wheelset.yaw_mrad`).
    pub yaw_mrad_per_mm: Option<f64>,
}

/// `[outputs]`.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawOutputs {
    /// Figure names (see [`crate::stage::Figure`]).
    pub figures: Option<Vec<String>>,
    /// Image formats: "svg", "png".
    pub formats: Option<Vec<String>>,
}
