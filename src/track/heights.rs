//! A uniform table of a placed rail's heights, with block maxima for the coarse scans.

use super::PlacedRail;
use wide::f64x4;

/// Step of the uniform table of rail heights [`PlacedRail::heights`] (mm): linear
/// interpolation errs by at most `Z'' h^2 / 8`, 4e-6 mm on the R13 gauge corner at the
/// 70-degree contact angle of a flange (`Z'' = (1 + tan^2)^1.5 / R`); the coarse scans that
/// read it allow [`crate::gap::COARSE_MARGIN_MM`].
pub(crate) const HEIGHT_TABLE_STEP_MM: f64 = 0.02;

/// A uniform table of a placed rail's heights `Z(Y)` in the side frame, interpolated
/// linearly: the cheap, approximate rail of coarse scans (and the paper's tabulated rail).
#[derive(Debug, Clone, Default)]
pub(crate) struct HeightTable {
    y0: f64,
    inv_step: f64,
    /// Largest table coordinate `t = (y - y0) / step` inside the table (`z.len() - 2`).
    t_max: f64,
    /// Per entry `i`, the height at `y0 + i step` and the difference to the next one (0
    /// after the last): interpolation reads one entry, and `z_i + f (z_i+1 - z_i)` is the
    /// same number with the difference made here or at each lookup.
    z: Vec<[f64; 2]>,
    /// `block_max[k][j]`: the highest of `z[j B ..= (j + 2^k) B]`, `B` = [`HEIGHT_BLOCK`] (a
    /// sparse table: the maximum over any run of blocks is the larger of two entries).
    block_max: Vec<Vec<f64>>,
    /// `block_min[k][j]`: the lowest of the same entries, NaN where one is NaN (a rail
    /// point the table has no height for).
    block_min: Vec<Vec<f64>>,
}

/// The smaller of `a` and `b`, NaN where either is: a lower bound that a missing height
/// cannot hide in.
fn min_or_nan(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.min(b)
    }
}

/// The heights of block `j` of the entries `z` (with the next block's first entry, and the
/// last entry twice in the last block) folded by `join` from `start`, in order.
#[inline]
fn fold_block(z: &[[f64; 2]], j: usize, start: f64, join: impl Fn(f64, f64) -> f64) -> f64 {
    let n = z.len() - 1;
    let (first, end) = (j * HEIGHT_BLOCK, j * HEIGHT_BLOCK + HEIGHT_BLOCK);
    let m = z[first..=end.min(n)]
        .iter()
        .fold(start, |m, e| join(m, e[0]));
    if end > n { join(m, z[n][0]) } else { m }
}

/// Entries of [`HeightTable`] per block of its block maxima.
const HEIGHT_BLOCK: usize = 16;

impl HeightTable {
    /// Tabulates `rail` over its [`PlacedRail::y_range`] with a step of at most `step_mm`.
    pub fn new(rail: &PlacedRail, step_mm: f64) -> HeightTable {
        let (lo, hi) = rail.y_range();
        let n = ((hi - lo) / step_mm).ceil().max(1.0) as usize;
        let step = (hi - lo) / n as f64;
        // The heights made in the table's own entries, their differences filled in after:
        // no vector of the heights alone (28 kB on the EN 15302 rail) to copy them from.
        // The heights increase in `y`: the rail inverted by a scan where it must be.
        // `i as f64` counted in floating point (exact below 2^53).
        let mut scan = rail.profile().scan();
        let mut z: Vec<[f64; 2]> = Vec::with_capacity(n + 1);
        let mut i = 0.0;
        for _ in 0..n + 1 {
            let y = (lo + i * step).min(hi);
            i += 1.0;
            z.push([rail.height_from(&mut scan, y).unwrap_or(f64::NAN), 0.0]);
        }
        // The difference after the last entry is to itself (a repeated last entry).
        let mut next = z[n][0];
        for e in z.iter_mut().rev() {
            e[1] = next - e[0];
            next = e[0];
        }
        // Every interpolated height between entries i and i + 1 lies below the maximum of
        // block i / B, which includes the first entry of the next block (the last entry
        // counted twice in the last block, as the repeated entry it interpolates to).
        let blocks = n / HEIGHT_BLOCK + 1;
        let block_max = super::sparse::doubling_levels(
            (0..blocks)
                .map(|j| fold_block(&z, j, f64::NEG_INFINITY, f64::max))
                .collect(),
            f64::max,
        );
        // Likewise every interpolated height lies above the minimum of its block (to
        // rounding).
        let block_min = super::sparse::doubling_levels(
            (0..blocks)
                .map(|j| fold_block(&z, j, f64::INFINITY, min_or_nan))
                .collect(),
            min_or_nan,
        );
        HeightTable {
            y0: lo,
            inv_step: 1.0 / step,
            t_max: n as f64,
            z,
            block_max,
            block_min,
        }
    }

    /// An upper bound of the interpolated height over `[y_lo, y_hi]`, or `None` where that
    /// interval misses the table. Exact to within the height variation of 16 entries.
    #[inline]
    pub fn max_over(&self, y_lo: f64, y_hi: f64) -> Option<f64> {
        let (t_lo, t_hi) = (self.coordinate(y_lo), self.coordinate(y_hi));
        // Also rejects NaN.
        if !(t_hi >= 0.0 && t_lo <= self.t_max && t_lo <= t_hi) {
            return None;
        }
        // An interpolated height at t lies below the maximum of block floor(t) / B. Through
        // i32 as in `height`; both are inside [0, t_max] after the clamps.
        let (k, first, second) = sparse_entries(t_lo.max(0.0), t_hi.min(self.t_max));
        let level = &self.block_max[k];
        let (a, b) = (level[first], level[second]);
        Some(if a > b { a } else { b })
    }

