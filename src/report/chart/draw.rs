//! Drawing a [`Figure`] on any plotters backend.
//!
//! plotters draws the grid, ticks, frame and data; all text (titles, tick labels, axis titles,
//! legend, marker-line labels) goes through [`text::draw_text`] so bitmaps get correctly spaced
//! glyphs. The legend is our own so that its box can be placed where it hides the least data.

use plotters::coord::Shift;
use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, ValueFormatter};
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::geometry::{AxisMap, Frame, Point, axis_range, data_bounds, equalize, polylines};
use super::text::{Align, Place, TextMode, TextSpec, draw_text};
use super::ticks::Ticks;
use super::{Chart, ChartError, Figure, LegendPosition, MarkerShape, Series, SeriesStyle};
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
    mode: TextMode,
) -> Result<(), ChartError> {
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
        return Ok(());
    }
    let body = root.margin(top, 0, 0, 0);
    let columns = figure.columns.min(figure.panels.len());
    let rows = figure.panels.len().div_ceil(columns);
    let cells = body.split_evenly((rows, columns));
    for (chart, cell) in figure.panels.iter().zip(&cells) {
        draw_panel(root, cell, chart, mode)?;
    }
    Ok(())
}

/// Pixel rectangle `(left, top, right, bottom)` in root coordinates.
type PxRect = (i32, i32, i32, i32);

