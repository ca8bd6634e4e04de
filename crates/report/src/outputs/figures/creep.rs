//! Figures of the creep stage: the forces against the shift, and force against creepage on
//! one patch for the three tangential models.

use super::{LEFT, QE, RIGHT, RIGID, SHIFT};

/// The palette's black, for reference lines.
const BLACK: usize = 6;
use crate::{Chart, Figure, Series};
use wheelrail::creep::Method;
use wheelrail::creep::sweep::{CreepSweep, Curve};
use wheelrail::track::Side;

/// `(y_ws, f(forces) / 1000)` of one wheel's patch `k` over the sweep, NaN where it has no
/// converged solution.
fn force_series(
    c: &CreepSweep,
    side: Side,
    k: usize,
    f: fn(&wheelrail::creep::PatchForces) -> f64,
) -> Vec<(f64, f64)> {
    c.positions()
        .iter()
        .map(|p| {
            let v = p
                .side(side)
                .patches
                .get(k)
                .and_then(|r| r.forces.as_ref().ok())
                .filter(|f| matches!(f.status, wheelrail::creep::Status::Converged { .. }))
                .map_or(f64::NAN, |x| f(x) / 1000.0);
            (p.y_ws, v)
        })
        .collect()
}

/// One panel of a force against the shift: each wheel's heaviest patch as a line (left
/// solid, right dashed), a second patch as markers.
fn force_panel(
    c: &CreepSweep,
    title: &str,
    y_label: &str,
    f: fn(&wheelrail::creep::PatchForces) -> f64,
) -> Chart {
    let mut chart = Chart::new(title, SHIFT, y_label);
    for (side, color) in [(Side::Left, LEFT), (Side::Right, RIGHT)] {
        let main = Series::line(side.name(), force_series(c, side, 0, f)).color(color);
        chart = chart.series(if side == Side::Right {
            main.dashed()
        } else {
            main
        });
        let second = force_series(c, side, 1, f);
        if second.iter().any(|p| p.1.is_finite()) {
            chart = chart.series(
                Series::markers(format!("{} second patch", side.name()), second).color(color),
            );
        }
    }
    chart
}

/// Longitudinal and lateral creep forces of each wheel against the shift.
pub(crate) fn creep_forces(c: &CreepSweep) -> Figure {
    Figure::grid(
        format!(
            "Creep forces of the wheel on the rail ({}, mu = {})",
            c.settings().method(),
            c.settings().friction()
        ),
        vec![
            force_panel(c, "Longitudinal Fx (along the rail)", "Fx (kN)", |f| {
                f.tangential.fx_n
            }),
            force_panel(c, "Lateral Fy (in the contact plane)", "Fy (kN)", |f| {
                f.tangential.fy_n
            }),
        ],
        2,
    )
}

/// Force against creepage on the patch of `curve`: Kalker's linear theory (its slope), FASTSIM
/// and Polach, with the patch's own creepage marked.
pub(crate) fn creep_curve(curve: Option<&Curve>) -> Figure {
    let Some(curve) = curve else {
        return Figure::single(Chart::new(
            "Force against creepage: no converged patch with creepage",
            "creepage sqrt(xi^2 + eta^2)",
            "sqrt(Fx^2 + Fy^2) / (mu FN)",
        ));
    };
    // Linear theory grows without bound: drawn up to 1.3 mu FN.
    const TOP: f64 = 1.3;
    let points = |m: Method| -> Vec<(f64, f64)> {
        let (_, f) = curve
            .force
            .iter()
            .find(|(k, _)| *k == m)
            .expect("all three");
        curve
            .creepage
            .iter()
            .zip(f)
            .map(|(&x, &y)| (1e3 * x, y))
            .take_while(|p| p.1 <= TOP)
            .collect()
    };
    let at = &curve.at;
    let slip = at.creepages.xi.hypot(at.creepages.eta);
    let chart = Chart::new(
        format!(
            "a = {:.2} mm, b = {:.2} mm, FN = {:.1} kN; mark: xi {:.2e}, eta {:.2e}, phi {:.2e} /mm",
            at.a_mm,
            at.b_mm,
            at.normal_force_n / 1000.0,
            at.creepages.xi,
            at.creepages.eta,
            at.creepages.phi_per_mm
        ),
        "creepage sqrt(xi^2 + eta^2) (per mille); xi : eta : phi kept in the patch's ratio",
        "sqrt(Fx^2 + Fy^2) / (mu FN)",
    )
    .series(
        Series::line("Kalker linear (slope C11, C22, C23)", points(Method::Linear))
            .color(RIGID)
            .dashed(),
    )
    .series(Series::line("FASTSIM", points(Method::Fastsim)).color(LEFT))
    .series(Series::line("Polach", points(Method::Polach)).color(QE))
    .series(
        Series::line(
            "saturation mu FN",
            vec![(0.0, 1.0), (1e3 * curve.creepage[curve.creepage.len() - 1], 1.0)],
        )
        .color(BLACK)
        .dashed(),
    )
    .vline(1e3 * slip, "this patch in the sweep")
    .y_range(0.0, TOP);
    Figure::grid(
        format!(
            "Force against creepage: {} wheel at y_ws = {} mm, patch {}",
            curve.side.name(),
            wheelrail::message::Number(curve.y_ws),
            curve.patch
        ),
        vec![chart],
        1,
    )
    .size(1000, 700)
}
