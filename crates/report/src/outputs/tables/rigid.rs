//! The rigid sweep's tables: `rigid.csv` and `rigid_jumps.csv`, and the contact-point
//! columns the quasi-elastic and creep tables share.

use super::{PER_WHEEL, TRACK_FRAME, yaw_comment};
use crate::{Table, TableBuilder, TableError};
use wheelrail::gap::ContactPoint;
use wheelrail::rigid::{ARTEFACT_HOLLOW_MM, JUMP_REFINE_MM, JumpKind, RigidSweep, Stop};
use wheelrail::track::Side;

/// The status of a converged position of a sweep whose centred wheelset has no contact.
const NO_CENTRED_CONTACT: &str = "; no contact at y_ws = 0: z_ws, epsilon, sigma undefined";

/// Rigid contact over the sweep (`rigid.csv`).
///
/// Wickens' parameters (Fundamentals of Rail Vehicle Dynamics, 2003), with `l0` half the
/// lateral distance between the contact points of the centred wheelset: equivalent
/// conicity `lambda = delta_r / (2 y_ws)`, contact angle parameter
/// `epsilon = l0 (tan gamma_l - tan gamma_r) / (2 y_ws)`, roll angle parameter
/// `sigma = l0 roll / y_ws`; undefined (NaN) at `y_ws = 0`.
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn rigid(sweep: &RigidSweep) -> Result<Table, TableError> {
    let l0 = sweep.l0_mm();
    // Without a contact on both wheels of the centred wheelset (very unequal radii, say)
    // z_ws and l0 have no reference: their columns are NaN and the status says so.
    let centred_reference = l0.is_finite() && sweep.centre().axle_height.is_finite();
    let mut t = Table::builder()
        .comment(format!("rigid contact, solver {}", sweep.solver().name()))
        .comment(TRACK_FRAME)
        .comment(PER_WHEEL)
        .comment("z_ws_mm relative to the centred wheelset; r_mm rolling radius; second_s_mm a second contact point within 0.01 mm of touching (NaN if none); jump_after 1 where the contact point jumps before the next position, 2 where it hops across a sampling artefact (see rigid_jumps.csv)")
        .comment(format!("Wickens: lambda = delta_r/(2 y_ws), epsilon = l0 (tan gamma_l - tan gamma_r)/(2 y_ws), sigma = l0 roll/y_ws, l0 = {l0:.6} mm; NaN at y_ws = 0"));
    let yawed = sweep.yaw().is_yawed();
    if yawed {
        t = t.comment(yaw_comment(sweep.yaw()));
    }
    t = t.numeric(
        "y_ws_mm",
        sweep.positions().iter().map(|p| p.y_ws).collect::<Vec<_>>(),
    );
    if yawed {
        t = t.numeric(
            "yaw_rad",
            sweep.positions().iter().map(|p| p.yaw).collect::<Vec<_>>(),
        );
    }
    t = t
        .numeric("roll_rad", converged(sweep, |p| p.roll))
        .numeric("z_ws_mm", converged(sweep, |p| sweep.z_ws(p)));
    for side in [Side::Left, Side::Right] {
        t = rigid_side_columns(t, sweep, side);
    }
    let positions = &sweep.positions();
    let wickens: Vec<_> = positions.iter().map(|p| sweep.wickens(p)).collect();
    let column = |f: &dyn Fn(&wheelrail::rigid::RigidPosition) -> f64| -> Vec<f64> {
        positions.iter().map(f).collect()
    };
    t.numeric("delta_r_mm", column(&|p| p.delta_r()))
        .numeric(
            "lambda",
            wickens.iter().map(|w| w.lambda).collect::<Vec<_>>(),
        )
        .numeric(
            "epsilon",
            wickens.iter().map(|w| w.epsilon).collect::<Vec<_>>(),
        )
        .numeric("sigma", wickens.iter().map(|w| w.sigma).collect::<Vec<_>>())
        .numeric("iterations", column(&|p| p.iterations as f64))
        .numeric("residual_mm", column(&|p| p.residual))
        .text(
            "status",
            positions.iter().map(|p| rigid_status(p, centred_reference)),
        )
        .build()
}

/// The columns of one wheel in `rigid.csv`: its contact point (with the rail's contact
/// angle), the second contact point and the jump flag.
fn rigid_side_columns(t: TableBuilder, sweep: &RigidSweep, side: Side) -> TableBuilder {
    let name = side.name();
    let contact = |p: &wheelrail::rigid::RigidPosition| match p.side(side) {
        Some(c) if p.stop == Stop::Converged => Some(*c),
        _ => None,
    };
    let points: Vec<ContactPoint> = sweep
        .positions()
        .iter()
        .map(|p| contact(p).map_or(ContactPoint::NAN, |c| c.point()))
        .collect();
    let jump_after = (0..sweep.positions().len()).map(|i| {
        let y0 = sweep.positions()[i].y_ws;
        let y1 = sweep
            .positions()
            .get(i + 1)
            .map_or(f64::INFINITY, |p| p.y_ws);
        // 1 for a jump, 2 for a sampling artefact (a jump wins where a step holds both).
        let within = |kind: JumpKind| {
            sweep
                .jumps()
                .iter()
                .any(|j| j.side == side && j.kind == kind && j.y_from >= y0 && j.y_to <= y1)
        };
        if within(JumpKind::Jump) {
            1.0
        } else if within(JumpKind::Artefact) {
            2.0
        } else {
            0.0
        }
    });
    contact_columns(
        t,
        side,
        &points,
        RailSlopeColumn::Written,
        sweep.yaw().is_yawed(),
    )
    .numeric(
        format!("{name}_second_s_mm"),
        sweep
            .positions()
            .iter()
            .map(|p| contact(p).and_then(|c| c.second).map_or(f64::NAN, |s| s.0))
            .collect::<Vec<_>>(),
    )
    .numeric(format!("{name}_jump_after"), jump_after.collect::<Vec<_>>())
}

