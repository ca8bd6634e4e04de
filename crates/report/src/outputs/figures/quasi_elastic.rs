//! Figures of the quasi-elastic contact search (paper Figs. 4 and 5) and its sensitivity to eps.

use super::rigid::{contact_links, left_contacts, map_chart, rigid_series, with_onsets};
use super::{QE, RIGID, SHIFT};
use crate::{Chart, Figure, Series};
use wheelrail::pipeline::EpsilonSweeps;
use wheelrail::quasi_elastic::QuasiElasticSweep;
use wheelrail::rigid::RigidSweep;
use wheelrail::track::{Placement, Side};

/// The heaviest quasi-elastic patch moving farther than this between neighbouring
/// positions has changed identity (another patch took over the weight): the line breaks
/// there. Within a patch, locations move at most ~1 mm per 0.1 mm of shift (measured in
/// `tests/quasi_elastic.rs`).
const PATCH_SWITCH_MM: f64 = 1.5;

/// `(y_ws, s)` of the heaviest quasi-elastic patch of wheel `k`, broken where another patch
/// takes over.
fn heaviest_patch_series(q: &QuasiElasticSweep, k: usize) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(q.positions().len());
    for p in q.positions() {
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

/// Rigid against quasi-elastic contact points (paper Fig. 4).
pub(crate) fn quasi_elastic_points(sweep: &RigidSweep, q: &QuasiElasticSweep) -> Figure {
    let panel = |side: Side, k: usize| {
        let main = heaviest_patch_series(q, k);
        let second: Vec<(f64, f64)> = q
            .positions()
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
            q.settings().epsilon_mm()
        ),
        vec![panel(Side::Left, 0), panel(Side::Right, 1)],
        2,
    )
}

/// Contact map with rigid and quasi-elastic points (paper Fig. 5).
pub(crate) fn quasi_elastic_map(
    placement: &Placement,
    sweep: &RigidSweep,
    q: &QuasiElasticSweep,
) -> Figure {
    let rigid = left_contacts(sweep);
    let qe: Vec<(f64, f64, f64)> = q
        .positions()
        .iter()
        .filter_map(|p| p.sides[0].main().map(|c| (c.s, c.y, c.z)))
        .collect();
    Figure::single(
        map_chart(
            placement,
            &format!(
                "Contact map: rigid and quasi-elastic (eps = {} mm), left wheel",
                q.settings().epsilon_mm()
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
pub(crate) fn epsilon_sensitivity(sweep: &RigidSweep, e: &EpsilonSweeps) -> Figure {
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
