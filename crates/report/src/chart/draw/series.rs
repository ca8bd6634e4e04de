//! The data of a chart: each series' colour, line and marker, and its points drawn clipped
//! to the frame.

use plotters::element::DashedPathElement;
use plotters::prelude::*;

use std::collections::HashSet;

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

/// What a series draws, at the chart's resolution: its lines clipped to the frame and its
/// markers, both thinned to the pixels they cover ([`thinned`], [`one_per_pixel`]); what is
/// drawn, and what the legend and label placement avoid.
pub(super) struct Drawn {
    /// Polylines (two points for each segment of a [`SeriesStyle::Segments`] series; one
    /// point where a line's neighbours are missing).
    pub(super) lines: Vec<Vec<Point>>,
    /// Marker positions within the frame.
    pub(super) markers: Vec<Point>,
}

/// A series' points mapped to the chart's axes, its lines and markers: see [`Drawn`].
/// `px` is the chart's pixel of a point (plotters' own mapping, so that what is kept is
/// judged by where it is drawn).
pub(super) fn drawn(
    series: &Series,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
    px: impl Fn(Point) -> (i32, i32),
) -> Drawn {
    let finite = |p: &Point| p.0.is_finite() && p.1.is_finite();
    let points: Vec<Point> = series
        .points
        .iter()
        .map(|&(x, y)| (xmap.forward(x), ymap.forward(y)))
        .collect();
    let lines = match series.style {
        SeriesStyle::Line | SeriesStyle::LineWithMarkers => {
            let (long, single): (Vec<_>, Vec<_>) = polylines(&points, frame)
                .into_iter()
                .partition(|l| l.len() >= 2);
            let dots: Vec<Point> = single.into_iter().map(|l| l[0]).collect();
            long.into_iter()
                .map(|l| thinned(&l, &px))
                .chain(one_per_pixel(dots, &px).into_iter().map(|p| vec![p]))
                .collect()
        }
        SeriesStyle::Segments => {
            let mut seen = HashSet::new();
            points
                .chunks_exact(2)
                .filter(|c| finite(&c[0]) && finite(&c[1]))
                .filter_map(|c| frame.clip(c[0], c[1]).map(|(a, b, _, _)| vec![a, b]))
                .filter(|l| seen.insert((px(l[0]), px(l[1]))))
                .collect()
        }
        SeriesStyle::Markers => Vec::new(),
    };
    let markers = match series.style {
        SeriesStyle::Markers | SeriesStyle::LineWithMarkers => one_per_pixel(
            points
                .iter()
                .copied()
                .filter(|p| finite(p) && frame.contains(*p)),
            &px,
        ),
        SeriesStyle::Line | SeriesStyle::Segments => Vec::new(),
    };
    Drawn { lines, markers }
}

/// The first point at each pixel: the later ones draw the same marker on it.
fn one_per_pixel(
    points: impl IntoIterator<Item = Point>,
    px: impl Fn(Point) -> (i32, i32),
) -> Vec<Point> {
    let mut seen = HashSet::new();
    points.into_iter().filter(|&p| seen.insert(px(p))).collect()
}

/// `line` thinned to what its pixels show: of each run of consecutive points in one pixel
/// column, the first, the lowest, the highest and the last, in their order; of those, a
/// point on the pixel of the point before it is dropped. Within a column a line's segments
/// are vertical and together cover the column from its lowest to its highest point, as the
/// kept points' segments do, and the segments between columns are kept: the picture is
/// the same, and a line has at most four points per pixel column it crosses (a sweep of
/// 100,001 positions across a plot of 800 pixels keeps at most 3,200).
pub(super) fn thinned(line: &[Point], px: impl Fn(Point) -> (i32, i32)) -> Vec<Point> {
    let pixels: Vec<(i32, i32)> = line.iter().map(|&p| px(p)).collect();
    let mut keep: Vec<usize> = Vec::with_capacity(line.len().min(4 * 2048));
    let mut start = 0;
    while start < line.len() {
        let column = pixels[start].0;
        let end = start + pixels[start..].iter().take_while(|q| q.0 == column).count();
        let run = start..end;
        let lowest = run.clone().max_by_key(|&i| (pixels[i].1, usize::MAX - i));
        let highest = run.clone().min_by_key(|&i| (pixels[i].1, i));
        let mut picks = [Some(start), lowest, highest, Some(end - 1)]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>();
        picks.sort_unstable();
        picks.dedup();
        for i in picks {
            if keep.last().is_none_or(|&k| pixels[k] != pixels[i]) {
                keep.push(i);
            }
        }
        start = end;
    }
    // A line within one pixel stays a line (a single point would be drawn as a dot).
    if keep.len() == 1 && line.len() > 1 {
        keep.push(line.len() - 1);
    }
    keep.into_iter().map(|i| line[i]).collect()
}

