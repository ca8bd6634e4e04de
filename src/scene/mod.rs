//! Scene files: a TOML description of one run (profiles, track, load, sweep, outputs).
//!
//! A serde mirror of the file (`raw.rs`) takes it exactly (unknown keys are rejected); [`Scene::from_toml`]
//! checks every value once and converts units, so nothing downstream re-checks. See the
//! README for the format; `reports/paper/scene.toml` is the paper's scene.

use crate::profile::{Profile, ProfileKind, read};
use crate::track::{Inclination, TrackLayout};
use std::fmt;
use std::path::{Path, PathBuf};

mod check;
mod creep;
mod raw;
mod sweep;

use raw::RawScene;

// The defaults of the scene keys: the paper's case (S1002 on UIC60 1:40, standard gauge and
// wheelset, 460 mm wheels, 70 kN, steel), in one place. Gauge, gauge-point depth and
// flange-back distance are the track module's standard values (`track::STANDARD_GAUGE_MM`,
// ...), the numerical settings the defaults of their stages (`rigid::Solver::default`,
// `quasi_elastic::QuasiElasticSettings::default`, `hertz::HertzSettings::default`).

/// Default wheel profile (both sides): the paper's S1002.
pub(crate) const DEFAULT_WHEEL_PROFILE: &str = "S1002";
/// Default rail profile (both sides): the paper's UIC60 (60E1).
pub(crate) const DEFAULT_RAIL_PROFILE: &str = "UIC60E1";
/// Default rail inclination of the track: the paper's 1:40.
pub(crate) const DEFAULT_INCLINATION: &str = "1:40";
/// Default inclination already in the rail profile data: upright (the built-in UIC60 and
/// most rail files are given upright).
pub(crate) const DEFAULT_RAIL_PROFILE_INCLINATION: &str = "vertical";
/// Default lateral sweep (mm): the paper's -15 to 15 mm.
pub(crate) const DEFAULT_SWEEP_MM: (f64, f64) = (-15.0, 15.0);
/// Default sweep step (mm): the paper's 0.1 mm (301 positions).
pub(crate) const DEFAULT_SWEEP_STEP_MM: f64 = 0.1;
/// Default nominal wheel radius (mm): the paper's 920 mm wheel.
pub(crate) const DEFAULT_NOMINAL_RADIUS_MM: f64 = 460.0;
/// Default vertical wheel load (kN): the paper's 70 kN.
pub(crate) const DEFAULT_WHEEL_LOAD_KN: f64 = 70.0;
/// Default Young's modulus of wheel and rail (GPa): steel.
pub(crate) const DEFAULT_YOUNG_GPA: f64 = 210.0;
/// Default Poisson's ratio of wheel and rail: steel.
pub(crate) const DEFAULT_POISSON: f64 = 0.3;

/// Newtons per kilonewton (the scene gives loads in kN, the numerics take N).
const N_PER_KN: f64 = 1000.0;
/// Megapascals per gigapascal (the scene gives moduli in GPa, the numerics take MPa).
const MPA_PER_GPA: f64 = 1000.0;

// The ranges of the wheel load and the materials are in `crate::plausible`, shared with
// `wheelrail hertz`.
/// The longest filter wavelength of the profile spline (mm): longer than a wheel's tread
/// and flange together, the filter flattens the profile itself.
pub(crate) const MAX_SMOOTHING_WAVELENGTH_MM: f64 = 100.0;
/// The largest number of values of eps in the sensitivity figure: each is a quasi-elastic
/// pass over the whole sweep.
pub(crate) const MAX_EPSILON_SENSITIVITY: usize = 16;

/// Default filter wavelength of the spline through profile points read from files (mm): 0,
/// the spline interpolates. Measured profiles want smoothing (4 mm is a good start, see
/// the profile spline's default filter); exact benchmark files do not.
pub(crate) const DEFAULT_SMOOTHING_WAVELENGTH_MM: f64 = 0.0;

/// The largest `[fleet] conicity_limit` accepted: equivalent conicities of railway wheel/rail
/// pairs lie far below 1 (limits in use are 0.15 to 0.5); a limit above 2 marks nothing.
pub(crate) const MAX_CONICITY_LIMIT: f64 = 2.0;

/// The largest maintenance limit of a flange dimension accepted (mm): flange heights and
/// thicknesses are a few tens of millimetres.
pub(crate) const MAX_LIMIT_MM: f64 = 100.0;

