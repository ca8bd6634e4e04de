//! The profiles as tables: the wheel and the placed rail (`wheel_profile.csv`,
//! `rail_profile.csv`), and a built-in profile as a point file (`wheelrail profile`).

use super::{WHEEL_SIDE_FRAME, col};
use crate::{Table, TableError};
use wheelrail::track::{PlacedRail, PlacedWheel, Side};

/// Sampling step of the profile tables (mm).
pub const PROFILE_TABLE_STEP_MM: f64 = 0.1;

/// Steepest `|tan_gamma|` a profile table writes as a number. Steeper is a vertical tangent:
/// the profiles evaluate it with a capped root (the S1002 flange back gives `1e6`, see
/// `profile::s1002`), and a finite stand-in for an infinite slope would read as data. No
/// profile face that is not vertical is this steep (89.9994°).
pub const VERTICAL_TAN_GAMMA: f64 = 1e5;

/// The wheel profile: `s_mm, F_mm, tan_gamma, curvature_per_mm, face`.
///
/// Where the profile's tangent is vertical (`|tan_gamma|` beyond [`VERTICAL_TAN_GAMMA`], the
/// flange back of S1002) `tan_gamma` is `NaN` and `face` says `vertical`; elsewhere `face` is
/// `regular`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn wheel_profile(wheel: &PlacedWheel) -> Result<Table, TableError> {
    let rows = wheel.profile().sample(PROFILE_TABLE_STEP_MM);
    let (tan_gamma, face) = slope_and_face(&rows);
    Table::builder()
        .comment(format!("wheel profile {} ({})", wheel.profile().name(), wheel.profile().source()))
        .comment(format!("frame: wheel side frame; {WHEEL_SIDE_FRAME}"))
        .comment("tan_gamma = -dF/ds (positive on the coned tread); curvature_per_mm convex positive; section joints included as extra rows")
        .comment(face_comment())
        .numeric("s_mm", col(&rows, 0))
        .numeric("F_mm", col(&rows, 1))
        .numeric("tan_gamma", tan_gamma)
        .numeric("curvature_per_mm", col(&rows, 3))
        .text("face", face)
        .build()
}

/// The `tan_gamma` and `face` columns of profile samples `[u, v, tan_gamma, curvature]`:
/// `NaN` and `vertical` where the tangent is vertical (see [`VERTICAL_TAN_GAMMA`]), the slope
/// and `regular` elsewhere.
fn slope_and_face(rows: &[[f64; 4]]) -> (Vec<f64>, Vec<&'static str>) {
    rows.iter()
        .map(|r| {
            if r[2].abs() > VERTICAL_TAN_GAMMA {
                (f64::NAN, "vertical")
            } else {
                (r[2], "regular")
            }
        })
        .unzip()
}

/// The `#` header line that explains the `face` column of [`slope_and_face`].
fn face_comment() -> String {
    format!(
        "face: vertical where the tangent is vertical (|tan_gamma| > {VERTICAL_TAN_GAMMA:e}, \
         infinite): tan_gamma NaN there; regular elsewhere"
    )
}

/// The placed rail in its side frame: `u_mm, y_mm, z_mm, tan_gamma, curvature_per_mm, face`.
///
/// `face` is `running` on the running surface (the lateral range of the contact search's
/// `Z(Y)` table) and `flank` beyond it, where `tan_gamma` and `curvature_per_mm` are `NaN`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn rail_profile(rail: &PlacedRail, side: Side) -> Result<Table, TableError> {
    // The rail's own profile is not evaluated: only where it is sampled.
    let us = rail.profile().sample_positions(PROFILE_TABLE_STEP_MM);
    let mut y = Vec::with_capacity(us.len());
    let mut z = Vec::with_capacity(us.len());
    let mut slope = Vec::with_capacity(us.len());
    let mut curvature = Vec::with_capacity(us.len());
    let mut face = Vec::with_capacity(us.len());
    let (y_lo, y_hi) = rail.y_range();
    for (y_side, q) in rail.surface_along(&us) {
        y.push(y_side);
        z.push(q.z);
        // Only the running surface has a slope that Z(Y) can carry; the flanks beyond it
        // are drawn but not used by the contact search.
        if (y_lo..=y_hi).contains(&y_side) {
            slope.push(q.slope);
            curvature.push(q.curvature());
            face.push("running");
        } else {
            slope.push(f64::NAN);
            curvature.push(f64::NAN);
            face.push("flank");
        }
    }
    Table::builder()
        .comment(format!("rail profile {} ({}), {} rail as placed", rail.profile().name(), rail.profile().source(), side.name()))
        .comment("frame: rail side frame = track frame mirrored per side; y_mm = |y| from the track centre (positive towards the field side), z_mm up from the top of rail; u_mm the profile's own lateral coordinate")
        .comment("tan_gamma = dz/dy in the side frame (inclination included); curvature_per_mm convex positive; NaN where the surface is steeper than the running surface")
        .comment("face: running on the running surface; flank beyond it (tan_gamma and curvature_per_mm NaN)")
        .numeric("u_mm", us)
        .numeric("y_mm", y)
        .numeric("z_mm", z)
        .numeric("tan_gamma", slope)
        .numeric("curvature_per_mm", curvature)
        .text("face", face)
        .build()
}

/// A built-in profile in its own frame as a point table readable by the CSV reader.
///
/// # Errors
/// Only internal inconsistencies.
pub fn profile_points(
    profile: &wheelrail::profile::Profile,
    step_mm: f64,
) -> Result<Table, TableError> {
    let rows = profile.sample(step_mm);
    let col = |k: usize| rows.iter().map(|r| r[k]).collect::<Vec<f64>>();
    let (tan_gamma, face) = slope_and_face(&rows);
    let (u, v, frame) = match profile.kind() {
        wheelrail::profile::ProfileKind::Wheel => (
            "s_mm",
            "F_mm",
            format!("wheel side frame: {WHEEL_SIDE_FRAME}"),
        ),
        wheelrail::profile::ProfileKind::Rail => (
            "y_mm",
            "z_mm",
            "rail side frame, upright rail: y_mm lateral from the rail axis, positive towards the field side; z_mm height, up positive, 0 at the top of rail".to_string(),
        ),
    };
    Table::builder()
        .comment(format!("{} generated by wheelrail {} from its definition: {}", profile.name(), env!("CARGO_PKG_VERSION"), profile.source()))
        .comment(format!("frame: {frame}"))
        .comment("tan_gamma positive on the coned tread; curvature_per_mm convex positive; section joints included as extra rows")
        .comment(face_comment())
        .comment(format!("regenerate: wheelrail profile {} --out FILE --step-mm {step_mm}", profile.name().to_ascii_lowercase()))
        .numeric(u, col(0))
        .numeric(v, col(1))
        .numeric("tan_gamma", tan_gamma)
        .numeric("curvature_per_mm", col(3))
        .text("face", face)
        .build()
}
