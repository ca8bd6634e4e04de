//! Checking a scene file's keys: one function per section of the file, each returning the
//! checked values or the offending key (as the user wrote it) and a message.

use super::raw::{RawConicity, RawFleet, RawLimits, RawQuasiElastic, RawScene};
use super::{
    DEFAULT_EPSILON_SENSITIVITY_MM, DEFAULT_INCLINATION, DEFAULT_NOMINAL_RADIUS_MM,
    DEFAULT_POISSON, DEFAULT_RAIL_PROFILE, DEFAULT_RAIL_PROFILE_INCLINATION,
    DEFAULT_SMOOTHING_WAVELENGTH_MM, DEFAULT_WHEEL_LOAD_KN, DEFAULT_WHEEL_PROFILE,
    DEFAULT_YOUNG_GPA, FleetSettings, ImageFormat, MAX_CONICITY_LIMIT, MAX_EPSILON_SENSITIVITY,
    MAX_LIMIT_MM, MAX_SMOOTHING_WAVELENGTH_MM, MPA_PER_GPA, N_PER_KN, ProfileRef, Scene,
};
use crate::hertz::Material;
use crate::hertz::{ContactSource, HertzSettings};
use crate::maintenance::{LimitOverrides, Limits};
use crate::message::Number;
use crate::plausible;
use crate::profile::Profile;
use crate::quasi_elastic::{
    EPSILON_RANGE_MM, Quadrature, QuasiElasticSettings as QeSettings, QuasiElasticSettingsError,
};
use crate::rigid::Solver;
use crate::stage::Figure;
use crate::track::{
    GAUGE_POINT_DEPTH_MM, Inclination, LayoutError, STANDARD_FLANGE_BACK_MM, STANDARD_GAUGE_MM,
    TrackLayout,
};
use std::path::Path;

