//! The figure of the tradeoff study (`wheelrail tradeoff`).

use super::{LEFT, QE, RIGHT};
use crate::report::{Chart, Figure, Series};

/// Run time against error (log-log): one point per setting, the Pareto front as a line, the
/// default and the paper's settings as their own series. Errors of exactly zero (the
/// reference's own settings) are drawn at 1e-17.
pub(crate) fn tradeoff(m: &[crate::tradeoff::Measurement]) -> Figure {
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
