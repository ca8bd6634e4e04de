//! The side's wheel as the rail sees it for one yaw: the outline of [`Yaw`] in place of the
//! profile in the coarse samples, the block extents, the certificate's cell bounds and the
//! tables, so that the scans, minima and certificate of the unyawed wheel apply to it.
//!
//! Without yaw (or in the small-angle form) everything here is the profile's, computed as
//! it always was. With yaw:
//!
//! * the coarse samples stay at their profile coordinates `s` and take the outline's
//!   lateral position and height there (the outline's `Y` grows with `s`, so every scan
//!   that looks samples up by `Y` still can);
//! * the wheel takes part only where the outline exists within [`Yaw`]'s margins: the run
//!   of coarse cells about the middle of the profile whose bounds
//!   ([`Yaw::outline_cell`](super::Yaw)) show it; samples beyond lie at `+inf` (never
//!   above the rail) with the lateral position of the last one inside;
//! * the certificate's bounds take the outline's cell bounds and measure lengths along
//!   `Yw`, the coordinate its derivatives are taken in (`bound.rs`, `certify.rs`).

use super::scan::SCAN_BLOCK;
use super::yaw::Steepness;
use super::{SideGap, Yaw, sample_blocks};
use crate::profile::bounds::DerivativeBounds;
use crate::track::{MAX_RAIL_SLOPE, WheelCell, WheelCells, WheelPoint};
use std::sync::Arc;
use wide::f64x4;

/// A cell with no point: its bounds rule it out.
const NO_CELL: WheelCell = WheelCell {
    d: DerivativeBounds::EMPTY,
    z: (f64::INFINITY, f64::INFINITY),
    jump: 0.0,
};

