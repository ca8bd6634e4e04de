//! Drawing a [`Figure`] on any plotters backend.
//!
//! plotters draws the grid, ticks, frame and data; all text (titles, tick labels, axis titles,
//! legend, marker-line labels) goes through [`text::draw_text`] so bitmaps get correctly spaced
//! glyphs. The legend is our own so that its box can be placed where it hides no data: an
//! occupancy grid of everything drawn in the plot (lines, markers, marker lines and their
//! labels, off-chart marks) finds a free place nearest a corner, and when there is none the
//! plot gives up room for it, right of it or below the x-axis title, whichever takes the
//! smaller share of the plot.

use plotters::coord::Shift;
use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, ValueFormatter};
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::geometry::{AxisMap, Frame, Point, axis_range, data_bounds, equalize, polylines};
use super::text::{Align, Place, TextMode, TextSpec, draw_text};
use super::ticks::Ticks;
use super::{Chart, ChartError, Figure, LegendPosition, MarkerShape, Series, SeriesStyle};
use super::{DrawOptions, PanelLayout, PxBox};
use super::{PALETTE, drawing_error, ensure_font};

const FIGURE_TITLE_PX: f64 = 28.0;
const PANEL_TITLE_PX: f64 = 22.0;
const AXIS_TITLE_PX: f64 = 19.0;
const TICK_PX: f64 = 16.0;
const LEGEND_PX: f64 = 16.0;
const VLINE_PX: f64 = 14.0;
const LINE_WIDTH: u32 = 2;
const MARKER_PX: i32 = 5;
/// Pixels per tick label the tick generator aims for, so labels never touch.
const X_TICK_SPACING_PX: f64 = 100.0;
const Y_TICK_SPACING_PX: f64 = 60.0;
/// Gap between an axis and its tick labels, and between tick labels and the axis title.
const TICK_GAP_PX: i32 = 8;
const AXIS_TITLE_GAP_PX: i32 = 10;
/// Space around a panel's plot area.
const MARGIN_TOP: i32 = 12;
const MARGIN_RIGHT: i32 = 24;
const MARGIN_LEFT: i32 = 10;
const MARGIN_BOTTOM: i32 = 12;
/// Legend: length of the line sample, inner padding, row height factor, inset from the frame.
const LEGEND_GLYPH_PX: i32 = 30;
const LEGEND_PAD_PX: i32 = 8;
const LEGEND_ROW: f64 = 1.35;
const LEGEND_INSET_PX: i32 = 8;
/// Least distance in pixels between a legend and anything drawn in the plot.
const LEGEND_CLEARANCE_PX: i32 = 4;
/// Cell size in pixels of the occupancy grid that places legends.
const OCCUPANCY_CELL_PX: i32 = 6;
/// Spacing in pixels of the samples that mark a line in the occupancy grid.
const SEGMENT_SAMPLE_PX: f64 = 3.0;
/// Half width in pixels of the triangles that mark where data leaves the chart.
const OFF_CHART_MARK_PX: i32 = 5;

const GRID_MAJOR: RGBColor = RGBColor(0xD0, 0xD0, 0xD0);
const GRID_MINOR: RGBColor = RGBColor(0xEE, 0xEE, 0xEE);
const ANNOTATION: RGBColor = RGBColor(0x44, 0x44, 0x44);

fn palette(index: usize) -> RGBColor {
    let (r, g, b) = PALETTE[index % PALETTE.len()];
    RGBColor(r, g, b)
}

/// Draws the whole figure on `root`.
pub(super) fn draw_figure<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    figure: &Figure,
    options: DrawOptions,
) -> Result<Vec<PanelLayout>, ChartError> {
    let mode = options.mode;
    ensure_font()?;
    root.fill(&WHITE).map_err(drawing_error)?;
    let mut top = 0;
    if !figure.title.is_empty() {
        let spec = TextSpec::new(FIGURE_TITLE_PX);
        let pad = (0.4 * FIGURE_TITLE_PX) as i32;
        let centre = (figure.width / 2) as i32;
        draw_text(
            root,
            mode,
            &figure.title,
            spec,
            Place::new((centre, pad), Align::Middle, Align::Start),
        )?;
        top = 2 * pad + spec.size(&figure.title).1;
    }
    if figure.panels.is_empty() {
        return Ok(Vec::new());
    }
    let body = root.margin(top, 0, 0, 0);
    let columns = figure.columns.min(figure.panels.len());
    let rows = figure.panels.len().div_ceil(columns);
    let cells = body.split_evenly((rows, columns));
    figure
        .panels
        .iter()
        .zip(&cells)
        .map(|(chart, cell)| draw_panel(root, cell, chart, options))
        .collect()
}

