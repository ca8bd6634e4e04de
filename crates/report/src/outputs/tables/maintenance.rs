//! The maintenance view of the profiles (`profile_dimensions.csv`): the wheels' flange
//! dimensions against their limits and the rails' wear.

use super::WHEEL_SIDE_FRAME;
use crate::{Table, TableError};
use wheelrail::track::Side;

/// The definitions of the flange dimensions, as the tables and pages state them.
pub const FLANGE_DIMENSIONS_TEXT: &str = "flange dimensions (EN 15313, UIC 510-2; TSI WAG Regulation (EU) No 321/2013 4.2.3.6.2 Figure 1): Sh flange height, the flange tip above the profile's point on the taping line (70 mm from the inner face, s = 0); Sd flange thickness, from the inner face (s = -70 mm) to the flank 10 mm above the taping-line point; qR, from the Sd point to the flank 2 mm below the tip; measured on the wheel's points joined by straight lines (a built-in profile on its definition), whatever smoothing_wavelength_mm filters for the contact";

/// The definitions of the rail wear, as the tables and pages state them.
pub const RAIL_WEAR_TEXT: &str = "rail wear against the nominal rail, both upright (profile_inclination taken out) in the frame their files give (no fitting): vertical_wear, nominal minus measured height on the centre line (halfway between the nominal head's faces at the gauge-point depth); gauge_face_wear, how far the gauge face lies towards the field side of the nominal's at the gauge-point depth below the nominal top; positive where material is gone";

/// The maintenance view of a placement's profiles: `side, body, profile, dimension,
/// value_mm, limit_min_mm, limit_max_mm, status`, one row per wheel dimension (Sh, Sd, qR)
/// and, when the scene names nominal rails, per rail wear (vertical, gauge face).
///
/// `status` is `ok` (`ok; no maximum limit` for qR, whose maximum is `NaN`), `below the
/// minimum`, `above the maximum`, `no limit` (rail wear) or `undefined: ` and why; a limit
/// that does not exist is `NaN`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn profile_dimensions(
    placement: &wheelrail::track::Placement,
    assessment: &wheelrail::maintenance::Assessment,
) -> Result<Table, TableError> {
    let sides = [
        (Side::Left, &placement.left()),
        (Side::Right, &placement.right()),
    ];
    let mut rows: Vec<DimensionRow> = Vec::new();
    let mut builder = Table::builder()
        .comment(FLANGE_DIMENSIONS_TEXT)
        .comment(format!(
            "frame: wheel side frame; {WHEEL_SIDE_FRAME}; every value in mm"
        ));
    for (k, (side, pair)) in sides.iter().enumerate() {
        let w = &assessment.wheels[k];
        builder = builder.comment(format!(
            "limits of the {} wheel (nominal diameter {} mm): {}",
            side.name(),
            2.0 * pair.wheel().nominal_radius_mm(),
            w.limits.describe()
        ));
        rows.extend(wheel_dimension_rows(
            *side,
            pair.wheel().profile().name(),
            w,
        ));
    }
    if let Some(rails) = &assessment.rails {
        builder = builder.comment(RAIL_WEAR_TEXT);
        for (k, (side, pair)) in sides.iter().enumerate() {
            rows.extend(rail_wear_rows(
                *side,
                pair.rail().profile().name(),
                &rails[k],
            ));
        }
    }
    let text = |f: fn(&DimensionRow) -> String| rows.iter().map(f).collect::<Vec<_>>();
    let number = |f: fn(&DimensionRow) -> f64| rows.iter().map(f).collect::<Vec<_>>();
    builder
        .comment("status: ok (qR: ok; no maximum limit), below the minimum, above the maximum (a limit broken is a result, not an error), no limit (rail wear), or undefined and why (value NaN); a limit that does not exist is NaN")
        .text("side", text(|r| r.side.name().to_string()))
        .text("body", text(|r| r.body.to_string()))
        .text("profile", text(|r| r.profile.clone()))
        .text("dimension", text(|r| r.dimension.to_string()))
        .numeric("value_mm", number(|r| r.value))
        .numeric("limit_min_mm", number(|r| r.limits.0))
        .numeric("limit_max_mm", number(|r| r.limits.1))
        .text("status", text(|r| r.status.clone()))
        .build()
}

/// One row of `profile_dimensions.csv`.
struct DimensionRow {
    side: Side,
    body: &'static str,
    profile: String,
    dimension: &'static str,
    /// The value (mm), NaN where undefined.
    value: f64,
    /// The limits (mm), NaN where there is none.
    limits: (f64, f64),
    status: String,
}

/// The rows of one wheel's flange dimensions Sh, Sd and qR against its limits.
fn wheel_dimension_rows(
    side: Side,
    profile: &str,
    w: &wheelrail::maintenance::WheelAssessment,
) -> Vec<DimensionRow> {
    use wheelrail::maintenance::limits::{Bound, Dimension};
    let l = &w.limits;
    let d = w.dimensions.as_ref();
    [
        (
            Dimension::Sh,
            d.map(|d| d.sh_mm),
            l.sh_min.value_mm,
            l.sh_max.value_mm,
        ),
        (
            Dimension::Sd,
            d.map(|d| d.sd_mm),
            l.sd_min.value_mm,
            l.sd_max.value_mm,
        ),
        (
            Dimension::QR,
            d.map(|d| d.qr_mm),
            l.qr_min.value_mm,
            f64::NAN,
        ),
    ]
    .into_iter()
    .map(|(dim, v, min, max)| {
        let (value, status) = match v {
            Ok(v) => {
                let broken = w.breaches.iter().find(|b| b.dimension == dim);
                let status = match broken.map(|b| b.bound) {
                    // The NaN maximum of qR is explained in the row, as every NaN is.
                    None if max.is_nan() => "ok; no maximum limit".into(),
                    None => "ok".into(),
                    Some(Bound::Min) => "below the minimum".into(),
                    Some(Bound::Max) => "above the maximum".into(),
                };
                (v, status)
            }
            Err(e) => (f64::NAN, format!("undefined: {e}")),
        };
        DimensionRow {
            side,
            body: "wheel",
            profile: profile.to_string(),
            dimension: dim.symbol(),
            value,
            limits: (min, max),
            status,
        }
    })
    .collect()
}

/// The rows of one rail's wear (no limits).
fn rail_wear_rows(
    side: Side,
    profile: &str,
    wear: &Result<wheelrail::maintenance::RailWear, wheelrail::maintenance::WearError>,
) -> Vec<DimensionRow> {
    [
        ("vertical_wear", wear.as_ref().map(|w| w.vertical_mm)),
        ("gauge_face_wear", wear.as_ref().map(|w| w.gauge_face_mm)),
    ]
    .into_iter()
    .map(|(name, v)| {
        let (value, status) = match v {
            Ok(v) => (v, "no limit".to_string()),
            Err(e) => (f64::NAN, format!("undefined: {e}")),
        };
        DimensionRow {
            side,
            body: "rail",
            profile: profile.to_string(),
            dimension: name,
            value,
            limits: (f64::NAN, f64::NAN),
            status,
        }
    })
    .collect()
}
