//! Charts of stage results. Each function takes the stage result it draws (its dependency
//! is its signature) and returns a [`report::Figure`](crate::report::Figure); rendering to
//! SVG/PNG bytes happens in [`super`].
//!
//! Jumps of a contact point are drawn as gaps (a NaN breaks the line), positions that did
//! not converge are left out, never joined across.

use crate::hertz::accuracy::HertzAccuracy;
use crate::pipeline::EpsilonSweeps;
use crate::quasi_elastic::QuasiElasticSweep;
use crate::report::{Chart, Figure, LegendPosition, Series};
use crate::rigid::{Position, RigidSweep, SideContact, Stop};
use crate::track::{Placement, Side};

/// Vertical offset of the wheel above the rail in contact maps (mm), so that the lines
/// linking contact points are visible.
const MAP_LIFT_MM: f64 = 8.0;

/// The heaviest quasi-elastic patch moving farther than this between neighbouring
/// positions has changed identity (another patch took over the weight): the line breaks
/// there. Within a patch, locations move at most ~1 mm per 0.1 mm of shift (measured in
/// `tests/quasi_elastic.rs`).
const PATCH_SWITCH_MM: f64 = 1.5;

const LEFT: usize = 0;
const RIGHT: usize = 1;
const RIGID: usize = 2;
const QE: usize = 3;

/// A polyline of `(x, y)` points.
type Line = Vec<(f64, f64)>;

/// Points of the wheel in its resting position on the rail (no shift, no roll) and of the
/// rail, in the side frame of `side`.
fn drawn_profiles(placement: &Placement, side: Side, lift: f64) -> (Line, Line) {
    let pair = placement.side(side);
    let axle = pair.wheel.nominal_radius_mm() - placement.resting_gap(side) + lift;
    let wheel = pair
        .wheel
        .profile()
        .sample(0.2)
        .iter()
        .map(|r| {
            let p = pair.wheel.at(r[0]);
            (p.y, axle + p.z)
        })
        .collect();
    let rail = pair
        .rail
        .profile()
        .sample(0.2)
        .iter()
        .map(|r| {
            let p = pair.rail.point_of(r[0]);
            (p[0], p[1])
        })
        .collect();
    (wheel, rail)
}

