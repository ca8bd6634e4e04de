//! The low regions of the gap: the stretches of the wheel the quasi-elastic pass
//! integrates, found by the coarse scan with blocks skipped where their bound reaches the
//! threshold.
//!
//! Bounds are taken on two levels: a group of [`GROUP_BLOCKS`] blocks first (the lowest
//! point of all its wheel samples against the highest rail point under their lateral span),
//! then each block of a group that may hold a low sample. A group's wheel extents contain
//! those of each of its blocks, so its bound lies below each block's: a skipped group holds
//! no block the one-level scan would have scanned, and the regions are those of a full
//! scan (checked in `gap/tests.rs`,
//! `skipping_blocks_finds_the_basins_and_low_regions_of_a_full_scan`).
//!
//! The quasi-elastic pass starts from the rigid contact point, where the gap is lowest: the
//! run of low samples around it is followed (its blocks would not be skipped anyway), a
//! whole block at a time where an upper bound of the block's coarse gaps lies below the
//! threshold (`SideGap::block_all_low`, checked in
//! `blocks_shown_all_low_have_only_low_samples`), else sample by sample; only the rest of
//! the wheel is scanned by lower bounds. Every sample's status is still known exactly, so
//! the regions are the same from any start
//! (`following_the_run_from_any_start_finds_the_regions_of_the_scan`).

use super::scan::{SCAN_BLOCK, block_samples};
use super::{SideGap, SidePose};
use std::ops::Range;

/// Blocks per group of the first level of bounds: 16 mm of wheel at the coarse step, about
/// the extent of a low region on the tread, so that most of the wheel is ruled out by a few
/// group bounds.
const GROUP_BLOCKS: usize = 8;

impl SideGap<'_> {
    /// Stretches of the wheel (`(s_lo, s_hi)`, increasing, disjoint) where the coarse gap
    /// lies below `threshold` (mm, same reference as [`GapPoint::g`](super::GapPoint)),
    /// each widened by one coarse step so that the fine gap below the threshold lies inside.
    #[cfg(test)]
    pub(crate) fn low_regions(&self, pose: &SidePose, threshold: f64, out: &mut Vec<(f64, f64)>) {
        self.low_regions_from(pose, threshold, None, out);
    }

    /// [`low_regions`](SideGap::low_regions), knowing that the gap is likely low at the
    /// wheel coordinate `start` (the rigid contact point): the run of low samples around it
    /// is followed sample by sample, without bounds, and only the rest of the wheel is
    /// scanned by blocks. The same regions for any `start`.
    pub(crate) fn low_regions_from(
        &self,
        pose: &SidePose,
        threshold: f64,
        start: Option<f64>,
        out: &mut Vec<(f64, f64)>,
    ) {
        out.clear();
        self.check_yaw(pose);
        // Samples outside `first..last` cannot lie above the rail (see `basins`): they are
        // not low, exactly as the table would answer.
        let (first, last) = self.over_rail(pose);
        if first >= last {
            return;
        }
        let mut runs = Runs {
            side: self,
            open: None,
            out,
        };
        let low = |i: usize| self.coarse_gap(i, pose) < threshold;
        let start = start.map(|s| {
            let i = self.coarse.partition_point(|c| c[0] < s);
            i.clamp(first, last - 1)
        });
        match start {
            Some(i) if low(i) => {
                // The run a..=b around i, and the high samples a - 1 and b + 1 (if any):
                // a whole block at a time where its bound shows every sample low.
                let all_low = |b: usize| self.block_all_low(b, pose, threshold);
                let (mut a, mut b) = (i, i);
                loop {
                    if a % SCAN_BLOCK == 0 && a >= first + SCAN_BLOCK && all_low(a / SCAN_BLOCK - 1)
                    {
                        a -= SCAN_BLOCK;
                    } else if a > first && low(a - 1) {
                        a -= 1;
                    } else {
                        break;
                    }
                }
                loop {
                    if (b + 1) % SCAN_BLOCK == 0
                        && b + SCAN_BLOCK < last
                        && all_low((b + 1) / SCAN_BLOCK)
                    {
                        b += SCAN_BLOCK;
                    } else if b + 1 < last && low(b + 1) {
                        b += 1;
                    } else {
                        break;
                    }
                }
                if a > first {
                    self.scan_blocks(pose, threshold, first..a - 1, &mut runs);
                    runs.high(a - 1);
                }
                runs.low(a);
                if b + 1 < last {
                    runs.high(b + 1);
                    self.scan_blocks(pose, threshold, b + 2..last, &mut runs);
                }
            }
            _ => self.scan_blocks(pose, threshold, first..last, &mut runs),
        }
        runs.high(last);
    }

    /// The coarse samples `samples` into `runs`, by groups of blocks, then blocks, then
    /// samples, each level skipped where its bound reaches the threshold.
    fn scan_blocks(&self, pose: &SidePose, threshold: f64, samples: Range<usize>, runs: &mut Runs) {
        let Range {
            start: first,
            end: last,
        } = samples;
        if first >= last {
            return;
        }
        let blocks = first / SCAN_BLOCK..(last - 1) / SCAN_BLOCK + 1;
        // Groups aligned on multiples of GROUP_BLOCKS, their extents tabulated; the first
        // and last may hold fewer of the scanned blocks, and their whole group's extent
        // holds those blocks' extents.
        let mut next = blocks.start;
        while next < blocks.end {
            let g = next / GROUP_BLOCKS;
            let group = next..((g + 1) * GROUP_BLOCKS).min(blocks.end);
            next = group.end;
            // A group or block whose bound reaches the threshold has no low sample (the
            // bound covers every sample of its blocks, in `samples` or not).
            if self.extent_bound(self.group_extents[g], pose) >= threshold {
                runs.high((group.start * SCAN_BLOCK).max(first));
                continue;
            }
            for b in group {
                if self.extent_bound(self.blocks[b], pose) >= threshold {
                    runs.high((b * SCAN_BLOCK).max(first));
                    continue;
                }
                for i in block_samples(b, first, last) {
                    if self.coarse_gap(i, pose) < threshold {
                        runs.low(i);
                    } else {
                        runs.high(i);
                    }
                }
            }
        }
    }

    /// The wheel extents of the groups of [`GROUP_BLOCKS`] blocks aligned on its multiples
    /// (the last group holding the blocks left), into `out`, for [`SideGap::new`].
    pub(super) fn group_extents(&self, out: &mut Vec<[f64; 4]>) {
        out.clear();
        out.extend(
            (0..self.blocks.len())
                .step_by(GROUP_BLOCKS)
                .map(|g| self.extent(g..(g + GROUP_BLOCKS).min(self.blocks.len()))),
        );
    }

    /// The wheel extents `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]` of a run of blocks.
    #[inline]
    fn extent(&self, blocks: Range<usize>) -> [f64; 4] {
        let run = &self.blocks[blocks];
        let (z_lo, z_hi) = run
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), e| {
                (a.min(e[2]), b.max(e[3]))
            });
        [run[0][0], run[run.len() - 1][1], z_lo, z_hi]
    }
}

