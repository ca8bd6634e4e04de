//! The creep stage's table (`creep.csv`) and the contact table (`contact_table.csv`).

use super::tables::{PER_WHEEL, RailSlopeColumn, TRACK_FRAME, contact_columns};
use crate::{Table, TableError};
use wheelrail::contact_table::ContactTable;
use wheelrail::creep::sweep::CreepSweep;
use wheelrail::gap::ContactPoint;
use wheelrail::rigid::Stop;
use wheelrail::track::Side;

/// One row of `creep.csv`.
struct Row {
    y_ws: f64,
    yaw: f64,
    side: Side,
    patch: String,
    delta: f64,
    lead: f64,
    numbers: [f64; 8],
    status: String,
}

/// Creep forces over the sweep (`creep.csv`), long form: one row per position, wheel and
/// patch (one row with NaN numbers for a wheel without contact).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn creep(c: &CreepSweep) -> Result<Table, TableError> {
    let rows = rows(c);
    let settings = c.settings();
    let k = c.kinematics();
    let pitch = match &k.pitch_rate {
        wheelrail::creep::sweep::PitchRate::FreeRolling => {
            "free rolling (pitch rate = speed / mean rolling radius of the two wheels' contacts at each position)".to_string()
        }
        wheelrail::creep::sweep::PitchRate::Given(_) => "pitch rates given per position".to_string(),
    };
    let col = |f: &dyn Fn(&Row) -> f64| rows.iter().map(f).collect::<Vec<_>>();
    let mut t = Table::builder()
        .comment(format!(
            "creep forces: method {}, bound {}, mu = {}, G = {} MPa, nu = {}; contacts {} (patch 0 the heaviest, 1 the second, each with its weight share of the wheel load)",
            settings.method(),
            settings.bound(),
            settings.friction(),
            settings.shear_modulus_mpa(),
            settings.poisson(),
            c.source().name()
        ))
        .comment(format!(
            "motion: speed {} mm/s, {pitch}, lateral velocity {} mm/s, yaw rate {} rad/s; roll and yaw of each position from the rigid search",
            k.speed_mm_s, k.lateral_velocity_mm_s, k.yaw_rate_rad_s
        ))
        .comment(TRACK_FRAME)
        .comment("yaw_rad right-hand about z (up): positive turns the wheelset's forward axis to the left; lead_mm the contact's distance ahead of the axle along the wheelset's own forward axis")
        .comment("contact frame of a patch: the track frame turned about x by contact_angle_rad (signed: + on the left wheel, - on the right one, roll included): t_x along the rail, t_y in the tangent plane, n out of the rail into the wheel")
        .comment("creepages (Kalker, CONTACT): velocity of the rail relative to the wheel over the rolling speed, xi along t_x, eta along t_y, phi_per_mm about n (1/mm)")
        .comment("forces of the WHEEL ON THE RAIL in the contact frame (N): fn_N normal force (vertical balance FN cos(delta) - Fy sin(delta) = patch load), fx_N along t_x, fy_N along t_y, mz_Nmm spin moment about n (N mm; NaN for linear theory and Polach); a positive creepage gives a negative force; CONTACT's FS, MN, eta, phi are minus ours (its frame is ours turned by pi about x)")
        .comment("patch 0 the heaviest of the wheel, 1 the second (empty where the wheel has no contact); adhesion_fraction share of the patch area in adhesion; status converged, iteration_cap, no_equilibrium (friction pulls the wheel down: Nadal's limit), not_hertzian, or why a wheel has no row")
        .numeric("y_ws_mm", col(&|r| r.y_ws))
        .numeric("yaw_rad", col(&|r| r.yaw))
        .text("side", rows.iter().map(|r| r.side.name()))
        .text("patch", rows.iter().map(|r| r.patch.clone()))
        .numeric("contact_angle_rad", col(&|r| r.delta))
        .numeric("lead_mm", col(&|r| r.lead));
    for (i, name) in [
        "xi",
        "eta",
        "phi_per_mm",
        "fn_N",
        "fx_N",
        "fy_N",
        "mz_Nmm",
        "adhesion_fraction",
    ]
    .into_iter()
    .enumerate()
    {
        // `+ 0.0`: a creepage of -0 (a product with a zero velocity) is written as 0.
        t = t.numeric(name, col(&|r| r.numbers[i] + 0.0));
    }
    t.text("status", rows.iter().map(|r| r.status.clone()))
        .build()
}

/// The rows of `creep.csv`: per position and wheel, one row per patch, or one row with
/// NaN numbers and the reason when the wheel has none.
fn rows(c: &CreepSweep) -> Vec<Row> {
    let mut rows = Vec::new();
    for p in c.positions() {
        for side in [Side::Left, Side::Right] {
            let s = p.side(side);
            if s.patches.is_empty() {
                rows.push(Row {
                    y_ws: p.y_ws,
                    yaw: p.yaw,
                    side,
                    patch: String::new(),
                    delta: f64::NAN,
                    lead: f64::NAN,
                    numbers: [f64::NAN; 8],
                    status: s.missing.clone(),
                });
            }
            for row in &s.patches {
                let numbers = match &row.forces {
                    Ok(f) => [
                        f.creepages.xi,
                        f.creepages.eta,
                        f.creepages.phi_per_mm,
                        f.normal_force_n,
                        f.tangential.fx_n,
                        f.tangential.fy_n,
                        f.tangential.mz_nmm,
                        f.tangential.adhesion_fraction,
                    ],
                    Err(_) => [f64::NAN; 8],
                };
                rows.push(Row {
                    y_ws: p.y_ws,
                    yaw: p.yaw,
                    side,
                    patch: row.patch.to_string(),
                    delta: row.point.contact_angle_rad,
                    lead: row.point.lead_mm,
                    numbers,
                    status: row.status(),
                });
            }
        }
    }
    rows
}