/// The sensitivity values of eps of the `qe_epsilon` figure (mm).
pub(crate) const DEFAULT_EPSILON_SENSITIVITY_MM: [f64; 5] = [0.001, 0.003, 0.01, 0.03, 0.05];

/// An error in a scene: the file, the key (dotted path) where known, and what was expected.
#[derive(Debug)]
#[non_exhaustive]
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
    pub(crate) path: String,
    /// Short name.
    pub(crate) name: String,
    /// Report title.
    pub(crate) title: String,
    /// Left and right wheel profiles.
    pub(crate) wheel_profiles: [ProfileRef; 2],
    /// Left and right nominal radii, mm.
    pub(crate) nominal_radius_mm: [f64; 2],
    /// Left and right rail profiles.
    pub(crate) rail_profiles: [ProfileRef; 2],
    /// The scene keys the wheel's left and right profiles came from, as the user wrote them
    /// (`wheel.profile` when one key names both), for messages.
    pub(crate) wheel_profile_keys: [&'static str; 2],
    /// The same for the rails.
    pub(crate) rail_profile_keys: [&'static str; 2],
    /// Inclination already in the rail profile data.
    pub(crate) rail_profile_inclination: Inclination,
    /// Filter wavelength of wheel and rail profiles read from files, mm (0: interpolate).
    pub(crate) smoothing_wavelength_mm: [f64; 2],
    /// Whether wheel and rail files may have points that step back dropped.
    pub(crate) drop_step_backs: [bool; 2],
    /// Track and wheelset dimensions.
    pub(crate) layout: TrackLayout,
    /// Vertical load per wheel, N.
    pub(crate) wheel_load_n: f64,
    /// Wheel material.
    pub(crate) wheel_material: crate::hertz::Material,
    /// Rail material.
    pub(crate) rail_material: crate::hertz::Material,
    /// Lateral shifts of the sweep, mm, increasing.
    pub(crate) sweep: crate::sweep::Sweep,
    /// Figures to render.
    pub(crate) figures: Vec<crate::stage::Figure>,
    /// Formats to render them in.
    pub(crate) formats: Vec<ImageFormat>,
    /// Rigid solver.
    pub(crate) rigid_solver: crate::rigid::Solver,
    /// Quasi-elastic settings.
    pub(crate) quasi_elastic: crate::quasi_elastic::QuasiElasticSettings,
    /// Values of eps for the sensitivity figure (mm).
    pub(crate) epsilon_sensitivity_mm: Vec<f64>,
    /// Hertz settings over the sweep.
    pub(crate) hertz: crate::hertz::HertzSettings,
    /// The contacts the Hertz ellipses are computed for.
    pub(crate) hertz_contact: crate::hertz::ContactSource,
    /// Equivalent conicity settings.
    pub(crate) conicity: crate::conicity::ConicitySettings,
    /// Settings of `wheelrail fleet` with this scene as its template.
    pub(crate) fleet: FleetSettings,
    /// `[limits]`: the maintenance limits that override the standard's.
    pub(crate) limits: crate::maintenance::LimitOverrides,
    /// Left and right nominal rails the rails' wear is measured against (`rail.nominal_profile`;
    /// a fleet of rails sets its template's rails); `None`: no rail wear.
    pub(crate) nominal_rails: Option<[ProfileRef; 2]>,
    /// `[creep]`, its defaults where the scene has none (the material is the scene's).
    pub(crate) creep: crate::creep::sweep::StageSettings,
    /// Whether the scene has `[creep]` (and so asks for `creep.csv`).
    pub(crate) asks_for_creep: bool,
    /// The contact table's grid (`[table]`), when the scene has one.
    pub(crate) contact_table: Option<crate::contact_table::Grid>,
}

/// `[fleet]`: what `wheelrail fleet` does beyond the scene's own stages.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FleetSettings {
    pub(crate) conicity_limit: Option<f64>,
}

impl FleetSettings {
    /// The limit of tan γe(3 mm) marked in the fleet's charts and listed pairs above it
    /// (dimensionless, above 0 and at most 2, checked with the scene); `None`: no limit.
    pub fn conicity_limit(&self) -> Option<f64> {
        self.conicity_limit
    }
}