impl SideGap<'_> {
    /// The yaw the side's outline is for.
    pub(crate) fn yaw(&self) -> &Yaw {
        &self.yaw
    }

    /// Panics where `pose` is of another yaw than the side's outline ([`SideGap::set_yaw`]):
    /// the scans' entry points check it, a mismatch is a bug of the caller.
    #[inline]
    pub(super) fn check_yaw(&self, pose: &super::SidePose) {
        assert_eq!(
            pose.yaw.to_bits(),
            self.yaw.psi().to_bits(),
            "a pose of yaw {} on a side prepared for yaw {}",
            pose.yaw,
            self.yaw.psi()
        );
    }

    /// The pose of this side for a wheelset shift and roll at the side's yaw.
    #[inline]
    pub(crate) fn pose(&self, y_ws: f64, roll: f64) -> super::SidePose {
        super::SidePose {
            yaw: self.yaw.psi(),
            ..super::SidePose::new(self.sign, y_ws, roll)
        }
    }

    /// [`SideGap::pose`] of both sides (left, right) for a wheelset shift and roll, the
    /// roll's sine and cosine taken once for both: the right side's `sin(-roll)` is
    /// `-sin(roll)` and its `cos(-roll)` is `cos(roll)`, to the bit (the C library's sine and
    /// cosine reduce `|x|` and restore the sign; the compiler folds the same identities), so
    /// that both poses are the ones [`SideGap::pose`] gives, at half its cost.
    #[inline]
    pub(crate) fn poses(sides: &[SideGap; 2], y_ws: f64, roll: f64) -> [super::SidePose; 2] {
        let (sin, cos) = roll.sin_cos();
        sides.each_ref().map(|side| super::SidePose {
            delta: side.sign * y_ws,
            cos,
            sin: side.sign * sin,
            yaw: side.yaw.psi(),
        })
    }

    /// Whether the side is yawed at all (its contacts lie ahead of or behind the axle, in
    /// the exact and in the small-angle form).
    #[inline]
    pub(crate) fn has_yaw(&self) -> bool {
        self.yaw.psi() != 0.0
    }

    /// Whether the side's wheel is seen through a yawed outline (not the profile itself).
    #[inline]
    pub(crate) fn yawed(&self) -> bool {
        !self.yaw.keeps_profile()
    }

    /// The point the rail sees on the circle of the profile point `p`: `p` itself without
    /// yaw.
    #[inline(always)]
    pub(super) fn outline(&self, p: WheelPoint) -> Option<WheelPoint> {
        if self.yaw.keeps_profile() {
            Some(p)
        } else {
            self.yawed_outline(p)
        }
    }

    /// [`Yaw::outline`] out of line: every gap evaluation inlines [`SideGap::outline`], and
    /// the unyawed ones, most of them, then carry a test instead of the outline's closed
    /// forms (their code and registers as without yaw).
    #[inline(never)]
    fn yawed_outline(&self, p: WheelPoint) -> Option<WheelPoint> {
        self.yaw.outline(p)
    }

    /// The wheel point the rail sees at profile coordinate `s`: the profile's (clamped to
    /// its domain as [`crate::profile::Profile::eval`] clamps) without yaw, the outline's
    /// with yaw, `None` outside the part of the wheel that takes part.
    #[inline]
    pub(crate) fn wheel_point(&self, s: f64) -> Option<WheelPoint> {
        if !self.yawed() {
            return Some(self.pair.wheel.at(s));
        }
        if !self.in_domain(s) {
            return None;
        }
        self.yaw.outline(self.pair.wheel.at(s))
    }

    /// Says whether the side's yaw will change from pose to pose (a sweep whose yaw grows
    /// with the shift): its boxes of poses then span nearby yaws, at the price of looser
    /// bounds, instead of holding one yaw each.
    pub(crate) fn set_yaw_varies(&mut self, varies: bool) {
        self.yaw_varies = varies;
    }

    /// Makes the side's wheel the one the rail sees at `yaw` (the side's own, see
    /// [`Yaw::new`]); poses of this side must then carry its [`Yaw::psi`]. Costs a pass
    /// over the coarse samples (four at a time) and the blocks when the yaw changes,
    /// nothing otherwise.
    pub(crate) fn set_yaw(&mut self, yaw: Yaw) {
        if yaw == self.yaw {
            return;
        }
        self.yaw = yaw;
        let base = Arc::clone(&self.outline_base);
        let base = base.get_or_init(|| OutlineBase::new(self));
        let (lo, hi) = self.pair.wheel.profile().domain();
        self.outline_jump = 0.0;
        if yaw.keeps_profile() {
            for (i, c) in self.coarse.iter_mut().enumerate() {
                (c[1], c[2]) = (base.yw[i], base.z[i]);
            }
            self.domain = (lo, hi);
            self.outline_samples = (0, self.coarse.len() - 1);
        } else {
            let (first, last) = base.admitted(&yaw);
            self.outline_samples = (first, last);
            base.outline(&yaw, first..last + 1, &mut self.coarse);
            // Outside: never above the rail, the lateral position of the nearest inside so
            // that the positions still grow.
            let (y_first, y_last) = (self.coarse[first][1], self.coarse[last][1]);
            for c in &mut self.coarse[..first] {
                (c[1], c[2]) = (y_first, f64::INFINITY);
            }
            for c in &mut self.coarse[last + 1..] {
                (c[1], c[2]) = (y_last, f64::INFINITY);
            }
            self.domain = (self.coarse[first][0], self.coarse[last][0]);
            self.outline_jump = self.outline_joint_jump(base);
        }
        sample_blocks(&self.coarse, &mut self.blocks);
        self.outline_widths.clear();
        if !yaw.keeps_profile() {
            // A cell is no wider along Yw than the coarse step times the largest dY/ds over
            // it (mean value theorem), here over its block; padded for rounding.
            let h = self.coarse[1][0] - self.coarse[0][0];
            let n = self.coarse.len() - 1;
            let (first, last) = self.outline_samples;
            let widths = base.blocks.iter().enumerate().map(|(b, (_, steep))| {
                let largest = if yaw.admits(steep) {
                    yaw.dy_ds_range(steep).1
                } else {
                    // Cell by cell, over the cells that take part.
                    let (i, j) = block_cells_of(n, b);
                    (i.max(first)..j.min(last))
                        .map(|k| yaw.dy_ds_range(&base.cells[k]).1)
                        .fold(0.0, f64::max)
                };
                h * largest * (1.0 + 1e-12)
            });
            self.outline_widths.extend(widths);
        }
        let mut cert_blocks = std::mem::take(&mut self.cert_blocks);
        self.certified_blocks(&mut cert_blocks);
        self.cert_blocks = cert_blocks;
        let mut group_extents = std::mem::take(&mut self.group_extents);
        self.group_extents(&mut group_extents);
        self.group_extents = group_extents;
        if self.tabulated.is_some() {
            self.tabulate_wheel();
        }
    }

    /// The largest step of the outline at a section joint of the profile inside the part
    /// that takes part: its vertical step plus [`MAX_RAIL_SLOPE`] times its sideways step
    /// (how far a gap can step there), mm.
    fn outline_joint_jump(&self, base: &OutlineBase) -> f64 {
        base.joints
            .iter()
            .filter(|&&(j, _, _)| self.in_domain(j) && self.in_domain(j - 1e-12))
            .filter_map(|&(_, above, below)| {
                let a = self.yaw.outline(above)?;
                let b = self.yaw.outline(below)?;
                Some((a.z - b.z).abs() + MAX_RAIL_SLOPE * (a.y - b.y).abs())
            })
            .fold(0.0, f64::max)
    }

    /// How far the outline of block `b` can move laterally and vertically `(mY, mZ)` (mm)
    /// while the yaw changes by up to `half` (rad) either way from the side's: `half` times
    /// the largest `|dY/dpsi| <= |sin psi| (|Yw| + r |F'| (1 + 1 / cos^2 psi))` and
    /// `|dZ/dpsi| = r F'^2 |tan psi| / (cos^2 psi w)` over the block's cells and those yaws;
    /// `(0, 0)` without yaw or for `half = 0`, infinite where the part of the wheel that
    /// takes part may differ over those yaws (the block's outline may appear or vanish).
    pub(super) fn outline_motion(&self, b: usize, half: f64) -> (f64, f64) {
        if !self.yawed() || half <= 0.0 {
            return (0.0, 0.0);
        }
        let base = self.outline_base.get().expect("made by set_yaw");
        let psi = self.yaw.psi();
        let n = self.coarse.len() - 1;
        let (i, j) = block_cells_of(n, b);
        let (first, last) = self.outline_samples;
        if j <= first || i >= last {
            // No point of the block takes part at any of those yaws: at +inf.
            return (0.0, 0.0);
        }
        let (cell, steep) = &base.blocks[b];
        // The steepest slope of the cells that take part (the block's where it takes part
        // whole).
        let q = if self.yaw.admits(steep) {
            steep.q_abs_max()
        } else {
            (i.max(first)..j.min(last))
                .map(|k| base.cells[k].q_abs_max())
                .fold(0.0, f64::max)
        };
        let r = -cell.z.0;
        let yw = base.yw[i].abs().max(base.yw[j].abs());
        let a = psi.abs() + half;
        let (sin, cos, tan) = (a.sin(), a.cos(), a.tan());
        let sec2 = 1.0 / (cos * cos);
        let w2 = 1.0 - (q * tan).powi(2);
        if w2.is_nan() || w2 <= 0.0 {
            return (f64::INFINITY, f64::INFINITY);
        }
        let pad = 1.0 + 1e-9;
        (
            half * sin * (yw + r * q * (1.0 + sec2)) * pad,
            half * r * q * q * tan * sec2 / w2.sqrt() * pad,
        )
    }

    /// The half width in yaw `half` a box of poses may span (rad): 0 without a yaw that
    /// moves the outline, and where the part of the wheel that takes part is not the same
    /// at both ends of the range (which part takes part depends on `|psi|` only, and
    /// shrinks as it grows).
    pub(super) fn box_yaw_half(&self, half: f64) -> f64 {
        if !self.yawed() || !self.yaw_varies {
            return 0.0;
        }
        let base = self.outline_base.get().expect("made by set_yaw");
        let (psi, model) = (self.yaw.psi().abs(), self.yaw.model());
        let wide = base.admitted(&Yaw::new(1.0, psi + half, model));
        let narrow = base.admitted(&Yaw::new(1.0, (psi - half).max(0.0), model));
        if wide == narrow { half } else { 0.0 }
    }

    /// The profiles' largest value jumps the certificate allows for (mm): the wheel's (its
    /// outline's with yaw) and the rail's.
    pub(super) fn value_jumps(&self) -> f64 {
        let wheel = if self.yawed() {
            self.outline_jump
        } else {
            self.pair.wheel.value_jump_mm()
        };
        wheel + self.pair.rail.value_jump_mm()
    }

    /// `[Yw_lo, Yw_hi, Zw_lo, Zw_hi]` of the wheel over the cells `b B..(b + 1) B` of the
    /// coarse grid (`B` = [`SCAN_BLOCK`]; the last block's one cell where it holds the last
    /// sample alone), for each block: the same ranges over the whole wheel between the
    /// samples, from the [`crate::track::PlacedWheel`] cell bounds (the outline's with yaw).
    pub(super) fn certified_blocks(&self, out: &mut Vec<[f64; 4]>) {
        let n = self.coarse.len() - 1;
        let cells = self.pair.wheel.cells(n);
        let base = self.outline_base.get();
        let (first, last) = self.outline_samples;
        out.clear();
        out.extend((0..self.blocks.len()).map(|b| {
            let (i, j) = block_cells_of(n, b);
            let z = match base {
                // A block whose cells all take part: its heights' range from its cells'
                // bounds, kept with the base.
                Some(base)
                    if self.yawed()
                        && i >= first
                        && j <= last
                        && self.yaw.admits(&base.blocks[b].1) =>
                {
                    let (cell, steep) = &base.blocks[b];
                    self.yaw.outline_z(cell, steep)
                }
                _ => self.cells_over(&cells, i, j).z,
            };
            [self.coarse[i][1], self.coarse[j][1], z.0, z.1]
        }));
    }

    /// The bounds of the wheel over the coarse cells `i..j` (the outline's with yaw; a cell
    /// with no point where none of them takes part).
    #[inline]
    pub(super) fn cells_over(&self, cells: &WheelCells, i: usize, j: usize) -> WheelCell {
        if self.yawed() {
            self.outline_cells_over(cells, i, j)
        } else {
            cells.over(i, j)
        }
    }

    /// [`SideGap::cells_over`] with yaw, out of line so that the unyawed bounds inline the
    /// profile's alone.
    #[inline(never)]
    fn outline_cells_over(&self, cells: &WheelCells, i: usize, j: usize) -> WheelCell {
        let h = self.coarse[1][0] - self.coarse[0][0];
        // Only the cells that take part (between the domain's samples).
        let (first, last) = self.outline_samples;
        let (i, j) = (i.max(first), j.min(last));
        if i >= j {
            return NO_CELL;
        }
        self.yaw
            .outline_cell(cells.over(i, j), h)
            .unwrap_or_else(|| {
                // The union's ranges are wider than any one cell's: cell by cell.
                cells.cells()[i..j]
                    .iter()
                    .filter_map(|&c| self.yaw.outline_cell(c, h))
                    .reduce(WheelCell::union)
                    .unwrap_or(NO_CELL)
            })
    }

    /// The bounds of the wheel over `[a, b]` inside one coarse cell (the outline's with
    /// yaw).
    pub(super) fn sub_cell(&self, a: f64, b: f64) -> WheelCell {
        let c = self.pair.wheel.cell(a, b, &self.joints);
        if !self.yawed() {
            return c;
        }
        if !(self.in_domain(a) && self.in_domain(b)) {
            return NO_CELL;
        }
        self.yaw.outline_cell(c, b - a).unwrap_or(NO_CELL)
    }

    /// The range of `Yw` over the profile coordinates `[a, b]` (taping line + `s` without
    /// yaw; the outline's, which grows with `s`, with yaw), `None` where no point of it
    /// takes part.
    pub(super) fn yw_range(&self, a: f64, b: f64) -> Option<(f64, f64)> {
        if !self.yawed() {
            let t = self.pair.wheel.taping_line_mm();
            return Some((t + a, t + b));
        }
        let (a, b) = (a.max(self.domain.0), b.min(self.domain.1));
        if a > b {
            return None;
        }
        let ya = self.wheel_point(a)?.y;
        let yb = self.wheel_point(b)?.y;
        let pad = 1e-12 * ya.abs().max(yb.abs());
        Some((ya - pad, yb + pad))
    }

    /// The widest lateral extent of one coarse cell of block `b` along `Yw` (mm): the
    /// coarse step without yaw.
    #[inline]
    pub(super) fn cell_width(&self, b: usize) -> f64 {
        if self.yawed() {
            self.outline_widths[b]
        } else {
            self.coarse[1][0] - self.coarse[0][0]
        }
    }
}

