//! The coordinate system of a plot: plotters' cartesian axes over our own ticks, and the tick
//! marks, tick labels and axis titles drawn around the plot.

use plotters::coord::Shift;
use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, ValueFormatter};
use plotters::prelude::*;

use super::super::geometry::{AxisMap, Frame};
use super::super::text::{Align, Place, TextMode, TextSpec, draw_text};
use super::super::ticks::Ticks;
use super::super::{Chart, ChartError, HBand, drawing_error};
use super::panel::PanelPlan;
use super::{AXIS_TITLE_GAP_PX, AXIS_TITLE_PX, Ctx, PxRect, TICK_GAP_PX, TICK_PX};

pub(super) fn build_context<'a, DB: DrawingBackend>(
    plot_area: &DrawingArea<DB, Shift>,
    plan: &PanelPlan,
) -> Result<Ctx<'a, DB>, ChartError> {
    ChartBuilder::on(plot_area)
        .build_cartesian_2d(
            TickAxis {
                range: plan.frame.x,
                ticks: plan.x_ticks.clone(),
            },
            TickAxis {
                range: plan.frame.y,
                ticks: plan.y_ticks.clone(),
            },
        )
        .map_err(drawing_error)
}

/// A linear axis over `range` (transformed units) with our own ticks and labels.
pub(super) struct TickAxis {
    range: (f64, f64),
    ticks: Ticks,
}

impl Ranged for TickAxis {
    type FormatOption = NoDefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.range.0) / (self.range.1 - self.range.0);
        let px = f64::from(limit.0) + t * f64::from(limit.1 - limit.0);
        // Clipping keeps drawn data inside; the clamp only guards the cast.
        px.round().clamp(-1e6, 1e6) as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.ticks.minor.clone()
        } else {
            self.ticks.major.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.range.0..self.range.1
    }
}

impl ValueFormatter<f64> for TickAxis {
    fn format(value: &f64) -> String {
        format!("{value}")
    }

    fn format_ext(&self, value: &f64) -> String {
        self.ticks.label(*value)
    }
}

/// The fill of a horizontal band: a light grey, between the grid's two greys.
const BAND: RGBColor = RGBColor(0xE6, 0xE6, 0xE6);

/// The band `b` on the y axis in transformed units, clipped to the frame; `None` where
/// nothing of it is within the frame.
fn band_span(b: &HBand, ymap: AxisMap, frame: &Frame) -> Option<(f64, f64)> {
    let (lo, hi) = (ymap.forward(b.from), ymap.forward(b.to));
    let (lo, hi) = (lo.min(hi).max(frame.y.0), hi.max(lo).min(frame.y.1));
    (lo.is_finite() && hi.is_finite() && lo < hi).then_some((lo, hi))
}

/// The chart's bands in pixel rows `(top, bottom)` of the plot, clipped to the frame, with
/// their labels.
fn band_rows<'c, DB: DrawingBackend>(
    ctx: &Ctx<'_, DB>,
    chart: &'c Chart,
    ymap: AxisMap,
    frame: &Frame,
) -> Vec<(i32, i32, &'c str)> {
    chart
        .hbands
        .iter()
        .filter_map(|b| {
            band_span(b, ymap, frame).map(|(lo, hi)| {
                let (_, top) = ctx.backend_coord(&(frame.x.0, hi));
                let (_, bottom) = ctx.backend_coord(&(frame.x.0, lo));
                (top, bottom, b.label.as_str())
            })
        })
        .collect()
}

/// The shaded horizontal bands across the plot.
pub(super) fn draw_hbands<DB: DrawingBackend>(
    ctx: &mut Ctx<'_, DB>,
    chart: &Chart,
    ymap: AxisMap,
    frame: &Frame,
) -> Result<(), ChartError> {
    for (lo, hi) in chart
        .hbands
        .iter()
        .filter_map(|b| band_span(b, ymap, frame))
    {
        ctx.draw_series(std::iter::once(Rectangle::new(
            [(frame.x.0, lo), (frame.x.1, hi)],
            BAND.filled(),
        )))
        .map_err(drawing_error)?;
    }
    Ok(())
}

/// Tick marks, tick labels and axis titles. A band's label stands at the y axis level
/// with its middle, in place of the tick labels that would meet it.
pub(super) fn draw_axes<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    ctx: &Ctx<'_, DB>,
    chart: &Chart,
    plot: PxRect,
    frame: &Frame,
    mode: TextMode,
    y_area: i32,
) -> Result<(), ChartError> {
    let tick_spec = TextSpec::new(TICK_PX);
    let axis_spec = TextSpec::new(AXIS_TITLE_PX);
    let tick_len = 5;
    let x_axis = &ctx.as_coord_spec().x_spec();
    let y_axis = &ctx.as_coord_spec().y_spec();
    for (&v, label) in x_axis.ticks.major.iter().zip(&x_axis.ticks.labels) {
        let (px, _) = ctx.backend_coord(&(v, frame.y.0));
        root.draw(&PathElement::new(
            vec![(px, plot.3), (px, plot.3 + tick_len)],
            BLACK.stroke_width(1),
        ))
        .map_err(drawing_error)?;
        let place = Place::new((px, plot.3 + TICK_GAP_PX), Align::Middle, Align::Start);
        draw_text(root, mode, label, tick_spec, place)?;
    }
    let tick_h = tick_spec.size("0").1;
    let bands = band_rows(ctx, chart, AxisMap { log: chart.y_log }, frame);
    let mut y_labels: Vec<(i32, &str)> = y_axis
        .ticks
        .major
        .iter()
        .zip(&y_axis.ticks.labels)
        .map(|(&v, label)| (ctx.backend_coord(&(frame.x.0, v)).1, label.as_str()))
        .filter(|&(py, _)| {
            bands
                .iter()
                .all(|&(top, bottom, _)| py + tick_h < top || py - tick_h > bottom)
        })
        .collect();
    y_labels.extend(
        bands
            .iter()
            .filter(|b| !b.2.is_empty())
            .map(|&(top, bottom, label)| ((top + bottom) / 2, label)),
    );
    for (py, label) in y_labels {
        root.draw(&PathElement::new(
            vec![(plot.0 - tick_len, py), (plot.0, py)],
            BLACK.stroke_width(1),
        ))
        .map_err(drawing_error)?;
        let place = Place::new((plot.0 - TICK_GAP_PX, py), Align::End, Align::Middle);
        draw_text(root, mode, label, tick_spec, place)?;
    }
    let x_title_top = plot.3 + TICK_GAP_PX + tick_h + AXIS_TITLE_GAP_PX;
    let centre_x = (plot.0 + plot.2) / 2;
    let place = Place::new((centre_x, x_title_top), Align::Middle, Align::Start);
    draw_text(root, mode, &chart.x_label, axis_spec, place)?;
    let y_title_left = plot.0 - y_area;
    let place = Place::new(
        (y_title_left, (plot.1 + plot.3) / 2),
        Align::Middle,
        Align::Start,
    );
    draw_text(root, mode, &chart.y_label, axis_spec, place.upwards())
}