/// Pixel rectangle `(left, top, right, bottom)` in root coordinates.
type PxRect = (i32, i32, i32, i32);

/// Where the parts of one panel go, decided before anything is drawn.
struct PanelPlan {
    frame: Frame,
    x_ticks: Ticks,
    y_ticks: Ticks,
    /// Width of the y tick label and title area left of the plot.
    y_area: i32,
    /// Extra space right of and below the plot (below the x-axis title) holding the legend
    /// when no place inside is free.
    legend_space: (i32, i32),
}

fn draw_panel<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    cell: &DrawingArea<DB, Shift>,
    chart: &Chart,
    options: DrawOptions,
) -> Result<PanelLayout, ChartError> {
    let mode = options.mode;
    let (cx, cy) = cell.get_base_pixel();
    let (cw, ch) = cell.dim_in_pixel();
    let (cw, ch) = (cw as i32, ch as i32);

    let title_spec = TextSpec::new(PANEL_TITLE_PX);
    let title_band = if chart.title.is_empty() {
        0
    } else {
        let pad = (0.5 * PANEL_TITLE_PX) as i32;
        draw_text(
            root,
            mode,
            &chart.title,
            title_spec,
            Place::new((cx + cw / 2, cy + pad), Align::Middle, Align::Start),
        )?;
        pad + title_spec.size(&chart.title).1
    };

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
    let x_area = TICK_GAP_PX + tick_h + AXIS_TITLE_GAP_PX + axis_h;
    let y_area_for = |ticks: &Ticks| {
        let widest = ticks
            .labels
            .iter()
            .map(|l| tick_spec.size(l).0)
            .max()
            .unwrap_or(0);
        TICK_GAP_PX + widest + AXIS_TITLE_GAP_PX + axis_h
    };
    let plot_size = |y_area: i32, (right, below): (i32, i32)| {
        (
            (cw - MARGIN_LEFT - MARGIN_RIGHT - right - y_area).max(1) as u32,
            (ch - title_band - MARGIN_TOP - MARGIN_BOTTOM - below - x_area).max(1) as u32,
        )
    };
    let make_ticks = |(lo, hi): (f64, f64), log: bool, px: u32, spacing: f64| {
        let max_ticks = ((f64::from(px) / spacing).floor() as usize).max(2);
        if log {
            Ticks::log(lo, hi, max_ticks)
        } else {
            Ticks::linear(lo, hi, max_ticks)
        }
    };
    // The y tick labels set the width of the label area, which sets the plot size, which (with
    // equal aspect) sets the ranges: one refinement pass is enough since labels change little.
    let plan_for = |legend_space: (i32, i32)| {
        let mut frame = data_frame;
        let guess = make_ticks(frame.y, ymap.log, ch as u32, Y_TICK_SPACING_PX);
        let mut y_area = y_area_for(&guess);
        if chart.equal_aspect && !xmap.log && !ymap.log {
            equalize(&mut frame, plot_size(y_area, legend_space));
        }
        let y_ticks = make_ticks(
            frame.y,
            ymap.log,
            plot_size(y_area, legend_space).1,
            Y_TICK_SPACING_PX,
        );
        y_area = y_area.max(y_area_for(&y_ticks));
        let (plot_w, _) = plot_size(y_area, legend_space);
        let x_ticks = make_ticks(frame.x, xmap.log, plot_w, X_TICK_SPACING_PX);
        PanelPlan {
            frame,
            x_ticks,
            y_ticks,
            y_area,
            legend_space,
        }
    };

    let mut plan = plan_for((0, 0));
    let off_chart = off_chart_runs(chart, xmap, ymap, &plan.frame);
    let legend = LegendBox::of(chart, xmap, ymap, &off_chart);
    let mut placed = None;
    for attempt in 0..2 {
        let plot_area = cell.margin(
            title_band + MARGIN_TOP,
            MARGIN_BOTTOM + plan.legend_space.1 + x_area,
            MARGIN_LEFT + plan.y_area,
            MARGIN_RIGHT + plan.legend_space.0,
        );
        let ctx = build_context(&plot_area, &plan)?;
        let (w, h) = plot_size(plan.y_area, plan.legend_space);
        let (left, top) = plot_area.get_base_pixel();
        let plot: PxRect = (left, top, left + w as i32, top + h as i32);
        let Some(size) = legend.size() else {
            placed = Some((plot, None));
            break;
        };
        let spot = if attempt == 0 {
            let grid = Occupancy::of(chart, &ctx, xmap, ymap, &plan.frame, plot);
            grid.free_spot(plot, size, chart.legend)
        } else if plan.legend_space.0 > 0 {
            // Outside, right of the plot, level with its top.
            Some((plot.2 + LEGEND_INSET_PX, plot.1))
        } else {
            // Outside, below the x-axis title, centred under the plot.
            let left = ((plot.0 + plot.2 - size.0) / 2).max(cx + MARGIN_LEFT);
            Some((left, plot.3 + x_area + LEGEND_INSET_PX / 2))
        };
        match spot {
            Some(at) => {
                placed = Some((plot, Some((at.0, at.1, at.0 + size.0, at.1 + size.1))));
                break;
            }
            None => {
                // Outside where it costs the plot the smaller share of its width or height.
                let (w, h) = (f64::from(w), f64::from(h));
                let right = f64::from(size.0 + LEGEND_INSET_PX) / w;
                let below = f64::from(size.1 + LEGEND_INSET_PX) / h;
                let fits_below = size.0 <= cw - MARGIN_LEFT - MARGIN_RIGHT;
                plan = if fits_below && below < right {
                    plan_for((0, size.1 + LEGEND_INSET_PX))
                } else {
                    plan_for((size.0 + LEGEND_INSET_PX, 0))
                };
            }
        }
    }
    let (plot, legend_rect) = placed.expect("the second attempt always places the legend");
    let plot_area = cell.margin(
        title_band + MARGIN_TOP,
        MARGIN_BOTTOM + plan.legend_space.1 + x_area,
        MARGIN_LEFT + plan.y_area,
        MARGIN_RIGHT + plan.legend_space.0,
    );
    let mut ctx = build_context(&plot_area, &plan)?;
    let frame = plan.frame;
    ctx.configure_mesh()
        .bold_line_style(GRID_MAJOR.stroke_width(1))
        .light_line_style(GRID_MINOR.stroke_width(1))
        .disable_axes()
        .draw()
        .map_err(drawing_error)?;

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
    for (i, series) in chart.series.iter().enumerate() {
        draw_series(&mut ctx, series, i, xmap, ymap, &frame)?;
    }
    draw_off_chart_marks(root, &ctx, chart, &off_chart, &frame, plot)?;
    root.draw(&Rectangle::new(
        [(plot.0, plot.1), (plot.2, plot.3)],
        BLACK.stroke_width(1),
    ))
    .map_err(drawing_error)?;

    draw_axes(root, &ctx, chart, plot, &frame, mode, (cx, plan.y_area))?;
    let labels = vline_labels(&ctx, chart, xmap, &frame, plot);
    for (label, place, _) in &labels {
        draw_text(root, mode, label, vline_spec(), *place)?;
    }
    if let Some(rect) = legend_rect
        && options.legends
    {
        legend.draw(root, chart, rect, mode)?;
    }
    Ok(PanelLayout {
        plot: px_box(plot),
        legend: legend_rect.map(px_box),
        legend_outside: plan.legend_space != (0, 0),
        off_chart: off_chart.len(),
    })
}

