//! One chart in its cell: the title, the sizes of the plot and its axis areas, where the
//! legend goes, and the order things are drawn in.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::super::geometry::{AxisMap, Frame, axis_range, data_bounds, equalize};
use super::super::text::{Align, Place, TextMode, TextSpec, draw_text};
use super::super::ticks::Ticks;
use super::super::{Chart, ChartError, DrawOptions, PanelLayout, drawing_error};
use super::annotations::{draw_off_chart_marks, draw_vlines, off_chart_runs};
use super::axes::{build_context, draw_axes, draw_hbands};
use super::labels::{Label, draw_labels, lay_out};
use super::legend::LegendBox;
use super::occupancy::Occupancy;
use super::series::{self, Drawn, draw_series};
use super::{
    AXIS_TITLE_GAP_PX, AXIS_TITLE_PX, LEGEND_INSET_PX, PxRect, TICK_GAP_PX, TICK_PX, px_box,
};

const PANEL_TITLE_PX: f64 = 22.0;
/// Pixels per tick label the tick generator aims for, so labels never touch.
const X_TICK_SPACING_PX: f64 = 100.0;
const Y_TICK_SPACING_PX: f64 = 60.0;
/// Space around a panel's plot area.
const MARGIN_TOP: i32 = 12;
const MARGIN_RIGHT: i32 = 24;
const MARGIN_LEFT: i32 = 10;
const MARGIN_BOTTOM: i32 = 12;

const GRID_MAJOR: RGBColor = RGBColor(0xD0, 0xD0, 0xD0);
const GRID_MINOR: RGBColor = RGBColor(0xEE, 0xEE, 0xEE);

/// Where the parts of one panel go, decided before anything is drawn.
pub(super) struct PanelPlan {
    pub(super) frame: Frame,
    pub(super) x_ticks: Ticks,
    pub(super) y_ticks: Ticks,
    /// Width of the y tick label and title area left of the plot.
    y_area: i32,
    /// Extra space right of and below the plot (below the x-axis title) holding the legend
    /// when no place inside is free.
    legend_space: (i32, i32),
}

/// The sizes of one panel that hold whatever the ticks are: what its plans are made from.
struct Sizing<'a> {
    chart: &'a Chart,
    xmap: AxisMap,
    ymap: AxisMap,
    /// The axis ranges from the data and the chart's fixed ranges, before equal aspect.
    data_frame: Frame,
    /// Width and height of the panel's cell.
    cell: (i32, i32),
    /// Height of the panel title and its padding.
    title_band: i32,
    /// Height of the x tick label and title area below the plot.
    x_area: i32,
    tick_spec: TextSpec,
    axis_h: i32,
}

