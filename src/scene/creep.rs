//! Checking `[creep]` and `[table]`: the creep stage's model and motion, and the contact
//! table's grid, each error naming its key.

use super::check::Invalid;
use super::raw::{OneOrMany, RawCreep, RawTable};
use crate::contact_table::{Grid, MAX_YAWS};
use crate::creep::sweep::{Kinematics, PitchRate, StageSettings};
use crate::creep::{Bound, CreepError, Method, Settings};
use crate::gap::YawModel;
use crate::hertz::ContactSource;
use crate::hertz::Material;
use crate::message::Number;
use crate::sweep::MAX_YAW_RAD;

/// Millimetres per metre (the scene gives the speed in m/s).
const MM_PER_M: f64 = 1000.0;

/// Forward speeds accepted, m/s: above 0 (the creepages divide by the speed) up to 150 m/s
/// (540 km/h, beyond the fastest trains in service).
pub const SPEED_RANGE_M_S: (f64, f64) = (0.0, 150.0);
/// The largest lateral velocity accepted, mm/s: 5 m/s, far beyond a hunting wheelset's.
pub const MAX_LATERAL_VELOCITY_MM_S: f64 = 5000.0;
/// The largest yaw rate accepted, rad/s: a hunting wheelset turns at a few hundredths.
pub const MAX_YAW_RATE_RAD_S: f64 = 10.0;
/// The rolling radii `V / ω` a pitch rate may imply, mm: any railway wheel.
pub const PITCH_RADIUS_RANGE_MM: (f64, f64) = (100.0, 1000.0);

/// The settings of `[creep]` (defaults where a key is missing), or the offending key.
/// `positions` is the sweep's length (a list of pitch rates has one per position); `wheel`
/// and `rail` are the scene's materials, combined as Kalker combines two elastically
/// different bodies (`model`).
pub(super) fn creep(
    raw: &RawCreep,
    positions: usize,
    wheel: &Material,
    rail: &Material,
) -> Result<StageSettings, Invalid> {
    let speed_m_s = speed(raw)?;
    let speed_mm_s = speed_m_s * MM_PER_M;
    let (settings, contact) = model(raw, wheel, rail)?;
    let lateral_velocity_mm_s = bounded(
        "creep.lateral_velocity_mm_s",
        raw.lateral_velocity_mm_s.unwrap_or(0.0),
        MAX_LATERAL_VELOCITY_MM_S,
        "mm/s",
    )?;
    let yaw_rate_rad_s = bounded(
        "creep.yaw_rate_rad_s",
        raw.yaw_rate_rad_s.unwrap_or(0.0),
        MAX_YAW_RATE_RAD_S,
        "rad/s",
    )?;
    let pitch_rate = pitch_rate(raw, positions, speed_m_s)?;
    Ok(StageSettings {
        settings,
        kinematics: Kinematics {
            speed_mm_s,
            pitch_rate,
            lateral_velocity_mm_s,
            yaw_rate_rad_s,
        },
        contact,
    })
}

/// `creep.speed_m_s` (m/s), within [`SPEED_RANGE_M_S`].
fn speed(raw: &RawCreep) -> Result<f64, Invalid> {
    let speed_m_s = raw
        .speed_m_s
        .unwrap_or(crate::creep::sweep::DEFAULT_SPEED_MM_S / MM_PER_M);
    if !(speed_m_s > SPEED_RANGE_M_S.0 && speed_m_s <= SPEED_RANGE_M_S.1) {
        return Err((
            "creep.speed_m_s",
            format!(
                "{} m/s is no forward speed of a wheelset; expected above {} up to {} m/s",
                Number(speed_m_s),
                SPEED_RANGE_M_S.0,
                SPEED_RANGE_M_S.1
            ),
        ));
    }
    Ok(speed_m_s)
}

/// The tangential model (`creep.method`, `creep.bound`, `creep.friction`) on the scene's
/// materials, and the contacts it acts on (`creep.contact`). The wheel's and the rail's
/// materials combine as Kalker combines two elastically different bodies:
/// `G = 2 G1 G2 / (G1 + G2)`, `ν = G (ν1/G1 + ν2/G2) / 2` (equal bodies keep theirs).
fn model(
    raw: &RawCreep,
    wheel: &Material,
    rail: &Material,
) -> Result<(Settings, ContactSource), Invalid> {
    let method = match raw.method.as_deref() {
        None | Some("fastsim") => Method::Fastsim,
        Some("linear") => Method::Linear,
        Some("polach") => Method::Polach,
        Some(other) => {
            return Err((
                "creep.method",
                format!("unknown method {other:?}; expected \"fastsim\", \"linear\" or \"polach\""),
            ));
        }
    };
    let bound = match raw.bound.as_deref() {
        None | Some("parabolic") => Bound::Parabolic,
        Some("elliptic") => Bound::Elliptic,
        Some(other) => {
            return Err((
                "creep.bound",
                format!("unknown bound {other:?}; expected \"parabolic\" or \"elliptic\""),
            ));
        }
    };
    let contact = match raw.contact.as_deref() {
        None | Some("quasi_elastic") => ContactSource::QuasiElastic,
        Some("rigid") => ContactSource::Rigid,
        Some(other) => {
            return Err((
                "creep.contact",
                format!("unknown contact {other:?}; expected \"quasi_elastic\" or \"rigid\""),
            ));
        }
    };
    let shear = |m: &Material| m.young_mpa / (2.0 * (1.0 + m.poisson));
    let (g1, g2) = (shear(wheel), shear(rail));
    let g = 2.0 * g1 * g2 / (g1 + g2);
    let nu = 0.5 * g * (wheel.poisson / g1 + rail.poisson / g2);
    let friction = raw.friction.unwrap_or(crate::creep::DEFAULT_FRICTION);
    let settings = Settings::new(method, friction, g, nu)
        .map_err(|e| {
            let key = match e {
                CreepError::Friction { .. } => "creep.friction",
                CreepError::Poisson { .. } => "material.poisson",
                _ => "material.young_GPa",
            };
            (key, e.to_string())
        })?
        .with_bound(bound);
    Ok((settings, contact))
}

