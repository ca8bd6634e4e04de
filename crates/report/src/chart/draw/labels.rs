//! The labels placed in a plot like its legend, on the same occupancy grid: those of the
//! marker lines (beside their line, as near the top as is free) and those of points (as
//! near their point as is free, with a leader line when they had to move away). Each
//! covers nothing drawn, no other marker line and no other label; the legend, placed after
//! them, covers none of them.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::super::geometry::{AxisMap, Frame};
use super::super::text::{Align, Place, TextMode, draw_text};
use super::super::{Chart, ChartError, drawing_error};
use super::annotations::vline_spec;
use super::occupancy::Marks;
use super::series::Drawn;
use super::{Ctx, MARKER_PX, PxRect};

/// Gap between a marker line and its label, and between a label and the plot's frame.
const LABEL_GAP_PX: i32 = 4;
/// Vertical step of the search for a free place beside a marker line.
const VLINE_STEP_PX: i32 = 2;
/// Distances (pixels beyond the marker) at which a point's label is tried, nearest first,
/// in eight directions each; the farthest is about a fifth of a default panel.
const POINT_RINGS_PX: [i32; 12] = [2, 6, 10, 16, 24, 34, 46, 60, 76, 94, 114, 136];
/// A label farther than this from its point gets a leader line.
const LEADER_FROM_PX: i32 = 10;
/// The leader line's colour: lighter than the label, so that it reads as a pointer.
const LEADER: RGBColor = RGBColor(0x88, 0x88, 0x88);

/// A label and where it goes.
pub(super) struct Label {
    text: String,
    place: Place,
    /// Its box, `(left, top, right, bottom)` in pixels.
    pub(super) rect: PxRect,
    /// A line from near its point to near its box, where it moved away from its point.
    leader: Option<((i32, i32), (i32, i32))>,
}

impl Label {
    fn at(text: &str, (left, top): (i32, i32), (w, h): (i32, i32)) -> Label {
        Label {
            text: text.to_owned(),
            place: Place::new((left, top), Align::Start, Align::Start),
            rect: (left, top, left + w, top + h),
            leader: None,
        }
    }
}

/// The labels of `chart`'s marker lines and points, each in a free place of the plot, and
/// the occupancy grid of everything the legend must then avoid: the data, the marker
/// lines, the labels and their leader lines.
pub(super) fn lay_out<DB: DrawingBackend>(
    chart: &Chart,
    drawn: &[Drawn],
    ctx: &Ctx<'_, DB>,
    xmap: AxisMap,
    ymap: AxisMap,
    frame: &Frame,
    plot: PxRect,
) -> (Vec<Label>, Marks) {
    let mut grid = Marks::of_data(chart, drawn, ctx, xmap, ymap, frame, plot);
    let mut labels = Vec::new();
    // The marker lines' own cells are left out while their labels are placed (a label sits
    // beside its line, nearer than the grid's clearance); the others are kept clear of
    // by their pixel column.
    let columns: Vec<Option<i32>> = chart
        .vlines
        .iter()
        .map(|v| {
            let x = xmap.forward(v.x);
            (x.is_finite() && x >= frame.x.0 && x <= frame.x.1)
                .then(|| ctx.backend_coord(&(x, frame.y.1)).0)
        })
        .collect();
    for (i, vline) in chart.vlines.iter().enumerate() {
        let Some(px) = columns[i] else { continue };
        if vline.label.is_empty() {
            continue;
        }
        let others_clear = |(l, _, r, _): PxRect| {
            columns.iter().enumerate().all(|(j, c)| {
                j == i || c.is_none_or(|x| x < l - LABEL_GAP_PX || x > r + LABEL_GAP_PX)
            })
        };
        let label = vline_label(&vline.label, px, plot, labels.len(), |rect| {
            grid.is_free(rect) && others_clear(rect)
        });
        grid.text_box(label.rect);
        labels.push(label);
    }
    grid.vlines(chart, ctx, xmap, frame);
    for point in &chart.labels {
        let (x, y) = (xmap.forward(point.x), ymap.forward(point.y));
        if point.text.is_empty() || !(x.is_finite() && y.is_finite() && frame.contains((x, y))) {
            continue;
        }
        let label = point_label(&point.text, ctx.backend_coord(&(x, y)), plot, &grid);
        grid.text_box(label.rect);
        if let Some((a, b)) = label.leader {
            let f = |p: (i32, i32)| (f64::from(p.0), f64::from(p.1));
            grid.segment(f(a), f(b), 1.0);
        }
        labels.push(label);
    }
    (labels, grid)
}

