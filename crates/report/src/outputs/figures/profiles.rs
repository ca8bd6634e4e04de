//! Figures of the profiles stage: the placed profiles, their slope and curvature.

use super::Line;
use crate::outputs::tables::VERTICAL_TAN_GAMMA;
use crate::{Chart, Figure, LegendPosition, Series};
use wheelrail::track::{Placement, Side};

/// Points of the wheel in its resting position on the rail (no shift, no roll) and of the
/// rail, in the side frame of `side`.
pub(super) fn drawn_profiles(placement: &Placement, side: Side, lift: f64) -> (Line, Line) {
    let pair = placement.side(side);
    let axle = pair.wheel().nominal_radius_mm() - placement.resting_gap(side) + lift;
    let wheel = pair
        .wheel()
        .profile()
        .sample(0.2)
        .iter()
        .map(|r| {
            let p = pair.wheel().at(r[0]);
            (p.y, axle + p.z)
        })
        .collect();
    let rail = pair
        .rail()
        .profile()
        .sample(0.2)
        .iter()
        .map(|r| {
            let p = pair.rail().point_of(r[0]);
            (p[0], p[1])
        })
        .collect();
    (wheel, rail)
}

/// Wheel and rail of the left side in their placed positions (paper Fig. 1, left).
pub(crate) fn profiles(placement: &Placement) -> Figure {
    let (wheel, rail) = drawn_profiles(placement, Side::Left, 0.0);
    let g = placement.left().rail().gauge_point();
    Figure::single(
        Chart::new(
            "Wheel and rail profiles, left side, centred wheelset",
            "lateral position y from the track centre (mm)",
            "height z (mm)",
        )
        .series(
            Series::line(
                format!("wheel {}", placement.left().wheel().profile().name()),
                wheel,
            )
            .color(0),
        )
        .series(
            Series::line(
                format!("rail {}", placement.left().rail().profile().name()),
                rail,
            )
            .color(1),
        )
        .series(Series::markers("gauge point", vec![(g[0], g[1])]).color(5))
        .equal_aspect()
        .legend(LegendPosition::UpperRight),
    )
}

/// The stated y range of the conicity chart: contact angles from -45° to 74°, the contact
/// angles a wheel and a rail can meet at (the S1002 flange reaches 70°, worn flanges a
/// little more). The flange back, the rail's gauge corner and field-side flank may leave
/// it; the chart marks where and says how far.
pub(crate) const CONICITY_RANGE: (f64, f64) = (-1.0, 3.5);

/// tan(gamma) of the wheel at `u`, `NaN` on a vertical face (the S1002 flange back), as the
/// profile table writes it ([`VERTICAL_TAN_GAMMA`]): the profiles evaluate a vertical
/// tangent with a capped root (`-1e6`), which is no slope to draw or to quote.
fn wheel_tan_gamma(p: &wheelrail::profile::Profile, u: f64) -> f64 {
    let t = p.tan_gamma(u);
    if t.abs() > VERTICAL_TAN_GAMMA {
        f64::NAN
    } else {
        t
    }
}

/// tan(gamma) of wheel and rail against the lateral position (paper Fig. 1, right), over
/// [`CONICITY_RANGE`]; the wheel's vertical faces are gaps.
pub(crate) fn conicity(placement: &Placement) -> Figure {
    let mut figure = profile_property(
        placement,
        "Conicity: tan(gamma) of wheel and rail, left side",
        "tan(gamma) (-)",
        wheel_tan_gamma,
        |r, y| r.at(y).map_or(f64::NAN, |q| q.slope),
    );
    for chart in &mut figure.panels {
        chart.y_range = Some(CONICITY_RANGE);
    }
    figure
}

