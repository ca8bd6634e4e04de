//! Sparse tables of unions: `levels[k][i]` joins the entries `i..i + 2^k` of a base array,
//! so that the join over any run of entries is two lookups (the two runs of length `2^k`
//! that cover it, overlapping). Used for the rail's height blocks (`heights.rs`), the rail
//! surface's bound bins (`rail/surface.rs`) and the wheel's cell bounds (`wheel.rs`); each
//! reads its own table, in its own index arithmetic.

use std::sync::OnceLock;

/// The levels of the sparse table over `base` with the associative, idempotent-enough
/// `join` (a maximum, a union of ranges; a sum over an overlap only bounds from above):
/// `levels[0]` is `base`, `levels[k]` has `base.len() - 2^k + 1` entries.
pub(crate) fn doubling_levels<T: Copy>(base: Vec<T>, join: impl Fn(T, T) -> T) -> Vec<Vec<T>> {
    let n = base.len();
    let mut levels = vec![base];
    let mut span = 1;
    while 2 * span <= n {
        let below = &levels[levels.len() - 1];
        let level = (0..=n - 2 * span)
            .map(|i| join(below[i], below[i + span]))
            .collect();
        levels.push(level);
        span *= 2;
    }
    levels
}

/// The levels of [`doubling_levels`] made as they are first asked for: the base at once, each
/// level above it from the one below, by the same joins in the same order (the same numbers
/// to the bit), when a run as long as its spans is first looked up. The searches of a
/// sweep ask for runs of a few entries mostly: on the EN 15302 E1 pair the searches read
/// the wheel's cell bounds on 5 of their 10 levels (runs of up to 31 cells), and the five
/// above are never made.
#[derive(Debug, Clone)]
pub(crate) struct LazyLevels<T> {
    /// The entries (level 0), read most often: a plain slice.
    base: Vec<T>,
    /// `upper[k - 1]`: level `k`, the joins over the entries `i..i + 2^k`.
    upper: Vec<OnceLock<Vec<T>>>,
    join: fn(T, T) -> T,
}

impl<T: Copy> LazyLevels<T> {
    /// The sparse table over `base` with `join` (as [`doubling_levels`]), only the base made.
    pub(crate) fn new(base: Vec<T>, join: fn(T, T) -> T) -> LazyLevels<T> {
        let above = if base.is_empty() {
            0
        } else {
            level_of(base.len())
        };
        LazyLevels {
            base,
            upper: (0..above).map(|_| OnceLock::new()).collect(),
            join,
        }
    }

    /// Level `k` (as `doubling_levels(..)[k]`), made now if it was not.
    #[inline]
    pub(crate) fn level(&self, k: usize) -> &[T] {
        if k == 0 {
            return &self.base;
        }
        self.upper[k - 1].get_or_init(|| {
            let below = self.level(k - 1);
            let span = 1 << (k - 1);
            (0..=self.base.len() - 2 * span)
                .map(|i| (self.join)(below[i], below[i + span]))
                .collect()
        })
    }
}

/// The level whose runs cover a run of `count >= 1` entries in two lookups:
/// `floor(log2(count))`.
#[inline]
pub(crate) fn level_of(count: usize) -> usize {
    (usize::BITS - 1 - count.leading_zeros()) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The levels made on first use are those made at once, to the bit (a join that is
    /// neither idempotent nor associative in floating point shows any other order), asked
    /// for in any order.
    #[test]
    fn lazy_levels_are_the_doubling_levels() {
        let join = |a: f64, b: f64| 0.7 * a + b * 1.3 + 1e-3;
        for n in [1usize, 2, 3, 7, 8, 37, 64, 100] {
            let base: Vec<f64> = (0..n).map(|i| ((i * 7919) % 101) as f64 / 7.0).collect();
            let eager = doubling_levels(base.clone(), join);
            let lazy = LazyLevels::new(base, join);
            for k in (0..eager.len()).rev() {
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(lazy.level(k)), bits(&eager[k]), "n = {n}, level {k}");
            }
            assert_eq!(lazy.upper.len() + 1, eager.len(), "n = {n}");
        }
    }

    /// Every run of every length is the maximum of its entries, from two lookups.
    #[test]
    fn two_lookups_give_the_maximum_of_any_run() {
        let base: Vec<u32> = (0..37u32).map(|i| (i * 7919) % 101).collect();
        let levels = doubling_levels(base.clone(), u32::max);
        for i in 0..base.len() {
            for j in i + 1..=base.len() {
                let k = level_of(j - i);
                let got = levels[k][i].max(levels[k][j - (1 << k)]);
                assert_eq!(got, *base[i..j].iter().max().unwrap(), "{i}..{j}");
            }
        }
    }
}