/// A failed check: the key as written and what is wrong with its value.
pub(super) type Invalid = (&'static str, String);

pub(super) fn invalid(key: &'static str, message: String) -> Invalid {
    (key, message)
}

/// The profiles of the four places (left and right wheel and rail) and the keys they came
/// from, as written (`wheel.profile` when one key names both sides).
struct ProfileRefs {
    wheels: [ProfileRef; 2],
    wheel_keys: [&'static str; 2],
    rails: [ProfileRef; 2],
    rail_keys: [&'static str; 2],
}

/// Every key of `raw` checked and converted (see [`Scene::from_toml`]); the offending key
/// and a message otherwise.
pub(super) fn checked(raw: &RawScene, origin: &str, dir: &Path) -> Result<Scene, Invalid> {
    let name = scene_name(raw)?;
    let title = raw.title.clone().unwrap_or_else(|| name.clone());
    let ProfileRefs {
        wheels: wheel_profiles,
        wheel_keys: wheel_profile_keys,
        rails: rail_profiles,
        rail_keys: rail_profile_keys,
    } = profile_refs(raw, dir);
    let nominal_radius_mm = nominal_radii(raw)?;
    let (layout, rail_profile_inclination, smoothing_wavelength_mm) = track(raw)?;
    let (wheel_load_n, wheel_material, rail_material) = load_and_materials(raw)?;
    let sweep = super::sweep::yawed(raw, super::sweep::sweep(&raw.sweep)?)?;
    let (figures, formats) = outputs(raw, sweep.yaw().is_yawed())?;
    let creep = super::creep::creep(
        raw.creep.as_ref().unwrap_or(&Default::default()),
        sweep.len(),
        &wheel_material,
        &rail_material,
    )?;
    let asks_for_creep = raw.creep.is_some();
    let contact_table = raw
        .table
        .as_ref()
        .map(|t| super::creep::table(t, sweep.yaw().model()))
        .transpose()?;
    let rigid_solver = rigid_solver(raw)?;
    let (quasi_elastic, epsilon_sensitivity_mm) = quasi_elastic(raw)?;
    let (hertz, hertz_contact) = hertz(raw)?;
    let conicity = conicity_settings(&raw.conicity)?;
    let fleet = fleet_settings(&raw.fleet)?;
    let limits = limits(&raw.limits, nominal_radius_mm)?;
    let nominal_rails = raw.rail.nominal_profile.as_deref().map(|text| {
        let r = profile_ref(text, dir);
        [r.clone(), r]
    });
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
        sweep,
        figures,
        formats,
        rigid_solver,
        quasi_elastic,
        epsilon_sensitivity_mm,
        hertz,
        hertz_contact,
        conicity,
        fleet,
        limits,
        nominal_rails,
        creep,
        asks_for_creep,
        contact_table,
    })
}

/// The scene's `name` ("scene" when missing): non-empty, of letters, digits, '-' and '_'.
fn scene_name(raw: &RawScene) -> Result<String, Invalid> {
    let name = raw.name.clone().unwrap_or_else(|| "scene".into());
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
    Ok(name)
}

/// A profile named in a scene: a built-in name, or a path relative to the scene's folder.
fn profile_ref(text: &str, dir: &Path) -> ProfileRef {
    if Profile::built_in(text).is_some() {
        ProfileRef::BuiltIn(text.to_string())
    } else {
        ProfileRef::File(dir.join(text))
    }
}

/// The overrides of `[limits]`: each above 0 and at most [`MAX_LIMIT_MM`], and every
/// minimum below the maximum it meets (set or the standard's for the wheels' diameters).
fn limits(raw: &RawLimits, nominal_radius_mm: [f64; 2]) -> Result<LimitOverrides, Invalid> {
    let checked = |key: &'static str, v: Option<f64>| -> Result<Option<f64>, Invalid> {
        match v {
            Some(v) if !(v.is_finite() && v > 0.0 && v <= MAX_LIMIT_MM) => Err(invalid(
                key,
                format!(
                    "{} must be above 0 and at most {MAX_LIMIT_MM} mm (a flange dimension)",
                    Number(v)
                ),
            )),
            v => Ok(v),
        }
    };
    let overrides = LimitOverrides {
        sh_min_mm: checked("limits.sh_min_mm", raw.sh_min_mm)?,
        sh_max_mm: checked("limits.sh_max_mm", raw.sh_max_mm)?,
        sd_min_mm: checked("limits.sd_min_mm", raw.sd_min_mm)?,
        sd_max_mm: checked("limits.sd_max_mm", raw.sd_max_mm)?,
        qr_min_mm: checked("limits.qr_min_mm", raw.qr_min_mm)?,
    };
    for radius in nominal_radius_mm {
        let l = Limits::with_overrides(2.0 * radius, &overrides);
        for (min, max, min_key, max_key, set_min) in [
            (
                &l.sh_min,
                &l.sh_max,
                "limits.sh_min_mm",
                "limits.sh_max_mm",
                overrides.sh_min_mm,
            ),
            (
                &l.sd_min,
                &l.sd_max,
                "limits.sd_min_mm",
                "limits.sd_max_mm",
                overrides.sd_min_mm,
            ),
        ] {
            if min.value_mm >= max.value_mm {
                let key = if set_min.is_some() { min_key } else { max_key };
                return Err(invalid(
                    key,
                    format!(
                        "the minimum {} mm ({}) must be below the maximum {} mm ({})",
                        min.value_mm, min.source, max.value_mm, max.source
                    ),
                ));
            }
        }
    }
    Ok(overrides)
}

/// The four profile references and the keys they were written under.
fn profile_refs(raw: &RawScene, dir: &Path) -> ProfileRefs {
    let profile_ref = |text: &str| profile_ref(text, dir);
    let wheel = raw
        .wheel
        .profile
        .as_deref()
        .unwrap_or(DEFAULT_WHEEL_PROFILE);
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
    let rail = raw.rail.profile.as_deref().unwrap_or(DEFAULT_RAIL_PROFILE);
    let rail_profiles = [
        profile_ref(raw.rail.left_profile.as_deref().unwrap_or(rail)),
        profile_ref(raw.rail.right_profile.as_deref().unwrap_or(rail)),
    ];
    ProfileRefs {
        wheels: wheel_profiles,
        wheel_keys: wheel_profile_keys,
        rails: rail_profiles,
        rail_keys: rail_profile_keys,
    }
}

