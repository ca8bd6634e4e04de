//! The coarse scans of the wheel against the rail's height table: the basins of the gap
//! (brackets to refine) here, its low regions (what the quasi-elastic pass integrates) in
//! `low.rs`, with blocks of samples skipped where a bound shows they cannot matter.
//!
//! The height table keeps block maxima in a sparse table, so that a scan can bound the gap
//! of [`SCAN_BLOCK`] wheel samples at once (their lowest point against the highest rail point
//! under them) and skip blocks that cannot hold a basin or a low region. The unit tests in
//! `gap/tests.rs` (`skipping_blocks_finds_the_basins_and_low_regions_of_a_full_scan`) check
//! that the scans find exactly what a full scan finds.

use super::{Basin, COARSE_MARGIN_MM, SideGap, SidePose};

/// Coarse samples per block of the scans: a block whose lower bound of the gap (its lowest
/// wheel point against the highest rail point under it) is too high to matter is skipped.
pub(super) const SCAN_BLOCK: usize = 8;
/// Block bounds kept on the stack by a scan (a wheel of 256 mm at the coarse step); a scan
/// over more computes them twice.
const MAX_SCAN_BLOCKS: usize = 128;

/// The coarse samples of block `b` inside `first..last`.
#[inline]
pub(super) fn block_samples(b: usize, first: usize, last: usize) -> std::ops::Range<usize> {
    (b * SCAN_BLOCK).max(first)..((b + 1) * SCAN_BLOCK).min(last)
}