fn px_box((left, top, right, bottom): PxRect) -> PxBox {
    PxBox {
        left,
        top,
        right,
        bottom,
    }
}

fn build_context<'a, DB: DrawingBackend>(
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

/// A run of consecutive points of one series that lie within the x range but above
/// (`above`) or below the y range: where a curve leaves the chart.
#[derive(Debug, Clone, Copy)]
struct OffChart {
    series: usize,
    /// x where the run leaves the chart (or comes back, for a run that starts the series
    /// or follows a gap), in transformed units.
    x: f64,
    /// The run's most extreme y value (transformed units).
    y: f64,
    above: bool,
}

fn off_chart_runs(chart: &Chart, xmap: AxisMap, ymap: AxisMap, frame: &Frame) -> Vec<OffChart> {
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
fn off_chart_note(runs: &[OffChart], ymap: AxisMap) -> Option<String> {
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
fn draw_off_chart_marks<DB: DrawingBackend>(
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

type Ctx<'a, DB> = ChartContext<'a, DB, Cartesian2d<TickAxis, TickAxis>>;

/// Tick marks, tick labels and axis titles.
fn draw_axes<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    ctx: &Ctx<'_, DB>,
    chart: &Chart,
    plot: PxRect,
    frame: &Frame,
    mode: TextMode,
    (cell_left, y_area): (i32, i32),
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
    for (&v, label) in y_axis.ticks.major.iter().zip(&y_axis.ticks.labels) {
        let (_, py) = ctx.backend_coord(&(frame.x.0, v));
        root.draw(&PathElement::new(
            vec![(plot.0 - tick_len, py), (plot.0, py)],
            BLACK.stroke_width(1),
        ))
        .map_err(drawing_error)?;
        let place = Place::new((plot.0 - TICK_GAP_PX, py), Align::End, Align::Middle);
        draw_text(root, mode, label, tick_spec, place)?;
    }
    let tick_h = tick_spec.size("0").1;
    let x_title_top = plot.3 + TICK_GAP_PX + tick_h + AXIS_TITLE_GAP_PX;
    let centre_x = (plot.0 + plot.2) / 2;
    let place = Place::new((centre_x, x_title_top), Align::Middle, Align::Start);
    draw_text(root, mode, &chart.x_label, axis_spec, place)?;
    let y_title_left = plot.0 - y_area;
    let _ = cell_left;
    let place = Place::new(
        (y_title_left, (plot.1 + plot.3) / 2),
        Align::Middle,
        Align::Start,
    );
    draw_text(root, mode, &chart.y_label, axis_spec, place.upwards())
}

fn vline_spec() -> TextSpec {
    TextSpec::new(VLINE_PX).color(ANNOTATION)
}

/// Labels of vertical marker lines with their placement and pixel box: beside the line near
/// the top, right of it unless that would leave the plot, in up to three staggered rows so
/// that neighbours do not collide.
fn vline_labels<DB: DrawingBackend>(
    ctx: &Ctx<'_, DB>,
    chart: &Chart,
    xmap: AxisMap,
    frame: &Frame,
    plot: PxRect,
) -> Vec<(String, Place, PxRect)> {
    let spec = vline_spec();
    let mut row = 0;
    let mut out = Vec::new();
    for vline in &chart.vlines {
        let x = xmap.forward(vline.x);
        if vline.label.is_empty() || !(x.is_finite() && x >= frame.x.0 && x <= frame.x.1) {
            continue;
        }
        let (px, _) = ctx.backend_coord(&(x, frame.y.1));
        let (w, h) = spec.size(&vline.label);
        let y = plot.1 + 4 + row * (h + 4);
        row = (row + 1) % 3;
        let (place, rect) = if px + 4 + w <= plot.2 - 2 {
            (
                Place::new((px + 4, y), Align::Start, Align::Start),
                (px + 4, y, px + 4 + w, y + h),
            )
        } else {
            (
                Place::new((px - 4, y), Align::End, Align::Start),
                (px - 4 - w, y, px - 4, y + h),
            )
        };
        out.push((vline.label.clone(), place, rect));
    }
    out
}

/// Legend entries: series with a label; a series with nothing to draw says so.
fn legend_entries(chart: &Chart, xmap: AxisMap, ymap: AxisMap) -> Vec<(usize, String)> {
    chart
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.label.is_empty())
        .map(|(i, s)| {
            let any = s
                .points
                .iter()
                .any(|&(x, y)| xmap.forward(x).is_finite() && ymap.forward(y).is_finite());
            let label = if any {
                s.label.clone()
            } else {
                format!("{} (no data)", s.label)
            };
            (i, label)
        })
        .collect()
}

/// The legend's content: one row per labelled series, then the note on values off the chart.
struct LegendBox {
    entries: Vec<(usize, String)>,
    note: Option<String>,
    hidden: bool,
}

impl LegendBox {
    fn of(chart: &Chart, xmap: AxisMap, ymap: AxisMap, off_chart: &[OffChart]) -> LegendBox {
        LegendBox {
            entries: legend_entries(chart, xmap, ymap),
            note: off_chart_note(off_chart, ymap),
            hidden: chart.legend == LegendPosition::Hidden,
        }
    }

    fn rows(&self) -> usize {
        if self.hidden {
            usize::from(self.note.is_some())
        } else {
            self.entries.len() + usize::from(self.note.is_some())
        }
    }

    /// Width and height in pixels; `None` when there is nothing to show.
    fn size(&self) -> Option<(i32, i32)> {
        if self.rows() == 0 {
            return None;
        }
        let spec = TextSpec::new(LEGEND_PX);
        let row_h = (LEGEND_PX * LEGEND_ROW).round() as i32;
        let widest_entry = if self.hidden {
            0
        } else {
            self.entries
                .iter()
                .map(|(_, l)| LEGEND_GLYPH_PX + LEGEND_PAD_PX + spec.size(l).0)
                .max()
                .unwrap_or(0)
        };
        let note = self.note.as_deref().map_or(0, |n| spec.size(n).0);
        let w = 2 * LEGEND_PAD_PX + widest_entry.max(note);
        let h = 2 * LEGEND_PAD_PX + row_h * self.rows() as i32;
        Some((w, h))
    }

    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &Chart,
        (left, top, right, bottom): PxRect,
        mode: TextMode,
    ) -> Result<(), ChartError> {
        let spec = TextSpec::new(LEGEND_PX);
        let row_h = (LEGEND_PX * LEGEND_ROW).round() as i32;
        root.draw(&Rectangle::new(
            [(left, top), (right, bottom)],
            WHITE.mix(0.9).filled(),
        ))
        .map_err(drawing_error)?;
        root.draw(&Rectangle::new(
            [(left, top), (right, bottom)],
            RGBColor(0x99, 0x99, 0x99).stroke_width(1),
        ))
        .map_err(drawing_error)?;
        let entries: &[(usize, String)] = if self.hidden { &[] } else { &self.entries };
        let row_y = |row: usize| top + LEGEND_PAD_PX + row_h * row as i32 + row_h / 2;
        for (row, (index, label)) in entries.iter().enumerate() {
            let series = &chart.series[*index];
            let y = row_y(row);
            let x = left + LEGEND_PAD_PX;
            let look = Look::of(series, *index);
            if !matches!(series.style, SeriesStyle::Markers) {
                let path = vec![(x, y), (x + LEGEND_GLYPH_PX, y)];
                if series.dashed {
                    root.draw(&DashedPathElement::new(path, 8, 4, look.line))
                } else {
                    root.draw(&PathElement::new(path, look.line))
                }
                .map_err(drawing_error)?;
            }
            if matches!(
                series.style,
                SeriesStyle::Markers | SeriesStyle::LineWithMarkers
            ) {
                root.draw(&(EmptyElement::at((x + LEGEND_GLYPH_PX / 2, y)) + look.marker::<DB>()))
                    .map_err(drawing_error)?;
            }
            let place = Place::new(
                (x + LEGEND_GLYPH_PX + LEGEND_PAD_PX, y),
                Align::Start,
                Align::Middle,
            );
            draw_text(root, mode, label, spec, place)?;
        }
        if let Some(note) = &self.note {
            let place = Place::new(
                (left + LEGEND_PAD_PX, row_y(entries.len())),
                Align::Start,
                Align::Middle,
            );
            draw_text(root, mode, note, spec.color(ANNOTATION), place)?;
        }
        Ok(())
    }
}