/// The coarse cells `i..j` of block `b` of a grid of `n` cells (`i < j`; the last block's one
/// cell where it holds the last sample alone).
#[inline]
pub(super) fn block_cells_of(n: usize, b: usize) -> (usize, usize) {
    ((b * SCAN_BLOCK).min(n - 1), ((b + 1) * SCAN_BLOCK).min(n))
}

/// What a side keeps to make the outline of any yaw quickly, made on the first yaw and
/// shared by the side's copies: the coarse samples' profile points (lanes of `Yw`, `Z` and
/// `F'`), and the bounds and steepness of each block's and each coarse cell's profile.
#[derive(Debug)]
pub(super) struct OutlineBase {
    yw: Vec<f64>,
    z: Vec<f64>,
    q: Vec<f64>,
    blocks: Vec<(WheelCell, Steepness)>,
    cells: Vec<Steepness>,
    /// The profile's section joints `j` with the profile points at `j` and just below it.
    joints: Vec<(f64, WheelPoint, WheelPoint)>,
}

impl OutlineBase {
    fn new(side: &SideGap) -> OutlineBase {
        let n = side.coarse.len() - 1;
        let points: Vec<WheelPoint> = side
            .coarse
            .iter()
            .map(|c| side.pair.wheel.at(c[0]))
            .collect();
        let cells = side.pair.wheel.cells(n);
        OutlineBase {
            yw: points.iter().map(|p| p.y).collect(),
            z: points.iter().map(|p| p.z).collect(),
            q: points.iter().map(|p| -p.slope).collect(),
            blocks: (0..side.blocks.len())
                .map(|b| {
                    let (i, j) = block_cells_of(n, b);
                    let c = cells.over(i, j);
                    (c, Steepness::of(&c))
                })
                .collect(),
            cells: cells.cells().iter().map(Steepness::of).collect(),
            joints: side
                .joints
                .iter()
                .map(|&j| (j, side.pair.wheel.at(j), side.pair.wheel.at(j - 1e-12)))
                .collect(),
        }
    }

