//! Scene files: a TOML description of one run (profiles, track, load, sweep, outputs).
//!
//! [`RawScene`] mirrors the file exactly (unknown keys are rejected); [`Scene::from_toml`]
//! checks every value once and converts units, so nothing downstream re-checks. See the
//! README for the format; `reports/paper/scene.toml` is the paper's scene.

use crate::error::Number;
use crate::profile::{Profile, ProfileKind, read};
use crate::quasi_elastic::{self, Quadrature};
use crate::track::{Inclination, TrackLayout};
use serde::Deserialize;
use std::fmt;
use std::path::{Path, PathBuf};

// The defaults of the scene keys: the paper's case (S1002 on UIC60 1:40, standard gauge and
// wheelset, 460 mm wheels, 70 kN, steel), in one place. Gauge, gauge-point depth and
// flange-back distance are the track module's standard values.

/// Default nominal wheel radius (mm): the paper's 920 mm wheel.
pub const DEFAULT_NOMINAL_RADIUS_MM: f64 = 460.0;
/// Default vertical wheel load (kN): the paper's 70 kN.
pub const DEFAULT_WHEEL_LOAD_KN: f64 = 70.0;
/// Default Young's modulus of wheel and rail (GPa): steel.
pub const DEFAULT_YOUNG_GPA: f64 = 210.0;
/// Default Poisson's ratio of wheel and rail: steel.
pub const DEFAULT_POISSON: f64 = 0.3;

/// Newtons per kilonewton (the scene gives loads in kN, the numerics take N).
const N_PER_KN: f64 = 1000.0;
/// Megapascals per gigapascal (the scene gives moduli in GPa, the numerics take MPa).
const MPA_PER_GPA: f64 = 1000.0;

/// The largest number of lateral positions a sweep may have. A sweep of a million positions
/// is almost certainly a unit mistake (metres for millimetres) and would run for minutes.
pub const MAX_SWEEP_POSITIONS: usize = 100_001;

/// The largest wheel load accepted (N): 1 MN, ten times the heaviest axle loads.
pub const MAX_WHEEL_LOAD_N: f64 = 1e6;
/// The smallest wheel load accepted (N): 1 N, the lower end of the loads the Hertz solution
/// is tested at (`tests/stress.rs`); a lighter wheel only touches its rail.
pub const MIN_WHEEL_LOAD_N: f64 = 1.0;
/// The nominal wheel radii accepted (mm): from small trolley wheels to the largest
/// locomotive wheels, with margin.
pub const NOMINAL_RADIUS_RANGE_MM: (f64, f64) = (100.0, 1000.0);
/// The gauges accepted (mm): every gauge in use, from 381 mm minimum-gauge railways to
/// 1676 mm broad gauge, with margin. The wheelset is placed from it; 1e300 mm is not a track.
pub const GAUGE_RANGE_MM: (f64, f64) = (300.0, 2000.0);
/// Young's moduli accepted (GPa): polymers used on model rigs (a few GPa) to tungsten
/// carbide (about 700 GPa), with margin; railway steels are about 210 GPa.
pub const YOUNG_RANGE_GPA: (f64, f64) = (1.0, 1000.0);
/// Poisson's ratios accepted, `[0, 0.5)`: the mathematical range is `(-1, 0.5)`, but no
/// wheel or rail material has a negative ratio (steels 0.27 to 0.30, polymers up to 0.45;
/// negative ratios belong to auxetic foams), and near -1 the combined modulus `E/(1-ν²)`
/// grows without bound. 0.5 (incompressible) is excluded by Hertz's formula itself.
pub const POISSON_RANGE: (f64, f64) = (0.0, 0.5);
/// The longest filter wavelength of the profile spline (mm): longer than a wheel's tread
/// and flange together, the filter flattens the profile itself.
pub const MAX_SMOOTHING_WAVELENGTH_MM: f64 = 100.0;
/// The smallest sweep step (mm): positions are rounded to 1e-9 mm (clean printed values),
/// so a step must be far above that rounding for positions to stay distinct and evenly
/// spaced; 1e-6 mm (a nanometre) is a thousand roundings and far below any physical use.
pub const MIN_SWEEP_STEP_MM: f64 = 1e-6;
/// The cut-off of the quasi-elastic weight, in units of eps: at least 1 (the weight is
/// cut within one width: the average would no longer be the paper's) and at most 700
/// (`exp(-700)` is near the smallest double; a larger cut-off cuts nothing and only widens
/// the regions integrated).
pub const CUTOFF_RANGE: (f64, f64) = (1.0, 700.0);
/// The largest starting step of the trapezoid quadrature (mm): the step is halved until it
/// resolves the weight, so a longer start only adds halvings (and above about 5e307 mm the
/// number of halvings overflows). 10 mm is wider than any low region of a contact.
pub const MAX_TRAPEZOID_STEP_MM: f64 = 10.0;
/// The largest number of values of eps in the sensitivity figure: each is a quasi-elastic
/// pass over the whole sweep.
pub const MAX_EPSILON_SENSITIVITY: usize = 16;
/// The smallest step of the trapezoid quadrature (mm): its nodes cover the low regions
/// (millimetres wide), so 1e-6 mm would take half a minute per position.
pub const MIN_TRAPEZOID_STEP_MM: f64 = 1e-4;
/// The shortest Gauss-Legendre panel accepted, in weight widths: the tradeoff study's
/// reference uses 0.5; 0.05 would already take seconds per sweep.
pub const MIN_PANEL_WIDTHS: f64 = 0.05;
/// The longest Gauss-Legendre panel accepted, in weight widths: 8 nodes over 8 widths no
/// longer resolve the weight (4 widths already err by 3e-7 in a and b on the paper scene).
pub const MAX_PANEL_WIDTHS: f64 = 8.0;
/// The smallest regularisation parameter (mm): below it the weight is narrower than the
/// spacing of double-precision numbers around a contact point.
pub const MIN_EPSILON_MM: f64 = 1e-6;