/// Cells of a plot's occupancy grid marked as drawn on.
struct Marks {
    left: f64,
    top: f64,
    cols: usize,
    rows: usize,
    occupied: Vec<bool>,
}

impl Marks {
    /// Marks the cells within `radius` plus [`LEGEND_CLEARANCE_PX`] of pixel `(x, y)`.
    fn mark(&mut self, (x, y): (f64, f64), radius: f64) {
        let r = radius + f64::from(LEGEND_CLEARANCE_PX);
        let cell = f64::from(OCCUPANCY_CELL_PX);
        let c1 = ((x + r - self.left) / cell).floor();
        let r1 = ((y + r - self.top) / cell).floor();
        if !(c1 >= 0.0 && r1 >= 0.0) {
            return;
        }
        let c0 = ((x - r - self.left) / cell).floor().max(0.0) as usize;
        let r0 = ((y - r - self.top) / cell).floor().max(0.0) as usize;
        let c1 = (c1 as usize).min(self.cols - 1);
        let r1 = (r1 as usize).min(self.rows - 1);
        for row in r0..=r1 {
            for col in c0..=c1 {
                self.occupied[row * self.cols + col] = true;
            }
        }
    }

    /// Marks a segment between two pixels, sampled every [`SEGMENT_SAMPLE_PX`] (less than
    /// the clearance, so that the marked discs overlap).
    fn segment(&mut self, a: (f64, f64), b: (f64, f64), radius: f64) {
        let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        if !len.is_finite() {
            return;
        }
        let n = (len / SEGMENT_SAMPLE_PX).ceil().max(1.0) as usize;
        for k in 0..=n {
            let t = k as f64 / n as f64;
            self.mark((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)), radius);
        }
    }
}

