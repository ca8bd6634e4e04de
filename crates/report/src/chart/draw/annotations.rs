//! What the plot says besides its data: vertical marker lines (their labels are placed in
//! `labels`), and the marks and legend note where data leaves the chart.

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::super::geometry::{AxisMap, Frame};
use super::super::text::TextSpec;
use super::super::{Chart, ChartError, drawing_error};
use super::series::Look;
use super::{ANNOTATION, Ctx, OFF_CHART_MARK_PX, PxRect};

const VLINE_PX: f64 = 14.0;

/// A run of consecutive points of one series that lie within the x range but above
/// (`above`) or below the y range: where a curve leaves the chart.
#[derive(Debug, Clone, Copy)]
pub(super) struct OffChart {
    pub(super) series: usize,
    /// x where the run leaves the chart (or comes back, for a run that starts the series
    /// or follows a gap), in transformed units.
    pub(super) x: f64,
    /// The run's most extreme y value (transformed units).
    pub(super) y: f64,
    pub(super) above: bool,
}

pub(super) fn off_chart_runs(
    chart: &Chart,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
) -> Vec<OffChart> {
    let mut runs: Vec<OffChart> = Vec::new();
    for (i, s) in chart.series.iter().enumerate() {
        // Whether the previous point is off the chart, and on the chart.
        let (mut open, mut after_inside) = (false, false);
        // The open run started right after a point on the chart: its mark stays where it
        // left; otherwise the mark follows the run to where it comes back.
        let mut exit_known = false;
        for &(x, y) in &s.points {
            let (x, y) = (xmap.forward(x), ymap.forward(y));
            let inside_x = x.is_finite() && x >= frame.x.0 && x <= frame.x.1;
            let side = if !(inside_x && y.is_finite()) {
                None
            } else if y > frame.y.1 {
                Some(true)
            } else if y < frame.y.0 {
                Some(false)
            } else {
                None
            };
            match (side, runs.last_mut()) {
                (Some(above), Some(last)) if open && last.above == above => {
                    if (above && y > last.y) || (!above && y < last.y) {
                        last.y = y;
                    }
                    if !exit_known {
                        last.x = x;
                    }
                }
                (Some(above), _) => {
                    exit_known = after_inside;
                    runs.push(OffChart {
                        series: i,
                        x,
                        y,
                        above,
                    });
                }
                (None, _) => {}
            }
            open = side.is_some();
            after_inside = inside_x && y.is_finite() && side.is_none();
        }
    }
    runs
}

/// The legend note on values left off the chart: how far they reach.
pub(super) fn off_chart_note(runs: &[OffChart], ymap: AxisMap) -> Option<String> {
    let value = |y: f64| {
        let v = if ymap.log { 10f64.powf(y) } else { y };
        // Four significant digits, trailing zeros dropped.
        let (mantissa, exponent) = if v.abs() >= 1e-3 && v.abs() < 1e5 {
            let decimals = (3 - v.abs().log10().floor() as i32).max(0) as usize;
            (format!("{v:.decimals$}"), String::new())
        } else {
            let text = format!("{v:.3e}");
            let (m, e) = text.split_once('e').unwrap_or((&text, ""));
            (m.to_owned(), format!("e{e}"))
        };
        let mantissa = if mantissa.contains('.') {
            mantissa
                .trim_end_matches('0')
                .trim_end_matches('.')
                .to_owned()
        } else {
            mantissa
        };
        format!("{mantissa}{exponent}")
    };
    let high = runs
        .iter()
        .filter(|r| r.above)
        .map(|r| r.y)
        .reduce(f64::max);
    let low = runs
        .iter()
        .filter(|r| !r.above)
        .map(|r| r.y)
        .reduce(f64::min);
    let parts: Vec<String> = [
        high.map(|h| format!("▲ up to {}", value(h))),
        low.map(|l| format!("▼ down to {}", value(l))),
    ]
    .into_iter()
    .flatten()
    .collect();
    (!parts.is_empty()).then(|| format!("off the chart: {}", parts.join(", ")))
}

/// A triangle at the frame edge above or below where each run leaves, in its series' colour.
pub(super) fn draw_off_chart_marks<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    ctx: &Ctx<'_, DB>,
    chart: &Chart,
    runs: &[OffChart],
    frame: &Frame,
    plot: PxRect,
) -> Result<(), ChartError> {
    for r in runs {
        let (px, _) = ctx.backend_coord(&(r.x, frame.y.0));
        let color = Look::of(&chart.series[r.series], r.series).color;
        let s = OFF_CHART_MARK_PX;
        let points = if r.above {
            vec![
                (px, plot.1 + 1),
                (px - s, plot.1 + 1 + 2 * s),
                (px + s, plot.1 + 1 + 2 * s),
            ]
        } else {
            vec![
                (px, plot.3 - 1),
                (px - s, plot.3 - 1 - 2 * s),
                (px + s, plot.3 - 1 - 2 * s),
            ]
        };
        root.draw(&Polygon::new(points, color.filled()))
            .map_err(drawing_error)?;
    }
    Ok(())
}

pub(super) fn vline_spec() -> TextSpec {
    TextSpec::new(VLINE_PX).color(ANNOTATION)
}

/// Dashed vertical marker lines across the plot, where they fall within the x range.
pub(super) fn draw_vlines<DB: DrawingBackend>(
    ctx: &mut Ctx<'_, DB>,
    chart: &Chart,
    xmap: AxisMap,
    frame: &Frame,
) -> Result<(), ChartError> {
    for vline in &chart.vlines {
        let x = xmap.forward(vline.x);
        if x.is_finite() && x >= frame.x.0 && x <= frame.x.1 {
            ctx.draw_series(std::iter::once(DashedPathElement::new(
                vec![(x, frame.y.0), (x, frame.y.1)],
                6,
                4,
                ANNOTATION.stroke_width(1),
            )))
            .map_err(drawing_error)?;
        }
    }
    Ok(())
}
