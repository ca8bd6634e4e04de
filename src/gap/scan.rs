//! The coarse scans of the wheel against the rail's height table: the basins of the gap
//! (brackets to refine) here, its low regions (what the quasi-elastic pass integrates) in
//! `low.rs`, with blocks of samples skipped where a bound shows they cannot matter.
//!
//! The height table keeps block maxima in a sparse table, so that a scan can bound the gap
//! of [`SCAN_BLOCK`] wheel samples at once (their lowest point against the highest rail point
//! under them) and skip blocks that cannot hold a basin or a low region. The unit tests in
//! `gap/tests.rs` (`skipping_blocks_finds_the_basins_and_low_regions_of_a_full_scan`) check
//! that the scans find exactly what a full scan finds. A scan reads block bounds made once
//! for a box of poses about it ([`PoseBox`]) and bounds at its own pose only the blocks those
//! leave, which changes the work, not the basins.
//!
//! The scan for basins bounds its blocks rigorously: the wheel over the block's cells (not
//! only its samples, [`crate::track::PlacedWheel`] cell bounds) against the highest the
//! exact rail can be under the lateral span they cover, widened by a step of the height
//! table (so that the bound lies below the table's samples too, which interpolate exact
//! heights at most a step away). A block it skips is then a block whose every point lies
//! above the lowest sample plus [`COARSE_MARGIN_MM`], which the certificate of the global
//! minimum at the same pose (`certify.rs`) reads together with the samples the scan
//! evaluated ([`Scanned`]).

use super::pose_box::PoseBox;
use super::{Basin, COARSE_MARGIN_MM, SideGap, SidePose};
use crate::track::HeightTable;
use wide::f64x4;

/// What a scan for basins saw at its pose, for the certificate of the global minimum there
/// (`certify.rs`): which blocks it evaluated, their samples' coarse gaps, the lowest of them.
#[derive(Debug, Clone, Default)]
pub(crate) struct Scanned {
    /// The pose scanned, `None` before the first scan.
    pub(super) pose: Option<SidePose>,
    /// The coarse samples that can lie above the rail, `first..last` ([`SideGap::over_rail`]).
    pub(super) range: (usize, usize),
    /// Per coarse sample, its coarse gap where its block was evaluated (stale elsewhere).
    pub(super) gaps: Vec<f64>,
    /// Per block, the scan (counted in `generation`) that last evaluated its samples: no
    /// clearing per scan.
    stamps: Vec<u32>,
    /// The number of the last scan.
    generation: u32,
    /// Per block the scan evaluated, the lowest coarse gap of its samples.
    pub(super) block_min: Vec<f64>,
    /// Per block the scan evaluated, whether all its samples lie over the rail (finite).
    block_on_rail: Vec<bool>,
    /// The lowest coarse gap the scan evaluated: every skipped block lies above it plus
    /// [`COARSE_MARGIN_MM`] at every point.
    pub(super) lowest: f64,
    /// The certificate's per-minimum zones (a buffer reused, `certify.rs`).
    pub(super) zones: Vec<(usize, usize)>,
}

impl Scanned {
    /// The pose scanned, `None` before the first scan.
    pub(crate) fn pose(&self) -> Option<SidePose> {
        self.pose
    }

    /// Whether the scan evaluated the samples of block `b`.
    #[inline]
    pub(super) fn evaluated(&self, b: usize) -> bool {
        self.stamps[b] == self.generation
    }

    /// Records that the samples of block `b` were evaluated, with what
    /// [`SideGap::block_gaps`] returned for them: the gaps (written into [`Self::gaps`]),
    /// their lowest and whether all are over the rail.
    #[inline]
    pub(super) fn record(&mut self, b: usize, (lowest, on_rail): (f64, bool)) {
        self.stamps[b] = self.generation;
        self.block_min[b] = lowest;
        self.block_on_rail[b] = on_rail;
    }

    /// Whether all samples of block `b`, which the scan evaluated, lie over the rail.
    #[inline]
    pub(super) fn on_rail(&self, b: usize) -> bool {
        self.block_on_rail[b]
    }
}