/// What is drawn inside a plot, on a grid of [`OCCUPANCY_CELL_PX`] cells, with a summed-area
/// table so that a legend-sized box is checked in constant time.
struct Occupancy {
    left: i32,
    top: i32,
    cols: usize,
    rows: usize,
    /// `sums[r * (cols + 1) + c]`: occupied cells above row `r` and left of column `c`.
    sums: Vec<u32>,
}

impl Occupancy {
    /// Marks every cell within [`LEGEND_CLEARANCE_PX`] (plus the line width or marker size)
    /// of a data point, of a line between points (sampled every [`SEGMENT_SAMPLE_PX`]), of a marker line and
    /// its label, and of the off-chart marks.
    fn of<DB: DrawingBackend>(
        chart: &Chart,
        ctx: &Ctx<'_, DB>,
        xmap: AxisMap,
        ymap: AxisMap,
        frame: &Frame,
        plot: PxRect,
    ) -> Occupancy {
        let cell = OCCUPANCY_CELL_PX;
        let cols = ((plot.2 - plot.0) / cell + 1).max(1) as usize;
        let rows = ((plot.3 - plot.1) / cell + 1).max(1) as usize;
        let mut grid = Marks {
            left: f64::from(plot.0),
            top: f64::from(plot.1),
            cols,
            rows,
            occupied: vec![false; cols * rows],
        };
        let to_px = |p: Point| {
            let (x, y) = ctx.backend_coord(&p);
            (f64::from(x), f64::from(y))
        };
        let line_radius = f64::from(LINE_WIDTH);
        for s in &chart.series {
            let (points, lines) = series_lines(s, xmap, ymap, frame);
            let finite = |p: &Point| p.0.is_finite() && p.1.is_finite();
            for line in &lines {
                if line.len() == 1 {
                    grid.mark(to_px(line[0]), 2.0);
                }
                for pair in line.windows(2) {
                    grid.segment(to_px(pair[0]), to_px(pair[1]), line_radius);
                }
            }
            if matches!(s.style, SeriesStyle::Markers | SeriesStyle::LineWithMarkers) {
                for p in points.iter().filter(|p| finite(p) && frame.contains(**p)) {
                    grid.mark(to_px(*p), f64::from(MARKER_PX + 1));
                }
            }
        }
        for vline in &chart.vlines {
            let x = xmap.forward(vline.x);
            if x.is_finite() && x >= frame.x.0 && x <= frame.x.1 {
                grid.segment(to_px((x, frame.y.0)), to_px((x, frame.y.1)), 1.0);
            }
        }
        for (_, _, (l, t, r, b)) in vline_labels(ctx, chart, xmap, frame, plot) {
            // Discs along the label's middle line cover its box.
            let cy = 0.5 * f64::from(t + b);
            grid.segment(
                (f64::from(l), cy),
                (f64::from(r), cy),
                0.5 * f64::from(b - t),
            );
        }
        for r in off_chart_runs(chart, xmap, ymap, frame) {
            let (px, _) = ctx.backend_coord(&(r.x, frame.y.0));
            let y = if r.above { plot.1 } else { plot.3 };
            grid.mark(
                (f64::from(px), f64::from(y)),
                f64::from(2 * OFF_CHART_MARK_PX + 1),
            );
        }
        let mut sums = vec![0u32; (cols + 1) * (rows + 1)];
        for row in 0..rows {
            for col in 0..cols {
                sums[(row + 1) * (cols + 1) + col + 1] = u32::from(grid.occupied[row * cols + col])
                    + sums[row * (cols + 1) + col + 1]
                    + sums[(row + 1) * (cols + 1) + col]
                    - sums[row * (cols + 1) + col];
            }
        }
        Occupancy {
            left: plot.0,
            top: plot.1,
            cols,
            rows,
            sums,
        }
    }