impl Scene {
    /// Whether the scene is the paper's case (Onat, Voltr & Lata 2014): S1002 wheels of
    /// 460 mm on UIC60 rails inclined 1:40, standard gauge and wheelset, 70 kN, steel; that
    /// is, every key that changes the numbers of a figure at its default (the sweep and the
    /// numerical settings may differ). The report cites the paper's figures only then.
    pub fn is_paper_case(&self) -> bool {
        let paper = Scene::from_toml("", "paper", Path::new("")).expect("the defaults are valid");
        let built_in = |r: &ProfileRef, name: &str| match r {
            ProfileRef::BuiltIn(n) => {
                Profile::built_in(n).map(|p| p.name().to_owned())
                    == Profile::built_in(name).map(|p| p.name().to_owned())
            }
            ProfileRef::File(_) => false,
        };
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        self.wheel_profiles
            .iter()
            .all(|r| built_in(r, DEFAULT_WHEEL_PROFILE))
            && self
                .rail_profiles
                .iter()
                .all(|r| built_in(r, DEFAULT_RAIL_PROFILE))
            && bits(&self.nominal_radius_mm) == bits(&paper.nominal_radius_mm)
            && self.layout == paper.layout
            && self.rail_profile_inclination == paper.rail_profile_inclination
            && self.wheel_load_n.to_bits() == paper.wheel_load_n.to_bits()
            && self.wheel_material == paper.wheel_material
            && self.rail_material == paper.rail_material
    }

    /// The scene with other numerical settings: the rigid solver, the quasi-elastic
    /// search's and the Hertz method (the variants a tradeoff study runs), each a checked
    /// value.
    pub fn with_numerics(
        &self,
        rigid_solver: crate::rigid::Solver,
        quasi_elastic: crate::quasi_elastic::QuasiElasticSettings,
        hertz_method: crate::hertz::EllipseMethod,
    ) -> Scene {
        let mut scene = self.clone();
        scene.rigid_solver = rigid_solver;
        scene.quasi_elastic = quasi_elastic;
        scene.hertz.method = hertz_method;
        scene
    }

    /// Whether both wheels are one: the same profile at the same radius (placed once and
    /// cloned, a mirror-symmetric wheelset with [`Scene::same_rails`]).
    pub fn same_wheels(&self) -> bool {
        self.wheel_profiles[1] == self.wheel_profiles[0]
            && self.nominal_radius_mm[1].to_bits() == self.nominal_radius_mm[0].to_bits()
    }

    /// Whether both rails name the same profile (placed once and shared).
    pub fn same_rails(&self) -> bool {
        self.rail_profiles[1] == self.rail_profiles[0]
    }

    /// The scene file (for messages and provenance).
    pub fn path(&self) -> &str {
        &self.path
    }

    /// Short name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Report title.
    pub fn title(&self) -> &str {
        &self.title
    }

    /// Left and right wheel profiles.
    pub fn wheel_profiles(&self) -> &[ProfileRef; 2] {
        &self.wheel_profiles
    }

    /// Left and right nominal radii, mm.
    pub fn nominal_radius_mm(&self) -> [f64; 2] {
        self.nominal_radius_mm
    }

    /// Left and right rail profiles.
    pub fn rail_profiles(&self) -> &[ProfileRef; 2] {
        &self.rail_profiles
    }

    /// Inclination already in the rail profile data.
    pub fn rail_profile_inclination(&self) -> Inclination {
        self.rail_profile_inclination
    }

    /// Filter wavelength of wheel and rail profiles read from files, mm (0: interpolate).
    pub fn smoothing_wavelength_mm(&self) -> [f64; 2] {
        self.smoothing_wavelength_mm
    }

    /// Track and wheelset dimensions.
    pub fn layout(&self) -> &TrackLayout {
        &self.layout
    }

    /// Vertical load per wheel, N.
    pub fn wheel_load_n(&self) -> f64 {
        self.wheel_load_n
    }

    /// Wheel material.
    pub fn wheel_material(&self) -> &crate::hertz::Material {
        &self.wheel_material
    }

    /// Rail material.
    pub fn rail_material(&self) -> &crate::hertz::Material {
        &self.rail_material
    }

    /// Lateral shifts of the sweep, mm, increasing.
    pub fn sweep(&self) -> &crate::sweep::Sweep {
        &self.sweep
    }

    /// Figures to render.
    pub fn figures(&self) -> &[crate::stage::Figure] {
        &self.figures
    }