/// The runs of low coarse samples of a scan, closed into regions as the scan goes.
struct Runs<'s, 'a, 'o> {
    side: &'s SideGap<'a>,
    /// The first low sample of the run being scanned.
    open: Option<usize>,
    out: &'o mut Vec<(f64, f64)>,
}

impl Runs<'_, '_, '_> {
    /// Sample `i` is low.
    #[inline]
    fn low(&mut self, i: usize) {
        self.open.get_or_insert(i);
    }

    /// Sample `i` (or the sample after the last) is not low: the open run ends before it.
    #[inline]
    fn high(&mut self, i: usize) {
        let Some(first_low) = self.open.take() else {
            return;
        };
        let coarse = &self.side.coarse;
        let lo = coarse[first_low.saturating_sub(1)][0];
        let hi = coarse[i.min(coarse.len() - 1)][0];
        match self.out.last_mut() {
            Some(last) if last.1 >= lo => last.1 = hi,
            _ => self.out.push((lo, hi)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::{RigidSweep, Solver, search};
    use crate::track::Placement;

    /// The paper placement and its rigid sweep over `n + 1` positions 0.5 mm apart from
    /// `from` (mm).
    fn paper_sweep(from: f64, n: u32) -> (Placement, RigidSweep) {
        let placement = super::super::tests::placement();
        let ys: Vec<f64> = (0..=n).map(|i| from + 0.5 * f64::from(i)).collect();
        let sweep = search(
            &placement,
            &crate::sweep::Sweep::from_slice(&ys).unwrap(),
            Solver::default(),
        );
        (placement, sweep)
    }

    /// A group's bound lies below the bound of each of its blocks (so a skipped group
    /// skips only blocks the one-level scan skips: the regions equal a full scan's, as
    /// `gap::tests` checks), and over the paper sweep groups are skipped.
    #[test]
    fn group_bounds_lie_below_their_blocks_and_rule_out_most_of_the_wheel() {
        let (placement, sweep) = paper_sweep(-15.0, 60);
        let side = SideGap::new(&placement.left, 1.0);
        let (mut groups, mut skipped) = (0, 0);
        for p in sweep.positions() {
            let pose = SidePose::new(1.0, p.y_ws, p.roll);
            let rigid = side.at(p.contact[0].unwrap().s, &pose).unwrap().g;
            // The default threshold: 25 eps of 0.01 mm and the coarse margin.
            let threshold = rigid + 0.25 + crate::gap::COARSE_MARGIN_MM;
            for group in (0..side.blocks.len()).step_by(GROUP_BLOCKS) {
                let group = group..(group + GROUP_BLOCKS).min(side.blocks.len());
                let extent = side.extent(group.clone());
                let tabulated = side.group_extents[group.start / GROUP_BLOCKS];
                assert_eq!(tabulated.map(f64::to_bits), extent.map(f64::to_bits));
                let bound = side.extent_bound(extent, &pose);
                for b in group {
                    let block = side.extent_bound(side.blocks[b], &pose);
                    assert!(bound <= block, "group {bound} above block {b} {block}");
                }
                groups += 1;
                skipped += usize::from(bound >= threshold);
            }
        }
        assert!(2 * skipped > groups, "{skipped} of {groups} groups skipped");
    }

    /// A block that `block_all_low` passes has every coarse sample below the threshold,
    /// on both wheels over the paper sweep at thresholds from 1e-3 to 10 mm above the rigid
    /// minimum; and blocks pass (the run is followed a block at a time).
    #[test]
    fn blocks_shown_all_low_have_only_low_samples() {
        let (placement, sweep) = paper_sweep(-20.0, 80);
        let (mut passed, mut blocks) = (0, 0);
        for (side, sign, k) in [(&placement.left, 1.0, 0), (&placement.right, -1.0, 1)] {
            let side = SideGap::new(side, sign);
            for p in sweep.positions() {
                let pose = SidePose::new(sign, p.y_ws, p.roll);
                let g = side.at(p.contact[k].unwrap().s, &pose).unwrap().g;
                for above in [1e-3, 0.01, 0.1, 0.3, 1.0, 10.0] {
                    let threshold = g + above;
                    for b in 0..side.blocks.len() {
                        blocks += 1;
                        if !side.block_all_low(b, &pose, threshold) {
                            continue;
                        }
                        passed += 1;
                        for i in block_samples(b, 0, side.coarse.len()) {
                            let gap = side.coarse_gap(i, &pose);
                            assert!(gap < threshold, "block {b} sample {i}: {gap} {threshold}");
                        }
                    }
                }
            }
        }
        assert!(passed > 2000 && passed < blocks, "{passed} of {blocks}");
    }

    /// Following the run around a start point finds the regions of the scan without one
    /// (itself checked against a full scan in `gap::tests`), from the rigid contact point,
    /// from 41 points along the wheel and from outside it, at thresholds from 1e-3 to 10 mm
    /// above the rigid minimum and at the sampled local maxima of the gap.
    #[test]
    fn following_the_run_from_any_start_finds_the_regions_of_the_scan() {
        let (placement, sweep) = paper_sweep(-20.0, 80);
        let (mut expected, mut found) = (Vec::new(), Vec::new());
        let mut followed = 0;
        for (side, sign, k) in [(&placement.left, 1.0, 0), (&placement.right, -1.0, 1)] {
            let side = SideGap::new(side, sign);
            let (lo, hi) = side.domain;
            for p in sweep.positions() {
                let pose = SidePose::new(sign, p.y_ws, p.roll);
                let rigid = p.contact[k].unwrap().s;
                let g = side.at(rigid, &pose).unwrap().g;
                // Thresholds above the rigid minimum, and at each sampled local maximum of
                // the gap: that sample alone is high between low neighbours.
                let (first, last) = side.over_rail(&pose);
                let gap = |i: usize| side.coarse_gap(i, &pose);
                let maxima = (first + 1..last - 1)
                    .filter(|&i| gap(i - 1) < gap(i) && gap(i + 1) < gap(i))
                    .map(gap);
                let above = [1e-3, 3e-3, 0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0].map(|a| g + a);
                for threshold in above.into_iter().chain(maxima) {
                    side.low_regions(&pose, threshold, &mut expected);
                    let along = (0..=40).map(|j| lo + (hi - lo) * f64::from(j) / 40.0);
                    for start in [rigid, lo - 5.0, hi + 5.0].into_iter().chain(along) {
                        side.low_regions_from(&pose, threshold, Some(start), &mut found);
                        assert_eq!(found, expected, "from {start} at {pose:?}, {threshold}");
                        let i = side.coarse.partition_point(|c| c[0] < start);
                        followed += usize::from(
                            side.coarse_gap(i.clamp(first, last - 1), &pose) < threshold,
                        );
                    }
                }
            }
        }
        assert!(followed > 5000, "a run was followed {followed} times");
    }
}
