//! Drawing a [`Figure`] on any plotters backend.
//!
//! plotters draws the grid, ticks, frame and data; all text (titles, tick labels, axis titles,
//! legend, labels, the figure's key) goes through [`text::draw_text`] so bitmaps get correctly
//! spaced glyphs. Labels and the legend are our own so that they can be placed where they
//! hide no data: an occupancy grid of everything drawn in the plot (lines, markers, marker
//! lines, off-chart marks) finds each label of a marker line a free place beside its line
//! and each label of a point a free place near it, then the legend a free place nearest a
//! corner; when there is none for the legend the plot gives up room for it, right of it or
//! below the x-axis title, whichever takes the smaller share of the plot.
//!
//! The parts: [`panel`] lays out one chart (title, plot, axis areas, where the legend goes),
//! [`axes`] the coordinate system with our own ticks and labels and the shaded bands,
//! [`series`] the data thinned to its pixels, [`annotations`] marker lines and the marks
//! where data leaves the chart, [`labels`] the labels of marker lines and points, [`legend`]
//! the legend box and [`occupancy`] the grid that finds them free places.

mod annotations;
mod axes;
mod labels;
mod legend;
mod occupancy;
mod panel;
mod series;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::text::{Align, Place, TextSpec, draw_text};
use super::{ChartError, DrawOptions, Figure, PanelLayout, PxBox};
use super::{drawing_error, ensure_font};
use axes::TickAxis;
use panel::draw_panel;

const FIGURE_TITLE_PX: f64 = 28.0;
const AXIS_TITLE_PX: f64 = 19.0;
const TICK_PX: f64 = 16.0;
const LINE_WIDTH: u32 = 2;
const MARKER_PX: i32 = 5;
/// Gap between an axis and its tick labels, and between tick labels and the axis title.
const TICK_GAP_PX: i32 = 8;
const AXIS_TITLE_GAP_PX: i32 = 10;
/// Inset of a legend from the plot frame.
const LEGEND_INSET_PX: i32 = 8;
/// Half width in pixels of the triangles that mark where data leaves the chart.
const OFF_CHART_MARK_PX: i32 = 5;
const ANNOTATION: RGBColor = RGBColor(0x44, 0x44, 0x44);
/// Text size, margin, column gap and row height factor of a figure's key.
const KEY_PX: f64 = 15.0;
const KEY_MARGIN_PX: i32 = 16;
const KEY_GAP_PX: i32 = 28;
const KEY_ROW: f64 = 1.3;

/// Where the entries of a figure's key go: its height and the number of rows of its
/// columns (read downwards, as wide as the widest entry and a gap).
struct KeyLayout {
    height: i32,
    rows: usize,
    column_px: i32,
    row_px: i32,
}

fn key_layout(figure: &Figure) -> Option<KeyLayout> {
    // Measuring text needs the font (and would remember a failed measure): without it the
    // figure fails to draw anyway.
    if figure.key.is_empty() || ensure_font().is_err() {
        return None;
    }
    let spec = TextSpec::new(KEY_PX);
    let widest = figure.key.iter().map(|k| spec.size(k).0).max().unwrap_or(0);
    let column_px = widest + KEY_GAP_PX;
    let usable = figure.width as i32 - 2 * KEY_MARGIN_PX + KEY_GAP_PX;
    let columns = (usable / column_px.max(1)).max(1) as usize;
    let rows = figure.key.len().div_ceil(columns);
    let row_px = (KEY_ROW * KEY_PX).round() as i32;
    Some(KeyLayout {
        height: KEY_MARGIN_PX + rows as i32 * row_px,
        rows,
        column_px,
        row_px,
    })
}

/// The height of `figure`'s key (0 without one).
pub(super) fn key_height(figure: &Figure) -> u32 {
    key_layout(figure).map_or(0, |k| k.height as u32)
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
    let key = key_layout(figure);
    if let Some(k) = &key {
        // The key's entries in columns at the bottom, read downwards.
        let spec = TextSpec::new(KEY_PX);
        let key_top = figure.height as i32 - k.height + KEY_MARGIN_PX / 2;
        for (i, entry) in figure.key.iter().enumerate() {
            let (column, row) = (i / k.rows, i % k.rows);
            let at = (
                KEY_MARGIN_PX + column as i32 * k.column_px,
                key_top + row as i32 * k.row_px,
            );
            draw_text(
                root,
                mode,
                entry,
                spec,
                Place::new(at, Align::Start, Align::Start),
            )?;
        }
    }
    if figure.panels.is_empty() {
        return Ok(Vec::new());
    }
    let body = root.margin(top, key.map_or(0, |k| k.height), 0, 0);
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

fn px_box((left, top, right, bottom): PxRect) -> PxBox {
    PxBox {
        left,
        top,
        right,
        bottom,
    }
}

type Ctx<'a, DB> = ChartContext<'a, DB, Cartesian2d<TickAxis, TickAxis>>;