    /// A lower bound of the interpolated height over `[y_lo, y_hi]` (to rounding: within
    /// an ulp of the heights), or `None` unless that interval lies inside the table and has
    /// a height everywhere. Exact to within the height variation of 16 entries.
    #[inline]
    pub fn min_over(&self, y_lo: f64, y_hi: f64) -> Option<f64> {
        let (t_lo, t_hi) = (self.coordinate(y_lo), self.coordinate(y_hi));
        // Also rejects NaN: outside the table there is no height to bound.
        if !(t_lo >= 0.0 && t_hi <= self.t_max && t_lo <= t_hi) {
            return None;
        }
        // An interpolated height at t lies between the entries floor(t) and floor(t) + 1,
        // both in block floor(t) / B (which holds the next block's first entry).
        let (k, first, second) = sparse_entries(t_lo, t_hi);
        let level = &self.block_min[k];
        let low = min_or_nan(level[first], level[second]);
        (!low.is_nan()).then_some(low)
    }

    /// The interpolated height at `y`, or `None` outside the table.
    #[inline]
    pub fn height(&self, y: f64) -> Option<f64> {
        let t = self.coordinate(y);
        // Also rejects NaN.
        if !(t >= 0.0 && t <= self.t_max) {
            return None;
        }
        // Through i32 (the table is far shorter): one conversion each way, where a usize
        // conversion adds saturation and sign handling.
        let ti = t as i32;
        let [a, d] = self.z[ti as usize];
        Some(interpolate(a, t - f64::from(ti), d))
    }

    /// The table read four lateral positions at a time ([`HeightLanes::height`]), its
    /// fields copied once for a loop (the compiler cannot keep them in registers across
    /// the stores of a loop that writes through another reference).
    #[inline]
    pub(crate) fn lanes(&self) -> HeightLanes<'_> {
        HeightLanes {
            y0: f64x4::splat(self.y0),
            inv_step: f64x4::splat(self.inv_step),
            t_max: f64x4::splat(self.t_max),
            z: &self.z,
        }
    }

    /// The table coordinate `t = (y - y0) / step` of `y` (`f64` or SIMD lanes).
    #[inline(always)]
    fn coordinate<T>(&self, y: T) -> T
    where
        T: Copy + From<f64> + std::ops::Sub<Output = T> + std::ops::Mul<Output = T>,
    {
        (y - T::from(self.y0)) * T::from(self.inv_step)
    }
}

/// A [`HeightTable`] read in SIMD lanes of four lateral positions ([`HeightTable::lanes`]).
pub(crate) struct HeightLanes<'a> {
    y0: f64x4,
    inv_step: f64x4,
    t_max: f64x4,
    z: &'a [[f64; 2]],
}

/// `2^52`: adding it to a number in `[0, 2^51)` rounds that number to an integer (the
/// spacing of doubles there is 1), whose value sits in the low bits of the sum.
const TWO_52: f64 = 4_503_599_627_370_496.0;

impl HeightLanes<'_> {
    /// [`HeightTable::height`] of four lateral positions at once, to the bit: the table
    /// coordinates, their integer parts and the interpolation in lanes (the same
    /// operations in the same order as `height`), the entries loaded per lane. Returns the
    /// heights and a mask whose lanes are all ones where `height` is `Some` (the height
    /// lanes elsewhere are meaningless).
    #[inline(always)]
    pub(crate) fn height(&self, y: f64x4) -> (f64x4, f64x4) {
        let t = (y - self.y0) * self.inv_step;
        // As `height`'s test; an ordered compare is false for NaN.
        let on = t.simd_ge(f64x4::ZERO) & t.simd_le(self.t_max);
        // Lanes off the table read entry 0 and are masked out.
        let t_on = on.select(t, f64x4::ZERO);
        // The integer part of `t` in [0, t_max] (t_max < 2^31), exactly `t as i32`: `t +
        // 2^52` rounds `t` to the nearest integer `r` (exact arithmetic below 2^52), one
        // less where that rounded up.
        let magic = f64x4::splat(TWO_52);
        let rounded = t_on + magic;
        let r = rounded - magic;
        let up = r.simd_gt(t_on) & f64x4::ONE;
        let whole = r - up;
        let index = (whole + magic)
            .to_array()
            .map(|w| self.z[w.to_bits() as u32 as usize]);
        let [e0, e1, e2, e3] = index;
        let h = interpolate(
            f64x4::from([e0[0], e1[0], e2[0], e3[0]]),
            t - whole,
            f64x4::from([e0[1], e1[1], e2[1], e3[1]]),
        );
        (h, on)
    }
}

/// The linear interpolation `a + f d` between an entry `a` and the next (`d` their
/// difference) at fraction `f`, for `f64` or SIMD lanes: one form, so lanes round as the
/// scalar lookup.
#[inline(always)]
fn interpolate<T>(a: T, f: T, d: T) -> T
where
    T: Copy + std::ops::Add<Output = T> + std::ops::Mul<Output = T>,
{
    a + f * d
}

/// The level `k` and the two entries of that level of a sparse table of block unions whose
/// union covers the blocks of the table coordinates `t_lo..=t_hi` (both in `[0, t_max]`,
/// `t_lo <= t_hi`). Through i32 as in [`HeightTable::height`].
#[inline]
fn sparse_entries(t_lo: f64, t_hi: f64) -> (usize, usize, usize) {
    let j_lo = (t_lo as i32 as u32) / HEIGHT_BLOCK as u32;
    let j_hi = (t_hi as i32 as u32) / HEIGHT_BLOCK as u32;
    let k = super::sparse::level_of((j_hi - j_lo + 1) as usize);
    (k, j_lo as usize, j_hi as usize + 1 - (1 << k))
}