    /// Whether the pixel box `(left, top, right, bottom)` touches an occupied cell.
    fn is_free(&self, (l, t, r, b): PxRect) -> bool {
        let cell = OCCUPANCY_CELL_PX;
        let c0 = ((l - self.left) / cell).clamp(0, self.cols as i32) as usize;
        let c1 = ((r - self.left) / cell + 1).clamp(0, self.cols as i32) as usize;
        let r0 = ((t - self.top) / cell).clamp(0, self.rows as i32) as usize;
        let r1 = ((b - self.top) / cell + 1).clamp(0, self.rows as i32) as usize;
        let at = |r: usize, c: usize| self.sums[r * (self.cols + 1) + c];
        at(r1, c1) + at(r0, c0) - at(r0, c1) - at(r1, c0) == 0
    }

    /// Top-left corner of a free place for a `w` × `h` legend inside `plot` (inset by
    /// [`LEGEND_INSET_PX`]): the preferred corner if free, else the free place nearest to a
    /// corner (upper right, upper left, lower right, lower left on ties); `None` if no place
    /// is free.
    fn free_spot(
        &self,
        plot: PxRect,
        (w, h): (i32, i32),
        preference: LegendPosition,
    ) -> Option<(i32, i32)> {
        let (x0, x1) = (plot.0 + LEGEND_INSET_PX, plot.2 - LEGEND_INSET_PX - w);
        let (y0, y1) = (plot.1 + LEGEND_INSET_PX, plot.3 - LEGEND_INSET_PX - h);
        if x1 < x0 || y1 < y0 {
            return None;
        }
        let corners = [
            (LegendPosition::UpperRight, (x1, y0)),
            (LegendPosition::UpperLeft, (x0, y0)),
            (LegendPosition::LowerRight, (x1, y1)),
            (LegendPosition::LowerLeft, (x0, y1)),
        ];
        // The requested corner, or for `Auto` the corners in order: most legends end there,
        // without the scan below.
        let first = corners
            .iter()
            .filter(|(p, _)| preference == LegendPosition::Auto || *p == preference)
            .map(|&(_, at)| at)
            .find(|at| self.is_free((at.0, at.1, at.0 + w, at.1 + h)));
        if first.is_some() {
            return first;
        }
        let step = OCCUPANCY_CELL_PX as usize;
        let mut best: Option<(i64, (i32, i32))> = None;
        for y in (y0..=y1).step_by(step).chain(std::iter::once(y1)) {
            for x in (x0..=x1).step_by(step).chain(std::iter::once(x1)) {
                if !self.is_free((x, y, x + w, y + h)) {
                    continue;
                }
                let distance = corners
                    .iter()
                    .enumerate()
                    .map(|(i, (_, c))| {
                        let d = i64::from((x - c.0).abs() + (y - c.1).abs());
                        4 * d + i as i64
                    })
                    .min()
                    .unwrap_or(0);
                if best.is_none_or(|(d, _)| distance < d) {
                    best = Some((distance, (x, y)));
                }
            }
        }
        best.map(|(_, at)| at)
    }
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

/// Colour, line style and marker shape of a series.
#[derive(Clone, Copy)]
struct Look {
    color: RGBColor,
    line: ShapeStyle,
    shape: MarkerShape,
}

impl Look {
    fn of(series: &Series, position: usize) -> Look {
        let index = series.color.unwrap_or(position);
        let color = palette(index);
        Look {
            color,
            line: color.stroke_width(LINE_WIDTH),
            shape: MarkerShape::for_color(index),
        }
    }