impl<'a> Sizing<'a> {
    fn new(chart: &'a Chart, cell: (i32, i32), title_band: i32) -> Sizing<'a> {
        let xmap = AxisMap { log: chart.x_log };
        let ymap = AxisMap { log: chart.y_log };
        let (bx, by) = data_bounds(chart, xmap, ymap);
        let data_frame = Frame {
            x: axis_range(chart.x_range, bx, xmap),
            y: axis_range(chart.y_range, by, ymap),
        };
        let tick_spec = TextSpec::new(TICK_PX);
        let axis_spec = TextSpec::new(AXIS_TITLE_PX);
        let tick_h = tick_spec.size("0").1;
        let axis_h = axis_spec.size("Ag").1;
        Sizing {
            chart,
            xmap,
            ymap,
            data_frame,
            cell,
            title_band,
            x_area: TICK_GAP_PX + tick_h + AXIS_TITLE_GAP_PX + axis_h,
            tick_spec,
            axis_h,
        }
    }

    /// Width of the y-axis area that holds `ticks`' widest label (or band label) and the
    /// axis title.
    fn y_area_for(&self, ticks: &Ticks) -> i32 {
        let widest = ticks
            .labels
            .iter()
            .chain(self.chart.hbands.iter().map(|b| &b.label))
            .map(|l| self.tick_spec.size(l).0)
            .max()
            .unwrap_or(0);
        TICK_GAP_PX + widest + AXIS_TITLE_GAP_PX + self.axis_h
    }

    /// Width and height of the plot in pixels.
    fn plot_size(&self, y_area: i32, (right, below): (i32, i32)) -> (u32, u32) {
        let (cw, ch) = self.cell;
        (
            (cw - MARGIN_LEFT - MARGIN_RIGHT - right - y_area).max(1) as u32,
            (ch - self.title_band - MARGIN_TOP - MARGIN_BOTTOM - below - self.x_area).max(1) as u32,
        )
    }

    /// The plan with `legend_space` given up to a legend outside the plot.
    ///
    /// The y tick labels set the width of the label area, which sets the plot size, which
    /// (with equal aspect) sets the ranges: one refinement pass is enough since labels change
    /// little.
    fn plan(&self, legend_space: (i32, i32)) -> PanelPlan {
        let (xmap, ymap) = (self.xmap, self.ymap);
        let mut frame = self.data_frame;
        let guess = make_ticks(frame.y, ymap.log, self.cell.1 as u32, Y_TICK_SPACING_PX);
        let mut y_area = self.y_area_for(&guess);
        if self.chart.equal_aspect && !xmap.log && !ymap.log {
            equalize(&mut frame, self.plot_size(y_area, legend_space));
        }
        let y_ticks = make_ticks(
            frame.y,
            ymap.log,
            self.plot_size(y_area, legend_space).1,
            Y_TICK_SPACING_PX,
        );
        y_area = y_area.max(self.y_area_for(&y_ticks));
        let (plot_w, _) = self.plot_size(y_area, legend_space);
        let x_ticks = make_ticks(frame.x, xmap.log, plot_w, X_TICK_SPACING_PX);
        PanelPlan {
            frame,
            x_ticks,
            y_ticks,
            y_area,
            legend_space,
        }
    }

    /// The plot's drawing area within `cell` under `plan`.
    fn plot_area<DB: DrawingBackend>(
        &self,
        cell: &DrawingArea<DB, Shift>,
        plan: &PanelPlan,
    ) -> DrawingArea<DB, Shift> {
        cell.margin(
            self.title_band + MARGIN_TOP,
            MARGIN_BOTTOM + plan.legend_space.1 + self.x_area,
            MARGIN_LEFT + plan.y_area,
            MARGIN_RIGHT + plan.legend_space.0,
        )
    }
}

/// Ticks over `(lo, hi)` for an axis of `px` pixels, about one per `spacing` pixels.
fn make_ticks((lo, hi): (f64, f64), log: bool, px: u32, spacing: f64) -> Ticks {
    let max_ticks = ((f64::from(px) / spacing).floor() as usize).max(2);
    if log {
        Ticks::log(lo, hi, max_ticks)
    } else {
        Ticks::linear(lo, hi, max_ticks)
    }
}

/// Draws one chart in its cell of the figure.
pub(super) fn draw_panel<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    cell: &DrawingArea<DB, Shift>,
    chart: &Chart,
    options: DrawOptions,
) -> Result<PanelLayout, ChartError> {
    let mode = options.mode;
    let (cw, ch) = cell.dim_in_pixel();
    let title_band = draw_title(root, cell, chart, mode)?;
    let sizing = Sizing::new(chart, (cw as i32, ch as i32), title_band);
    let (xmap, ymap) = (sizing.xmap, sizing.ymap);

    let first = sizing.plan((0, 0));
    let off_chart = off_chart_runs(chart, xmap, ymap, &first.frame);
    let legend = LegendBox::of(chart, xmap, ymap, &off_chart);
    let Placed {
        plan,
        plot,
        legend_rect,
        labels,
        drawn,
    } = place_legend(cell, &sizing, first, &legend)?;
    let mut ctx = build_context(&sizing.plot_area(cell, &plan), &plan)?;
    let frame = plan.frame;
    ctx.configure_mesh()
        .bold_line_style(GRID_MAJOR.stroke_width(1))
        .light_line_style(GRID_MINOR.stroke_width(1))
        .disable_axes()
        .draw()
        .map_err(drawing_error)?;
    draw_hbands(&mut ctx, chart, ymap, &frame)?;
    draw_vlines(&mut ctx, chart, xmap, &frame)?;
    for (i, (series, drawn)) in chart.series.iter().zip(drawn).enumerate() {
        draw_series(&mut ctx, series, i, drawn)?;
    }
    draw_off_chart_marks(root, &ctx, chart, &off_chart, &frame, plot)?;
    root.draw(&Rectangle::new(
        [(plot.0, plot.1), (plot.2, plot.3)],
        BLACK.stroke_width(1),
    ))
    .map_err(drawing_error)?;

    draw_axes(root, &ctx, chart, plot, &frame, mode, plan.y_area)?;
    if options.legends {
        draw_labels(root, &labels, mode)?;
        if let Some(rect) = legend_rect {
            legend.draw(root, chart, rect, mode)?;
        }
    }
    Ok(PanelLayout {
        plot: px_box(plot),
        legend: legend_rect.map(px_box),
        legend_outside: plan.legend_space != (0, 0),
        off_chart: off_chart.len(),
        labels: labels.iter().map(|l| px_box(l.rect)).collect(),
    })
}