/// How far below the threshold [`SideGap::block_all_low`] wants its bound (mm): the
/// sample's own rounding (the pose applied, the height interpolated between two entries
/// above their minimum) moves its coarse gap by ulps of the 500 mm wheel radius, 1e-13 mm;
/// this margin covers that 10,000 times, and costs nothing measurable (a block that close
/// to the threshold is checked sample by sample).
pub(super) const ALL_LOW_MARGIN_MM: f64 = 1e-9;

/// The side-frame span `[Y_lo, Y_hi, z_lo, z_hi]` of the wheel points with `Yw` and `Zw`
/// within `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]` at `pose`, by the operations of
/// [`SidePose::apply`] on the range ends: rounding is monotone in each operand, so the
/// span holds each point's own rounded `Y` and `z`.
#[inline]
fn extent_span([yw_lo, yw_hi, zw_lo, zw_hi]: [f64; 4], pose: &SidePose) -> [f64; 4] {
    let (cos, sin) = (pose.cos, pose.sin);
    // Y = delta + cos Yw - sin Zw, z = sin Yw + cos Zw (cos > 0); Yw and Zw vary
    // independently within their ranges, so the extremes lie at range ends.
    let (a, c) = (-sin * zw_lo, -sin * zw_hi);
    let y_lo = pose.delta + cos * yw_lo + a.min(c);
    let y_hi = pose.delta + cos * yw_hi + a.max(c);
    let (u, v) = (sin * yw_lo, sin * yw_hi);
    [y_lo, y_hi, u.min(v) + cos * zw_lo, u.max(v) + cos * zw_hi]
}

/// Coarse samples per block of the scans: a block whose lower bound of the gap (its lowest
/// wheel point against the highest rail point under it) is too high to matter is skipped.
/// Wider blocks have looser bounds (more samples evaluated in vain) but fewer bounds, box
/// entries and certificate blocks; 16 does the least work of the paper sweep among 4, 8, 16
/// and 32.
pub(super) const SCAN_BLOCK: usize = 16;

/// The coarse samples of block `b` inside `first..last`.
#[inline]
pub(super) fn block_samples(b: usize, first: usize, last: usize) -> std::ops::Range<usize> {
    (b * SCAN_BLOCK).max(first)..((b + 1) * SCAN_BLOCK).min(last)
}

/// The index of the lowest of `bounds` (the first of equals; 0 where all are NaN or the
/// slice is empty): a plain compare, where `min_by(total_cmp)` costs a dozen instructions
/// per element. Which block is taken first changes the work of a scan, not its basins.
#[inline]
fn lowest_bound(bounds: &[f64]) -> usize {
    let (mut best, mut low) = (0, f64::INFINITY);
    for (k, &v) in bounds.iter().enumerate() {
        if v < low {
            (best, low) = (k, v);
        }
    }
    best
}

/// The coarse gap of the wheel point `(yw, zw)` at `pose` against the rail's height
/// `table`, `+inf` where it is not above the rail: what [`SideGap::block_gaps`] computes in
/// lanes.
#[inline(always)]
fn sample_gap(table: &HeightTable, pose: &SidePose, yw: f64, zw: f64) -> f64 {
    let [y, z] = pose.apply(yw, zw);
    table.height(y).map_or(f64::INFINITY, |zr| z - zr)
}

/// The lower of `low` and `g`, as `f64::min` where `g` is NaN (passed over) without its NaN
/// handling: the running minimum of the coarse gaps.
#[inline(always)]
fn lower(low: f64, g: f64) -> f64 {
    if g < low { g } else { low }
}

/// The sampled local minima of a scan for basins, followed sample by sample: `(gap,
/// index)` of the lowest few (more than 16 coarse minima within one wheel would be noise;
/// the lowest are the ones refined), and the lowest of all.
struct SampledMinima {
    found: [(f64, usize); 16],
    count: usize,
    lowest: f64,
    /// The gaps of the two samples before the next one (`+inf` before the first, and for
    /// the samples of a skipped block): the next one tells whether `here` is a minimum.
    prev: f64,
    here: f64,
}

impl SampledMinima {
    fn new() -> SampledMinima {
        SampledMinima {
            found: [(0.0, 0); 16],
            count: 0,
            lowest: f64::INFINITY,
            prev: f64::INFINITY,
            here: f64::INFINITY,
        }
    }