/// Default filter wavelength of the spline through profile points read from files (mm): 0,
/// the spline interpolates. Measured profiles want smoothing (4 mm is a good start, see
/// [`crate::profile::spline::DEFAULT_FILTER_WAVELENGTH_MM`]); exact benchmark files do not.
pub const DEFAULT_SMOOTHING_WAVELENGTH_MM: f64 = 0.0;

/// The sensitivity values of eps of the `qe_epsilon` figure (mm).
pub const DEFAULT_EPSILON_SENSITIVITY_MM: [f64; 5] = [0.001, 0.003, 0.01, 0.03, 0.05];

/// An error in a scene: the file, the key (dotted path) where known, and what was expected.
#[derive(Debug)]
pub enum SceneError {
    /// The scene file could not be read.
    Io {
        /// The scene file.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The TOML is malformed, has an unknown key or a value of the wrong type.
    Syntax {
        /// The scene file.
        path: String,
        /// The parser's message (names the key, line and column).
        message: String,
    },
    /// A value is out of its allowed range or inconsistent with another.
    Invalid {
        /// The scene file.
        path: String,
        /// The dotted key, e.g. `track.gauge_mm`.
        key: &'static str,
        /// What is wrong and what was expected.
        message: String,
    },
    /// A profile named by the scene could not be read or placed.
    Profile {
        /// The scene file.
        path: String,
        /// The dotted key naming the profile.
        key: &'static str,
        /// The reader's or placement's error.
        message: String,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Io { path, source } => {
                write!(f, "{}: cannot read scene: {source}", path.display())
            }
            SceneError::Syntax { path, message } => write!(f, "{path}: {message}"),
            SceneError::Invalid { path, key, message } => {
                write!(f, "{path}: key `{key}`: {message}")
            }
            SceneError::Profile { path, key, message } => {
                write!(f, "{path}: key `{key}`: {message}")
            }
        }
    }
}

impl std::error::Error for SceneError {}

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

/// Where a profile comes from: a built-in definition or a file.
#[derive(Debug, Clone, PartialEq)]
pub enum ProfileRef {
    /// A built-in profile by name.
    BuiltIn(String),
    /// A file, resolved against the scene's folder.
    File(PathBuf),
}

/// Image formats a figure can be written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageFormat {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics (text drawn with the committed font).
    Png,
}

