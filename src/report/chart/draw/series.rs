//! The data of a chart: each series' colour, line and marker, and its points drawn clipped
//! to the frame.

use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::super::geometry::{AxisMap, Frame, Point, polylines};
use super::super::{ChartError, MarkerShape, PALETTE, Series, SeriesStyle, drawing_error};
use super::{Ctx, LINE_WIDTH, MARKER_PX};

fn palette(index: usize) -> RGBColor {
    let (r, g, b) = PALETTE[index % PALETTE.len()];
    RGBColor(r, g, b)
}

/// Colour, line style and marker shape of a series.
#[derive(Clone, Copy)]
pub(super) struct Look {
    pub(super) color: RGBColor,
    pub(super) line: ShapeStyle,
    shape: MarkerShape,
}

impl Look {
    pub(super) fn of(series: &Series, position: usize) -> Look {
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
    pub(super) fn marker<DB: DrawingBackend>(&self) -> DynElement<'static, DB, (i32, i32)> {
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
pub(super) fn series_lines(
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

pub(super) fn draw_series<DB: DrawingBackend>(
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
