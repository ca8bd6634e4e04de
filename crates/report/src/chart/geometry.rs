//! Data-space geometry of a panel: axis transforms, ranges, clipping, gaps at non-finite
//! points. Pure functions, no drawing.

use super::Chart;

/// Fraction of the data span added on each side of an automatic range.
const AUTO_RANGE_PAD: f64 = 0.04;

/// Share of the finite values at each end of an automatic y range that is looked at as
/// possible isolated extremes (at least one value once there are [`ROBUST_MIN_VALUES`]).
const TRIM_FRACTION: f64 = 0.01;
/// Values beyond the trimmed range by more than this fraction of its span are isolated
/// extremes (a pole, a vertical face, one wild sample): the automatic range leaves them off
/// the chart, where marks and a legend note show them. Nearer values are kept, so a smooth
/// curve keeps its ends.
const OUTLIER_REACH: f64 = 0.5;
/// Fewer finite values than this are all kept.
const ROBUST_MIN_VALUES: usize = 8;

/// An axis after transformation: log axes work in log10 units throughout.
#[derive(Debug, Clone, Copy)]
pub(super) struct AxisMap {
    pub(super) log: bool,
}

impl AxisMap {
    pub(super) fn forward(self, v: f64) -> f64 {
        if !self.log {
            v
        } else if v > 0.0 {
            v.log10()
        } else {
            f64::NAN
        }
    }
}

pub(super) type Point = (f64, f64);

/// A closed interval `(min, max)` on one axis.
pub(super) type Span = (f64, f64);

/// The plot rectangle in transformed units.
#[derive(Debug, Clone, Copy)]
pub(super) struct Frame {
    pub(super) x: (f64, f64),
    pub(super) y: (f64, f64),
}

impl Frame {
    pub(super) fn contains(&self, (x, y): Point) -> bool {
        x >= self.x.0 && x <= self.x.1 && y >= self.y.0 && y <= self.y.1
    }

