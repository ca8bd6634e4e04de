//! The `[sweep]` section and the wheelset's yaw checked: the shifts of a sweep and the yaw
//! they carry.

use super::check::{Invalid, invalid};
use super::raw::{RawScene, RawSweep};
use super::{DEFAULT_SWEEP_MM, DEFAULT_SWEEP_STEP_MM};
use crate::message::Number;
use crate::sweep::{Sweep, SweepError};

/// The largest `sweep.yaw_mrad_per_mm` (mrad/mm): faster, the yaw would pass the 50 mrad of
/// [`crate::sweep::MAX_YAW_RAD`] within 5 mm of shift (the Manchester benchmark's is 2.4).
const MAX_YAW_MRAD_PER_MM: f64 = 10.0;

/// `sweep` with the wheelset's yaw of `[wheelset] yaw_mrad`, `yaw_model` and `[sweep]
/// yaw_mrad_per_mm`, or the offending key and a message.
pub(super) fn yawed(raw: &RawScene, sweep: Sweep) -> Result<Sweep, Invalid> {
    use crate::gap::YawModel;
    let max_mrad = crate::sweep::MAX_YAW_RAD * 1e3;
    let yaw_mrad = raw.wheelset.yaw_mrad.unwrap_or(0.0);
    let per_mm = raw.sweep.yaw_mrad_per_mm.unwrap_or(0.0);
    for (key, v, bound, what) in [
        ("wheelset.yaw_mrad", yaw_mrad, max_mrad, "mrad"),
        (
            "sweep.yaw_mrad_per_mm",
            per_mm,
            MAX_YAW_MRAD_PER_MM,
            "mrad/mm",
        ),
    ] {
        if v.is_nan() || v.abs() > bound {
            return Err(invalid(
                key,
                format!(
                    "{} {what} is no wheelset's yaw; expected -{} to {} {what} (a yaw in radians or degrees would be a unit mistake)",
                    Number(v),
                    Number(bound),
                    Number(bound)
                ),
            ));
        }
    }
    let model = match raw.wheelset.yaw_model.as_deref() {
        None => YawModel::Exact,
        Some(name) => YawModel::from_name(name).ok_or_else(|| {
            invalid(
                "wheelset.yaw_model",
                format!("unknown yaw model {name:?}; expected \"exact\" or \"small_angle\""),
            )
        })?,
    };
    let key = if per_mm != 0.0 {
        "sweep.yaw_mrad_per_mm"
    } else {
        "wheelset.yaw_mrad"
    };
    sweep
        .with_yaw(crate::sweep::YawRule::new(
            yaw_mrad * 1e-3,
            per_mm * 1e-3,
            model,
        ))
        .map_err(|e| invalid(key, e.to_string()))
}

/// The lateral shifts of a `[sweep]`, or the offending key and a message.
pub(super) fn sweep(raw: &RawSweep) -> Result<Sweep, (&'static str, String)> {
    shifts(
        raw.from_mm.unwrap_or(DEFAULT_SWEEP_MM.0),
        raw.to_mm.unwrap_or(DEFAULT_SWEEP_MM.1),
        raw.step_mm.unwrap_or(DEFAULT_SWEEP_STEP_MM),
        ["sweep.from_mm", "sweep.to_mm", "sweep.step_mm"],
    )
}

/// The lateral shifts `from` to `to` by `step` (mm), or the offending key of `keys` (from,
/// to, step: `[sweep]`'s or `[table]`'s) and a message.
pub(super) fn shifts(
    from: f64,
    to: f64,
    step: f64,
    keys: [&'static str; 3],
) -> Result<Sweep, (&'static str, String)> {
    let [from_key, to_key, step_key] = keys;
    for (key, v) in [(from_key, from), (to_key, to), (step_key, step)] {
        if !v.is_finite() {
            return Err((key, format!("{} must be a finite number", Number(v))));
        }
    }
    // `Sweep::range` checks the step and the number of positions; the keys' own
    // conditions (the order of the ends, their bounds) come in between, as before.
    let step_error = |e: SweepError| (step_key, e.to_string());
    if let Err(e @ SweepError::StepTooSmall { .. }) = Sweep::range(0.0, 0.0, step) {
        return Err(step_error(e));
    }
    if to < from {
        return Err((
            to_key,
            format!(
                "{} is below {from_key} = {}: the sweep is empty",
                Number(to),
                Number(from)
            ),
        ));
    }
    for (key, v) in [(from_key, from), (to_key, to)] {
        if v.abs() > 100.0 {
            return Err((
                key,
                format!(
                    "{} mm is beyond any flange clearance (expected -100 to 100 mm)",
                    Number(v)
                ),
            ));
        }
    }
    Sweep::range(from, to, step).map_err(step_error)
}