/// A checked scene: all values valid, units converted to mm, N, MPa, rad.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The scene file (for messages and provenance).
    pub path: String,
    /// Short name.
    pub name: String,
    /// Report title.
    pub title: String,
    /// Left and right wheel profiles.
    pub wheel_profiles: [ProfileRef; 2],
    /// Left and right nominal radii, mm.
    pub nominal_radius_mm: [f64; 2],
    /// Left and right rail profiles.
    pub rail_profiles: [ProfileRef; 2],
    /// The scene keys the wheel's left and right profiles came from, as the user wrote them
    /// (`wheel.profile` when one key names both), for messages.
    pub wheel_profile_keys: [&'static str; 2],
    /// The same for the rails.
    pub rail_profile_keys: [&'static str; 2],
    /// Inclination already in the rail profile data.
    pub rail_profile_inclination: Inclination,
    /// Filter wavelength of wheel and rail profiles read from files, mm (0: interpolate).
    pub smoothing_wavelength_mm: [f64; 2],
    /// Whether wheel and rail files may have points that step back dropped.
    pub drop_step_backs: [bool; 2],
    /// Track and wheelset dimensions.
    pub layout: TrackLayout,
    /// Vertical load per wheel, N.
    pub wheel_load_n: f64,
    /// Wheel material.
    pub wheel_material: crate::hertz::Material,
    /// Rail material.
    pub rail_material: crate::hertz::Material,
    /// Lateral shifts of the sweep, mm, increasing.
    pub sweep_mm: Vec<f64>,
    /// Figures to render.
    pub figures: Vec<crate::stage::Figure>,
    /// Formats to render them in.
    pub formats: Vec<ImageFormat>,
    /// Rigid solver.
    pub rigid_solver: crate::rigid::Solver,
    /// Quasi-elastic settings.
    pub quasi_elastic: crate::quasi_elastic::Settings,
    /// Values of eps for the sensitivity figure (mm).
    pub epsilon_sensitivity_mm: Vec<f64>,
    /// Hertz settings over the sweep.
    pub hertz: crate::hertz::sweep::Settings,
    /// Equivalent conicity settings.
    pub conicity: crate::conicity::Settings,
}

impl Scene {
    /// Reads and checks a scene file.
    ///
    /// # Errors
    /// [`SceneError`] naming the file and key.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let dir = path.parent().unwrap_or(Path::new("."));
        Scene::from_toml(&text, &path.display().to_string(), dir)
    }

    /// Checks a scene given as TOML text; `origin` names it in messages, relative profile
    /// paths are resolved against `dir`.
    ///
    /// # Errors
    /// [`SceneError`] naming the key and what was expected.
    pub fn from_toml(text: &str, origin: &str, dir: &Path) -> Result<Scene, SceneError> {
        let raw: RawScene = toml::from_str(text).map_err(|e| SceneError::Syntax {
            path: origin.to_string(),
            message: e.to_string().trim_end().to_string(),
        })?;
        Scene::check(raw, origin, dir)
    }

    fn check(raw: RawScene, origin: &str, dir: &Path) -> Result<Scene, SceneError> {
        let invalid = |key: &'static str, message: String| SceneError::Invalid {
            path: origin.to_string(),
            key,
            message,
        };
        let positive =
            |key: &'static str, v: Option<f64>, default: f64| -> Result<f64, SceneError> {
                let v = v.unwrap_or(default);
                if v.is_finite() && v > 0.0 {
                    Ok(v)
                } else {
                    Err(invalid(
                        key,
                        format!("{} must be a positive finite number", Number(v)),
                    ))
                }
            };

        let name = raw.name.unwrap_or_else(|| "scene".into());
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
        {
            return Err(invalid(
                "name",
                format!("{name:?} must be non-empty and use only letters, digits, '-' and '_'"),
            ));
        }
        let title = raw.title.unwrap_or_else(|| name.clone());

        let profile_ref = |text: &str| -> ProfileRef {
            if Profile::built_in(text).is_some() {
                ProfileRef::BuiltIn(text.to_string())
            } else {
                ProfileRef::File(dir.join(text))
            }
        };
        let wheel = raw.wheel.profile.as_deref().unwrap_or("S1002");
        let wheel_profiles = [
            profile_ref(raw.wheel.left_profile.as_deref().unwrap_or(wheel)),
            profile_ref(raw.wheel.right_profile.as_deref().unwrap_or(wheel)),
        ];
        // The key each profile came from, as written (or the shared key, default included).
        let key_of = |side: &Option<String>, side_key: &'static str, shared: &'static str| {
            if side.is_some() { side_key } else { shared }
        };
        let wheel_profile_keys = [
            key_of(
                &raw.wheel.left_profile,
                "wheel.left_profile",
                "wheel.profile",
            ),
            key_of(
                &raw.wheel.right_profile,
                "wheel.right_profile",
                "wheel.profile",
            ),
        ];
        let rail_profile_keys = [
            key_of(&raw.rail.left_profile, "rail.left_profile", "rail.profile"),
            key_of(
                &raw.rail.right_profile,
                "rail.right_profile",
                "rail.profile",
            ),
        ];
        let rail = raw.rail.profile.as_deref().unwrap_or("UIC60E1");
        let rail_profiles = [
            profile_ref(raw.rail.left_profile.as_deref().unwrap_or(rail)),
            profile_ref(raw.rail.right_profile.as_deref().unwrap_or(rail)),
        ];

        // Errors name the key the user wrote: the per-side key, else the shared one.
        let w = &raw.wheel;
        let mut nominal_radius_mm = [0.0; 2];
        for (r, own_key, own) in nominal_radius_mm
            .iter_mut()
            .zip([
                ("wheel.left_nominal_radius_mm", w.left_nominal_radius_mm),
                ("wheel.right_nominal_radius_mm", w.right_nominal_radius_mm),
            ])
            .map(|(r, (k, v))| (r, k, v))
        {
            let (key, v) = written(own_key, own, "wheel.nominal_radius_mm", w.nominal_radius_mm);
            *r = within(
                v.unwrap_or(DEFAULT_NOMINAL_RADIUS_MM),
                NOMINAL_RADIUS_RANGE_MM,
                "mm",
                "not a railway wheel radius",
            )
            .map_err(|m| invalid(key, m))?;
        }

        let inclination = Inclination::parse(raw.rail.inclination.as_deref().unwrap_or("1:40"))
            .map_err(|m| invalid("rail.inclination", m))?;
        let rail_profile_inclination = Inclination::parse(
            raw.rail
                .profile_inclination
                .as_deref()
                .unwrap_or("vertical"),
        )
        .map_err(|m| invalid("rail.profile_inclination", m))?;
        let smoothing = |key: &'static str, v: Option<f64>| -> Result<f64, SceneError> {
            let v = v.unwrap_or(DEFAULT_SMOOTHING_WAVELENGTH_MM);
            within(
                v,
                (0.0, MAX_SMOOTHING_WAVELENGTH_MM),
                "mm",
                "not a filter wavelength for a profile (longer ones flatten the profile itself)",
            )
            .map_err(|m| invalid(key, m))
        };
        let smoothing_wavelength_mm = [
            smoothing(
                "wheel.smoothing_wavelength_mm",
                raw.wheel.smoothing_wavelength_mm,
            )?,
            smoothing(
                "rail.smoothing_wavelength_mm",
                raw.rail.smoothing_wavelength_mm,
            )?,
        ];

        let gauge_mm = within(
            raw.track
                .gauge_mm
                .unwrap_or(crate::track::STANDARD_GAUGE_MM),
            GAUGE_RANGE_MM,
            "mm",
            "not a railway gauge",
        )
        .map_err(|m| invalid("track.gauge_mm", m))?;
        let gauge_point_depth_mm = positive(
            "track.gauge_point_depth_mm",
            raw.track.gauge_point_depth_mm,
            crate::track::GAUGE_POINT_DEPTH_MM,
        )?;
        if gauge_point_depth_mm > 30.0 {
            return Err(invalid(
                "track.gauge_point_depth_mm",
                format!(
                    "{gauge_point_depth_mm} mm is below the rail head (expected 0 to 30 mm, usually 14)"
                ),
            ));
        }
        let flange_back_mm = positive(
            "wheelset.flange_back_mm",
            raw.wheelset.flange_back_mm,
            crate::track::STANDARD_FLANGE_BACK_MM,
        )?;
        if !(0.8 * gauge_mm..gauge_mm).contains(&flange_back_mm) {
            return Err(invalid(
                "wheelset.flange_back_mm",
                format!(
                    "{flange_back_mm} mm does not fit a {gauge_mm} mm gauge (expected between 80 % of the gauge and the gauge)"
                ),
            ));
        }
        let layout = TrackLayout {
            gauge_mm,
            gauge_point_depth_mm,
            inclination,
            flange_back_mm,
        };

        let wheel_load_n = N_PER_KN
            * within(
                raw.load.wheel_load_kN.unwrap_or(DEFAULT_WHEEL_LOAD_KN),
                (MIN_WHEEL_LOAD_N / N_PER_KN, MAX_WHEEL_LOAD_N / N_PER_KN),
                "kN",
                "not a wheel load",
            )
            .map_err(|m| invalid("load.wheel_load_kN", m))?;

        let m = &raw.material;
        // Per-body keys override the shared ones; errors name the key that was written.
        let young = |own_key: &'static str, own: Option<f64>| -> Result<f64, SceneError> {
            let (key, v) = written(own_key, own, "material.young_GPa", m.young_GPa);
            let e = within(
                v.unwrap_or(DEFAULT_YOUNG_GPA),
                YOUNG_RANGE_GPA,
                "GPa",
                "not the Young's modulus of a wheel or rail material",
            )
            .map_err(|msg| invalid(key, msg))?;
            Ok(MPA_PER_GPA * e)
        };
        let poisson = |own_key: &'static str, own: Option<f64>| -> Result<f64, SceneError> {
            let (key, v) = written(own_key, own, "material.poisson", m.poisson);
            let nu = v.unwrap_or(DEFAULT_POISSON);
            if nu.is_finite() && nu >= POISSON_RANGE.0 && nu < POISSON_RANGE.1 {
                Ok(nu)
            } else {
                Err(invalid(
                    key,
                    format!(
                        "{nu} is not the Poisson's ratio of a wheel or rail material; expected {} <= poisson < {} (negative ratios are auxetic foams, 0.5 is incompressible)",
                        POISSON_RANGE.0, POISSON_RANGE.1
                    ),
                ))
            }
        };
        let material = |young_key: &'static str, nu_key: &'static str, e: f64, nu: f64| {
            crate::hertz::Material::new(e, nu).map_err(|err| {
                let key = if matches!(err, crate::hertz::HertzError::PoissonOutOfRange { .. }) {
                    nu_key
                } else {
                    young_key
                };
                invalid(key, err.to_string())
            })
        };
        let wheel_material = material(
            "material.wheel_young_GPa",
            "material.wheel_poisson",
            young("material.wheel_young_GPa", m.wheel_young_GPa)?,
            poisson("material.wheel_poisson", m.wheel_poisson)?,
        )?;
        let rail_material = material(
            "material.rail_young_GPa",
            "material.rail_poisson",
            young("material.rail_young_GPa", m.rail_young_GPa)?,
            poisson("material.rail_poisson", m.rail_poisson)?,
        )?;

        let sweep_mm = sweep(&raw.sweep).map_err(|(key, message)| invalid(key, message))?;

        let figures = match raw.outputs.figures {
            None => crate::stage::Figure::ALL.to_vec(),
            Some(names) => names
                .iter()
                .map(|n| {
                    crate::stage::Figure::from_name(n).ok_or_else(|| {
                        invalid(
                            "outputs.figures",
                            format!(
                                "unknown figure {n:?}; known figures: {}",
                                crate::stage::Figure::ALL
                                    .iter()
                                    .map(|f| f.name())
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ),
                        )
                    })
                })
                .collect::<Result<Vec<_>, _>>()?,
        };
        let formats = match raw.outputs.formats {
            None => vec![ImageFormat::Svg, ImageFormat::Png],
            Some(names) => names
                .iter()
                .map(|n| match n.to_ascii_lowercase().as_str() {
                    "svg" => Ok(ImageFormat::Svg),
                    "png" => Ok(ImageFormat::Png),
                    _ => Err(invalid(
                        "outputs.formats",
                        format!("unknown format {n:?}; expected \"svg\" or \"png\""),
                    )),
                })
                .collect::<Result<Vec<_>, _>>()?,
        };

        let rigid_solver = match raw.rigid.solver.as_deref() {
            None => crate::rigid::Solver::Default,
            Some(name) => crate::rigid::Solver::from_name(name).ok_or_else(|| {
                invalid(
                    "rigid.solver",
                    format!("unknown solver {name:?}; expected \"default\" or \"paper\""),
                )
            })?,
        };
        let rigid_solver = match raw.rigid.roll.as_deref() {
            None | Some("solved") => rigid_solver,
            Some("none") if rigid_solver == crate::rigid::Solver::Default => {
                crate::rigid::Solver::NoRoll
            }
            Some("none") => {
                return Err(invalid(
                    "rigid.roll",
                    "\"none\" needs no roll iteration: it goes with solver = \"default\" only"
                        .into(),
                ));
            }
            Some(other) => {
                return Err(invalid(
                    "rigid.roll",
                    format!("unknown roll {other:?}; expected \"solved\" or \"none\""),
                ));
            }
        };
        let qe = &raw.quasi_elastic;
        let quasi_elastic = crate::quasi_elastic::Settings {
            epsilon_mm: positive(
                "quasi_elastic.epsilon_mm",
                qe.epsilon_mm,
                crate::quasi_elastic::DEFAULT_EPSILON_MM,
            )?,
            cutoff: within(
                qe.cutoff.unwrap_or(crate::quasi_elastic::DEFAULT_CUTOFF),
                CUTOFF_RANGE,
                "eps",
                "not a useful cut-off of the weight exp(-gap/eps) (exp(-700) is near the smallest double)",
            )
            .map_err(|m| invalid("quasi_elastic.cutoff", m))?,
            quadrature: quadrature(qe).map_err(|(key, message)| invalid(key, message))?,
        };
        if quasi_elastic.epsilon_mm < MIN_EPSILON_MM {
            return Err(invalid(
                "quasi_elastic.epsilon_mm",
                format!(
                    "{} mm is below {MIN_EPSILON_MM} mm",
                    quasi_elastic.epsilon_mm
                ),
            ));
        }
        if quasi_elastic.epsilon_mm > 1.0 {
            return Err(invalid(
                "quasi_elastic.epsilon_mm",
                format!(
                    "{} mm is far beyond any elastic approach (paper: 0.01 to 0.05 mm); expected at most 1 mm",
                    quasi_elastic.epsilon_mm
                ),
            ));
        }
        let epsilon_sensitivity_mm = qe
            .sensitivity_epsilon_mm
            .clone()
            .unwrap_or_else(|| DEFAULT_EPSILON_SENSITIVITY_MM.to_vec());
        let key = "quasi_elastic.sensitivity_epsilon_mm";
        if epsilon_sensitivity_mm.is_empty()
            || epsilon_sensitivity_mm.len() > MAX_EPSILON_SENSITIVITY
            || epsilon_sensitivity_mm
                .iter()
                .any(|e| !(e.is_finite() && *e >= MIN_EPSILON_MM && *e <= 1.0))
        {
            return Err(invalid(
                key,
                format!(
                    "expected 1 to {MAX_EPSILON_SENSITIVITY} values from {MIN_EPSILON_MM} to 1 mm"
                ),
            ));
        }
        for (i, e) in epsilon_sensitivity_mm.iter().enumerate() {
            if epsilon_sensitivity_mm[..i]
                .iter()
                .any(|f| f.to_bits() == e.to_bits())
            {
                return Err(invalid(
                    key,
                    format!("{e} mm is listed twice: each value is one curve of the figure"),
                ));
            }
        }
        let h = &raw.hertz;
        let hertz = crate::hertz::sweep::Settings {
            method: match h.method.as_deref() {
                None | Some("exact") => crate::hertz::Method::Exact,
                Some("paper") => crate::hertz::Method::Paper,
                Some(other) => {
                    return Err(invalid(
                        "hertz.method",
                        format!("unknown method {other:?}; expected \"exact\" or \"paper\""),
                    ));
                }
            },
            source: match h.contact.as_deref() {
                None | Some("quasi_elastic") => crate::hertz::sweep::ContactSource::QuasiElastic,
                Some("rigid") => crate::hertz::sweep::ContactSource::Rigid,
                Some(other) => {
                    return Err(invalid(
                        "hertz.contact",
                        format!(
                            "unknown contact {other:?}; expected \"quasi_elastic\" or \"rigid\""
                        ),
                    ));
                }
            },
            normal_load: match h.normal_load.as_deref() {
                None | Some("projected") => crate::hertz::sweep::NormalLoad::Projected,
                Some("vertical") => crate::hertz::sweep::NormalLoad::Vertical,
                Some(other) => {
                    return Err(invalid(
                        "hertz.normal_load",
                        format!("unknown rule {other:?}; expected \"projected\" or \"vertical\""),
                    ));
                }
            },
        };

        let conicity = conicity_settings(&raw.conicity).map_err(|(key, m)| invalid(key, m))?;

        Ok(Scene {
            path: origin.to_string(),
            name,
            title,
            wheel_profiles,
            wheel_profile_keys,
            rail_profile_keys,
            nominal_radius_mm,
            rail_profiles,
            rail_profile_inclination,
            smoothing_wavelength_mm,
            drop_step_backs: [
                raw.wheel.drop_step_backs.unwrap_or(false),
                raw.rail.drop_step_backs.unwrap_or(false),
            ],
            layout,
            wheel_load_n,
            wheel_material,
            rail_material,
            sweep_mm,
            figures,
            formats,
            rigid_solver,
            quasi_elastic,
            epsilon_sensitivity_mm,
            hertz,
            conicity,
        })
    }

    /// Loads the profile `r` of `kind`, naming `key` in errors.
    ///
    /// # Errors
    /// [`SceneError::Profile`] when the file cannot be read or is not a valid profile.
    pub fn load_profile(
        &self,
        r: &ProfileRef,
        kind: ProfileKind,
        key: &'static str,
    ) -> Result<Profile, SceneError> {
        let err = |message: String| SceneError::Profile {
            path: self.path.clone(),
            key,
            message,
        };
        match r {
            ProfileRef::BuiltIn(name) => {
                let p = Profile::built_in(name)
                    .ok_or_else(|| err(format!("unknown profile {name:?}")))?;
                if p.kind() == kind {
                    Ok(p)
                } else {
                    Err(err(format!(
                        "{name} is a {} profile, expected a {kind} profile",
                        p.kind()
                    )))
                }
            }
            ProfileRef::File(path) => {
                let i = match kind {
                    ProfileKind::Wheel => 0,
                    ProfileKind::Rail => 1,
                };
                let options = read::ReadOptions {
                    step_back: if self.drop_step_backs[i] {
                        read::StepBack::Drop
                    } else {
                        read::StepBack::Refuse
                    },
                };
                let points = read::read_profile_with(path, kind, &options).map_err(|e| {
                    // The fix for a measured file that folds back is a scene option: name it.
                    let hint = match (&e, options.step_back) {
                        (read::ReadError::NonMonotonic { .. }, read::StepBack::Refuse) => format!(
                            " (measured profiles fold back at vertical faces: `drop_step_backs = true` under [{}] drops the points that step back)",
                            if i == 0 { "wheel" } else { "rail" }
                        ),
                        _ => String::new(),
                    };
                    err(format!("{e}{hint}"))
                })?;
                let smoothing = self.smoothing_wavelength_mm[i];
                Profile::from_points(points, smoothing)
                    .map_err(|e| err(format!("{}: {e}", path.display())))
            }
        }
    }
}

