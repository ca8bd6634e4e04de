//! The figure of the tradeoff study (`wheelrail tradeoff`).

use super::{LEFT, QE, RIGHT};
use crate::tradeoff::{ChartPoint, fastsim, pareto_indices};
use crate::{Chart, Figure, Series};

/// Height of the figure's two panels (pixels): taller than a default grid, so that the
/// numbers of clustered points find room.
const PANEL_HEIGHT_PX: u32 = 560;
/// Decades of the "exact" band at the foot of a panel with errors of exactly 0, and the
/// decades between it and the smallest error that is not 0.
const BAND_DECADES: f64 = 1.0;
const BAND_GAP_DECADES: f64 = 1.0;

/// The role of a point of a study chart: the project's default and the paper's choices
/// stand out in their own colours.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Role {
    Default,
    Paper,
    Other,
}

impl Role {
    /// The role of the point labelled `label`: `default` or a label ending in
    /// [`fastsim::DEFAULT_MARK`], `paper`, or another.
    fn of(label: &str) -> Role {
        if label == "default" || label.ends_with(fastsim::DEFAULT_MARK) {
            Role::Default
        } else if label == "paper" {
            Role::Paper
        } else {
            Role::Other
        }
    }
}

/// The words of a study chart: its title, time axis, the legend name of the points that are
/// neither default nor paper, and each panel's title and error axis.
struct Texts {
    title: &'static str,
    time_axis: &'static str,
    others: &'static str,
    panels: [(&'static str, &'static str); 2],
}

/// Run time against error (log-log), one panel for the contact position and one for the
/// ellipse: each setting a point numbered as in the key below the panels, the default and
/// the paper's settings in their own colours, the Pareto front as the staircase that
/// bounds what it dominates. Errors of exactly 0 (settings that reproduce the reference to
/// the last bit) are drawn in a shaded band "exact (0)" at the foot of the panel, below the
/// decades of the errors that are not.
pub(crate) fn tradeoff(points: &[ChartPoint]) -> Figure {
    let texts = Texts {
        title: "Run time against error: each point a setting, numbered as in the key below",
        time_axis: "median run time (ms, log)",
        others: "other settings",
        panels: [
            ("Contact position", "max rigid contact error (mm)"),
            ("Contact ellipse", "max relative error of a and b"),
        ],
    };
    study(points, &texts)
}

/// FASTSIM's grids as [`tradeoff`] draws the settings: run time of one patch against the
/// force and the spin-moment error, the default grid in its own colour.
pub(crate) fn fastsim_tradeoff(points: &[ChartPoint]) -> Figure {
    study(
        points,
        &Texts {
            title: "FASTSIM's grid (strips x elements): run time against error, numbered as in the key below",
            time_axis: "median run time of one patch (µs, log)",
            others: "other grids",
            panels: [
                ("Creep force", "max force error / (mu FN)"),
                ("Spin moment", "max spin-moment error / (mu FN c)"),
            ],
        },
    )
}

/// A study's figure: a panel of time against each of the points' two errors, as
/// [`tradeoff`] describes.
fn study(points: &[ChartPoint], texts: &Texts) -> Figure {
    let times: Vec<f64> = points.iter().map(|p| p.median).collect();
    let roles: Vec<Role> = points.iter().map(|p| Role::of(&p.label)).collect();
    let (t_lo, t_hi) = log_span(&times);
    let x_range = (t_lo / 1.3, t_hi * 1.3);
    let panel = |k: usize| {
        let (title, y_label) = texts.panels[k];
        let errors: Vec<f64> = points.iter().map(|p| p.errors[k]).collect();
        let nonzero: Vec<f64> = errors.iter().copied().filter(|e| *e > 0.0).collect();
        let (e_lo, e_hi) = log_span(&nonzero);
        let exact = errors.contains(&0.0);
        // The band's middle stands in for 0: the band lies BAND_GAP_DECADES below the
        // decade of the smallest error that is not 0.
        let band_top = 10f64.powf(e_lo.log10().floor() - BAND_GAP_DECADES);
        let band = (band_top / 10f64.powf(BAND_DECADES), band_top);
        let zero = (band.0 * band.1).sqrt();
        let y_range = (if exact { band.0 } else { e_lo / 3.0 }, e_hi * 3.0);
        // Errors not computed stay NaN: left out of the chart, not drawn as exact.
        let y = |e: f64| if e == 0.0 { zero } else { e };
        let at = |i: usize| (times[i], y(errors[i]));
        let front = pareto_indices(
            &times
                .iter()
                .copied()
                .zip(errors.iter().copied())
                .collect::<Vec<_>>(),
        );
        let pick = |role: Role| -> Vec<(f64, f64)> {
            (0..points.len())
                .filter(|&i| roles[i] == role)
                .map(at)
                .collect()
        };
        let mut chart = Chart::new(title, texts.time_axis, y_label)
            .series(
                Series::line("Pareto front", staircase(&front, &at, x_range, y_range)).color(QE),
            )
            .series(Series::markers(texts.others, pick(Role::Other)).color(6));
        // The highlighted roles that occur (FASTSIM's grids have no paper's).
        for (role, name, color) in [
            (Role::Default, "default", LEFT),
            (Role::Paper, "paper", RIGHT),
        ] {
            if roles.contains(&role) {
                chart = chart.series(Series::markers(name, pick(role)).color(color));
            }
        }
        chart = chart
            .x_range(x_range.0, x_range.1)
            .y_range(y_range.0, y_range.1)
            .x_log()
            .y_log();
        if exact {
            chart = chart.hband(band.0, band.1, "exact (0)");
        }
        for i in 0..points.len() {
            let (x, y) = at(i);
            chart = chart.label(x, y, format!("{}", i + 1));
        }
        chart
    };
    let figure = Figure::grid(texts.title, vec![panel(0), panel(1)], 2);
    let width = figure.width;
    figure.size(width, PANEL_HEIGHT_PX + 50).with_key(
        points
            .iter()
            .enumerate()
            .map(|(i, p)| format!("{}  {}", i + 1, p.label))
            .collect(),
    )
}

/// The smallest and largest of the positive finite `values` (1 and 10 without any).
fn log_span(values: &[f64]) -> (f64, f64) {
    let finite = values.iter().copied().filter(|v| v.is_finite() && *v > 0.0);
    let lo = finite.clone().fold(f64::INFINITY, f64::min);
    let hi = finite.fold(0.0, f64::max);
    if lo.is_finite() {
        (lo, hi)
    } else {
        (1.0, 10.0)
    }
}

/// The Pareto front of `front` (fastest first, errors falling; `at` gives a point) as the
/// staircase that bounds what it dominates: down from the top of the chart to the fastest
/// point, then across to each next point's time and down to its error, and across to the
/// right edge from the last.
fn staircase(
    front: &[usize],
    at: &dyn Fn(usize) -> (f64, f64),
    x_range: (f64, f64),
    y_range: (f64, f64),
) -> Vec<(f64, f64)> {
    let mut line = Vec::new();
    for (k, &i) in front.iter().enumerate() {
        let (t, e) = at(i);
        let above = if k == 0 {
            y_range.1
        } else {
            line.last().map_or(e, |p: &(f64, f64)| p.1)
        };
        line.push((t, above));
        line.push((t, e));
    }
    if let Some(&(_, e)) = line.last() {
        line.push((x_range.1, e));
    }
    line
}