/// Keeps the coarse minimum `(g, i)` among the lowest `found.len()`.
#[inline]
fn record(found: &mut [(f64, usize); 16], count: &mut usize, g: f64, i: usize) {
    if *count < found.len() {
        found[*count] = (g, i);
        *count += 1;
    } else if let Some(worst) = found
        .iter_mut()
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .filter(|w| w.0 > g)
    {
        *worst = (g, i);
    }
}
impl SideGap<'_> {
    /// Basins of the gap found by the coarse scan: brackets around every sampled local
    /// minimum within [`COARSE_MARGIN_MM`] of the lowest, lowest first.
    pub(crate) fn basins(&self, pose: &SidePose, out: &mut Vec<Basin>) {
        out.clear();
        // Only wheel samples that can lie above the rail.
        let (first, last) = self.over_rail(pose);
        let coarse = &self.coarse[first..last];
        let n = coarse.len();
        if n == 0 {
            return;
        }
        // The lowest sample is a sampled local minimum, and the lowest of them: a block
        // whose bound lies more than the margin above some sample's gap holds no minimum
        // that is refined. The block with the lowest bound gives that sample first.
        let blocks = first / SCAN_BLOCK..(last - 1) / SCAN_BLOCK + 1;
        let mut bounds = [0.0; MAX_SCAN_BLOCKS];
        let stored = blocks.len() <= MAX_SCAN_BLOCKS;
        let bound = |b: usize, bounds: &[f64]| {
            if stored {
                bounds[b - blocks.start]
            } else {
                self.block_bound(b, pose)
            }
        };
        let mut best = (f64::INFINITY, blocks.start);
        for b in blocks.clone() {
            let v = self.block_bound(b, pose);
            if stored {
                bounds[b - blocks.start] = v;
            }
            if v < best.0 {
                best = (v, b);
            }
        }
        let b = best.1;
        let mut running = block_samples(b, first, last)
            .fold(f64::INFINITY, |m, i| m.min(self.coarse_gap(i, pose)));
        // Sampled local minima `(gap, index)`, the lowest few kept (more than 16 coarse
        // minima within one wheel would be noise; the lowest are the ones refined).
        let mut found: [(f64, usize); 16] = [(0.0, 0); 16];
        let mut count = 0;
        let mut lowest = f64::INFINITY;
        // The gap of sample i is known when sample i + 1 is computed: `here` is sample i - 1.
        // Samples of skipped blocks count as off the rail (+inf): higher than any sample
        // that could be refined, so the minima that matter are found as without skipping.
        let (mut prev, mut here) = (f64::INFINITY, f64::INFINITY);
        for b in blocks.clone() {
            let skip = bound(b, &bounds) > running + COARSE_MARGIN_MM;
            for i in block_samples(b, first, last) {
                let next = if skip {
                    f64::INFINITY
                } else {
                    self.coarse_gap(i, pose)
                };
                running = running.min(next);
                if here <= prev && here <= next && here < f64::INFINITY {
                    lowest = lowest.min(here);
                    record(&mut found, &mut count, here, i - first - 1);
                }
                prev = here;
                here = next;
            }
        }
        // The last sample has no right neighbour.
        if here <= prev && here < f64::INFINITY {
            lowest = lowest.min(here);
            record(&mut found, &mut count, here, n - 1);
        }
        let found = &mut found[..count];
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(g, i) in found.iter() {
            if g <= lowest + COARSE_MARGIN_MM {
                let lo = coarse[i.saturating_sub(1)][0];
                let hi = coarse[(i + 1).min(n - 1)][0];
                out.push((lo, hi));
            }
        }
    }

    /// The coarse gap (table rail) of sample `i`, `+inf` where it is not above the rail.
    #[inline]
    pub(super) fn coarse_gap(&self, i: usize, pose: &SidePose) -> f64 {
        let [_, yw, zw] = self.coarse[i];
        let [y, z] = pose.apply(yw, zw);
        self.pair
            .rail
            .heights()
            .height(y)
            .map_or(f64::INFINITY, |zr| z - zr)
    }

    /// A lower bound of the coarse gaps of block `b` at `pose` (`+inf` when none of its
    /// samples can be above the rail): the lowest its points can be, against the highest
    /// the rail table is under the lateral span they can cover.
    #[inline]
    pub(super) fn block_bound(&self, b: usize, pose: &SidePose) -> f64 {
        let [yw_lo, yw_hi, zw_lo, zw_hi] = self.blocks[b];
        let (cos, sin) = (pose.cos, pose.sin);
        // Y = delta + cos Yw - sin Zw, z = sin Yw + cos Zw (cos > 0); Yw and Zw vary
        // independently within their ranges, so the extremes lie at range ends.
        let (a, c) = (-sin * zw_lo, -sin * zw_hi);
        let y_lo = pose.delta + cos * yw_lo + a.min(c);
        let y_hi = pose.delta + cos * yw_hi + a.max(c);
        let z_lo = (sin * yw_lo).min(sin * yw_hi) + cos * zw_lo;
        self.pair
            .rail
            .heights()
            .max_over(y_lo, y_hi)
            .map_or(f64::INFINITY, |rail| z_lo - rail)
    }

    /// The index range of the coarse samples that can lie above the rail at `pose`:
    /// `Y = delta + Yw +- |sin phi| |Zw|`, with one sample more on each side.
    pub(super) fn over_rail(&self, pose: &SidePose) -> (usize, usize) {
        let (y_lo, y_hi) = self.pair.rail.y_range();
        // Y = delta + cos Yw - sin Zw differs from delta + Yw by at most
        // |sin| |Zw| + (1 - cos) |Yw|, with |Zw| <= r0 + 100 and |Yw| <= taping line + 100:
        // the second term is 13 mm at a roll of 0.19 rad (very unequal wheel radii).
        let wheel = &self.pair.wheel;
        let reach = pose.sin.abs() * (wheel.nominal_radius_mm() + 100.0)
            + (1.0 - pose.cos) * (wheel.taping_line_mm() + 100.0)
            + 1.0;
        let first = self
            .coarse
            .partition_point(|c| pose.delta + c[1] < y_lo - reach)
            .saturating_sub(1);
        let last = (self
            .coarse
            .partition_point(|c| pose.delta + c[1] <= y_hi + reach)
            + 1)
        .min(self.coarse.len());
        (first, last)
    }
}