/// Wheel and rail of the left side in their placed positions (paper Fig. 1, left).
pub fn profiles(placement: &Placement) -> Figure {
    let (wheel, rail) = drawn_profiles(placement, Side::Left, 0.0);
    let g = placement.left.rail.gauge_point();
    Figure::single(
        Chart::new(
            "Wheel and rail profiles, left side, centred wheelset",
            "lateral position y from the track centre (mm)",
            "height z (mm)",
        )
        .series(
            Series::line(
                format!("wheel {}", placement.left.wheel.profile().name()),
                wheel,
            )
            .color(0),
        )
        .series(
            Series::line(
                format!("rail {}", placement.left.rail.profile().name()),
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
/// little more). The flange back's vertical face, the rail's gauge corner and field-side
/// flank leave it; the chart marks where and says how far.
pub const CONICITY_RANGE: (f64, f64) = (-1.0, 3.5);

/// tan(gamma) of wheel and rail against the lateral position (paper Fig. 1, right), over
/// [`CONICITY_RANGE`].
pub fn conicity(placement: &Placement) -> Figure {
    let mut figure = profile_property(
        placement,
        "Conicity: tan(gamma) of wheel and rail, left side",
        "tan(gamma) (-)",
        |p, u| p.tan_gamma(u),
        |r, y| r.at(y).map_or(f64::NAN, |q| q.slope),
    );
    for chart in &mut figure.panels {
        chart.y_range = Some(CONICITY_RANGE);
    }
    figure
}

/// Lateral curvature of wheel and rail against the lateral position.
pub fn curvature(placement: &Placement) -> Figure {
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
    wheel_value: impl Fn(&crate::profile::Profile, f64) -> f64,
    rail_value: impl Fn(&crate::track::PlacedRail, f64) -> f64,
) -> Figure {
    let w = &placement.left.wheel;
    let r = &placement.left.rail;
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
    profile: &crate::profile::Profile,
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

/// A series of one per-wheel quantity over a rigid sweep, broken at jumps of that wheel's
/// contact point and at positions that did not converge.
fn rigid_series(
    sweep: &RigidSweep,
    side: Side,
    f: impl Fn(&Position, &SideContact) -> f64,
) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(sweep.positions.len());
    for (i, p) in sweep.positions.iter().enumerate() {
        match p.side(side) {
            Some(c) if p.stop == Stop::Converged => out.push((p.y_ws, f(p, c))),
            _ => out.push((p.y_ws, f64::NAN)),
        }
        if let Some(next) = sweep.positions.get(i + 1)
            && sweep
                .jumps
                .iter()
                .any(|j| j.side == side && j.y_from >= p.y_ws && j.y_to <= next.y_ws)
        {
            out.push((f64::NAN, f64::NAN));
        }
    }
    out
}

/// `(y_ws, s)` of the heaviest quasi-elastic patch of wheel `k`, broken where another patch
/// takes over.
fn heaviest_patch_series(q: &QuasiElasticSweep, k: usize) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(q.positions.len());
    for p in &q.positions {
        let s = p.sides[k].main().map_or(f64::NAN, |c| c.s);
        if out
            .last()
            .is_some_and(|&(_, prev)| (s - prev).abs() > PATCH_SWITCH_MM)
        {
            out.push((f64::NAN, f64::NAN));
        }
        out.push((p.y_ws, s));
    }
    out
}

/// A wheelset quantity over a rigid sweep, broken where either contact point jumps.
fn rigid_wheelset_series(sweep: &RigidSweep, f: impl Fn(&Position) -> f64) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(sweep.positions.len());
    for (i, p) in sweep.positions.iter().enumerate() {
        out.push((
            p.y_ws,
            if p.stop == Stop::Converged {
                f(p)
            } else {
                f64::NAN
            },
        ));
        if let Some(next) = sweep.positions.get(i + 1)
            && sweep
                .jumps
                .iter()
                .any(|j| j.y_from >= p.y_ws && j.y_to <= next.y_ws)
        {
            out.push((f64::NAN, f64::NAN));
        }
    }
    out
}

/// The shifts where flange contact begins on either side
/// ([`RigidSweep::flange_contact_mm`](crate::rigid::RigidSweep::flange_contact_mm)), with their labels.
pub fn flange_onsets(sweep: &RigidSweep) -> Vec<(f64, &'static str)> {
    [
        (Side::Left, "left flange contact"),
        (Side::Right, "right flange contact"),
    ]
    .into_iter()
    .map(|(side, label)| (sweep.flange_contact_mm(side), label))
    .filter(|(y, _)| y.is_finite())
    .collect()
}

fn with_onsets(mut chart: Chart, sweep: &RigidSweep) -> Chart {
    for (y, label) in flange_onsets(sweep) {
        chart = chart.vline(y, label);
    }
    chart
}

const SHIFT: &str = "lateral shift of the wheelset y_ws (mm)";

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
pub fn contact_points(placement: &Placement, sweep: &RigidSweep) -> Figure {
    let wheel = left_right(
        sweep,
        "On the wheel",
        "wheel coordinate s (mm, + field side)",
        |c| c.s,
    );
    let top = |side: Side| placement.side(side).rail.top()[0];
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
pub fn rolling_radius(sweep: &RigidSweep) -> Figure {
    let dr = |p: &Position| match p.contact {
        [Some(l), Some(r)] => l.r - r.r,
        _ => f64::NAN,
    };
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
pub fn contact_angles(sweep: &RigidSweep) -> Figure {
    Figure::single(left_right(
        sweep,
        "Contact angles (track frame, roll included)",
        "gamma (rad)",
        |c| c.gamma,
    ))
}

/// Roll angle against the shift (paper Fig. 2).
pub fn roll(sweep: &RigidSweep) -> Figure {
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
pub fn contact_angle_parameter(sweep: &RigidSweep) -> Figure {
    let eps = |p: &Position| sweep.wickens(p).epsilon;
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
fn contact_links(
    placement: &Placement,
    side: Side,
    points: &[(f64, f64, f64)],
) -> Vec<[(f64, f64); 2]> {
    let pair = placement.side(side);
    let axle = pair.wheel.nominal_radius_mm() - placement.resting_gap(side) + MAP_LIFT_MM;
    points
        .iter()
        .filter(|(s, y, z)| s.is_finite() && y.is_finite() && z.is_finite())
        .map(|&(s, y, z)| {
            let w = pair.wheel.at(s);
            [(w.y, axle + w.z), (y.abs(), z)]
        })
        .collect()
}

fn map_chart(placement: &Placement, title: &str) -> Chart {
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

/// Profiles with the rigid contact points of the sweep linked wheel to rail (left wheel;
/// by symmetry the right wheel at -y_ws is the same).
pub fn contact_map(placement: &Placement, sweep: &RigidSweep) -> Figure {
    let pts: Vec<(f64, f64, f64)> = sweep
        .positions
        .iter()
        .filter(|p| p.stop == Stop::Converged)
        .filter_map(|p| p.side(Side::Left).map(|c| (c.s, c.y, c.z)))
        .collect();
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

/// Rigid against quasi-elastic contact points (paper Fig. 4).
pub fn quasi_elastic_points(sweep: &RigidSweep, q: &QuasiElasticSweep) -> Figure {
    let panel = |side: Side, k: usize| {
        let main = heaviest_patch_series(q, k);
        let second: Vec<(f64, f64)> = q
            .positions
            .iter()
            .filter_map(|p| p.sides[k].second().map(|c| (p.y_ws, c.s)))
            .collect();
        with_onsets(
            Chart::new(
                format!("{} wheel", side.name()),
                SHIFT,
                "wheel coordinate s (mm)",
            )
            .series(Series::line("rigid", rigid_series(sweep, side, |_, c| c.s)).color(RIGID))
            .series(Series::line("quasi-elastic, heaviest patch", main).color(QE))
            .series(Series::markers("quasi-elastic, second patch", second).color(5)),
            sweep,
        )
    };
    Figure::grid(
        format!(
            "Rigid and quasi-elastic contact points (eps = {} mm)",
            q.settings.epsilon_mm
        ),
        vec![panel(Side::Left, 0), panel(Side::Right, 1)],
        2,
    )
}

/// Contact map with rigid and quasi-elastic points (paper Fig. 5).
pub fn quasi_elastic_map(
    placement: &Placement,
    sweep: &RigidSweep,
    q: &QuasiElasticSweep,
) -> Figure {
    let rigid: Vec<(f64, f64, f64)> = sweep
        .positions
        .iter()
        .filter(|p| p.stop == Stop::Converged)
        .filter_map(|p| p.side(Side::Left).map(|c| (c.s, c.y, c.z)))
        .collect();
    let qe: Vec<(f64, f64, f64)> = q
        .positions
        .iter()
        .filter_map(|p| p.sides[0].main().map(|c| (c.s, c.y, c.z)))
        .collect();
    Figure::single(
        map_chart(
            placement,
            &format!(
                "Contact map: rigid and quasi-elastic (eps = {} mm), left wheel",
                q.settings.epsilon_mm
            ),
        )
        .series(
            Series::segments("rigid", &contact_links(placement, Side::Left, &rigid)).color(RIGID),
        )
        .series(
            Series::segments("quasi-elastic", &contact_links(placement, Side::Left, &qe))
                .color(QE)
                .dashed(),
        ),
    )
}

/// Quasi-elastic contact position for several eps, rigid for reference.
pub fn epsilon_sensitivity(sweep: &RigidSweep, e: &EpsilonSweeps) -> Figure {
    let mut chart = Chart::new(
        "Sensitivity to eps: left wheel contact position",
        SHIFT,
        "wheel coordinate s (mm)",
    )
    .series(Series::line("rigid", rigid_series(sweep, Side::Left, |_, c| c.s)).color(RIGID));
    for (i, (eps, q)) in e.runs.iter().enumerate() {
        let pts = heaviest_patch_series(q, 0);
        chart = chart
            .series(Series::line(format!("eps = {eps} mm"), pts).color([0, 1, 3, 4, 5, 6][i % 6]));
    }
    Figure::single(with_onsets(chart, sweep))
}

/// `(y_ws, f(ellipse))` of wheel `k` over a Hertz sweep, NaN where there is no ellipse.
fn ellipse_series(
    h: &[crate::hertz::sweep::Position],
    k: usize,
    f: fn(&crate::hertz::Ellipse) -> f64,
) -> Vec<(f64, f64)> {
    h.iter()
        .map(|p| (p.y_ws, p.sides[k].ellipse().map_or(f64::NAN, f)))
        .collect()
}

/// Semi-axes of the contact ellipses (paper Fig. 6).
pub fn semi_axes(h: &[crate::hertz::sweep::Position]) -> Figure {
    let get = |k, f| ellipse_series(h, k, f);
    Figure::single(
        Chart::new("Semi-axes of the contact ellipses", SHIFT, "semi-axis (mm)")
            .series(Series::line("left a (rolling)", get(0, |e| e.a_mm)).color(LEFT))
            .series(
                Series::line("left b (lateral)", get(0, |e| e.b_mm))
                    .color(LEFT)
                    .dashed(),
            )
            .series(Series::line("right a (rolling)", get(1, |e| e.a_mm)).color(RIGHT))
            .series(
                Series::line("right b (lateral)", get(1, |e| e.b_mm))
                    .color(RIGHT)
                    .dashed(),
            ),
    )
}

/// Maximum contact pressure.
pub fn pressure(h: &[crate::hertz::sweep::Position]) -> Figure {
    Figure::single(
        Chart::new("Maximum contact pressure", SHIFT, "p0 (MPa)")
            .series(Series::line("left", ellipse_series(h, 0, |e| e.p0_mpa)).color(LEFT))
            .series(
                Series::line("right", ellipse_series(h, 1, |e| e.p0_mpa))
                    .color(RIGHT)
                    .dashed(),
            ),
    )
}

/// Accuracy of the paper's Hertz numerics, log scale.
pub fn hertz_accuracy(a: &HertzAccuracy) -> Figure {
    let floor = |v: f64| v.abs().max(1e-17);
    let series = Chart::new(
        "Paper's series for K and E",
        "eccentricity e",
        "|relative error|",
    )
    .series(
        Series::line(
            "K, paper series",
            a.series.iter().map(|r| (r.0, floor(r.1))).collect(),
        )
        .color(LEFT),
    )
    .series(
        Series::line(
            "E, paper series",
            a.series.iter().map(|r| (r.0, floor(r.2))).collect(),
        )
        .color(RIGHT)
        .dashed(),
    )
    .y_log();
    let ratio = Chart::new(
        "Paper's iteration for b/a",
        "curvature ratio A/B",
        "|relative error of b/a|",
    )
    .series(Series::line("paper", a.ratio.iter().map(|r| (r.0, floor(r.1))).collect()).color(LEFT))
    .series(
        Series::markers(
            "exact, against mpmath (errors below 1e-17 drawn at 1e-17)",
            a.exact_ratio.iter().map(|r| (r.0, floor(r.1))).collect(),
        )
        .color(QE),
    )
    .y_range(1e-18, 1e4)
    .legend(LegendPosition::UpperRight)
    .x_log()
    .y_log();
    Figure::grid(
        "Accuracy of the paper's Hertz numerics against the exact method",
        vec![series, ratio],
        2,
    )
}

/// Run time against error (log-log): one point per setting, the Pareto front as a line, the
/// default and the paper's settings as their own series. Errors of exactly zero (the
/// reference's own settings) are drawn at 1e-17.
pub fn tradeoff(m: &[crate::tradeoff::Measurement]) -> Figure {
    let panel = |title: &str, y_label: &str, error: fn(&crate::tradeoff::Errors) -> f64| {
        let point =
            |x: &crate::tradeoff::Measurement| (1e3 * x.median_s, error(&x.errors).max(1e-17));
        let front: Vec<(f64, f64)> = crate::tradeoff::pareto_front(m, error)
            .into_iter()
            .map(|i| point(&m[i]))
            .collect();
        let pick = |label: &str| {
            m.iter()
                .filter(|x| x.setting.label == label)
                .map(point)
                .collect::<Vec<_>>()
        };
        let others = m
            .iter()
            .filter(|x| x.setting.label != "default" && x.setting.label != "paper")
            .map(point)
            .collect();
        Chart::new(title, "median run time (ms, log)", y_label)
            .series(Series::line("Pareto front", front).color(QE))
            .series(Series::markers("other settings", others).color(6))
            .series(Series::markers("default", pick("default")).color(LEFT))
            .series(Series::markers("paper", pick("paper")).color(RIGHT))
            .x_log()
            .y_log()
    };
    Figure::grid(
        "Run time against error (each point a setting; see tradeoff.csv for the labels)",
        vec![
            panel("Contact position", "max rigid contact error (mm)", |e| {
                e.contact_mm
            }),
            panel("Contact ellipse", "max relative error of a and b", |e| {
                e.a_rel.max(e.b_rel)
            }),
        ],
        2,
    )
}

/// The equivalent conicity function by both methods, `tan γe(3 mm)` marked (EN 15302).
pub fn equivalent_conicity(c: &crate::conicity::PairConicity) -> Figure {
    use crate::conicity::{Method, REFERENCE_AMPLITUDE_MM};
    let series = |m: Method| -> Line {
        c.by(m)
            .points
            .iter()
            .map(|p| (p.amplitude_mm, p.tan_gamma_e))
            .collect()
    };
    let method = c.parameters.method;
    let at3 = c.parameters.tan_gamma_e[1];
    let mut chart = Chart::new(
        "Equivalent conicity (EN 15302)",
        "amplitude of the kinematic motion ŷ (mm)",
        "equivalent conicity tan γe",
    )
    .series(Series::line("Klingel wavelength (Annex B)", series(Method::Klingel)).color(0))
    .series(
        Series::line("regression of Δr (Annex C)", series(Method::Regression))
            .color(1)
            .dashed(),
    );
    if at3.is_finite() {
        chart = chart
            .series(
                Series::markers(
                    format!("tan γe(3 mm) = {at3:.3} ({})", method.name()),
                    vec![(REFERENCE_AMPLITUDE_MM, at3)],
                )
                .color(2),
            )
            .vline(REFERENCE_AMPLITUDE_MM, "ŷ = 3 mm");
    }
    Figure::single(chart.legend(LegendPosition::Auto))
}

/// Δr of the rigid sweep with the linear function of the equivalent cone at ŷ = 3 mm,
/// `2 tan γe(3 mm) (y - y_eq)`, over the motion `y_eq ± 3 mm`.
pub fn delta_r_linearised(c: &crate::conicity::PairConicity) -> Figure {
    use crate::conicity::REFERENCE_AMPLITUDE_MM;
    let p = &c.parameters;
    let eq = if p.equilibrium_mm.is_finite() {
        p.equilibrium_mm
    } else {
        0.0
    };
    let a = REFERENCE_AMPLITUDE_MM;
    // The window: twice the motion, scaled to Δr within it (flange contact beyond would
    // flatten the part that matters).
    let (x_lo, x_hi) = (eq - 2.2 * a, eq + 2.2 * a);
    let within: Line = c
        .delta_r
        .points()
        .filter(|(y, _)| *y >= x_lo && *y <= x_hi)
        .collect();
    let span = within
        .iter()
        .filter(|(y, _)| (y - eq).abs() <= 1.6 * a)
        .map(|(_, d)| d.abs())
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max)
        .max(1e-3);
    let tan = p.tan_gamma_e[1];
    let mut chart = Chart::new(
        "Rolling radius difference and its equivalent cone at ŷ = 3 mm",
        SHIFT,
        "Δr = r_left - r_right (mm)",
    )
    .x_range(x_lo, x_hi)
    .y_range(-1.25 * span, 1.25 * span)
    .series(Series::line("Δr (rigid)", within).color(RIGID));
    if tan.is_finite() {
        chart = chart.series(
            Series::line(
                format!("2 tan γe(3 mm) (y - y_eq), tan γe = {tan:.3}"),
                vec![(eq - a, -2.0 * tan * a), (eq + a, 2.0 * tan * a)],
            )
            .color(1)
            .dashed(),
        );
    }
    Figure::single(
        chart
            .vline(eq - a, "y_eq - 3 mm")
            .vline(eq + a, "y_eq + 3 mm")
            .legend(LegendPosition::LowerRight),
    )
}