    /// Whether `here`, between `prev` and `next`, is a sampled local minimum (over the rail).
    #[inline(always)]
    fn is_minimum(prev: f64, here: f64, next: f64) -> bool {
        here <= prev && here <= next && here < f64::INFINITY
    }

    /// Keeps the minimum `g` of the sample `i` (counted from the scan's first).
    #[inline]
    fn keep(&mut self, g: f64, i: usize) {
        self.lowest = self.lowest.min(g);
        if self.count < self.found.len() {
            self.found[self.count] = (g, i);
            self.count += 1;
        } else if let Some(worst) = self
            .found
            .iter_mut()
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .filter(|w| w.0 > g)
        {
            *worst = (g, i);
        }
    }

    /// The next sample `i` (counted from the scan's first) with gap `next`.
    #[inline(always)]
    fn step(&mut self, next: f64, i: usize) {
        if Self::is_minimum(self.prev, self.here, next) {
            self.keep(self.here, i - 1);
        }
        (self.prev, self.here) = (self.here, next);
    }

    /// The samples `i0..` with the gaps `gaps` (an evaluated block), as [`Self::step`] on
    /// each in turn: the same compares and the same minima kept in the same order, four
    /// samples tested at a time in SIMD lanes (minima are rare: a lane mask that is all
    /// zero passes four samples at once), instead of a compare and a branch per sample.
    #[inline]
    fn block(&mut self, gaps: &[f64], i0: usize) {
        let n = gaps.len();
        let mut m = 0;
        if n >= 4 {
            let lanes = |a: usize| f64x4::from([gaps[a], gaps[a + 1], gaps[a + 2], gaps[a + 3]]);
            let inf = f64x4::splat(f64::INFINITY);
            // Lane `l` of a group from sample `m` on: `here` is the gap before sample
            // `m + l`, `prev` the one before that (the first group's from before the block).
            let mut prev = f64x4::from([self.prev, self.here, gaps[0], gaps[1]]);
            let mut here = f64x4::from([self.here, gaps[0], gaps[1], gaps[2]]);
            loop {
                let next = lanes(m);
                let mask =
                    (here.simd_le(prev) & here.simd_le(next) & here.simd_lt(inf)).to_bitmask();
                if mask != 0 {
                    for (l, &g) in here.to_array().iter().enumerate() {
                        if mask & (1 << l) != 0 {
                            self.keep(g, i0 + m + l - 1);
                        }
                    }
                }
                m += 4;
                if m + 4 > n {
                    break;
                }
                (prev, here) = (lanes(m - 2), lanes(m - 1));
            }
            (self.prev, self.here) = (gaps[m - 2], gaps[m - 1]);
        }
        for (k, &next) in gaps.iter().enumerate().skip(m) {
            self.step(next, i0 + k);
        }
    }
}
impl SideGap<'_> {
    /// Basins of the gap found by the coarse scan: brackets around every sampled local
    /// minimum within [`COARSE_MARGIN_MM`] of the lowest, lowest first.
    ///
    /// `pose_box` holds block bounds for a box of poses (made here when `pose` lies outside
    /// it): blocks it shows too high are skipped without bounding them at `pose`. Which
    /// blocks are skipped changes the work, not the basins. `scanned` receives what the
    /// scan saw, for the certificate at this pose.
    pub(crate) fn basins(
        &self,
        pose: &SidePose,
        pose_box: &mut PoseBox,
        scanned: &mut Scanned,
        out: &mut Vec<Basin>,
    ) {
        out.clear();
        count!(Scan, 1);
        self.check_yaw(pose);
        // Only wheel samples that can lie above the rail.
        let (first, last) = self.over_rail(pose);
        let coarse = &self.coarse[first..last];
        let n = coarse.len();
        scanned.pose = Some(*pose);
        scanned.range = (first, last);
        scanned.lowest = f64::INFINITY;
        if scanned.stamps.len() != self.blocks.len() {
            scanned.gaps = vec![f64::INFINITY; self.coarse.len()];
            scanned.block_min = vec![f64::INFINITY; self.blocks.len()];
            scanned.block_on_rail = vec![false; self.blocks.len()];
            scanned.stamps = vec![0; self.blocks.len()];
        }
        scanned.generation = scanned.generation.wrapping_add(1);
        if scanned.generation == 0 {
            // Wrapped: stamps of old scans could match again.
            scanned.stamps.fill(0);
            scanned.generation = 1;
        }
        if n == 0 {
            return;
        }
        // The lowest sample is a sampled local minimum, and the lowest of them: a block
        // whose bound lies more than the margin above some sample's gap holds no minimum
        // that is refined. The block with the lowest box bound gives that sample first.
        if !pose_box.holds(pose) || pose_box.bounds.len() != self.blocks.len() {
            self.fill_pose_box(pose, pose_box);
        }
        let [yc, zc] = pose_box.reference;
        let common = pose.sin * yc + pose.cos * zc;
        let boxed = &pose_box.bounds;
        let blocks = first / SCAN_BLOCK..(last - 1) / SCAN_BLOCK + 1;
        let first_block = lowest_bound(&boxed[blocks.clone()]) + blocks.start;
        // Its gaps are kept in `scanned.gaps` for the loop below, which reaches it too (its
        // bound lies below them, so it is not skipped).
        let first_eval = self.block_gaps(block_samples(first_block, first, last), pose, scanned);
        let mut running = first_eval.0;
        // The gap of sample i is known when sample i + 1 is computed: `here` is sample i - 1.
        // Samples of skipped blocks count as off the rail (+inf): higher than any sample
        // that could be refined, so the minima that matter are found as without skipping.
        let mut minima = SampledMinima::new();
        for b in blocks.clone() {
            let samples = block_samples(b, first, last);
            let above = running + COARSE_MARGIN_MM;
            if boxed[b] + common > above || self.block_bound(b, pose) > above {
                // In one step what its samples at +inf would do one by one: the first makes
                // the sample before the block a minimum where it is not above its own left
                // neighbour; after two, `prev` and `here` are both +inf.
                let SampledMinima { prev, here, .. } = minima;
                if here <= prev && here < f64::INFINITY {
                    minima.keep(here, samples.start - first - 1);
                }
                minima.prev = if samples.len() > 1 {
                    f64::INFINITY
                } else {
                    here
                };
                minima.here = f64::INFINITY;
                continue;
            }
            let eval = if b == first_block {
                first_eval
            } else {
                self.block_gaps(samples.clone(), pose, scanned)
            };
            scanned.record(b, eval);
            let block_min = eval.0;
            if block_min < running {
                running = block_min;
            }
            minima.block(&scanned.gaps[samples.clone()], samples.start - first);
        }
        scanned.lowest = running;
        // The last sample has no right neighbour.
        let SampledMinima { prev, here, .. } = minima;
        if here <= prev && here < f64::INFINITY {
            minima.keep(here, n - 1);
        }
        let lowest = minima.lowest;
        let found = &mut minima.found[..minima.count];
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(g, i) in found.iter() {
            if g <= lowest + COARSE_MARGIN_MM {
                let lo = coarse[i.saturating_sub(1)][0];
                let hi = coarse[(i + 1).min(n - 1)][0];
                out.push((lo, hi));
            }
        }
    }

    /// The coarse gaps of the samples `range` at `pose` into `scanned.gaps[range]` (as
    /// [`Self::coarse_gap`] of each, bit for bit), the lowest of them (`+inf` where none is
    /// above the rail) and whether all are above the rail, for [`Scanned::record`]. One pass
    /// over the samples with the height table's lookup inlined: the inner loop of the scans.
    #[inline]
    pub(super) fn block_gaps(
        &self,
        range: std::ops::Range<usize>,
        pose: &SidePose,
        scanned: &mut Scanned,
    ) -> (f64, bool) {
        // Exactly no roll: the identity of the rotation is what the fast form needs.
        #[allow(clippy::float_cmp)]
        let level = pose.sin == 0.0 && pose.cos == 1.0;
        if level {
            self.block_gaps_posed::<true>(range, pose, scanned)
        } else {
            self.block_gaps_posed::<false>(range, pose, scanned)
        }
    }

    /// [`Self::block_gaps`]; `LEVEL`: the pose has no roll (`sin phi = 0`, `cos phi = 1`,
    /// the level wheelset's), and a wheel point lies at `Y = delta + Yw`, `z = Zw`. Those
    /// are the gaps [`SidePose::apply`] gives, to the bit: `cos Yw` is `Yw`, `sin Zw` and
    /// `sin Yw` are zeros, which leave a sum unchanged but for the sign of a zero `Y`
    /// (`delta + Yw = -0` needs both -0), and the height of a signed zero is the same
    /// height. Four multiplications and two additions fewer a group of four samples, and
    /// a loop the compiler keeps in registers.
    #[inline(always)]
    fn block_gaps_posed<const LEVEL: bool>(
        &self,
        range: std::ops::Range<usize>,
        pose: &SidePose,
        scanned: &mut Scanned,
    ) -> (f64, bool) {
        count!(CoarseSample, range.len());
        let heights = self.rail.heights();
        let lanes = heights.lanes();
        let gaps = &mut scanned.gaps[range.clone()];
        let coarse = &self.coarse[range];
        // Four samples at a time in SIMD lanes: the pose and the interpolation are four
        // independent chains side by side.
        let inf = f64x4::splat(f64::INFINITY);
        let (mut low4, mut on4) = (inf, inf.simd_eq(inf));
        let tail = coarse.len() / 4 * 4;
        let (quads, rest) = gaps.split_at_mut(tail);
        for (g4, c4) in quads.chunks_exact_mut(4).zip(coarse.chunks_exact(4)) {
            let yw = f64x4::from([c4[0][1], c4[1][1], c4[2][1], c4[3][1]]);
            let zw = f64x4::from([c4[0][2], c4[1][2], c4[2][2], c4[3][2]]);
            let [y, z] = if LEVEL {
                [f64x4::splat(pose.delta) + yw, zw]
            } else {
                pose.apply_to(yw, zw)
            };
            let (zr, on_table) = lanes.height(y);
            let g = on_table.select(z - zr, inf);
            g4.copy_from_slice(&g.to_array());
            // Per lane as `f64::min` (a NaN gap is passed over): a NaN compares false.
            low4 = g.simd_lt(low4).select(g, low4);
            // Over the rail: finite (`g < inf` is false for +inf and NaN).
            on4 &= g.simd_lt(inf);
        }
        // The lanes' lowest, then the samples left over. The lowest of a set of gaps does
        // not depend on the order they are visited in: a gap is never -0 (that needs
        // z = -0, but the wheel lies hundreds of mm below the axle), so equal gaps are the
        // same bits.
        let (mut low, mut on_rail) = (f64::INFINITY, on4.all());
        for l in low4.to_array() {
            low = lower(low, l);
        }
        for (g, &[_, yw, zw]) in rest.iter_mut().zip(&coarse[tail..]) {
            *g = sample_gap(heights, pose, yw, zw);
            low = lower(low, *g);
            on_rail &= *g < f64::INFINITY;
        }
        (low, on_rail)
    }

    /// The coarse gap (table rail) of sample `i`, `+inf` where it is not above the rail.
    #[inline]
    pub(super) fn coarse_gap(&self, i: usize, pose: &SidePose) -> f64 {
        count!(CoarseSample, 1);
        let [_, yw, zw] = self.coarse[i];
        sample_gap(self.rail.heights(), pose, yw, zw)
    }

    /// A lower bound of the coarse gaps of block `b` at `pose` (`+inf` when none of its
    /// samples can be above the rail): [`Self::extent_bound`] of the block.
    #[inline]
    pub(super) fn block_bound(&self, b: usize, pose: &SidePose) -> f64 {
        self.extent_bound(self.blocks[b], pose)
    }

    /// A lower bound of the coarse gaps of the wheel samples within `extent` at `pose`
    /// (`+inf` when none can be above the rail): the lowest they can be, against the highest
    /// the rail table is under the lateral span they can cover.
    #[inline]
    pub(super) fn extent_bound(
        &self,
        [yw_lo, yw_hi, zw_lo, zw_hi]: [f64; 4],
        pose: &SidePose,
    ) -> f64 {
        let [y_lo, y_hi, z_lo, _] = extent_span([yw_lo, yw_hi, zw_lo, zw_hi], pose);
        self.rail
            .heights()
            .max_over(y_lo, y_hi)
            .map_or(f64::INFINITY, |rail| z_lo - rail)
    }

    /// Whether every coarse sample of block `b` has a coarse gap below `threshold` at
    /// `pose`: an upper bound of their gaps (the highest they can be against the lowest the
    /// rail table is under the lateral span they cover) lies below it by more than
    /// [`ALL_LOW_MARGIN_MM`]. False where a sample may lie off the table.
    #[inline]
    pub(super) fn block_all_low(&self, b: usize, pose: &SidePose, threshold: f64) -> bool {
        let [y_lo, y_hi, _, z_hi] = extent_span(self.blocks[b], pose);
        self.rail
            .heights()
            .min_over(y_lo, y_hi)
            .is_some_and(|rail| z_hi - rail < threshold - ALL_LOW_MARGIN_MM)
    }

    /// A lower bound of the gap of the whole wheel over the cells of block `b` (its
    /// samples and the next block's first, and every point between) at `pose` against the
    /// exact rail, `+inf` where none of it can be above the rail: the lowest the wheel can
    /// be there against the highest the rail is under the lateral span it covers
    /// ([`PlacedRail::binned_max_height`](crate::track::PlacedRail)) widened by a step of
    /// the height table, so that it lies below the coarse gap of each sample too.
    #[inline]
    pub(super) fn certified_block_bound(&self, b: usize, pose: &SidePose) -> f64 {
        let [yw_lo, yw_hi, zw_lo, zw_hi] = self.cert_blocks[b];
        let [y_lo, y_hi, z_lo] = super::bound::span(pose, (yw_lo, yw_hi), (zw_lo, zw_hi));
        let w = crate::track::HEIGHT_TABLE_STEP_MM;
        self.rail
            .binned_max_height(y_lo - w, y_hi + w)
            .map_or(f64::INFINITY, |rail| z_lo - rail)
    }

    /// The index range of the coarse samples that can lie above the rail at `pose`:
    /// `Y = delta + Yw +- |sin phi| |Zw|`, with one sample more on each side.
    pub(super) fn over_rail(&self, pose: &SidePose) -> (usize, usize) {
        let (y_lo, y_hi) = self.rail.y_range();
        // Y = delta + cos Yw - sin Zw differs from delta + Yw by at most
        // |sin| |Zw| + (1 - cos) |Yw|, with |Zw| <= r0 + 100 and |Yw| <= taping line + 100:
        // the second term is 13 mm at a roll of 0.19 rad (very unequal wheel radii).
        let wheel = &self.pair.wheel;
        let reach = pose.sin.abs() * (wheel.nominal_radius_mm() + 100.0)
            + (1.0 - pose.cos) * (wheel.taping_line_mm() + 100.0)
            + 1.0;
        let coarse = &self.coarse;
        let first = partition_near(coarse, y_lo - reach - pose.delta, |c| {
            pose.delta + c[1] < y_lo - reach
        })
        .saturating_sub(1);
        let last = (partition_near(coarse, y_hi + reach - pose.delta, |c| {
            pose.delta + c[1] <= y_hi + reach
        }) + 1)
            .min(coarse.len());
        (first, last)
    }
}

/// `coarse.partition_point(below)` (`below` holds for the samples up to some `Yw` and for
/// none after), found by walking from the sample whose `Yw` would be `yw` were the samples
/// evenly spaced in it (they are without yaw): the same index, in a few tests of `below`
/// instead of the ten of a bisection of 541 samples (two calls per scan).
#[inline]
pub(super) fn partition_near(
    coarse: &[[f64; 3]],
    yw: f64,
    below: impl Fn(&[f64; 3]) -> bool,
) -> usize {
    let n = coarse.len();
    let mut i = 0;
    if n >= 2 {
        let step = (coarse[n - 1][1] - coarse[0][1]) / (n - 1) as f64;
        // Saturating: a NaN or negative guess is 0, one beyond the end is clamped.
        i = (((yw - coarse[0][1]) / step) as usize).min(n);
    }
    // Below the partition point `below` holds, from it on not: down to the first sample
    // where it fails after one where it holds, then up past any where it still holds.
    while i > 0 && !below(&coarse[i - 1]) {
        i -= 1;
    }
    while i < n && below(&coarse[i]) {
        i += 1;
    }
    i
}
