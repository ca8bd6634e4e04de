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
use super::{SideGap, Yaw, sample_blocks};
use crate::profile::bounds::DerivativeBounds;
use crate::track::{MAX_RAIL_SLOPE, WheelCell, WheelCells, WheelPoint};

/// A cell with no point: its bounds rule it out.
const NO_CELL: WheelCell = WheelCell {
    d: DerivativeBounds::EMPTY,
    z: (f64::INFINITY, f64::INFINITY),
    jump: 0.0,
};

impl SideGap<'_> {
    /// The yaw the side's outline is for.
    pub fn yaw(&self) -> &Yaw {
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
    pub fn pose(&self, y_ws: f64, roll: f64) -> super::SidePose {
        super::SidePose {
            yaw: self.yaw.psi(),
            ..super::SidePose::new(self.sign, y_ws, roll)
        }
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
            self.yaw.outline(p)
        }
    }

    /// The wheel point the rail sees at profile coordinate `s`: the profile's (clamped to
    /// its domain as [`crate::profile::Profile::eval`] clamps) without yaw, the outline's
    /// with yaw, `None` outside the part of the wheel that takes part.
    #[inline]
    pub fn wheel_point(&self, s: f64) -> Option<WheelPoint> {
        if !self.yawed() {
            return Some(self.pair.wheel.at(s));
        }
        if !self.in_domain(s) {
            return None;
        }
        self.yaw.outline(self.pair.wheel.at(s))
    }

    /// Makes the side's wheel the one the rail sees at `yaw` (the side's own, see
    /// [`Yaw::new`]); poses of this side must then carry its [`Yaw::psi`]. Costs a pass
    /// over the coarse samples when the yaw changes, nothing otherwise.
    pub fn set_yaw(&mut self, yaw: Yaw) {
        if yaw == self.yaw {
            return;
        }
        self.yaw = yaw;
        let (lo, hi) = self.pair.wheel.profile().domain();
        let n = self.coarse.len() - 1;
        self.outline_widths.clear();
        self.outline_jump = 0.0;
        if yaw.keeps_profile() {
            for (c, p) in self.coarse.iter_mut().zip(&self.base) {
                (c[1], c[2]) = (p.y, p.z);
            }
            self.domain = (lo, hi);
        } else {
            let (first, last) = self.outline_cells();
            self.outline_samples = (first, last);
            for (i, (c, p)) in self.coarse.iter_mut().zip(&self.base).enumerate() {
                let outline = if (first..=last).contains(&i) {
                    yaw.outline(*p)
                } else {
                    None
                };
                match outline {
                    Some(p) => (c[1], c[2]) = (p.y, p.z),
                    None => c[2] = f64::INFINITY,
                }
            }
            // Lateral positions outside copy the nearest inside, so that they still grow.
            let (y_first, y_last) = (self.coarse[first][1], self.coarse[last][1]);
            for c in &mut self.coarse[..first] {
                c[1] = y_first;
            }
            for c in &mut self.coarse[last + 1..] {
                c[1] = y_last;
            }
            self.domain = (self.coarse[first][0], self.coarse[last][0]);
            let blocks = n.div_ceil(SCAN_BLOCK).max(1);
            self.outline_widths = (0..blocks)
                .map(|b| {
                    let (i, j) = self.block_cells(b);
                    (i..j)
                        .map(|k| self.coarse[k + 1][1] - self.coarse[k][1])
                        .fold(0.0, f64::max)
                })
                .collect();
            self.outline_jump = self.outline_joint_jump();
        }
        self.blocks = sample_blocks(&self.coarse);
        self.cert_blocks = self.certified_blocks();
        self.group_extents = self.group_extents();
        if self.tabulated.is_some() {
            self.tabulate_wheel();
        }
    }

    /// The coarse cells `first..last` (sample indices) of the run about the middle of the
    /// profile whose outline exists within the margins: by blocks, then by cells in a block
    /// whose bound does not show it whole.
    fn outline_cells(&self) -> (usize, usize) {
        let n = self.coarse.len() - 1;
        let cells = self.pair.wheel.cells(n);
        let h = self.coarse[1][0] - self.coarse[0][0];
        let mut valid = vec![false; n];
        for b in 0..n.div_ceil(SCAN_BLOCK) {
            let (i, j) = self.block_cells(b);
            if self.yaw.outline_cell(cells.over(i, j), h).is_some() {
                valid[i..j].fill(true);
            } else {
                for (k, v) in valid.iter_mut().enumerate().take(j).skip(i) {
                    *v = self.yaw.outline_cell(cells.cells()[k], h).is_some();
                }
            }
        }
        let middle = n / 2;
        let first = (0..=middle).rev().find(|&k| !valid[k]).map_or(0, |k| k + 1);
        let last = (middle..n).find(|&k| !valid[k]).unwrap_or(n);
        // An empty run (an outline that exists nowhere): the middle sample alone.
        (first.min(middle), last.max(first.min(middle)))
    }

    /// The largest step of the outline at a section joint of the profile inside the part
    /// that takes part: its vertical step plus [`MAX_RAIL_SLOPE`] times its sideways step
    /// (how far a gap can step there), mm.
    fn outline_joint_jump(&self) -> f64 {
        let wheel = &self.pair.wheel;
        self.joints
            .iter()
            .filter(|&&j| self.in_domain(j) && self.in_domain(j - 1e-12))
            .filter_map(|&j| {
                let a = self.yaw.outline(wheel.at(j))?;
                let b = self.yaw.outline(wheel.at(j - 1e-12))?;
                Some((a.z - b.z).abs() + MAX_RAIL_SLOPE * (a.y - b.y).abs())
            })
            .fold(0.0, f64::max)
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
    pub(super) fn certified_blocks(&self) -> Vec<[f64; 4]> {
        let n = self.coarse.len() - 1;
        let cells = self.pair.wheel.cells(n);
        (0..self.blocks.len())
            .map(|b| {
                let i = (b * SCAN_BLOCK).min(n - 1);
                let j = ((b + 1) * SCAN_BLOCK).min(n);
                let z = self.cells_over(&cells, i, j).z;
                [self.coarse[i][1], self.coarse[j][1], z.0, z.1]
            })
            .collect()
    }

    /// The bounds of the wheel over the coarse cells `i..j` (the outline's with yaw; a cell
    /// with no point where none of them takes part).
    #[inline]
    pub(super) fn cells_over(&self, cells: &WheelCells, i: usize, j: usize) -> WheelCell {
        if !self.yawed() {
            return cells.over(i, j);
        }
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