/// The quadrature of `[quasi_elastic]`: its kind and the one step key that kind takes, or
/// the offending key and a message.
fn quadrature(qe: &RawQuasiElastic) -> Result<Quadrature, (&'static str, String)> {
    let finite_positive = |key: &'static str, v: f64| {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err((
                key,
                format!("{} must be a positive finite number", Number(v)),
            ))
        }
    };
    match (qe.quadrature.as_deref(), qe.max_step_mm, qe.panel_widths) {
        (None | Some("gauss_legendre"), Some(_), _) => Err((
            "quasi_elastic.max_step_mm",
            "applies to quadrature = \"trapezoid\" only".into(),
        )),
        (None | Some("gauss_legendre"), None, panel_widths) => {
            let key = "quasi_elastic.panel_widths";
            let panel_widths = finite_positive(
                key,
                panel_widths.unwrap_or(quasi_elastic::DEFAULT_PANEL_WIDTHS),
            )?;
            if !(MIN_PANEL_WIDTHS..=MAX_PANEL_WIDTHS).contains(&panel_widths) {
                return Err((
                    key,
                    format!(
                        "{panel_widths} is outside {MIN_PANEL_WIDTHS} to {MAX_PANEL_WIDTHS} weight widths: shorter panels would take minutes, longer ones no longer resolve the weight"
                    ),
                ));
            }
            Ok(Quadrature::GaussLegendre { panel_widths })
        }
        (Some("trapezoid"), _, Some(_)) => Err((
            "quasi_elastic.panel_widths",
            "applies to quadrature = \"gauss_legendre\" only".into(),
        )),
        (Some("trapezoid"), step, None) => {
            let key = "quasi_elastic.max_step_mm";
            let max_step_mm =
                finite_positive(key, step.unwrap_or(quasi_elastic::DEFAULT_MAX_STEP_MM))?;
            if max_step_mm < MIN_TRAPEZOID_STEP_MM {
                return Err((
                    key,
                    format!(
                        "{max_step_mm} mm is below {MIN_TRAPEZOID_STEP_MM} mm: the quadrature would not finish"
                    ),
                ));
            }
            if max_step_mm > MAX_TRAPEZOID_STEP_MM {
                return Err((
                    key,
                    format!(
                        "{} mm is above {MAX_TRAPEZOID_STEP_MM} mm: the step is halved until it resolves the weight, a longer start only adds halvings",
                        Number(max_step_mm)
                    ),
                ));
            }
            Ok(Quadrature::Trapezoid { max_step_mm })
        }
        (Some(other), _, _) => Err((
            "quasi_elastic.quadrature",
            format!("unknown quadrature {other:?}; expected \"gauss_legendre\" or \"trapezoid\""),
        )),
    }
}

