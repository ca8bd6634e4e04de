//! The occupancy grid of a plot: every cell near something drawn is marked, so that a
//! legend can be put where it hides nothing.

use plotters::prelude::*;

use super::super::geometry::{AxisMap, Frame, Point};
use super::super::{Chart, LegendPosition};
use super::annotations::off_chart_runs;
use super::series::Drawn;
use super::{Ctx, LEGEND_INSET_PX, LINE_WIDTH, MARKER_PX, OFF_CHART_MARK_PX, PxRect};

/// Least distance in pixels between a legend and anything drawn in the plot.
const LEGEND_CLEARANCE_PX: i32 = 4;
/// Cell size in pixels of the occupancy grid that places legends.
const OCCUPANCY_CELL_PX: i32 = 6;
/// Spacing in pixels of the samples that mark a line in the occupancy grid.
const SEGMENT_SAMPLE_PX: f64 = 3.0;

/// Cells of a plot's occupancy grid marked as drawn on.
pub(super) struct Marks {
    left: i32,
    top: i32,
    cols: usize,
    rows: usize,
    occupied: Vec<bool>,
}

impl Marks {
    /// An empty grid over `plot`.
    fn new(plot: PxRect) -> Marks {
        let cell = OCCUPANCY_CELL_PX;
        let cols = ((plot.2 - plot.0) / cell + 1).max(1) as usize;
        let rows = ((plot.3 - plot.1) / cell + 1).max(1) as usize;
        Marks {
            left: plot.0,
            top: plot.1,
            cols,
            rows,
            occupied: vec![false; cols * rows],
        }
    }

