//! Figures of the Hertz stage (paper Fig. 6) and of the accuracy of the paper's Hertz numerics.

use super::{LEFT, QE, RIGHT, SHIFT};
use crate::{Chart, Figure, LegendPosition, Series};
use wheelrail::hertz::accuracy::HertzAccuracy;

/// `(y_ws, f(ellipse))` of wheel `k` over a Hertz sweep, NaN where there is no ellipse.
fn ellipse_series(
    h: &[wheelrail::hertz::HertzPosition],
    k: usize,
    f: fn(&wheelrail::hertz::Ellipse) -> f64,
) -> Vec<(f64, f64)> {
    h.iter()
        .map(|p| (p.y_ws, p.sides[k].ellipse().map_or(f64::NAN, f)))
        .collect()
}

/// Semi-axes of the contact ellipses (paper Fig. 6).
pub(crate) fn semi_axes(h: &[wheelrail::hertz::HertzPosition]) -> Figure {
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
pub(crate) fn pressure(h: &[wheelrail::hertz::HertzPosition]) -> Figure {
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
pub(crate) fn hertz_accuracy(a: &HertzAccuracy) -> Figure {
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