/// The left and right nominal wheel radii (mm).
fn nominal_radii(raw: &RawScene) -> Result<[f64; 2], Invalid> {
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
        *r = crate::track::check_nominal_radius(v.unwrap_or(DEFAULT_NOMINAL_RADIUS_MM))
            .map_err(|e| invalid(key, e.to_string()))?;
    }
    Ok(nominal_radius_mm)
}

/// The track layout, the inclination the rail data already has and the smoothing
/// wavelengths of wheel and rail files (mm).
fn track(raw: &RawScene) -> Result<(TrackLayout, Inclination, [f64; 2]), Invalid> {
    let inclination = Inclination::parse(
        raw.rail
            .inclination
            .as_deref()
            .unwrap_or(DEFAULT_INCLINATION),
    )
    .map_err(|e| invalid("rail.inclination", e.to_string()))?;
    let rail_profile_inclination = Inclination::parse(
        raw.rail
            .profile_inclination
            .as_deref()
            .unwrap_or(DEFAULT_RAIL_PROFILE_INCLINATION),
    )
    .map_err(|e| invalid("rail.profile_inclination", e.to_string()))?;
    let smoothing = |key: &'static str, v: Option<f64>| -> Result<f64, Invalid> {
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

    let layout = TrackLayout::new(
        raw.track.gauge_mm.unwrap_or(STANDARD_GAUGE_MM),
        raw.track
            .gauge_point_depth_mm
            .unwrap_or(GAUGE_POINT_DEPTH_MM),
        raw.wheelset
            .flange_back_mm
            .unwrap_or(STANDARD_FLANGE_BACK_MM),
        inclination,
    )
    .map_err(|e| {
        let key = match e {
            LayoutError::Gauge { .. } => "track.gauge_mm",
            LayoutError::GaugePointDepth { .. } => "track.gauge_point_depth_mm",
            LayoutError::FlangeBack { .. } => "wheelset.flange_back_mm",
            LayoutError::InclinationText { .. } | LayoutError::InclinationOutOfRange { .. } => {
                "rail.inclination"
            }
        };
        invalid(key, e.to_string())
    })?;
    Ok((layout, rail_profile_inclination, smoothing_wavelength_mm))
}

/// The vertical wheel load (N) and the materials of wheel and rail, each checked against
/// its range in [`crate::plausible`] (shared with `wheelrail hertz`).
fn load_and_materials(raw: &RawScene) -> Result<(f64, Material, Material), Invalid> {
    let wheel_load_n = N_PER_KN
        * plausible::WHEEL_LOAD_KN
            .check(raw.load.wheel_load_kN.unwrap_or(DEFAULT_WHEEL_LOAD_KN))
            .map_err(|e| invalid("load.wheel_load_kN", e.to_string()))?;

    let m = &raw.material;
    // Per-body keys override the shared ones; errors name the key that was written.
    let young = |own_key: &'static str, own: Option<f64>| -> Result<f64, Invalid> {
        let (key, v) = written(own_key, own, "material.young_GPa", m.young_GPa);
        let e = plausible::YOUNG_GPA
            .check(v.unwrap_or(DEFAULT_YOUNG_GPA))
            .map_err(|e| invalid(key, e.to_string()))?;
        Ok(MPA_PER_GPA * e)
    };
    let poisson = |own_key: &'static str, own: Option<f64>| -> Result<f64, Invalid> {
        let (key, v) = written(own_key, own, "material.poisson", m.poisson);
        plausible::POISSON
            .check(v.unwrap_or(DEFAULT_POISSON))
            .map_err(|e| invalid(key, e.to_string()))
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
    Ok((wheel_load_n, wheel_material, rail_material))
}