/// The largest amplitude of the equivalent conicity accepted (mm): the motion must stay on
/// the rail heads, and `[sweep]` is limited to ±100 mm.
pub const MAX_CONICITY_AMPLITUDE_MM: f64 = 100.0;

/// The settings of `[conicity]`, or the offending key and a message.
fn conicity_settings(
    raw: &RawConicity,
) -> Result<crate::conicity::Settings, (&'static str, String)> {
    use crate::conicity::Method;
    let method = match raw.method.as_deref() {
        None => Method::Klingel,
        Some(name) => Method::from_name(name).ok_or_else(|| {
            (
                "conicity.method",
                format!("unknown method {name:?}; expected \"klingel\" or \"regression\""),
            )
        })?,
    };
    if let Some(a) = &raw.amplitudes_mm {
        let key = "conicity.amplitudes_mm";
        if a.is_empty() || a.len() > MAX_SWEEP_POSITIONS {
            return Err((
                key,
                format!(
                    "expected 1 to {MAX_SWEEP_POSITIONS} amplitudes, found {}",
                    a.len()
                ),
            ));
        }
        for (i, v) in a.iter().enumerate() {
            if !(v.is_finite() && *v > 0.0 && *v <= MAX_CONICITY_AMPLITUDE_MM) {
                return Err((
                    key,
                    format!(
                        "amplitude {v} (item {}) must be a number above 0 and at most {MAX_CONICITY_AMPLITUDE_MM} mm",
                        i + 1
                    ),
                ));
            }
            if i > 0 && *v <= a[i - 1] {
                return Err((
                    key,
                    format!("amplitudes must increase: {v} follows {}", a[i - 1]),
                ));
            }
        }
    }
    Ok(crate::conicity::Settings {
        method,
        amplitudes_mm: raw.amplitudes_mm.clone(),
    })
}