    /// The marker centred on the pixel origin, to be composed with [`EmptyElement::at`].
    ///
    /// Built from elements that do not mention the backend so that it can be `'static`, as
    /// plotters requires of elements inside a composition.
    fn marker<DB: DrawingBackend>(&self) -> DynElement<'static, DB, (i32, i32)> {
        let r = MARKER_PX;
        let filled = self.color.filled();
        let stroke = self.color.stroke_width(2);
        let square = [(-r + 1, -r + 1), (r - 1, r - 1)];
        match self.shape {
            MarkerShape::Circle => Circle::new((0, 0), r, filled).into_dyn(),
            MarkerShape::OpenCircle => Circle::new((0, 0), r, stroke).into_dyn(),
            MarkerShape::Square => Rectangle::new(square, filled).into_dyn(),
            MarkerShape::OpenSquare => Rectangle::new(square, stroke).into_dyn(),
            MarkerShape::Triangle => {
                Polygon::new(vec![(0, -r - 1), (r, r - 1), (-r, r - 1)], filled).into_dyn()
            }
            MarkerShape::Diamond => {
                Polygon::new(vec![(0, -r - 1), (r, 0), (0, r + 1), (-r, 0)], filled).into_dyn()
            }
            // One path that retraces through the centre draws both strokes.
            MarkerShape::Cross => {
                PathElement::new(vec![(-r, -r), (r, r), (0, 0), (-r, r), (r, -r)], stroke)
                    .into_dyn()
            }
            MarkerShape::Plus => {
                PathElement::new(vec![(-r, 0), (r, 0), (0, 0), (0, -r), (0, r)], stroke).into_dyn()
            }
        }
    }
}