    /// The first and last coarse sample of the run of cells about the middle of the profile
    /// whose outline exists within the margins (by the bounds of a cell's block, else of the
    /// cell); the middle sample alone where none does.
    fn admitted(&self, yaw: &Yaw) -> (usize, usize) {
        let n = self.cells.len();
        let middle = n / 2;
        // Whole blocks where their bounds admit them (most of a wheel), else cell by cell.
        let block_ok = |b: usize| yaw.admits(&self.blocks[b].1);
        let cell_ok = |k: usize| block_ok(k / SCAN_BLOCK) || yaw.admits(&self.cells[k]);
        let mut first = middle;
        while first > 0 {
            let k = first - 1;
            if k % SCAN_BLOCK == SCAN_BLOCK - 1 && block_ok(k / SCAN_BLOCK) {
                first -= SCAN_BLOCK;
            } else if cell_ok(k) {
                first -= 1;
            } else {
                break;
            }
        }
        let mut last = middle;
        while last < n {
            if last.is_multiple_of(SCAN_BLOCK)
                && last + SCAN_BLOCK <= n
                && block_ok(last / SCAN_BLOCK)
            {
                last += SCAN_BLOCK;
            } else if cell_ok(last) {
                last += 1;
            } else {
                break;
            }
        }
        (first, last)
    }

