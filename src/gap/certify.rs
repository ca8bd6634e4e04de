//! The certificate of the global minimum of the gap at a pose: every coarse cell of the
//! wheel over the rail is shown to lie no lower than the lowest minimum found less a stated
//! tolerance, or searched until the lower point in it is found.
//!
//! The coarse scan (`scan.rs`) brackets the sampled minima near the lowest sample and Newton
//! (`minimum.rs`) refines one local minimum per bracket; neither proves that no lower minimum
//! lies between the samples or inside a bracket (on noisy measured profiles two minima 0.4 mm
//! apart can share one bracket). [`SideGap::certify_scanned`] closes that gap, reading what
//! the scan for basins at the same pose saw ([`Scanned`]), from the cheapest bound up (the
//! bounds are stated in `bound.rs`):
//!
//! 1. a block of [`SCAN_BLOCK`] coarse cells the scan skipped lies, at every point, above the
//!    lowest sample plus [`COARSE_MARGIN_MM`] (its bound is rigorous, `scan.rs`): nothing to
//!    do where that reaches the threshold;
//! 2. a cell of a block the scan evaluated: the interpolation bound on its two samples,
//!    `min(g_i, g_i+1) - c_b >= g* - tol`, one compare, with one cushion `c_b` per block:
//!    `max(M_b, 0) h^2 / 8` for the largest `g''` over the block, the profiles' joint terms,
//!    and the height table's error (the samples read a linear interpolation of exact heights
//!    0.02 mm apart, below the exact rail by at most `max(-Z'', 0) 0.02^2 / 8`);
//! 3. a cell left over: its zeroth-order bound; then convexity about the nearest known
//!    minimum `p_k` (`g'' >= 0` over the cells from it to the cell: `g >= g_k - |g'_k| L`);
//! 4. the deep search of the cell (`bound.rs`): exact ends, Taylor bounds, halving.
//!
//! # What is guaranteed
//!
//! No point of the gap over the rail lies lower than the minimum returned by more than
//! `tol` = [`CERTIFY_TOL_MM`] plus the profiles' largest value jumps at section joints (S1002:
//! 1.2e-4 mm at s = -35; UIC60: 2.6e-7 mm at the crown/shoulder joints, the drawing's rounded
//! arc centres; 0 for sampled profiles): next to a joint the solver reports the stationary
//! minimum of one section, which the other section's limit may undercut by the jump (the
//! penetration check of `tests/stress.rs` allows the same). The exact gap is the gap on the
//! rail's surface table, which errs against the exact rail by at most 8.5e-13 mm
//! (`track::rail` tests): [`EXACT_PAD_MM`] covers it. Unit tests (`bound_tests.rs`) check
//! each bound below a dense sample of the gap on analytic and noisy profiles and the
//! certified minimum against full scans every 0.002 mm.

use super::bound::{CERTIFY_TOL_MM, Search, curvature_range, joint_terms, pose_trig, span};
use super::pose_box::PoseBox;
use super::scan::{SCAN_BLOCK, Scanned, block_samples};
use super::{GapPoint, SideGap, SidePose};
use crate::track::{HEIGHT_TABLE_STEP_MM, WheelCells};

/// What the bounds allow for the difference between the gaps they are computed from (on
/// the rail's surface and height tables) and the exact gap (mm): the surface table errs by
/// at most 8.5e-13 mm, rounding of gaps near `-r0` adds 1e-13.
pub const EXACT_PAD_MM: f64 = 1e-11;
/// Relative widening of the height table's interpolation error bound for rounding.
const TABLE_PAD: f64 = 1e-6;

/// The outcome of [`SideGap::certify`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Certificate {
    /// A point lower than the minimum given by more than [`CERTIFY_TOL_MM`], the lowest found.
    pub lower: Option<GapPoint>,
    /// Whether every cell was bounded (false: a cell reached the depth or work limit).
    pub complete: bool,
    /// Cells the deep search examined.
    pub cells: usize,
    /// Coarse cells that needed more than the interpolation bound on their samples.
    pub hard: usize,
}