/// The contact table (`contact_table.csv`): one row per yaw and shift, per wheel the rigid
/// contact, its Hertz ellipse and Kalker's coefficients.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn contact_table(table: &ContactTable) -> Result<Table, TableError> {
    // (yaw row, position) pairs in yaw-major order.
    let index: Vec<(usize, usize)> = table
        .rows
        .iter()
        .enumerate()
        .flat_map(|(i, r)| (0..r.rigid.positions().len()).map(move |j| (i, j)))
        .collect();
    let position = |(i, j): (usize, usize)| &table.rows[i].rigid.positions()[j];
    let col = |f: &dyn Fn((usize, usize)) -> f64| index.iter().map(|&ij| f(ij)).collect::<Vec<_>>();
    let converged = |ij| position(ij).stop == Stop::Converged;
    let mut t = Table::builder()
        .comment(format!(
            "contact table: rigid contact, Hertz ellipse ({} method, normal load {}, vertical wheel load {} N) and Kalker's creep coefficients (nu = {}) on a grid of {} yaws x {} shifts; yaw outline {}",
            table.hertz.method(),
            table.hertz.normal_load().name(),
            table.wheel_load_n,
            table.poisson,
            table.grid.yaws_rad().len(),
            table.grid.shifts().len(),
            table.grid.model().name()
        ))
        .comment(TRACK_FRAME)
        .comment(PER_WHEEL)
        .comment("yaw_rad right-hand about z (up): positive turns the wheelset's forward axis to the left, each yaw a rigid sweep with that fixed yaw; per wheel x_mm the contact along the track (x forward) from the wheelset centre, lead_mm ahead of the axle along the wheelset's forward axis, y_mm, z_mm track frame, r_mm rolling radius")
        .comment("A_per_mm, B_per_mm relative curvatures (rolling, lateral); a_mm along the rolling direction, b_mm lateral; p0_MPa maximum pressure; c11, c22, c23 Kalker's coefficients of the ellipse (linear theory on the rail: Fx = -G a b c11 xi, Fy = -G a b c22 eta - G (ab)^1.5 c23 phi)")
        .comment("interpolation: values at the nodes; linear interpolation between nodes holds where the contact point moves continuously, not across a jump of a wheel's contact point (flange contact onset: the status names two-point contacts)")
        .numeric("yaw_rad", col(&|(i, _)| table.rows[i].yaw_rad))
        .numeric("y_ws_mm", col(&|ij| position(ij).y_ws))
        .numeric("roll_rad", col(&|ij| if converged(ij) { position(ij).roll } else { f64::NAN }));
    for side in [Side::Left, Side::Right] {
        let k = usize::from(side == Side::Right);
        let points: Vec<ContactPoint> = index
            .iter()
            .map(|&ij| match position(ij).contact[k] {
                Some(c) if converged(ij) => c.point(),
                _ => ContactPoint::NAN,
            })
            .collect();
        t = contact_columns(t, side, &points, RailSlopeColumn::Omitted, true);
        let name = side.name();
        let hertz = |(i, j): (usize, usize)| &table.rows[i].hertz.positions()[j].sides[k];
        let ellipse = |f: fn(&wheelrail::hertz::Ellipse) -> f64| {
            col(&|ij| hertz(ij).ellipse().map_or(f64::NAN, f))
        };
        let coefficient = |f: fn(&wheelrail::creep::coefficients::Coefficients) -> f64| {
            col(&|(i, j)| {
                table.rows[i].coefficients[j][k]
                    .as_ref()
                    .map_or(f64::NAN, f)
            })
        };
        t = t
            .numeric(format!("{name}_A_per_mm"), col(&|ij| hertz(ij).a_curvature))
            .numeric(format!("{name}_B_per_mm"), col(&|ij| hertz(ij).b_curvature))
            .numeric(
                format!("{name}_normal_load_N"),
                col(&|ij| hertz(ij).normal_load_n),
            )
            .numeric(format!("{name}_a_mm"), ellipse(|e| e.a_mm))
            .numeric(format!("{name}_b_mm"), ellipse(|e| e.b_mm))
            .numeric(format!("{name}_p0_MPa"), ellipse(|e| e.p0_mpa))
            .numeric(format!("{name}_c11"), coefficient(|c| c.c11))
            .numeric(format!("{name}_c22"), coefficient(|c| c.c22))
            .numeric(format!("{name}_c23"), coefficient(|c| c.c23));
    }
    t.text(
        "status",
        index.iter().map(|&(i, j)| table_status(&table.rows[i], j)),
    )
    .build()
}

/// The `status` of one row of the contact table: the rigid stop in words, two-point
/// contacts, and an ellipse that is not `ok`.
fn table_status(row: &wheelrail::contact_table::YawRow, j: usize) -> String {
    let p = &row.rigid.positions()[j];
    let mut s = p.stop.status_text().to_string();
    for (k, side) in ["left", "right"].iter().enumerate() {
        if p.contact[k].is_some_and(|c| c.second.is_some()) {
            s.push_str(&format!("; two-point contact {side}"));
        }
        let h = &row.hertz.positions()[j].sides[k];
        if p.stop == Stop::Converged && h.status != "ok" {
            s.push_str(&format!("; {side} ellipse: {}", h.status));
        }
    }
    s
}