    /// Liang–Barsky clipping of segment `p`–`q`; returns the visible part and whether each end
    /// was moved.
    pub(super) fn clip(&self, p: Point, q: Point) -> Option<(Point, Point, bool, bool)> {
        let (dx, dy) = (q.0 - p.0, q.1 - p.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (step, dist) in [
            (-dx, p.0 - self.x.0),
            (dx, self.x.1 - p.0),
            (-dy, p.1 - self.y.0),
            (dy, self.y.1 - p.1),
        ] {
            if step == 0.0 {
                if dist < 0.0 {
                    return None;
                }
            } else {
                let t = dist / step;
                if step < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
        if t0 > t1 {
            return None;
        }
        let at = |t: f64| (p.0 + t * dx, p.1 + t * dy);
        let a = if t0 > 0.0 { at(t0) } else { p };
        let b = if t1 < 1.0 { at(t1) } else { q };
        Some((a, b, t0 > 0.0, t1 < 1.0))
    }
}

/// Splits `points` at non-finite values and clips each piece to `frame`. A piece with a single
/// visible point is returned as a one-point polyline.
pub(super) fn polylines(points: &[Point], frame: &Frame) -> Vec<Vec<Point>> {
    let mut out: Vec<Vec<Point>> = Vec::new();
    for run in points
        .split(|p| !(p.0.is_finite() && p.1.is_finite()))
        .filter(|r| !r.is_empty())
    {
        if run.len() == 1 {
            if frame.contains(run[0]) {
                out.push(vec![run[0]]);
            }
            continue;
        }
        let mut open = false;
        for pair in run.windows(2) {
            match frame.clip(pair[0], pair[1]) {
                Some((a, b, start_moved, end_moved)) => {
                    if open && !start_moved {
                        out.last_mut().expect("open polyline").push(b);
                    } else {
                        out.push(vec![a, b]);
                    }
                    open = !end_moved;
                }
                None => open = false,
            }
        }
    }
    out
}

/// The span of `values` (finite, any order) without its isolated extremes: sorted, the
/// [`TRIM_FRACTION`] at each end is set aside, and of it only the values within
/// [`OUTLIER_REACH`] times the remaining span of the rest are kept, unless all of them are
/// within that reach of the kept span (a peak that stands out little is shown whole).
/// `None` without values.
pub(super) fn robust_span(values: &mut [f64]) -> Option<Span> {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    let (&first, &last) = (values.first()?, values.last()?);
    if n < ROBUST_MIN_VALUES {
        return Some((first, last));
    }
    let k = ((TRIM_FRACTION * n as f64) as usize).max(1);
    let (q_lo, q_hi) = (values[k], values[n - 1 - k]);
    let reach = OUTLIER_REACH * (q_hi - q_lo);
    let lo = values[..=k]
        .iter()
        .copied()
        .find(|&v| v >= q_lo - reach)
        .unwrap_or(q_lo);
    let hi = values[n - 1 - k..]
        .iter()
        .copied()
        .rev()
        .find(|&v| v <= q_hi + reach)
        .unwrap_or(q_hi);
    // Extremes that would widen the kept span by little are shown rather than cut.
    let keep = OUTLIER_REACH * (hi - lo);
    let lo = if lo - first <= keep { first } else { lo };
    let hi = if last - hi <= keep { last } else { hi };
    Some((lo, hi))
}

/// Data bounds of the transformed finite points and vline positions: x over all of them,
/// y without isolated extremes ([`robust_span`]).
pub(super) fn data_bounds(
    chart: &Chart,
    xmap: AxisMap,
    ymap: AxisMap,
) -> (Option<Span>, Option<Span>) {
    let grow = |b: &mut Option<(f64, f64)>, v: f64| {
        if v.is_finite() {
            *b = Some(match *b {
                None => (v, v),
                Some((lo, hi)) => (lo.min(v), hi.max(v)),
            });
        }
    };
    let mut bx = None;
    let mut ys = Vec::new();
    for s in &chart.series {
        for &(x, y) in &s.points {
            let (tx, ty) = (xmap.forward(x), ymap.forward(y));
            if tx.is_finite() && ty.is_finite() {
                grow(&mut bx, tx);
                ys.push(ty);
            }
        }
    }
    for v in &chart.vlines {
        grow(&mut bx, xmap.forward(v.x));
    }
    (bx, robust_span(&mut ys))
}

/// The displayed range (transformed units) of one axis.
pub(super) fn axis_range(
    fixed: Option<(f64, f64)>,
    data: Option<(f64, f64)>,
    map: AxisMap,
) -> (f64, f64) {
    if let Some((lo, hi)) = fixed {
        return (map.forward(lo), map.forward(hi));
    }
    match data {
        None => (0.0, 1.0),
        Some((lo, hi)) if hi - lo <= f64::EPSILON * lo.abs().max(hi.abs()).max(1e-300) => {
            // Zero span: a window around the value (half a decade on a log axis).
            let half = if map.log {
                0.5
            } else if lo.abs() > 0.0 {
                0.1 * lo.abs()
            } else {
                1.0
            };
            (lo - half, hi + half)
        }
        Some((lo, hi)) => {
            let pad = AUTO_RANGE_PAD * (hi - lo);
            (lo - pad, hi + pad)
        }
    }
}

/// Widens the ranges about their centres so that both axes have the same units per pixel.
pub(super) fn equalize(frame: &mut Frame, (w, h): (u32, u32)) {
    let (w, h) = (f64::from(w.max(1)), f64::from(h.max(1)));
    let per_px = ((frame.x.1 - frame.x.0) / w).max((frame.y.1 - frame.y.0) / h);
    let widen = |(lo, hi): (f64, f64), px: f64| {
        let c = 0.5 * (lo + hi);
        (c - 0.5 * per_px * px, c + 0.5 * per_px * px)
    };
    frame.x = widen(frame.x, w);
    frame.y = widen(frame.y, h);
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: Frame = Frame {
        x: (0.0, 1.0),
        y: (0.0, 1.0),
    };

    #[test]
    fn nan_breaks_a_line_into_pieces() {
        let nan = f64::NAN;
        let pts = [
            (0.1, 0.1),
            (0.2, 0.2),
            (nan, 0.5),
            (0.3, 0.3),
            (0.4, 0.4),
            (0.5, nan),
            (0.6, 0.6),
        ];
        let lines = polylines(&pts, &UNIT);
        assert_eq!(
            lines,
            vec![
                vec![(0.1, 0.1), (0.2, 0.2)],
                vec![(0.3, 0.3), (0.4, 0.4)],
                vec![(0.6, 0.6)]
            ]
        );
    }

    #[test]
    fn leaving_and_reentering_the_frame_splits_the_line() {
        let pts = [(0.5, 0.5), (1.5, 0.5), (1.5, 0.8), (0.5, 0.8)];
        let lines = polylines(&pts, &UNIT);
        assert_eq!(
            lines,
            vec![vec![(0.5, 0.5), (1.0, 0.5)], vec![(1.0, 0.8), (0.5, 0.8)]]
        );
    }

    #[test]
    fn clip_crossing_segment() {
        let (a, b, moved_a, moved_b) = UNIT.clip((-1.0, 0.5), (2.0, 0.5)).unwrap();
        assert_eq!(
            (a, b, moved_a, moved_b),
            ((0.0, 0.5), (1.0, 0.5), true, true)
        );
        assert!(UNIT.clip((-1.0, 2.0), (2.0, 2.0)).is_none());
    }

    #[test]
    fn zero_span_and_missing_data_give_usable_ranges() {
        let lin = AxisMap { log: false };
        assert_eq!(axis_range(None, None, lin), (0.0, 1.0));
        assert_eq!(axis_range(None, Some((0.0, 0.0)), lin), (-1.0, 1.0));
        let (lo, hi) = axis_range(None, Some((5.0, 5.0)), lin);
        assert!((lo - 4.5).abs() < 1e-12 && (hi - 5.5).abs() < 1e-12);
        let log = AxisMap { log: true };
        assert_eq!(axis_range(Some((1.0, 100.0)), None, log), (0.0, 2.0));
        assert!(log.forward(0.0).is_nan() && log.forward(-1.0).is_nan());
    }

    #[test]
    fn robust_span_leaves_out_isolated_extremes_only() {
        // A smooth ramp keeps both ends.
        let mut ramp: Vec<f64> = (0..500).map(|i| f64::from(i) * 0.01).collect();
        assert_eq!(robust_span(&mut ramp), Some((0.0, 4.99)));
        // One vertical-face sample (the S1002 flange back evaluates to -1e6) is left out.
        let mut face = ramp.clone();
        face.push(-1e6);
        assert_eq!(robust_span(&mut face), Some((0.0, 4.99)));
        // A pole: values growing without bound over a few samples at one end.
        let mut pole: Vec<f64> = (0..500).map(|i| f64::from(i % 50) * 0.1).collect();
        pole.extend([10.0, 30.0, 100.0, 1e3, 1e4]);
        assert_eq!(robust_span(&mut pole), Some((0.0, 4.9)));
        // A peak standing out by less than half the span is shown whole.
        let mut peak: Vec<f64> = (0..500).map(|i| f64::from(i % 50) * 0.1).collect();
        peak.extend([5.5, 6.0, 6.5]);
        assert_eq!(robust_span(&mut peak), Some((0.0, 6.5)));
        // Too few values to tell an extreme from data: all kept.
        let mut few = vec![0.0, 1.0, 1e6];
        assert_eq!(robust_span(&mut few), Some((0.0, 1e6)));
        assert_eq!(robust_span(&mut []), None);
    }

    #[test]
    fn equalize_gives_same_units_per_pixel() {
        let mut f = Frame {
            x: (0.0, 100.0),
            y: (0.0, 10.0),
        };
        equalize(&mut f, (500, 400));
        let per_px_x = (f.x.1 - f.x.0) / 500.0;
        let per_px_y = (f.y.1 - f.y.0) / 400.0;
        assert!((per_px_x - per_px_y).abs() < 1e-12);
        assert!((f.y.0 + f.y.1 - 10.0).abs() < 1e-12, "centred");
    }
}