/// The label of the marker line at pixel column `px`: beside it, right or else left, at
/// the highest place where `free` holds; without one, at the top in the `k`-th of three
/// staggered rows.
fn vline_label(
    text: &str,
    px: i32,
    plot: PxRect,
    k: usize,
    free: impl Fn(PxRect) -> bool,
) -> Label {
    let size = vline_spec().size(text);
    let (w, h) = size;
    let right = px + LABEL_GAP_PX;
    let left = px - LABEL_GAP_PX - w;
    let sides: Vec<i32> = [right, left]
        .into_iter()
        .filter(|&l| l >= plot.0 + LABEL_GAP_PX / 2 && l + w <= plot.2 - LABEL_GAP_PX / 2)
        .collect();
    let mut top = plot.1 + LABEL_GAP_PX;
    while top + h <= plot.3 - LABEL_GAP_PX {
        for &l in &sides {
            if free((l, top, l + w, top + h)) {
                return Label::at(text, (l, top), size);
            }
        }
        top += VLINE_STEP_PX;
    }
    let top = plot.1 + LABEL_GAP_PX + (k % 3) as i32 * (h + LABEL_GAP_PX);
    Label::at(text, (sides.first().copied().unwrap_or(right), top), size)
}

/// The label of the point at pixel `p`: in the nearest free place around it (rings of
/// [`POINT_RINGS_PX`], eight directions each, the sides first), with a leader line when it
/// is farther than [`LEADER_FROM_PX`]; without a free place, right of the point.
fn point_label(text: &str, p: (i32, i32), plot: PxRect, grid: &Marks) -> Label {
    let size = vline_spec().size(text);
    let (w, h) = size;
    let m = MARKER_PX + 2;
    let inside = |(l, t, r, b): PxRect| {
        l >= plot.0 + LABEL_GAP_PX
            && r <= plot.2 - LABEL_GAP_PX
            && t >= plot.1 + LABEL_GAP_PX
            && b <= plot.3 - LABEL_GAP_PX
    };
    // Top-left corners at distance d beyond the marker: east, north, west, south, then the
    // diagonals.
    let corners = |d: i32| {
        let (x, y) = p;
        let diag = (m + d) * 7 / 10;
        [
            (x + m + d, y - h / 2),
            (x - w / 2, y - m - d - h),
            (x - m - d - w, y - h / 2),
            (x - w / 2, y + m + d),
            (x + diag, y - diag - h),
            (x - diag - w, y - diag - h),
            (x + diag, y + diag),
            (x - diag - w, y + diag),
        ]
    };
    for d in POINT_RINGS_PX {
        for (l, t) in corners(d) {
            let rect = (l, t, l + w, t + h);
            if inside(rect) && grid.is_free(rect) {
                let mut label = Label::at(text, (l, t), size);
                if d > LEADER_FROM_PX {
                    label.leader = leader(p, rect);
                }
                return label;
            }
        }
    }
    let (l, t) = corners(POINT_RINGS_PX[0])[0];
    Label::at(text, (l, t), size)
}

/// A leader line from the marker's edge at `p` towards the box `rect`, stopping short of
/// it (so that it touches neither the marker nor the text).
fn leader(p: (i32, i32), (l, t, r, b): PxRect) -> Option<((i32, i32), (i32, i32))> {
    let near = (p.0.clamp(l, r), p.1.clamp(t, b));
    let (dx, dy) = (f64::from(near.0 - p.0), f64::from(near.1 - p.1));
    let len = dx.hypot(dy);
    let (start, stop) = (f64::from(MARKER_PX + 2), len - 3.0);
    if stop <= start {
        return None;
    }
    let at = |s: f64| {
        (
            p.0 + (dx * s / len).round() as i32,
            p.1 + (dy * s / len).round() as i32,
        )
    };
    Some((at(start), at(stop)))
}

/// Draws the labels and their leader lines.
pub(super) fn draw_labels<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    labels: &[Label],
    mode: TextMode,
) -> Result<(), ChartError> {
    for label in labels {
        if let Some((a, b)) = label.leader {
            root.draw(&PathElement::new(vec![a, b], LEADER.stroke_width(1)))
                .map_err(drawing_error)?;
        }
    }
    for label in labels {
        draw_text(root, mode, &label.text, vline_spec(), label.place)?;
    }
    Ok(())
}
