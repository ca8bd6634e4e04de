//! Sparse tables of unions: `levels[k][i]` joins the entries `i..i + 2^k` of a base array,
//! so that the join over any run of entries is two lookups (the two runs of length `2^k`
//! that cover it, overlapping). Used for the rail's height blocks (`heights.rs`), the rail
//! surface's bound bins (`rail/surface.rs`) and the wheel's cell bounds (`wheel.rs`); each
//! reads its own table, in its own index arithmetic.

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

/// The level whose runs cover a run of `count >= 1` entries in two lookups:
/// `floor(log2(count))`.
#[inline]
pub(crate) fn level_of(count: usize) -> usize {
    (usize::BITS - 1 - count.leading_zeros()) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

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
