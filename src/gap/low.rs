//! The low regions of the gap: the stretches of the wheel the quasi-elastic pass
//! integrates, found by the coarse scan with blocks skipped where their bound reaches the
//! threshold (checked against a full scan in `gap/tests.rs`).

use super::scan::{SCAN_BLOCK, block_samples};
use super::{SideGap, SidePose};

impl SideGap<'_> {
    /// Stretches of the wheel (`(s_lo, s_hi)`, increasing, disjoint) where the coarse gap
    /// lies below `threshold` (mm, same reference as [`GapPoint::g`]), each widened by one
    /// coarse step so that the fine gap below the threshold lies inside.
    pub(crate) fn low_regions(&self, pose: &SidePose, threshold: f64, out: &mut Vec<(f64, f64)>) {
        out.clear();
        let n = self.coarse.len();
        // Samples outside `first..last` cannot lie above the rail (see `basins`): they are
        // not low, exactly as the table would answer.
        let (first, last) = self.over_rail(pose);
        if first >= last {
            return;
        }
        let mut open: Option<usize> = None;
        let close = |first_low: usize, i: usize, out: &mut Vec<(f64, f64)>| {
            let lo = self.coarse[first_low.saturating_sub(1)][0];
            let hi = self.coarse[i.min(n - 1)][0];
            match out.last_mut() {
                Some(last) if last.1 >= lo => last.1 = hi,
                _ => out.push((lo, hi)),
            }
        };
        for b in first / SCAN_BLOCK..(last - 1) / SCAN_BLOCK + 1 {
            // A block whose bound reaches the threshold has no low sample.
            let skip = self.block_bound(b, pose) >= threshold;
            for i in block_samples(b, first, last) {
                let low = !skip && self.coarse_gap(i, pose) < threshold;
                match (low, open) {
                    (true, None) => open = Some(i),
                    (false, Some(first_low)) => {
                        close(first_low, i, out);
                        open = None;
                    }
                    _ => {}
                }
            }
        }
        if let Some(first_low) = open {
            close(first_low, last, out);
        }
    }
}