    /// Marks the cells within `radius` plus [`LEGEND_CLEARANCE_PX`] of pixel `(x, y)`.
    pub(super) fn mark(&mut self, (x, y): (f64, f64), radius: f64) {
        let r = radius + f64::from(LEGEND_CLEARANCE_PX);
        let cell = f64::from(OCCUPANCY_CELL_PX);
        let (left, top) = (f64::from(self.left), f64::from(self.top));
        // Cells from the pixel coordinates without `floor` (a call into the C library on
        // x86-64's baseline): `as usize` truncates, which floors what is not negative, and
        // takes a negative or NaN coordinate to 0 (the first cell), as flooring and then
        // clamping at 0 did.
        let (c1, r1) = ((x + r - left) / cell, (y + r - top) / cell);
        if !(c1 >= 0.0 && r1 >= 0.0) {
            return;
        }
        let c0 = ((x - r - left) / cell) as usize;
        let r0 = ((y - r - top) / cell) as usize;
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
    pub(super) fn segment(&mut self, a: (f64, f64), b: (f64, f64), radius: f64) {
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

    /// Marks a text box `(left, top, right, bottom)`: discs along its middle line.
    pub(super) fn text_box(&mut self, (l, t, r, b): PxRect) {
        let cy = 0.5 * f64::from(t + b);
        self.segment(
            (f64::from(l), cy),
            (f64::from(r), cy),
            0.5 * f64::from(b - t),
        );
    }

    /// The cell ranges (columns, rows) a pixel box touches, clamped to the grid.
    fn cells(&self, (l, t, r, b): PxRect) -> (std::ops::Range<usize>, std::ops::Range<usize>) {
        let cell = OCCUPANCY_CELL_PX;
        let clamp = |v: i32, n: usize| v.clamp(0, n as i32) as usize;
        (
            clamp((l - self.left) / cell, self.cols)..clamp((r - self.left) / cell + 1, self.cols),
            clamp((t - self.top) / cell, self.rows)..clamp((b - self.top) / cell + 1, self.rows),
        )
    }

    /// Whether the pixel box touches no marked cell.
    pub(super) fn is_free(&self, rect: PxRect) -> bool {
        let (cols, rows) = self.cells(rect);
        rows.into_iter()
            .all(|r| cols.clone().all(|c| !self.occupied[r * self.cols + c]))
    }

    /// The cells near what the plot's data draws: every line (sampled every
    /// [`SEGMENT_SAMPLE_PX`]), point and marker, and the off-chart marks, within
    /// [`LEGEND_CLEARANCE_PX`] plus the line width or marker size. `drawn` is what each
    /// series draws ([`drawn`](super::series::drawn)), in series order.
    pub(super) fn of_data<DB: DrawingBackend>(
        chart: &Chart,
        drawn: &[Drawn],
        ctx: &Ctx<'_, DB>,
        xmap: AxisMap,
        ymap: AxisMap,
        frame: &Frame,
        plot: PxRect,
    ) -> Marks {
        let mut grid = Marks::new(plot);
        let to_px = |p: Point| {
            let (x, y) = ctx.backend_coord(&p);
            (f64::from(x), f64::from(y))
        };
        let line_radius = f64::from(LINE_WIDTH);
        for d in drawn {
            for line in &d.lines {
                if line.len() == 1 {
                    grid.mark(to_px(line[0]), 2.0);
                }
                for pair in line.windows(2) {
                    grid.segment(to_px(pair[0]), to_px(pair[1]), line_radius);
                }
            }
            for p in &d.markers {
                grid.mark(to_px(*p), f64::from(MARKER_PX + 1));
            }
        }
        for r in off_chart_runs(chart, xmap, ymap, frame) {
            let (px, _) = ctx.backend_coord(&(r.x, frame.y.0));
            let y = if r.above { plot.1 } else { plot.3 };
            grid.mark(
                (f64::from(px), f64::from(y)),
                f64::from(2 * OFF_CHART_MARK_PX + 1),
            );
        }
        grid
    }

    /// Marks the chart's vertical marker lines.
    pub(super) fn vlines<DB: DrawingBackend>(
        &mut self,
        chart: &Chart,
        ctx: &Ctx<'_, DB>,
        xmap: AxisMap,
        frame: &Frame,
    ) {
        let to_px = |p: Point| {
            let (x, y) = ctx.backend_coord(&p);
            (f64::from(x), f64::from(y))
        };
        for vline in &chart.vlines {
            let x = xmap.forward(vline.x);
            if x.is_finite() && x >= frame.x.0 && x <= frame.x.1 {
                self.segment(to_px((x, frame.y.0)), to_px((x, frame.y.1)), 1.0);
            }
        }
    }
}

/// What is drawn inside a plot, on a grid of [`OCCUPANCY_CELL_PX`] cells, with a summed-area
/// table so that a legend-sized box is checked in constant time.
pub(super) struct Occupancy {
    left: i32,
    top: i32,
    cols: usize,
    rows: usize,
    /// `sums[r * (cols + 1) + c]`: occupied cells above row `r` and left of column `c`.
    sums: Vec<u32>,
}

impl Occupancy {
    /// The summed-area table of `grid`: everything a legend must not cover (the data, the
    /// marker lines, the labels) marked.
    pub(super) fn of(grid: &Marks) -> Occupancy {
        Occupancy {
            left: grid.left,
            top: grid.top,
            cols: grid.cols,
            rows: grid.rows,
            sums: summed_area(&grid.occupied, grid.cols),
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
    pub(super) fn free_spot(
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
        // A box is looked at only where it would be nearer than the best so far, and a row
        // only where its nearest place would be (a distance is at least 4 times the row's
        // distance to the nearer corner row): the same place as testing every box in scan
        // order, for a fraction of the boxes.
        let beats =
            |best: Option<(i64, (i32, i32))>, distance: i64| best.is_none_or(|(d, _)| distance < d);
        for y in (y0..=y1).step_by(step).chain(std::iter::once(y1)) {
            if !beats(best, 4 * i64::from((y - y0).min(y1 - y))) {
                continue;
            }
            for x in (x0..=x1).step_by(step).chain(std::iter::once(x1)) {
                let distance = corners
                    .iter()
                    .enumerate()
                    .map(|(i, (_, c))| {
                        let d = i64::from((x - c.0).abs() + (y - c.1).abs());
                        4 * d + i as i64
                    })
                    .min()
                    .unwrap_or(0);
                if beats(best, distance) && self.is_free((x, y, x + w, y + h)) {
                    best = Some((distance, (x, y)));
                }
            }
        }
        best.map(|(_, at)| at)
    }
}

/// The summed-area table of `occupied` (row-major, `cols` wide): row by row, each entry
/// the one above plus the row's running count, the rows walked as slices (no index
/// checked). The same integers as adding and subtracting the three neighbours at every
/// cell.
fn summed_area(occupied: &[bool], cols: usize) -> Vec<u32> {
    let width = cols + 1;
    let rows = occupied.len().checked_div(cols).unwrap_or(0);
    let mut sums = vec![0u32; width * (rows + 1)];
    for (row, cells) in occupied.chunks_exact(cols.max(1)).take(rows).enumerate() {
        let (done, rest) = sums.split_at_mut((row + 1) * width);
        let above = &done[row * width + 1..];
        let mut count = 0;
        for ((sum, &up), &cell) in rest[1..width].iter_mut().zip(above).zip(cells) {
            count += u32::from(cell);
            *sum = up + count;
        }
    }
    sums
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid of `cells` (row-major, `cols` wide) over a plot at `(left, top)`.
    fn grid(left: i32, top: i32, cols: usize, cells: &[bool]) -> Occupancy {
        Occupancy {
            left,
            top,
            cols,
            rows: cells.len() / cols,
            sums: summed_area(cells, cols),
        }
    }

    #[test]
    fn the_summed_area_table_counts_every_box() {
        // Against counting the cells of every box that starts at the origin.
        let mut rng = wheelrail::rng::SplitMix64::new(7);
        for (cols, rows) in [(1, 1), (1, 5), (7, 1), (13, 9), (150, 100)] {
            let cells: Vec<bool> = (0..cols * rows)
                .map(|_| rng.next_u64().is_multiple_of(3))
                .collect();
            let sums = summed_area(&cells, cols);
            assert_eq!(sums.len(), (cols + 1) * (rows + 1));
            for r in 0..=rows {
                for c in 0..=cols {
                    let count = (0..r)
                        .flat_map(|rr| (0..c).map(move |cc| (rr, cc)))
                        .filter(|&(rr, cc)| cells[rr * cols + cc])
                        .count();
                    assert_eq!(sums[r * (cols + 1) + c] as usize, count, "{cols} x {rows}");
                }
            }
        }
    }

    /// The scan `free_spot` prunes: every box in scan order, the first of least distance.
    fn every_box(o: &Occupancy, plot: PxRect, (w, h): (i32, i32)) -> Option<(i32, i32)> {
        let (x0, x1) = (plot.0 + LEGEND_INSET_PX, plot.2 - LEGEND_INSET_PX - w);
        let (y0, y1) = (plot.1 + LEGEND_INSET_PX, plot.3 - LEGEND_INSET_PX - h);
        let corners = [(x1, y0), (x0, y0), (x1, y1), (x0, y1)];
        let step = OCCUPANCY_CELL_PX as usize;
        let mut best: Option<(i64, (i32, i32))> = None;
        for y in (y0..=y1).step_by(step).chain(std::iter::once(y1)) {
            for x in (x0..=x1).step_by(step).chain(std::iter::once(x1)) {
                if !o.is_free((x, y, x + w, y + h)) {
                    continue;
                }
                let distance = (0..4)
                    .map(|i| {
                        let (cx, cy) = corners[i];
                        4 * i64::from((x - cx).abs() + (y - cy).abs()) + i as i64
                    })
                    .min()
                    .unwrap();
                if best.is_none_or(|(d, _)| distance < d) {
                    best = Some((distance, (x, y)));
                }
            }
        }
        best.map(|(_, at)| at)
    }

    #[test]
    fn the_pruned_scan_finds_the_place_of_the_full_scan() {
        // Random blobs over a plot of odd size (the last row and column are partial), all
        // corners taken so that the scan runs; densities from empty to nearly full.
        let mut rng = wheelrail::rng::SplitMix64::new(20_261_123);
        let plot: PxRect = (37, 21, 37 + 401, 21 + 277);
        let (cols, rows) = (401 / 6 + 1, 277 / 6 + 1);
        let (mut found, mut none) = (0, 0);
        for case in 0..300 {
            let mut cells = vec![false; cols * rows];
            let blobs = case % 40;
            for _ in 0..blobs {
                let (c, r) = (
                    (rng.next_u64() % cols as u64) as usize,
                    (rng.next_u64() % rows as u64) as usize,
                );
                let radius = 1 + (rng.next_u64() % 8) as usize;
                for rr in r.saturating_sub(radius)..(r + radius).min(rows) {
                    for cc in c.saturating_sub(radius)..(c + radius).min(cols) {
                        cells[rr * cols + cc] = true;
                    }
                }
            }
            for (r, c) in [(0, 0), (0, cols - 1), (rows - 1, 0), (rows - 1, cols - 1)] {
                cells[r * cols + c] = true;
            }
            let o = grid(plot.0, plot.1, cols, &cells);
            let size = (
                20 + (rng.next_u64() % 150) as i32,
                10 + (rng.next_u64() % 100) as i32,
            );
            let want = every_box(&o, plot, size);
            assert_eq!(
                o.free_spot(plot, size, LegendPosition::Auto),
                want,
                "case {case}"
            );
            if want.is_some() {
                found += 1
            } else {
                none += 1
            }
        }
        // Both outcomes are exercised.
        assert!(found > 100 && none > 10, "{found} found, {none} none");
    }
}
