//! How far the gap rises between two of its minima: the hollow a contact point crosses when
//! it jumps from one to the other (`rigid` tells sampling artefacts from real jumps by it).

use super::{SideGap, SidePose};

/// The largest distance between the samples of the gap between two minima (mm): the
/// highest sample lies within `g'' h² / 8` of the highest point, 3e-5 mm for a relative
/// curvature of 0.1 / mm (a flange root) at 0.05 mm, before the parabola through it and its
/// neighbours refines it further.
const HOLLOW_STEP_MM: f64 = 0.05;
/// The fewest intervals the gap between two minima is sampled in.
const HOLLOW_MIN_INTERVALS: usize = 8;

impl SideGap<'_> {
    /// The hollow between two points of the gap at `pose`, `(s, g)` each (mm): how far the
    /// gap rises between them above the higher of the two (mm, 0 where it does not rise).
    /// Between two minima of the gap it is the depth of the ridge the contact point crosses
    /// when it jumps from one to the other. The highest point is found among samples at
    /// most [`HOLLOW_STEP_MM`] apart and refined by the parabola through the highest and
    /// its neighbours. `None` where a point between them is not above the rail or outside
    /// the wheel.
    pub(crate) fn hollow(&self, pose: &SidePose, a: (f64, f64), b: (f64, f64)) -> Option<f64> {
        let g = self.samples_between(pose, a.0, b.0)?;
        let n = g.len() - 1;
        let (mut top, mut at) = (f64::NEG_INFINITY, 0);
        for (i, &gi) in g.iter().enumerate() {
            if gi > top {
                (top, at) = (gi, i);
            }
        }
        if at > 0 && at < n {
            // The vertex of the parabola through the highest sample and its neighbours.
            let (l, m, r) = (g[at - 1], g[at], g[at + 1]);
            let curvature = l - 2.0 * m + r;
            if curvature < 0.0 {
                top = m - (r - l) * (r - l) / (8.0 * curvature);
            }
        }
        Some((top - a.1.max(b.1)).max(0.0))
    }

    /// The gap at `pose` at evenly spaced points from the lower of `a` and `b` to the higher,
    /// at most [`HOLLOW_STEP_MM`] apart, at least [`HOLLOW_MIN_INTERVALS`] intervals.
    fn samples_between(&self, pose: &SidePose, a: f64, b: f64) -> Option<Vec<f64>> {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        let n = (((hi - lo) / HOLLOW_STEP_MM).ceil() as usize).max(HOLLOW_MIN_INTERVALS);
        let h = (hi - lo) / n as f64;
        (0..=n)
            .map(|i| Some(self.at(lo + h * i as f64, pose)?.g))
            .collect()
    }

    /// Whether the wheel or the rail of this side is a sampled profile (read from a file):
    /// a spline through points, whose shape between the points its sampling decides.
    pub(crate) fn is_sampled(&self) -> bool {
        self.pair.wheel.profile().is_sampled() || self.pair.rail.profile().is_sampled()
    }
}