/// The key a value was written under: `own` (a per-side or per-body key) when given, else
/// the shared key when given; the value, if any.
fn written(
    own_key: &'static str,
    own: Option<f64>,
    shared_key: &'static str,
    shared: Option<f64>,
) -> (&'static str, Option<f64>) {
    match (own, shared) {
        (Some(v), _) => (own_key, Some(v)),
        (None, Some(v)) => (shared_key, Some(v)),
        (None, None) => (own_key, None),
    }
}

/// `v` if it is finite and within `[lo, hi]`, else a message saying what it is not
/// (`what`) and the accepted range in `unit`.
fn within(v: f64, (lo, hi): (f64, f64), unit: &str, what: &str) -> Result<f64, String> {
    if v.is_finite() && v >= lo && v <= hi {
        Ok(v)
    } else {
        Err(format!(
            "{} {unit} is {what}; expected {lo} to {hi} {unit}",
            Number(v)
        ))
    }
}

/// The lateral shifts of a `[sweep]`, or the offending key and a message.
fn sweep(raw: &RawSweep) -> Result<Vec<f64>, (&'static str, String)> {
    let from = raw.from_mm.unwrap_or(-15.0);
    let to = raw.to_mm.unwrap_or(15.0);
    let step = raw.step_mm.unwrap_or(0.1);
    for (key, v) in [
        ("sweep.from_mm", from),
        ("sweep.to_mm", to),
        ("sweep.step_mm", step),
    ] {
        if !v.is_finite() {
            return Err((key, format!("{v} must be a finite number")));
        }
    }
    if step < MIN_SWEEP_STEP_MM {
        return Err((
            "sweep.step_mm",
            format!(
                "{} mm is below {MIN_SWEEP_STEP_MM:e} mm: positions are rounded to 1e-9 mm and would repeat or be unevenly spaced",
                Number(step)
            ),
        ));
    }
    if to < from {
        return Err((
            "sweep.to_mm",
            format!("{to} is below sweep.from_mm = {from}: the sweep is empty"),
        ));
    }
    for (key, v) in [("sweep.from_mm", from), ("sweep.to_mm", to)] {
        if v.abs() > 100.0 {
            return Err((
                key,
                format!("{v} mm is beyond any flange clearance (expected -100 to 100 mm)"),
            ));
        }
    }
    // A step that divides the range to within 1e-9 of a step includes `to`.
    let n = ((to - from) / step + 1e-9).floor();
    if n + 1.0 > MAX_SWEEP_POSITIONS as f64 {
        return Err((
            "sweep.step_mm",
            format!(
                "{step} mm gives {} positions; at most {MAX_SWEEP_POSITIONS} are allowed",
                n + 1.0
            ),
        ));
    }
    let n = n as usize;
    // Positions computed as from + i * step (not accumulated) so that 0.0 is hit exactly
    // when it lies on the grid, and rounded to 1e-9 mm so printed values stay clean.
    let positions: Vec<f64> = (0..=n)
        .map(|i| ((from + i as f64 * step) * 1e9).round() / 1e9)
        .collect();
    // MIN_SWEEP_STEP_MM guarantees this; checked because every stage relies on it.
    if positions.windows(2).any(|p| p[1] <= p[0]) {
        return Err((
            "sweep.step_mm",
            format!(
                "{step} mm gives positions that are not strictly increasing after rounding to 1e-9 mm"
            ),
        ));
    }
    Ok(positions)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(text: &str) -> Result<Scene, SceneError> {
        Scene::from_toml(text, "test.toml", Path::new("."))
    }

    #[test]
    fn defaults_are_the_paper_case() {
        let s = scene("").unwrap();
        assert_eq!(s.sweep_mm.len(), 301);
        assert!(s.sweep_mm[150].abs() < 1e-15 && (s.sweep_mm[300] - 15.0).abs() < 1e-12);
        assert!((s.wheel_load_n - 70_000.0).abs() < 1e-9);
        assert!((s.wheel_material.young_mpa - 210_000.0).abs() < 1e-9);
    }

    #[test]
    fn errors_name_the_key() {
        let cases = [
            ("[track]\ngauge_mm = -1435.0", "track.gauge_mm"),
            ("[material]\npoisson = 0.5", "material.poisson"),
            ("[sweep]\nstep_mm = 0.0", "sweep.step_mm"),
            ("[sweep]\nfrom_mm = 5.0\nto_mm = 1.0", "sweep.to_mm"),
            (
                "[sweep]\nfrom_mm = -15.0\nto_mm = 15.0\nstep_mm = 1e-5",
                "sweep.step_mm",
            ),
            ("[load]\nwheel_load_kN = -70.0", "load.wheel_load_kN"),
            ("[rail]\ninclination = \"1:x\"", "rail.inclination"),
            ("[outputs]\nfigures = [\"nope\"]", "outputs.figures"),
            (
                "[quasi_elastic]\npanel_widths = 20.0",
                "quasi_elastic.panel_widths",
            ),
            (
                "[quasi_elastic]\npanel_widths = 0.01",
                "quasi_elastic.panel_widths",
            ),
            (
                "[quasi_elastic]\nquadrature = \"trapezoid\"\npanel_widths = 2.0",
                "quasi_elastic.panel_widths",
            ),
            (
                "[quasi_elastic]\nmax_step_mm = 0.05",
                "quasi_elastic.max_step_mm",
            ),
            // Bounds of issue 16, each naming the key as written.
            ("[material]\npoisson = -0.967", "material.poisson"),
            ("[material]\nrail_poisson = -0.1", "material.rail_poisson"),
            ("[material]\nyoung_GPa = 1e300", "material.young_GPa"),
            (
                "[material]\nwheel_young_GPa = 1e-300",
                "material.wheel_young_GPa",
            ),
            (
                "[wheel]\nnominal_radius_mm = 1e300",
                "wheel.nominal_radius_mm",
            ),
            (
                "[wheel]\nright_nominal_radius_mm = 50.0",
                "wheel.right_nominal_radius_mm",
            ),
            ("[track]\ngauge_mm = 1e300", "track.gauge_mm"),
            ("[load]\nwheel_load_kN = 5e-324", "load.wheel_load_kN"),
            (
                "[wheel]\nsmoothing_wavelength_mm = 1e300",
                "wheel.smoothing_wavelength_mm",
            ),
            ("[quasi_elastic]\ncutoff = 1.2e57", "quasi_elastic.cutoff"),
            ("[quasi_elastic]\ncutoff = 0.5", "quasi_elastic.cutoff"),
            (
                "[quasi_elastic]\nquadrature = \"trapezoid\"\nmax_step_mm = 1.7976931348623157e308",
                "quasi_elastic.max_step_mm",
            ),
            (
                "[quasi_elastic]\nsensitivity_epsilon_mm = [0.01, 0.01]",
                "quasi_elastic.sensitivity_epsilon_mm",
            ),
            (
                "[sweep]\nfrom_mm = 0.0\nto_mm = 1e-9\nstep_mm = 1e-10",
                "sweep.step_mm",
            ),
        ];
        for (text, key) in cases {
            let e = scene(text).unwrap_err().to_string();
            assert!(e.contains(key), "{text:?} gave {e}");
        }
    }

    #[test]
    fn unknown_keys_are_rejected_with_their_name() {
        let e = scene("[track]\ngauge = 1435.0").unwrap_err().to_string();
        assert!(e.contains("gauge") && e.contains("unknown field"), "{e}");
        let e = scene("colour = \"red\"").unwrap_err().to_string();
        assert!(e.contains("colour"), "{e}");
    }
}