fn draw_panel<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    cell: &DrawingArea<DB, Shift>,
    chart: &Chart,
    mode: TextMode,
) -> Result<(), ChartError> {
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
    let mut frame = Frame {
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
    let plot_size = |y_area: i32| {
        (
            (cw - MARGIN_LEFT - MARGIN_RIGHT - y_area).max(1) as u32,
            (ch - title_band - MARGIN_TOP - MARGIN_BOTTOM - x_area).max(1) as u32,
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
    let guess = make_ticks(frame.y, ymap.log, ch as u32, Y_TICK_SPACING_PX);
    let mut y_area = y_area_for(&guess);
    if chart.equal_aspect && !xmap.log && !ymap.log {
        equalize(&mut frame, plot_size(y_area));
    }
    let y_ticks = make_ticks(frame.y, ymap.log, plot_size(y_area).1, Y_TICK_SPACING_PX);
    y_area = y_area.max(y_area_for(&y_ticks));
    let (plot_w, plot_h) = plot_size(y_area);
    let x_ticks = make_ticks(frame.x, xmap.log, plot_w, X_TICK_SPACING_PX);

    let plot_area = cell.margin(
        title_band + MARGIN_TOP,
        MARGIN_BOTTOM + x_area,
        MARGIN_LEFT + y_area,
        MARGIN_RIGHT,
    );
    let mut ctx = ChartBuilder::on(&plot_area)
        .build_cartesian_2d(
            TickAxis {
                range: frame.x,
                ticks: x_ticks,
            },
            TickAxis {
                range: frame.y,
                ticks: y_ticks,
            },
        )
        .map_err(drawing_error)?;
    ctx.configure_mesh()
        .bold_line_style(GRID_MAJOR.stroke_width(1))
        .light_line_style(GRID_MINOR.stroke_width(1))
        .disable_axes()
        .draw()
        .map_err(drawing_error)?;

    let (left, top) = plot_area.get_base_pixel();
    let plot: PxRect = (left, top, left + plot_w as i32, top + plot_h as i32);

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
    root.draw(&Rectangle::new(
        [(plot.0, plot.1), (plot.2, plot.3)],
        BLACK.stroke_width(1),
    ))
    .map_err(drawing_error)?;

    draw_axes(root, &ctx, chart, plot, &frame, mode, (cx, y_area))?;
    draw_vline_labels(root, &ctx, chart, xmap, &frame, plot, mode)?;
    draw_legend(root, chart, xmap, ymap, &frame, plot, mode)?;
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

/// Labels of vertical marker lines: beside the line near the top, right of it unless that would
/// leave the plot, in up to three staggered rows so that neighbours do not collide.
fn draw_vline_labels<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    ctx: &Ctx<'_, DB>,
    chart: &Chart,
    xmap: AxisMap,
    frame: &Frame,
    plot: PxRect,
    mode: TextMode,
) -> Result<(), ChartError> {
    let spec = TextSpec::new(VLINE_PX).color(ANNOTATION);
    let mut row = 0;
    for vline in &chart.vlines {
        let x = xmap.forward(vline.x);
        if vline.label.is_empty() || !(x.is_finite() && x >= frame.x.0 && x <= frame.x.1) {
            continue;
        }
        let (px, _) = ctx.backend_coord(&(x, frame.y.1));
        let (w, h) = spec.size(&vline.label);
        let y = plot.1 + 4 + row * (h + 4);
        row = (row + 1) % 3;
        let place = if px + 4 + w <= plot.2 - 2 {
            Place::new((px + 4, y), Align::Start, Align::Start)
        } else {
            Place::new((px - 4, y), Align::End, Align::Start)
        };
        draw_text(root, mode, &vline.label, spec, place)?;
    }
    Ok(())
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

fn draw_legend<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    chart: &Chart,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
    plot: PxRect,
    mode: TextMode,
) -> Result<(), ChartError> {
    let entries = legend_entries(chart, xmap, ymap);
    if entries.is_empty() || chart.legend == LegendPosition::Hidden {
        return Ok(());
    }
    let spec = TextSpec::new(LEGEND_PX);
    let row_h = (LEGEND_PX * LEGEND_ROW).round() as i32;
    let widest = entries
        .iter()
        .map(|(_, l)| spec.size(l).0)
        .max()
        .unwrap_or(0);
    let w = 2 * LEGEND_PAD_PX + LEGEND_GLYPH_PX + LEGEND_PAD_PX + widest;
    let h = 2 * LEGEND_PAD_PX + row_h * entries.len() as i32;
    let corner = match chart.legend {
        LegendPosition::Auto => emptiest_corner(chart, xmap, ymap, frame, plot, (w, h)),
        other => other,
    };
    let (left, top) = match corner {
        LegendPosition::UpperLeft => (plot.0 + LEGEND_INSET_PX, plot.1 + LEGEND_INSET_PX),
        LegendPosition::LowerLeft => (plot.0 + LEGEND_INSET_PX, plot.3 - LEGEND_INSET_PX - h),
        LegendPosition::LowerRight => (plot.2 - LEGEND_INSET_PX - w, plot.3 - LEGEND_INSET_PX - h),
        _ => (plot.2 - LEGEND_INSET_PX - w, plot.1 + LEGEND_INSET_PX),
    };
    root.draw(&Rectangle::new(
        [(left, top), (left + w, top + h)],
        WHITE.mix(0.9).filled(),
    ))
    .map_err(drawing_error)?;
    root.draw(&Rectangle::new(
        [(left, top), (left + w, top + h)],
        RGBColor(0x99, 0x99, 0x99).stroke_width(1),
    ))
    .map_err(drawing_error)?;
    for (row, (index, label)) in entries.iter().enumerate() {
        let series = &chart.series[*index];
        let y = top + LEGEND_PAD_PX + row_h * row as i32 + row_h / 2;
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
    Ok(())
}

/// The inside corner whose legend-sized box covers the fewest data points and marker-line
/// labels (lines are sampled along their segments). Ties prefer upper right, upper left, lower
/// right, lower left.
fn emptiest_corner(
    chart: &Chart,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
    plot: PxRect,
    (box_w, box_h): (i32, i32),
) -> LegendPosition {
    let (plot_w, plot_h) = (f64::from(plot.2 - plot.0), f64::from(plot.3 - plot.1));
    let fx = f64::from(box_w + 2 * LEGEND_INSET_PX) / plot_w.max(1.0);
    let fy = f64::from(box_h + 2 * LEGEND_INSET_PX) / plot_h.max(1.0);
    let to_unit = |(x, y): Point| {
        (
            (x - frame.x.0) / (frame.x.1 - frame.x.0),
            (y - frame.y.0) / (frame.y.1 - frame.y.0),
        )
    };
    const CORNERS: [LegendPosition; 4] = [
        LegendPosition::UpperRight,
        LegendPosition::UpperLeft,
        LegendPosition::LowerRight,
        LegendPosition::LowerLeft,
    ];
    let mut counts = [0usize; 4];
    let mut count = |(u, v): Point, weight: usize| {
        let right = (1.0 - fx..=1.0).contains(&u);
        let left = (0.0..=fx).contains(&u);
        let upper = (1.0 - fy..=1.0).contains(&v);
        let lower = (0.0..=fy).contains(&v);
        for (n, inside) in
            counts
                .iter_mut()
                .zip([right && upper, left && upper, right && lower, left && lower])
        {
            *n += weight * usize::from(inside);
        }
    };
    for s in &chart.series {
        let pts: Vec<Point> = s
            .points
            .iter()
            .map(|&(x, y)| to_unit((xmap.forward(x), ymap.forward(y))))
            .collect();
        let finite = |p: &Point| p.0.is_finite() && p.1.is_finite();
        for p in pts.iter().filter(|p| finite(p)) {
            count(*p, 1);
        }
        let pairs: Vec<(Point, Point)> = match s.style {
            SeriesStyle::Markers => Vec::new(),
            SeriesStyle::Segments => pts.chunks_exact(2).map(|c| (c[0], c[1])).collect(),
            SeriesStyle::Line | SeriesStyle::LineWithMarkers => {
                pts.windows(2).map(|w| (w[0], w[1])).collect()
            }
        };
        const SAMPLES: usize = 16;
        for (a, b) in pairs.into_iter().filter(|(a, b)| finite(a) && finite(b)) {
            for k in 1..SAMPLES {
                let t = k as f64 / SAMPLES as f64;
                count((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)), 1);
            }
        }
    }
    // Marker-line labels sit at the top next to their line; covering one hides it entirely.
    for v in chart.vlines.iter().filter(|v| !v.label.is_empty()) {
        let (u, _) = to_unit((xmap.forward(v.x), frame.y.1));
        if u.is_finite() {
            count((u, 1.0), 1000);
        }
    }
    let best = (0..4).min_by_key(|&i| counts[i]).unwrap_or(0);
    CORNERS[best]
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
    let points: Vec<Point> = series
        .points
        .iter()
        .map(|&(x, y)| (xmap.forward(x), ymap.forward(y)))
        .collect();
    let lines: Vec<Vec<Point>> = match series.style {
        SeriesStyle::Line | SeriesStyle::LineWithMarkers => polylines(&points, frame),
        SeriesStyle::Segments => points
            .chunks_exact(2)
            .filter(|c| finite(&c[0]) && finite(&c[1]))
            .filter_map(|c| frame.clip(c[0], c[1]).map(|(a, b, _, _)| vec![a, b]))
            .collect(),
        SeriesStyle::Markers => Vec::new(),
    };
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