/// The certificate's state over one pose.
struct Pass<'c> {
    search: Search,
    cells: &'c WheelCells,
    known: &'c [GapPoint],
    /// Per known minimum, the coarse cells `lo..hi` about it shown no lower than its gap
    /// (empty at first).
    zones: &'c mut Vec<(usize, usize)>,
    /// The profiles' value jumps: lower points by less do not count.
    slack: f64,
    hard: usize,
}

impl Pass<'_> {
    /// The threshold a bound must reach.
    #[inline]
    fn threshold(&self) -> f64 {
        self.search.threshold - self.slack
    }
}

impl SideGap<'_> {
    /// Certifies that no point of the gap at `pose` lies lower than `best` (the lowest of the
    /// `known` minima) by more than the tolerance (module docs), or finds the lowest such
    /// point: a scan for basins at `pose` first, then the certificate on what the scan saw.
    pub(crate) fn certify(
        &self,
        pose: &SidePose,
        best: GapPoint,
        known: &[GapPoint],
    ) -> Certificate {
        let (mut pose_box, mut scanned) = (PoseBox::default(), Scanned::default());
        self.basins(pose, &mut pose_box, &mut scanned, &mut Vec::new());
        self.certify_scanned(pose, best, known, &mut pose_box, &mut scanned)
    }

    /// [`SideGap::certify`] reading what the scan for basins at this very `pose` saw and
    /// the box of poses it read.
    pub(crate) fn certify_scanned(
        &self,
        pose: &SidePose,
        best: GapPoint,
        known: &[GapPoint],
        pose_box: &mut PoseBox,
        scanned: &mut Scanned,
    ) -> Certificate {
        count!(Certificate, 1);
        debug_assert_eq!(scanned.pose, Some(*pose));
        debug_assert!(pose_box.holds(pose));
        let cells = self.pair.wheel.cells(self.coarse.len() - 1);
        let mut zones = std::mem::take(&mut scanned.zones);
        zones.clear();
        zones.resize(known.len(), (usize::MAX, 0));
        let mut pass = Pass {
            search: Search::new(best),
            cells: &cells,
            known,
            zones: &mut zones,
            slack: self.value_jumps(),
            hard: 0,
        };
        // The cushions read the outline's bounds at one yaw: made again at another.
        if pose_box.cushion_yaw != pose.yaw.to_bits() {
            pose_box.cushions.fill(f64::NAN);
            pose_box.cushion_yaw = pose.yaw.to_bits();
        }
        let (first, last) = scanned.range;
        if last >= first + 2 {
            let [yc, zc] = pose_box.reference;
            let common = pose.sin * yc + pose.cos * zc;
            for b in first / SCAN_BLOCK..=(last - 2) / SCAN_BLOCK {
                // Step 1 for most blocks, in the loop: a block the scan skipped whose bound
                // over the box reaches the threshold (`certify_block` tests the same first).
                if !scanned.evaluated(b) && pose_box.certified[b] + common >= pass.threshold() {
                    continue;
                }
                self.certify_block(b, pose, pose_box, scanned, &mut pass);
            }
        }
        let (search, hard) = (pass.search, pass.hard);
        scanned.zones = zones;
        Certificate {
            lower: (search.best.g < best.g - CERTIFY_TOL_MM).then_some(search.best),
            complete: search.complete,
            cells: search.cells,
            hard,
        }
    }

    /// The cells of block `b` (those from its first sample to the next block's first,
    /// within the scanned range).
    fn certify_block(
        &self,
        b: usize,
        pose: &SidePose,
        pose_box: &mut PoseBox,
        scanned: &mut Scanned,
        pass: &mut Pass,
    ) {
        let (first, last) = scanned.range;
        let t = pass.threshold();
        if !scanned.evaluated(b) {
            let [yc, zc] = pose_box.reference;
            let common = pose.sin * yc + pose.cos * zc;
            if pose_box.certified[b] + common >= t || self.certified_block_bound(b, pose) >= t {
                return;
            }
            let eval = self.block_gaps(block_samples(b, first, last), pose, scanned);
            scanned.record(b, eval);
        }
        let cells = (b * SCAN_BLOCK).max(first)..((b + 1) * SCAN_BLOCK).min(last - 1);
        if cells.is_empty() {
            return;
        }
        // The sample after the last cell (the next block's first, or this block's last).
        let end = if scanned.evaluated(cells.end / SCAN_BLOCK) {
            scanned.gaps[cells.end]
        } else {
            self.coarse_gap(cells.end, pose)
        };
        // The whole block at once: its lowest sample and the next block's first, less the
        // cushion over the box.
        let lowest = scanned.block_min[b].min(end);
        if lowest >= t {
            if pose_box.cushions[b].is_nan() {
                pose_box.cushions[b] = self.box_cushion(b, pass.cells, pose_box);
            }
            let cushion = pose_box.cushions[b];
            // All the block's samples over the rail covers its cells' (a subset).
            let on_rail = end < f64::INFINITY
                && (scanned.on_rail(b) || cells.clone().all(|i| scanned.gaps[i] < f64::INFINITY));
            if on_rail && lowest - cushion >= t {
                return;
            }
        }
        let mut cushion = None;
        let last_cell = cells.end - 1;
        for i in cells {
            // The block's own gaps, then `end`: one test of which block a sample is in
            // less per cell.
            let ga = scanned.gaps[i];
            let gb = if i == last_cell {
                end
            } else {
                scanned.gaps[i + 1]
            };
            let (lo, t) = (ga.min(gb), pass.threshold());
            // Both samples over the rail: the cell does not leave it between them.
            if ga.max(gb) < f64::INFINITY
                && lo >= t
                && lo - *cushion.get_or_insert_with(|| self.block_cushion(b, pass.cells, pose)) >= t
            {
                continue;
            }
            pass.hard += 1;
            self.certify_cell(i, pose, pass);
        }
    }

    /// The coarse cells `i..j` of block `b` (`i < j`).
    pub(super) fn block_cells(&self, b: usize) -> (usize, usize) {
        let n = self.coarse.len() - 1;
        ((b * SCAN_BLOCK).min(n - 1), ((b + 1) * SCAN_BLOCK).min(n))
    }

    /// What the interpolation bound on the coarse samples of a cell of block `b` subtracts
    /// (mm) at every pose of `pose_box`: as [`SideGap::block_cushion`] over the box's lateral
    /// span of the block and its ranges of `cos phi` and `sin phi`.
    pub(super) fn box_cushion(&self, b: usize, cells: &WheelCells, pose_box: &PoseBox) -> f64 {
        let (i, j) = self.block_cells(b);
        let [y_lo, y_hi] = pose_box.spans[b];
        let trig = pose_box.trig;
        let sin_abs = trig[1].0.abs().max(trig[1].1.abs());
        let w = self.cells_over(cells, i, j);
        self.cushion(w, (y_lo, y_hi), trig, sin_abs, self.cell_width(b))
    }

    /// What the interpolation bound on the coarse samples of a cell of block `b` subtracts
    /// (mm) at `pose`: `max(M, 0) h^2 / 8` for the largest `g''` over the block, the
    /// profiles' joint terms, the height table's interpolation error, [`EXACT_PAD_MM`];
    /// `+inf` where the rail is not bounded there.
    pub(super) fn block_cushion(&self, b: usize, cells: &WheelCells, pose: &SidePose) -> f64 {
        let (i, j) = self.block_cells(b);
        let w = self.cells_over(cells, i, j);
        let [y_lo, y_hi, _] = span(pose, (self.coarse[i][1], self.coarse[j][1]), w.z);
        let h = self.cell_width(b);
        self.cushion(w, (y_lo, y_hi), pose_trig(pose), pose.sin.abs(), h)
    }

    /// The cushion of wheel cells `w`, none wider than `h` along `Yw`, over the lateral span
    /// `y` with `cos phi`, `sin phi` in `trig` and `|sin phi| <= sin_abs`.
    fn cushion(
        &self,
        w: crate::track::WheelCell,
        (y_lo, y_hi): (f64, f64),
        trig: [(f64, f64); 2],
        sin_abs: f64,
        h: f64,
    ) -> f64 {
        // The table's samples interpolate exact heights up to a step outside the span.
        let step = HEIGHT_TABLE_STEP_MM;
        let Some(r) = self.pair.rail.binned_bounds(y_lo - step, y_hi + step) else {
            return f64::INFINITY;
        };
        let (_, big_m) = curvature_range(trig, &w.d, &r);
        let table = (-r.d2.0).max(0.0) * step * step / 8.0 * (1.0 + TABLE_PAD);
        big_m.max(0.0) * h * h / 8.0 + joint_terms(w.jump, &r, sin_abs) + table + EXACT_PAD_MM
    }

    /// A coarse cell the interpolation bound left: its zeroth-order bound, convexity about a
    /// known minimum, or the deep search.
    fn certify_cell(&self, i: usize, pose: &SidePose, pass: &mut Pass) {
        let w = self.cells_over(pass.cells, i, i + 1);
        let [y_lo, y_hi, z_lo] = span(pose, (self.coarse[i][1], self.coarse[i + 1][1]), w.z);
        match self.pair.rail.binned_max_height(y_lo, y_hi) {
            // No point of the cell over the rail.
            None => return,
            Some(z) if z_lo - z - EXACT_PAD_MM >= pass.threshold() => return,
            _ => {}
        }
        if self.convex_about_known(i, pose, pass) {
            return;
        }
        let (cells, known, slack) = (pass.cells, pass.known, pass.slack);
        self.search_cell(i, cells, known, pose, slack, &mut pass.search);
    }

    /// Whether the coarse cell `i` lies no lower than the threshold by convexity about the
    /// nearest known minimum (`g'' >= 0` on the cells from its cell to `i`: see
    /// [`SideGap::convex_bound`]); the cells shown join that minimum's zone.
    fn convex_about_known(&self, i: usize, pose: &SidePose, pass: &mut Pass) -> bool {
        if pass.zones.iter().any(|&(lo, hi)| lo <= i && i < hi) {
            return true;
        }
        let mid = 0.5 * (self.coarse[i][0] + self.coarse[i + 1][0]);
        let Some((k, p)) = pass
            .known
            .iter()
            .enumerate()
            .min_by(|a, b| (a.1.s - mid).abs().total_cmp(&(b.1.s - mid).abs()))
        else {
            return false;
        };
        let Some((low, lo, hi)) = self.convex_bound(i, p, pose, pass.cells) else {
            return false;
        };
        if low < pass.threshold() {
            return false;
        }
        let zone = &mut pass.zones[k];
        *zone = (zone.0.min(lo), zone.1.max(hi));
        true
    }

    /// A lower bound `(low, lo, hi)` of the gap at `pose` on the coarse cells `lo..hi` from
    /// the minimum `p`'s cell to the coarse cell `i`, where the gap is convex there
    /// (`g'' >= 0`, all over the rail): `g >= p.g - |p.dg| L` less the joint terms, `L` their
    /// length (the tangent at `p` lies below a convex function; `p.dg` is 0 at a smooth
    /// minimum, not at one held at a joint or a bracket end). `None` where convexity is not
    /// shown.
    pub(super) fn convex_bound(
        &self,
        i: usize,
        p: &GapPoint,
        pose: &SidePose,
        cells: &WheelCells,
    ) -> Option<(f64, usize, usize)> {
        let n = self.coarse.len() - 1;
        let h = self.coarse[1][0] - self.coarse[0][0];
        let ik = (((p.s - self.coarse[0][0]) / h).max(0.0) as usize).min(n - 1);
        let (lo, hi) = (i.min(ik), (i + 1).max(ik + 1));
        let w = self.cells_over(cells, lo, hi);
        let [y_lo, y_hi, _] = span(pose, (self.coarse[lo][1], self.coarse[hi][1]), w.z);
        let (r_lo, r_hi) = self.pair.rail.y_range();
        if y_lo < r_lo || y_hi > r_hi {
            return None;
        }
        let r = self.pair.rail.binned_bounds(y_lo, y_hi)?;
        let (m, _) = curvature_range(pose_trig(pose), &w.d, &r);
        if m < 0.0 {
            return None;
        }
        let length = self.coarse[hi][0] - self.coarse[lo][0];
        // The wheel's slope jumps count over the whole length, not a cell's.
        let jumps = joint_terms(w.jump * (length / h).max(1.0), &r, pose.sin.abs());
        // The tangent's lever along Yw, which `dg` is taken along.
        let lever = if self.yawed() {
            self.coarse[hi][1] - self.coarse[lo][1]
        } else {
            length
        };
        Some((p.g - p.dg.abs() * lever - jumps - EXACT_PAD_MM, lo, hi))
    }
}
