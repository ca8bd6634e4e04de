//! Stage results as CSV tables, one file per stage. Every table states its frame, signs
//! and units in `#` comment lines above the header, and every column name carries its unit.

mod conicity;
mod hertz;
mod maintenance;
mod profiles;
mod quasi_elastic;
mod rigid;
mod tradeoff;

pub use conicity::{conicity_method_text, conicity_points, equivalent_conicity, parameters};
pub use hertz::{hertz, hertz_accuracy};
pub use maintenance::{FLANGE_DIMENSIONS_TEXT, RAIL_WEAR_TEXT, profile_dimensions};
pub use profiles::{
    PROFILE_TABLE_STEP_MM, VERTICAL_TAN_GAMMA, profile_points, rail_profile, wheel_profile,
};
pub use quasi_elastic::{epsilon_sensitivity, quasi_elastic};
pub(super) use rigid::{RailSlopeColumn, contact_columns};
pub use rigid::{rigid, rigid_jumps};
pub use tradeoff::{fastsim_tradeoff, tradeoff};

/// The track frame as every sweep table states it.
pub(super) const TRACK_FRAME: &str = "frame: track, x forward, y lateral positive to the left, z up, origin on the track centre line at the top of the rails; roll positive lifts the left wheel";
/// The per-wheel quantities as the sweep tables state them.
pub(super) const PER_WHEEL: &str = "per wheel: s_mm wheel coordinate from the taping line, positive towards the field side (flange at s < 0); gamma contact angle in the track frame with roll, mirrored per side, positive on tread and flange; curvatures convex positive";

/// What the yaw columns of a yawed sweep mean.
const YAW_COLUMNS: &str = "yaw_rad right-hand about z (up): positive turns the wheelset's forward axis to the left (the left wheel back, the right forward); per wheel: x_mm the contact's position along the track (x forward) from the wheelset centre, lead_mm its distance ahead of the axle along the wheelset's own forward axis; with yaw the rail meets the wheel's outline seen along the track (its points whose normal has no x component), not its profile";

/// The yaw comment of a sweep yawed by `yaw`: the rule and the outline's model.
fn yaw_comment(yaw: &wheelrail::sweep::YawRule) -> String {
    format!(
        "{YAW_COLUMNS}; yaw = {} mrad + {} mrad/mm * y_ws, outline {}",
        wheelrail::message::Number(yaw.yaw_rad() * 1e3),
        wheelrail::message::Number(yaw.yaw_rad_per_mm() * 1e3),
        yaw.model().name()
    )
}

/// The wheel's side frame as the profile tables state it.
const WHEEL_SIDE_FRAME: &str = "s_mm from the taping line, positive towards the field side (flange at s < 0); F_mm radius increase over the nominal radius, positive towards the flange tip";

/// Column `k` of sampled rows.
fn col(rows: &[[f64; 4]], k: usize) -> Vec<f64> {
    rows.iter().map(|r| r[k]).collect()
}