/// A series' points mapped to the chart's axes, and the lines to draw through them clipped
/// to the frame (none for markers): what is drawn, and what the legend placement avoids.
fn series_lines(
    series: &Series,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
) -> (Vec<Point>, Vec<Vec<Point>>) {
    let finite = |p: &Point| p.0.is_finite() && p.1.is_finite();
    let points: Vec<Point> = series
        .points
        .iter()
        .map(|&(x, y)| (xmap.forward(x), ymap.forward(y)))
        .collect();
    let lines = match series.style {
        SeriesStyle::Line | SeriesStyle::LineWithMarkers => polylines(&points, frame),
        SeriesStyle::Segments => points
            .chunks_exact(2)
            .filter(|c| finite(&c[0]) && finite(&c[1]))
            .filter_map(|c| frame.clip(c[0], c[1]).map(|(a, b, _, _)| vec![a, b]))
            .collect(),
        SeriesStyle::Markers => Vec::new(),
    };
    (points, lines)
}

fn draw_series<DB: DrawingBackend>(
    ctx: &mut Ctx<'_, DB>,
    series: &Series,
    position: usize,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
) -> Result<(), ChartError> {
    let look = Look::of(series, position);
    let finite = |p: &Point| p.0.is_finite() && p.1.is_finite();
    let (points, lines) = series_lines(series, xmap, ymap, frame);
    let markers: Vec<Point> = match series.style {
        SeriesStyle::Markers | SeriesStyle::LineWithMarkers => points
            .iter()
            .copied()
            .filter(|p| finite(p) && frame.contains(*p))
            .collect(),
        SeriesStyle::Line | SeriesStyle::Segments => Vec::new(),
    };
    // A point of a line whose neighbours are missing would be invisible: show it as a dot.
    let (long, single): (Vec<_>, Vec<_>) = lines.into_iter().partition(|l| l.len() >= 2);
    if series.dashed {
        ctx.draw_series(
            long.into_iter()
                .map(|l| DashedPathElement::new(l, 10, 6, look.line)),
        )
        .map_err(drawing_error)?;
    } else {
        ctx.draw_series(long.into_iter().map(|l| PathElement::new(l, look.line)))
            .map_err(drawing_error)?;
    }
    ctx.draw_series(
        single
            .into_iter()
            .map(|l| EmptyElement::at(l[0]) + Circle::new((0, 0), 2, look.color.filled())),
    )
    .map_err(drawing_error)?;
    ctx.draw_series(
        markers
            .into_iter()
            .map(|p| EmptyElement::at(p) + look.marker::<DB>()),
    )
    .map_err(drawing_error)?;
    Ok(())
}