/// Draws `series` (the `position`th of its chart), `drawn` being what it draws ([`drawn`]
/// on `ctx`'s frame).
pub(super) fn draw_series<DB: DrawingBackend>(
    ctx: &mut Ctx<'_, DB>,
    series: &Series,
    position: usize,
    drawn: Drawn,
) -> Result<(), ChartError> {
    let look = Look::of(series, position);
    let Drawn { lines, markers } = drawn;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The pixels a one-pixel line through `pixels` covers (Bresenham).
    fn raster(pixels: &[(i32, i32)]) -> HashSet<(i32, i32)> {
        let mut out = HashSet::new();
        out.extend(pixels.first());
        for w in pixels.windows(2) {
            let ((mut x, mut y), (x1, y1)) = (w[0], w[1]);
            let (dx, dy) = ((x1 - x).abs(), -(y1 - y).abs());
            let (sx, sy) = ((x1 - x).signum(), (y1 - y).signum());
            let mut err = dx + dy;
            loop {
                out.insert((x, y));
                if (x, y) == (x1, y1) {
                    break;
                }
                let e2 = 2 * err;
                if e2 >= dy {
                    err += dy;
                    x += sx;
                }
                if e2 <= dx {
                    err += dx;
                    y += sy;
                }
            }
        }
        out
    }

    /// Noisy lines far denser than their pixels (a sweep of 100,001 positions over 640
    /// pixels, a profile that turns back over itself): thinned, they cover the same pixels
    /// and keep at most four points per pixel column they cross.
    #[test]
    fn thinned_lines_cover_the_same_pixels_with_at_most_four_points_a_column() {
        let px = |(x, y): Point| ((x * 640.0).floor() as i32, (y * 400.0).floor() as i32);
        let mut rng = wheelrail::rng::SplitMix64::new(32);
        let mut noise = move || (rng.next_u64() % 1000) as f64 / 1000.0 - 0.5;
        let sweep: Vec<Point> = (0..=100_000)
            .map(|i| {
                let x = f64::from(i) / 1e5;
                (x, 0.5 + 0.3 * (20.0 * x).sin() + 0.05 * noise())
            })
            .collect();
        let turning: Vec<Point> = (0..=20_000)
            .map(|i| {
                let t = f64::from(i) / 2e4 * std::f64::consts::TAU;
                (
                    0.5 + 0.4 * t.cos(),
                    0.5 + 0.4 * (2.0 * t).sin() + 0.002 * noise(),
                )
            })
            .collect();
        for (line, most) in [(sweep, 4 * 641), (turning, 20_001 / 4)] {
            let kept = thinned(&line, px);
            let all: Vec<(i32, i32)> = line.iter().map(|&p| px(p)).collect();
            let few: Vec<(i32, i32)> = kept.iter().map(|&p| px(p)).collect();
            assert!(raster(&all) == raster(&few), "the pixels differ");
            // Runs of one column: at most four points each.
            let mut columns = few.clone();
            columns.dedup_by_key(|p| p.0);
            assert!(
                few.len() <= 4 * columns.len(),
                "{} points, {} runs",
                few.len(),
                columns.len()
            );
            assert!(kept.len() <= most, "{} of {}", kept.len(), line.len());
        }
        // A line within one pixel keeps two points.
        assert_eq!(
            thinned(&[(0.1, 0.1), (0.1001, 0.1), (0.1, 0.1001)], px).len(),
            2
        );
    }
}