/// The `status` of one position in `rigid.csv`: the stop reason in words, two-point
/// contacts, and why Wickens' parameters are undefined where they are.
fn rigid_status(p: &wheelrail::rigid::RigidPosition, centred_reference: bool) -> String {
    let mut s = p.stop.status_text().to_string();
    for (k, side) in ["left", "right"].iter().enumerate() {
        if p.contact[k].is_some_and(|c| c.second.is_some()) {
            s.push_str(&format!("; two-point contact {side}"));
        }
    }
    if p.y_ws.abs() < wheelrail::rigid::WICKENS_CENTRE_MM {
        s.push_str("; y_ws = 0: lambda, epsilon, sigma undefined");
    } else if p.stop == Stop::Converged && !centred_reference {
        s.push_str(NO_CENTRED_CONTACT);
    }
    s
}

/// Whether [`contact_columns`] writes the rail's contact angle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum RailSlopeColumn {
    /// `{side}_rail_tan_gamma` after `gamma_rad` (`rigid.csv`).
    Written,
    /// Not written (`quasi_elastic.csv`).
    Omitted,
}

/// The contact-point columns of one wheel, one row per point (NaN rows where there is no
/// contact): `{side}_s_mm`, with yaw `_x_mm`, then `_y_mm, _z_mm`, with yaw `_lead_mm`,
/// then `_r_mm, _gamma_rad`, `_rail_tan_gamma` where written, and
/// `_wheel_curvature_per_mm, _rail_curvature_per_mm`.
pub(crate) fn contact_columns(
    t: TableBuilder,
    side: Side,
    points: &[ContactPoint],
    rail_slope: RailSlopeColumn,
    yawed: bool,
) -> TableBuilder {
    let name = side.name();
    let column = |f: fn(&ContactPoint) -> f64| points.iter().map(f).collect::<Vec<_>>();
    let mut t = t.numeric(format!("{name}_s_mm"), column(|c| c.s));
    if yawed {
        t = t.numeric(format!("{name}_x_mm"), column(|c| c.x));
    }
    t = t
        .numeric(format!("{name}_y_mm"), column(|c| c.y))
        .numeric(format!("{name}_z_mm"), column(|c| c.z));
    if yawed {
        t = t.numeric(format!("{name}_lead_mm"), column(|c| c.lead));
    }
    let mut t = t
        .numeric(format!("{name}_r_mm"), column(|c| c.r))
        .numeric(format!("{name}_gamma_rad"), column(|c| c.gamma));
    if rail_slope == RailSlopeColumn::Written {
        t = t.numeric(
            format!("{name}_rail_tan_gamma"),
            column(|c| c.rail_tan_gamma),
        );
    }
    t.numeric(
        format!("{name}_wheel_curvature_per_mm"),
        column(|c| c.wheel_curvature),
    )
    .numeric(
        format!("{name}_rail_curvature_per_mm"),
        column(|c| c.rail_curvature),
    )
}

pub(super) fn converged(
    sweep: &RigidSweep,
    f: impl Fn(&wheelrail::rigid::RigidPosition) -> f64,
) -> Vec<f64> {
    sweep
        .positions()
        .iter()
        .map(|p| {
            if p.stop == Stop::Converged {
                f(p)
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// The contact-point jumps of a rigid sweep (`rigid_jumps.csv`).
///
/// # Errors
/// [`TableError`] only if the columns were built inconsistently (a bug).
pub fn rigid_jumps(sweep: &RigidSweep) -> Result<Table, TableError> {
    let j = &sweep.jumps();
    Table::builder()
        .comment(format!("intervals of y_ws across which a rigid contact point jumps; kind jump: refined to {JUMP_REFINE_MM} mm; kind artefact: a sampled profile's contact point hopping between two minima of the gap that a hollow shallower than {ARTEFACT_HOLLOW_MM} mm separates, over the sweep step that holds it (not refined; continuous in delta_r and in the charts)"))
        .comment("hollow_mm: how far the gap rises between the two contact points above the higher of them, where they exchange (NaN, with the reason in hollow_status, where they could not be followed to one pose)")
        .comment(PER_WHEEL)
        .text("side", j.iter().map(|j| j.side.name()))
        .numeric("y_from_mm", j.iter().map(|j| j.y_from).collect::<Vec<_>>())
        .numeric("y_to_mm", j.iter().map(|j| j.y_to).collect::<Vec<_>>())
        .numeric("s_from_mm", j.iter().map(|j| j.s_from).collect::<Vec<_>>())
        .numeric("s_to_mm", j.iter().map(|j| j.s_to).collect::<Vec<_>>())
        .text("kind", j.iter().map(|j| j.kind.name()))
        .numeric("hollow_mm", j.iter().map(|j| j.hollow_mm).collect::<Vec<_>>())
        .text(
            "hollow_status",
            j.iter().map(|j| {
                if j.hollow_mm.is_finite() {
                    "ok"
                } else {
                    "not measured: the two contacts could not be followed to one pose (kind jump)"
                }
            }),
        )
        .build()
}
