//! Figures of the rigid contact search (paper Fig. 2) and its contact map.

use super::profiles::drawn_profiles;
use super::{LEFT, RIGHT, RIGID, SHIFT};
use crate::{Chart, Figure, Series};
use wheelrail::rigid::{JumpKind, RigidPosition, RigidSweep, SideContact, Stop};
use wheelrail::track::{Placement, Side};

/// Vertical offset of the wheel above the rail in contact maps (mm), so that the lines
/// linking contact points are visible.
const MAP_LIFT_MM: f64 = 8.0;

/// A series of one per-wheel quantity over a rigid sweep, broken at jumps of that wheel's
/// contact point (not at sampling artefacts, which are drawn as continuous) and at
/// positions that did not converge.
pub(super) fn rigid_series(
    sweep: &RigidSweep,
    side: Side,
    f: impl Fn(&RigidPosition, &SideContact) -> f64,
) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(sweep.positions().len());
    for (i, p) in sweep.positions().iter().enumerate() {
        match p.side(side) {
            Some(c) if p.stop == Stop::Converged => out.push((p.y_ws, f(p, c))),
            _ => out.push((p.y_ws, f64::NAN)),
        }
        if let Some(next) = sweep.positions().get(i + 1)
            && sweep.jumps().iter().any(|j| {
                j.side == side
                    && j.kind == JumpKind::Jump
                    && j.y_from >= p.y_ws
                    && j.y_to <= next.y_ws
            })
        {
            out.push((f64::NAN, f64::NAN));
        }
    }
    out
}

/// A wheelset quantity over a rigid sweep, broken where either contact point jumps (not at
/// sampling artefacts).
fn rigid_wheelset_series(sweep: &RigidSweep, f: impl Fn(&RigidPosition) -> f64) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(sweep.positions().len());
    for (i, p) in sweep.positions().iter().enumerate() {
        out.push((
            p.y_ws,
            if p.stop == Stop::Converged {
                f(p)
            } else {
                f64::NAN
            },
        ));
        if let Some(next) = sweep.positions().get(i + 1)
            && sweep
                .jumps()
                .iter()
                .any(|j| j.kind == JumpKind::Jump && j.y_from >= p.y_ws && j.y_to <= next.y_ws)
        {
            out.push((f64::NAN, f64::NAN));
        }
    }
    out
}

/// The shifts where flange contact begins on either side
/// ([`RigidSweep::flange_contact_mm`](wheelrail::rigid::RigidSweep::flange_contact_mm)), with their labels.
pub(crate) fn flange_onsets(sweep: &RigidSweep) -> Vec<(f64, &'static str)> {
    [
        (Side::Left, "left flange contact"),
        (Side::Right, "right flange contact"),
    ]
    .into_iter()
    .map(|(side, label)| (sweep.flange_contact_mm(side), label))
    .filter(|(y, _)| y.is_finite())
    .collect()
}

pub(super) fn with_onsets(mut chart: Chart, sweep: &RigidSweep) -> Chart {
    for (y, label) in flange_onsets(sweep) {
        chart = chart.vline(y, label);
    }
    chart
}

/// A chart of one per-wheel rigid quantity against the shift: left solid, right dashed,
/// broken at jumps, flange onsets marked.
fn left_right(
    sweep: &RigidSweep,
    title: &str,
    y_label: &str,
    f: impl Fn(&SideContact) -> f64,
) -> Chart {
    with_onsets(
        Chart::new(title, SHIFT, y_label)
            .series(Series::line("left", rigid_series(sweep, Side::Left, |_, c| f(c))).color(LEFT))
            .series(
                Series::line("right", rigid_series(sweep, Side::Right, |_, c| f(c)))
                    .color(RIGHT)
                    .dashed(),
            ),
        sweep,
    )
}

/// Contact positions on wheel and rail against the shift (paper Fig. 2).
pub(crate) fn contact_points(placement: &Placement, sweep: &RigidSweep) -> Figure {
    let wheel = left_right(
        sweep,
        "On the wheel",
        "wheel coordinate s (mm, + field side)",
        |c| c.s,
    );
    let top = |side: Side| placement.side(side).rail().top()[0];
    // Track-frame |y| of the contact from the top of the rail of its side.
    let rail = left_right(
        sweep,
        "On the rail",
        "from the top of rail (mm, + field side)",
        |c| c.y.abs() - top(if c.y > 0.0 { Side::Left } else { Side::Right }),
    );
    Figure::grid("Rigid contact points", vec![wheel, rail], 2)
}