/// The caption of [`conicity`] (after "Paper Fig. 1: " on the paper's case), its remarks
/// only where they apply: section joints where the wheel has them, a vertical face where
/// it has one, which curves leave the chart where any does.
pub(crate) fn conicity_caption(placement: &Placement) -> String {
    let figure = conicity(placement);
    let chart = &figure.panels[0];
    let (lo, hi) = CONICITY_RANGE;
    let leaves = |series: usize| {
        chart.series[series]
            .points
            .iter()
            .any(|&(x, y)| x.is_finite() && y.is_finite() && !(lo..=hi).contains(&y))
    };
    let wheel = placement.left().wheel().profile();
    let vertical_face = wheel
        .sample(0.05)
        .iter()
        .any(|r| wheel_tan_gamma(wheel, r[0]).is_nan());
    let mut text = "tangent of the profile angle (conicity angle, paper Eq. 1) of wheel and rail against the lateral position".to_string();
    let breaks: Vec<&str> = [
        (!wheel.joints().is_empty()).then_some("at its section joints"),
        vertical_face.then_some("where its face is vertical (the flange back: no slope)"),
    ]
    .into_iter()
    .flatten()
    .collect();
    if !breaks.is_empty() {
        text += &format!("; the wheel is broken {}", breaks.join(" and "));
    }
    text += ". The y axis runs over contact angles from -45° to 74° (tan γ from -1 to 3.5)";
    let off = match (leaves(0), leaves(1)) {
        (true, true) => Some("the wheel's and the rail's curves leave"),
        (true, false) => Some("the wheel's curve leaves"),
        (false, true) => Some("the rail's curve leaves"),
        (false, false) => None,
    };
    if let Some(off) = off {
        text += &format!("; triangles at the frame mark where {off} it");
    }
    text + "."
}

/// Lateral curvature of wheel and rail against the lateral position.
pub(crate) fn curvature(placement: &Placement) -> Figure {
    profile_property(
        placement,
        "Lateral curvature of wheel and rail (convex positive), left side",
        "curvature (1/mm)",
        |p, u| p.convex_curvature(u),
        |r, y| r.at(y).map_or(f64::NAN, |q| q.curvature()),
    )
}

fn profile_property(
    placement: &Placement,
    title: &str,
    y_label: &str,
    wheel_value: impl Fn(&wheelrail::profile::Profile, f64) -> f64,
    rail_value: impl Fn(&wheelrail::track::PlacedRail, f64) -> f64,
) -> Figure {
    let w = &placement.left().wheel();
    let r = &placement.left().rail();
    // Section joints break the lines: values jump there.
    let wheel: Vec<(f64, f64)> = with_breaks(w.profile(), |u| {
        (w.taping_line_mm() + u, wheel_value(w.profile(), u))
    });
    let (lo, hi) = r.y_range();
    let n = ((hi - lo) / 0.05).ceil() as usize;
    let rail: Vec<(f64, f64)> = (0..=n)
        .map(|i| {
            let y = lo + (hi - lo) * i as f64 / n as f64;
            (y, rail_value(r, y))
        })
        .collect();
    Figure::single(
        Chart::new(
            title,
            "lateral position y from the track centre (mm)",
            y_label,
        )
        .series(Series::line(format!("wheel {}", w.profile().name()), wheel).color(0))
        .series(Series::line(format!("rail {}", r.profile().name()), rail).color(1))
        .x_range(
            lo.min(w.taping_line_mm() - 70.0),
            hi.max(w.taping_line_mm() + 60.0),
        ),
    )
}

/// Samples of `f(u)` every 0.05 mm with a NaN point at each section joint.
fn with_breaks(
    profile: &wheelrail::profile::Profile,
    f: impl Fn(f64) -> (f64, f64),
) -> Vec<(f64, f64)> {
    let (lo, hi) = profile.domain();
    let joints = profile.joints();
    let n = ((hi - lo) / 0.05).ceil() as usize;
    let mut out = Vec::with_capacity(n + joints.len() + 1);
    let mut next_joint = 0;
    for i in 0..=n {
        let u = lo + (hi - lo) * i as f64 / n as f64;
        while next_joint < joints.len() && joints[next_joint] < u {
            let j = joints[next_joint];
            out.push(f(j - 1e-9));
            out.push((f64::NAN, f64::NAN));
            out.push(f(j + 1e-9));
            next_joint += 1;
        }
        out.push(f(u));
    }
    out
}