/// Draws the chart's title at the top of its cell; the height it takes.
fn draw_title<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    cell: &DrawingArea<DB, Shift>,
    chart: &Chart,
    mode: TextMode,
) -> Result<i32, ChartError> {
    if chart.title.is_empty() {
        return Ok(0);
    }
    let (cx, cy) = cell.get_base_pixel();
    let (cw, _) = cell.dim_in_pixel();
    let title_spec = TextSpec::new(PANEL_TITLE_PX);
    let pad = (0.5 * PANEL_TITLE_PX) as i32;
    draw_text(
        root,
        mode,
        &chart.title,
        title_spec,
        Place::new((cx + cw as i32 / 2, cy + pad), Align::Middle, Align::Start),
    )?;
    Ok(pad + title_spec.size(&chart.title).1)
}

/// Where the legend and the labels go, from [`place_legend`].
struct Placed {
    /// The plan (which gives up room outside the plot when no place inside is free for the
    /// legend).
    plan: PanelPlan,
    /// The plot's pixel box.
    plot: PxRect,
    /// The legend's pixel box, `None` with nothing to show.
    legend_rect: Option<PxRect>,
    /// The labels, placed first, in the final plot.
    labels: Vec<Label>,
    /// What each series draws in the final plot: thinned once, for the labels' grid and for
    /// drawing.
    drawn: Vec<Drawn>,
}

/// Where the legend and the labels go: see [`Placed`].
fn place_legend<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    sizing: &Sizing<'_>,
    mut plan: PanelPlan,
    legend: &LegendBox,
) -> Result<Placed, ChartError> {
    let (cx, _) = cell.get_base_pixel();
    let (cw, _) = sizing.cell;
    let (chart, xmap, ymap) = (sizing.chart, sizing.xmap, sizing.ymap);
    for attempt in 0..2 {
        let plot_area = sizing.plot_area(cell, &plan);
        let ctx = build_context(&plot_area, &plan)?;
        let (w, h) = sizing.plot_size(plan.y_area, plan.legend_space);
        let (left, top) = plot_area.get_base_pixel();
        let plot: PxRect = (left, top, left + w as i32, top + h as i32);
        let drawn: Vec<Drawn> = chart
            .series
            .iter()
            .map(|s| series::drawn(s, xmap, ymap, &plan.frame, |p| ctx.backend_coord(&p)))
            .collect();
        let (labels, grid) = lay_out(chart, &drawn, &ctx, xmap, ymap, &plan.frame, plot);
        let Some(size) = legend.size() else {
            return Ok(Placed {
                plan,
                plot,
                legend_rect: None,
                labels,
                drawn,
            });
        };
        let spot = if attempt == 0 {
            Occupancy::of(&grid).free_spot(plot, size, chart.legend)
        } else if plan.legend_space.0 > 0 {
            // Outside, right of the plot, level with its top.
            Some((plot.2 + LEGEND_INSET_PX, plot.1))
        } else {
            // Outside, below the x-axis title, centred under the plot.
            let left = ((plot.0 + plot.2 - size.0) / 2).max(cx + MARGIN_LEFT);
            Some((left, plot.3 + sizing.x_area + LEGEND_INSET_PX / 2))
        };
        if let Some(at) = spot {
            let rect = (at.0, at.1, at.0 + size.0, at.1 + size.1);
            return Ok(Placed {
                plan,
                plot,
                legend_rect: Some(rect),
                labels,
                drawn,
            });
        }
        // Outside where it costs the plot the smaller share of its width or height.
        let (w, h) = (f64::from(w), f64::from(h));
        let right = f64::from(size.0 + LEGEND_INSET_PX) / w;
        let below = f64::from(size.1 + LEGEND_INSET_PX) / h;
        let fits_below = size.0 <= cw - MARGIN_LEFT - MARGIN_RIGHT;
        plan = if fits_below && below < right {
            sizing.plan((0, size.1 + LEGEND_INSET_PX))
        } else {
            sizing.plan((size.0 + LEGEND_INSET_PX, 0))
        };
    }
    unreachable!("the second attempt always places the legend")
}