/// Rolling radius difference against the shift (paper Fig. 2).
pub(crate) fn rolling_radius(sweep: &RigidSweep) -> Figure {
    let dr = |p: &RigidPosition| p.delta_r();
    Figure::single(with_onsets(
        Chart::new(
            "Rolling radius difference",
            SHIFT,
            "delta r = r_left - r_right (mm)",
        )
        .series(Series::line("rigid", rigid_wheelset_series(sweep, dr)).color(RIGID)),
        sweep,
    ))
}

/// Contact angles against the shift (paper Fig. 2).
pub(crate) fn contact_angles(sweep: &RigidSweep) -> Figure {
    Figure::single(left_right(
        sweep,
        "Contact angles (track frame, roll included)",
        "gamma (rad)",
        |c| c.gamma,
    ))
}

/// Lead of each wheel's contact ahead of the axle against the shift (yaw).
pub(crate) fn contact_lead(sweep: &RigidSweep) -> Figure {
    Figure::single(left_right(
        sweep,
        "Contact point ahead of the axle (yawed wheelset)",
        "lead (mm, + ahead of the axle)",
        |c| c.lead,
    ))
}

/// Roll angle against the shift (paper Fig. 2).
pub(crate) fn roll(sweep: &RigidSweep) -> Figure {
    Figure::single(with_onsets(
        Chart::new(
            "Wheelset roll angle",
            SHIFT,
            "roll (mrad, + lifts the left wheel)",
        )
        .series(Series::line("rigid", rigid_wheelset_series(sweep, |p| 1e3 * p.roll)).color(RIGID)),
        sweep,
    ))
}

/// Wickens' contact angle parameter against the shift (paper Fig. 2).
pub(crate) fn contact_angle_parameter(sweep: &RigidSweep) -> Figure {
    let eps = |p: &RigidPosition| sweep.wickens(p).epsilon;
    Figure::single(with_onsets(
        Chart::new(
            "Contact angle parameter epsilon = l0 (tan gamma_l - tan gamma_r) / (2 y_ws)",
            SHIFT,
            "epsilon (-)",
        )
        .series(Series::line("rigid", rigid_wheelset_series(sweep, eps)).color(RIGID)),
        sweep,
    ))
}

/// Links between wheel and rail contact points of one side, with the wheel drawn lifted.
pub(super) fn contact_links(
    placement: &Placement,
    side: Side,
    points: &[(f64, f64, f64)],
) -> Vec<[(f64, f64); 2]> {
    let pair = placement.side(side);
    let axle = pair.wheel().nominal_radius_mm() - placement.resting_gap(side) + MAP_LIFT_MM;
    points
        .iter()
        .filter(|(s, y, z)| s.is_finite() && y.is_finite() && z.is_finite())
        .map(|&(s, y, z)| {
            let w = pair.wheel().at(s);
            [(w.y, axle + w.z), (y.abs(), z)]
        })
        .collect()
}

pub(super) fn map_chart(placement: &Placement, title: &str) -> Chart {
    let (wheel, rail) = drawn_profiles(placement, Side::Left, MAP_LIFT_MM);
    Chart::new(
        title,
        "lateral position |y| from the track centre (mm)",
        "height z (mm; wheel drawn 8 mm high)",
    )
    .series(Series::line("wheel (left, centred)", wheel).color(0))
    .series(Series::line("rail (left)", rail).color(1))
    .equal_aspect()
    .x_range(690.0, 800.0)
}

/// `(s, y, z)` of the left wheel's rigid contact at every converged position.
pub(super) fn left_contacts(sweep: &RigidSweep) -> Vec<(f64, f64, f64)> {
    sweep
        .positions()
        .iter()
        .filter(|p| p.stop == Stop::Converged)
        .filter_map(|p| p.side(Side::Left).map(|c| (c.s, c.y, c.z)))
        .collect()
}

/// Profiles with the rigid contact points of the sweep linked wheel to rail (left wheel;
/// by symmetry the right wheel at -y_ws is the same).
pub(crate) fn contact_map(placement: &Placement, sweep: &RigidSweep) -> Figure {
    let pts = left_contacts(sweep);
    Figure::single(
        map_chart(
            placement,
            "Contact map: rigid contact points of the sweep, left wheel",
        )
        .series(
            Series::segments(
                "rigid contact (wheel - rail)",
                &contact_links(placement, Side::Left, &pts),
            )
            .color(RIGID),
        ),
    )
}