/// The figures and image formats asked for; by default every figure (the contact's lead
/// only for a `yawed` wheelset: without yaw it is 0; the creep figures only for a scene
/// with `[creep]`).
fn outputs(raw: &RawScene, yawed: bool) -> Result<(Vec<Figure>, Vec<ImageFormat>), Invalid> {
    let creep = raw.creep.is_some();
    let figures = match &raw.outputs.figures {
        None => crate::stage::Figure::ALL
            .into_iter()
            .filter(|&f| yawed || f != Figure::ContactLead)
            .filter(|&f| creep || f.stage() != crate::stage::Stage::Creep)
            .collect(),
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
    let formats = match &raw.outputs.formats {
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
    Ok((figures, formats))
}

/// The rigid solver, with the roll option.
fn rigid_solver(raw: &RawScene) -> Result<Solver, Invalid> {
    let rigid_solver = match raw.rigid.solver.as_deref() {
        None => crate::rigid::Solver::default(),
        Some(name @ ("default" | "paper")) => {
            crate::rigid::Solver::from_name(name).expect("a solver's name")
        }
        Some(name) => {
            return Err(invalid(
                "rigid.solver",
                format!("unknown solver {name:?}; expected \"default\" or \"paper\""),
            ));
        }
    };
    let rigid_solver = match raw.rigid.roll.as_deref() {
        None | Some("solved") => rigid_solver,
        Some("none") if matches!(rigid_solver, crate::rigid::Solver::Default(_)) => {
            crate::rigid::Solver::NoRoll
        }
        Some("none") => {
            return Err(invalid(
                "rigid.roll",
                "\"none\" needs no roll iteration: it goes with solver = \"default\" only".into(),
            ));
        }
        Some(other) => {
            return Err(invalid(
                "rigid.roll",
                format!("unknown roll {other:?}; expected \"solved\" or \"none\""),
            ));
        }
    };
    Ok(rigid_solver)
}

/// The quasi-elastic settings and the eps values of the sensitivity figure (mm).
fn quasi_elastic(raw: &RawScene) -> Result<(QeSettings, Vec<f64>), Invalid> {
    let qe = &raw.quasi_elastic;
    let quadrature = quadrature(qe).map_err(|(key, message)| invalid(key, message))?;
    let quasi_elastic = QeSettings::new(
        qe.epsilon_mm
            .unwrap_or(crate::quasi_elastic::DEFAULT_EPSILON_MM),
        qe.cutoff.unwrap_or(crate::quasi_elastic::DEFAULT_CUTOFF),
        quadrature,
    )
    .map_err(|e| {
        let key = match e {
            QuasiElasticSettingsError::Epsilon { .. } => "quasi_elastic.epsilon_mm",
            QuasiElasticSettingsError::Cutoff { .. } => "quasi_elastic.cutoff",
            QuasiElasticSettingsError::PanelWidths { .. } => "quasi_elastic.panel_widths",
            QuasiElasticSettingsError::MaxStep { .. } => "quasi_elastic.max_step_mm",
        };
        invalid(key, e.to_string())
    })?;
    let epsilon_sensitivity_mm = qe
        .sensitivity_epsilon_mm
        .clone()
        .unwrap_or_else(|| DEFAULT_EPSILON_SENSITIVITY_MM.to_vec());
    let key = "quasi_elastic.sensitivity_epsilon_mm";
    if epsilon_sensitivity_mm.is_empty()
        || epsilon_sensitivity_mm.len() > MAX_EPSILON_SENSITIVITY
        || epsilon_sensitivity_mm
            .iter()
            .any(|&e| quasi_elastic.with_epsilon(e).is_err())
    {
        return Err(invalid(
            key,
            format!(
                "expected 1 to {MAX_EPSILON_SENSITIVITY} values from {} to {} mm",
                EPSILON_RANGE_MM.0, EPSILON_RANGE_MM.1
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
                format!(
                    "{} mm is listed twice: each value is one curve of the figure",
                    Number(*e)
                ),
            ));
        }
    }
    Ok((quasi_elastic, epsilon_sensitivity_mm))
}

/// The Hertz settings, and the contacts the ellipses are computed for.
fn hertz(raw: &RawScene) -> Result<(HertzSettings, ContactSource), Invalid> {
    let h = &raw.hertz;
    let method = match h.method.as_deref() {
        None | Some("exact") => crate::hertz::EllipseMethod::Exact,
        Some("paper") => crate::hertz::EllipseMethod::Paper,
        Some(other) => {
            return Err(invalid(
                "hertz.method",
                format!("unknown method {other:?}; expected \"exact\" or \"paper\""),
            ));
        }
    };
    let contact = match h.contact.as_deref() {
        None | Some("quasi_elastic") => ContactSource::QuasiElastic,
        Some("rigid") => ContactSource::Rigid,
        Some(other) => {
            return Err(invalid(
                "hertz.contact",
                format!("unknown contact {other:?}; expected \"quasi_elastic\" or \"rigid\""),
            ));
        }
    };
    let normal_load = match h.normal_load.as_deref() {
        None | Some("projected") => crate::hertz::NormalLoad::Projected,
        Some("vertical") => crate::hertz::NormalLoad::Vertical,
        Some(other) => {
            return Err(invalid(
                "hertz.normal_load",
                format!("unknown rule {other:?}; expected \"projected\" or \"vertical\""),
            ));
        }
    };
    Ok((HertzSettings::new(method, normal_load), contact))
}

/// The quadrature of `[quasi_elastic]`: its kind and the one step key that kind takes, or
/// the offending key and a message.
fn quadrature(qe: &RawQuasiElastic) -> Result<Quadrature, (&'static str, String)> {
    match (qe.quadrature.as_deref(), qe.max_step_mm, qe.panel_widths) {
        (None | Some("gauss_legendre"), Some(_), _) => Err((
            "quasi_elastic.max_step_mm",
            "applies to quadrature = \"trapezoid\" only".into(),
        )),
        (None | Some("gauss_legendre"), None, panel_widths) => Ok(Quadrature::GaussLegendre {
            panel_widths: panel_widths.unwrap_or(crate::quasi_elastic::DEFAULT_PANEL_WIDTHS),
        }),
        (Some("trapezoid"), _, Some(_)) => Err((
            "quasi_elastic.panel_widths",
            "applies to quadrature = \"gauss_legendre\" only".into(),
        )),
        (Some("trapezoid"), step, None) => Ok(Quadrature::Trapezoid {
            max_step_mm: step.unwrap_or(crate::quasi_elastic::DEFAULT_MAX_STEP_MM),
        }),
        (Some(other), _, _) => Err((
            "quasi_elastic.quadrature",
            format!("unknown quadrature {other:?}; expected \"gauss_legendre\" or \"trapezoid\""),
        )),
    }
}

/// The settings of `[fleet]`, or the offending key and a message.
fn fleet_settings(raw: &RawFleet) -> Result<FleetSettings, Invalid> {
    let conicity_limit = match raw.conicity_limit {
        None => None,
        Some(v) if v.is_finite() && v > 0.0 && v <= MAX_CONICITY_LIMIT => Some(v),
        Some(v) => {
            return Err(invalid(
                "fleet.conicity_limit",
                format!(
                    "{} must be above 0 and at most {MAX_CONICITY_LIMIT} (a limit of tan gamma_e at 3 mm, dimensionless)",
                    Number(v)
                ),
            ));
        }
    };
    Ok(FleetSettings { conicity_limit })
}

/// The settings of `[conicity]`, or the offending key and a message.
fn conicity_settings(
    raw: &RawConicity,
) -> Result<crate::conicity::ConicitySettings, (&'static str, String)> {
    use crate::conicity::ConicityMethod;
    let method = match raw.method.as_deref() {
        None => ConicityMethod::Klingel,
        Some(name) => ConicityMethod::from_name(name).ok_or_else(|| {
            (
                "conicity.method",
                format!("unknown method {name:?}; expected \"klingel\" or \"regression\""),
            )
        })?,
    };
    let settings = crate::conicity::ConicitySettings::new(method);
    match &raw.amplitudes_mm {
        None => Ok(settings),
        Some(a) => settings
            .with_amplitudes_mm(a.clone())
            .map_err(|e| ("conicity.amplitudes_mm", e.to_string())),
    }
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