    /// Formats to render them in.
    pub fn formats(&self) -> &[ImageFormat] {
        &self.formats
    }

    /// Rigid solver.
    pub fn rigid_solver(&self) -> crate::rigid::Solver {
        self.rigid_solver
    }

    /// Quasi-elastic settings.
    pub fn quasi_elastic(&self) -> &crate::quasi_elastic::QuasiElasticSettings {
        &self.quasi_elastic
    }

    /// Values of eps for the sensitivity figure (mm).
    pub fn epsilon_sensitivity_mm(&self) -> &[f64] {
        &self.epsilon_sensitivity_mm
    }

    /// Hertz settings over the sweep.
    pub fn hertz(&self) -> &crate::hertz::HertzSettings {
        &self.hertz
    }

    /// The contacts the Hertz ellipses are computed for (`[hertz] contact`).
    pub fn hertz_contact(&self) -> crate::hertz::ContactSource {
        self.hertz_contact
    }

    /// Equivalent conicity settings.
    pub fn conicity(&self) -> &crate::conicity::ConicitySettings {
        &self.conicity
    }

    /// Settings of `wheelrail fleet` with this scene as its template (`[fleet]`).
    pub fn fleet(&self) -> &FleetSettings {
        &self.fleet
    }

    /// The maintenance limits set by `[limits]` (the standard's apply to the others).
    pub fn limits(&self) -> &crate::maintenance::LimitOverrides {
        &self.limits
    }

    /// Left and right nominal rails the rails' wear is measured against, if any.
    pub fn nominal_rails(&self) -> Option<&[ProfileRef; 2]> {
        self.nominal_rails.as_ref()
    }

    /// The creep stage's settings: the scene's `[creep]` with the defaults for missing keys,
    /// the material from `[material]` (the stage runs for `creep.csv` when `[creep]` is
    /// there, and for the creep figures).
    pub fn creep(&self) -> &crate::creep::sweep::StageSettings {
        &self.creep
    }

    /// Whether the scene has a `[creep]` table (and so asks for `creep.csv`).
    pub fn asks_for_creep(&self) -> bool {
        self.asks_for_creep
    }

    /// The contact table's grid (`[table]`), if the scene asks for one.
    pub fn contact_table(&self) -> Option<&crate::contact_table::Grid> {
        self.contact_table.as_ref()
    }

    /// The scene with `figures` in place of its own (what a run computes follows them).
    pub fn with_figures(mut self, figures: Vec<crate::stage::Figure>) -> Scene {
        self.figures = figures;
        self
    }

    /// The scene with its figures rendered in `formats` instead of its own.
    pub fn with_formats(mut self, formats: Vec<ImageFormat>) -> Scene {
        self.formats = formats;
        self
    }

    /// Reads and checks a scene file; relative profile paths are resolved against the
    /// file's folder.
    ///
    /// # Errors
    /// [`SceneError`] naming the file and key.
    ///
    /// # Example
    /// ```
    /// use wheelrail::scene::Scene;
    /// let scene = Scene::load("reports/paper/scene.toml".as_ref()).unwrap();
    /// assert_eq!(scene.sweep().len(), 301);
    /// assert_eq!(scene.wheel_load_n(), 70_000.0); // 70 kN in the file
    /// ```
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
    ///
    /// # Example
    /// ```
    /// use wheelrail::scene::Scene;
    /// let scene = Scene::from_toml("[track]\ngauge_mm = 1668.0", "mine", ".".as_ref()).unwrap();
    /// assert_eq!(scene.layout().gauge_mm(), 1668.0);
    /// let error = Scene::from_toml("[track]\ngauge_mm = 14350.0", "mine", ".".as_ref());
    /// assert!(error.unwrap_err().to_string().contains("track.gauge_mm"));
    /// ```
    pub fn from_toml(text: &str, origin: &str, dir: &Path) -> Result<Scene, SceneError> {
        let raw: RawScene = toml::from_str(text).map_err(|e| SceneError::Syntax {
            path: origin.to_string(),
            message: e.to_string().trim_end().to_string(),
        })?;
        Scene::check(raw, origin, dir)
    }

    fn check(raw: RawScene, origin: &str, dir: &Path) -> Result<Scene, SceneError> {
        check::checked(&raw, origin, dir).map_err(|(key, message)| SceneError::Invalid {
            path: origin.to_string(),
            key,
            message,
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

#[cfg(test)]
mod tests;