/// `v` if it is finite and within `±max` (in `unit`), or `key` with why not.
fn bounded(key: &'static str, v: f64, max: f64, unit: &str) -> Result<f64, Invalid> {
    if v.is_finite() && v.abs() <= max {
        Ok(v)
    } else {
        Err((
            key,
            format!("{} {unit}: expected -{max} to {max} {unit}", Number(v)),
        ))
    }
}

/// `creep.pitch_rate_rad_s`: free rolling when missing, else one rate for every position
/// or one per position, each rolling a wheel of a radius in [`PITCH_RADIUS_RANGE_MM`] at
/// `speed_m_s`.
fn pitch_rate(raw: &RawCreep, positions: usize, speed_m_s: f64) -> Result<PitchRate, Invalid> {
    let rates = match &raw.pitch_rate_rad_s {
        None => return Ok(PitchRate::FreeRolling),
        Some(OneOrMany::One(rate)) => vec![*rate; positions],
        Some(OneOrMany::Many(rates)) => {
            if rates.len() != positions {
                return Err((
                    "creep.pitch_rate_rad_s",
                    format!(
                        "{} rates for a sweep of {positions} positions: expected one rate, or one per position",
                        rates.len()
                    ),
                ));
            }
            rates.clone()
        }
    };
    let speed_mm_s = speed_m_s * MM_PER_M;
    let (lo, hi) = PITCH_RADIUS_RANGE_MM;
    for (i, &rate) in rates.iter().enumerate() {
        let radius = speed_mm_s / rate;
        if !(rate.is_finite() && rate > 0.0 && (lo..=hi).contains(&radius)) {
            return Err((
                "creep.pitch_rate_rad_s",
                format!(
                    "{} rad/s (position {}) at {} m/s rolls a wheel of {} mm; expected a positive rate (forward rolling) of a radius from {lo} to {hi} mm",
                    Number(rate),
                    i + 1,
                    Number(speed_m_s),
                    Number(radius)
                ),
            ));
        }
    }
    Ok(PitchRate::Given(rates))
}

/// The grid of `[table]`, or the offending key. Every key is required: a table's extent is
/// the user's choice.
pub(super) fn table(raw: &RawTable, model: YawModel) -> Result<Grid, Invalid> {
    let need = |key: &'static str, v: Option<f64>| -> Result<f64, Invalid> {
        match v {
            Some(v) if v.is_finite() => Ok(v),
            Some(v) => Err((key, format!("{} must be a finite number", Number(v)))),
            None => Err((key, "is required in [table]".into())),
        }
    };
    let from = need("table.from_mm", raw.from_mm)?;
    let to = need("table.to_mm", raw.to_mm)?;
    let step = need("table.step_mm", raw.step_mm)?;
    let shifts = super::sweep::shifts(
        from,
        to,
        step,
        ["table.from_mm", "table.to_mm", "table.step_mm"],
    )?;
    let yaw_from = need("table.yaw_from_mrad", raw.yaw_from_mrad)?;
    let yaw_to = need("table.yaw_to_mrad", raw.yaw_to_mrad)?;
    let yaw_step = need("table.yaw_step_mrad", raw.yaw_step_mrad)?;
    let max_mrad = MAX_YAW_RAD * 1e3;
    for (key, v) in [
        ("table.yaw_from_mrad", yaw_from),
        ("table.yaw_to_mrad", yaw_to),
    ] {
        if v.abs() > max_mrad {
            return Err((
                key,
                format!(
                    "{} mrad is no wheelset's yaw; expected -{max_mrad} to {max_mrad} mrad",
                    Number(v)
                ),
            ));
        }
    }
    if yaw_to < yaw_from {
        return Err((
            "table.yaw_to_mrad",
            format!(
                "{} is below table.yaw_from_mrad = {}",
                Number(yaw_to),
                Number(yaw_from)
            ),
        ));
    }
    let count = if yaw_step > 0.0 {
        ((yaw_to - yaw_from) / yaw_step + 1e-9).floor() + 1.0
    } else {
        f64::INFINITY
    };
    if !(yaw_step >= 1e-3 && count <= MAX_YAWS as f64) {
        return Err((
            "table.yaw_step_mrad",
            format!(
                "{} mrad: expected at least 0.001 mrad and at most {MAX_YAWS} yaws (each is a rigid sweep)",
                Number(yaw_step)
            ),
        ));
    }
    // Each yaw from its index, rounded to 1e-12 rad, so that opposite yaws are exactly
    // opposite (the table's mirror symmetry) and 0 is hit when it lies on the grid.
    let yaws_rad: Vec<f64> = (0..count as usize)
        .map(|i| ((yaw_from + i as f64 * yaw_step) * 1e9).round() / 1e12)
        .collect();
    Grid::new(shifts, yaws_rad, model).map_err(|e| ("table.yaw_step_mrad", e.to_string()))
}