    /// The outline's lateral positions and heights of the coarse samples `range` into
    /// `coarse`, four at a time ([`Yaw::outline_yz`], bit for bit as each alone).
    fn outline(&self, yaw: &Yaw, range: std::ops::Range<usize>, coarse: &mut [[f64; 3]]) {
        let (yw, z, q) = (
            &self.yw[range.clone()],
            &self.z[range.clone()],
            &self.q[range.clone()],
        );
        let coarse = &mut coarse[range];
        let quads = coarse.len() / 4 * 4;
        let lanes = yw[..quads]
            .chunks_exact(4)
            .zip(z[..quads].chunks_exact(4))
            .zip(q[..quads].chunks_exact(4));
        for (((yw, z), q), c) in lanes.zip(coarse[..quads].chunks_exact_mut(4)) {
            let lane = |v: &[f64]| f64x4::from([v[0], v[1], v[2], v[3]]);
            let (y, zo) = yaw.outline_yz(lane(yw), lane(z), lane(q));
            let (y, zo) = (y.to_array(), zo.to_array());
            for l in 0..4 {
                (c[l][1], c[l][2]) = (y[l], zo[l]);
            }
        }
        for (i, c) in coarse.iter_mut().enumerate().skip(quads) {
            (c[1], c[2]) = yaw.outline_yz(yw[i], z[i], q[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One cell, which `WheelCells::over` reads directly, is what the lookup through the
    /// levels gives, to the bit: the cell joined with itself (compared through `Debug`,
    /// which tells -0 from 0), on S1002, whose joints give some cells joint terms.
    #[test]
    fn one_cell_is_the_cell_over_itself() {
        let placement = super::super::tests::placement();
        let side = SideGap::new(&placement.left, 1.0);
        let n = side.coarse.len() - 1;
        let cells = side.pair.wheel.cells(n);
        assert!(cells.cells().iter().any(|c| c.jump > 0.0));
        for i in 0..n {
            let c = cells.cells()[i];
            let (direct, looked_up) = (cells.over(i, i + 1), c.union(c));
            assert_eq!(format!("{direct:?}"), format!("{looked_up:?}"), "cell {i}");
        }
    }
}
