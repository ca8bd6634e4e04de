//! The weights `exp(-z)` of the quadrature nodes, inline and without libm's call, checks
//! and wrapper (half the instructions of its `exp`).
//!
//! `exp(-z) = 2^k 2^(j/32) exp(r)`, `n = 32 k + j = round(-32 z / ln 2)`,
//! `r = -z - n ln(2) / 32` in two parts (Cody and Waite: `n ln2_hi` is exact for
//! `|n| < 2^21`), `|r| <= ln(2) / 64`; `2^(j/32)` from a table of the 32 correctly rounded
//! values, `exp(r) - 1` by its Taylor polynomial of degree 6 (the remainder
//! `0.0109^7 / 7!` is 4e-18 of `exp(r)`), `2^k` put together from its exponent bits. For `|z| <= `[`FAST_RANGE`] the
//! relative error against libm's `exp` is below 2.3e-16, one unit in the last place
//! (measured on 14 million points over the whole range by
//! `fast_weights_agree_with_libm_to_one_ulp`): the weights move by rounding, the averages
//! (ratios of weighted sums) by a few units in their last place.
//! Beyond that range (gaps far below the reference, or cut-offs near the end of
//! [`CUTOFF_RANGE`](super::CUTOFF_RANGE)) the weights are libm's.

/// The range of `z` where the fast form is used: `2^k` stays a normal number.
const FAST_RANGE: f64 = 700.0;

/// `exp(-z)`: by the fast form for `|z| <= FAST_RANGE`, by libm beyond.
#[inline]
pub(super) fn exp_neg(z: f64) -> f64 {
    if z.abs() <= FAST_RANGE {
        exp_neg_fast(z)
    } else {
        (-z).exp()
    }
}

/// `2^(j / 32)` for `j` in `0..32`, rounded to the nearest double (computed to 50 digits).
const TWO_TO_J_32: [f64; 32] = [
    1.0,
    1.0218971486541166,
    1.0442737824274138,
    1.0671404006768237,
    1.0905077326652577,
    1.1143867425958924,
    1.1387886347566916,
    1.1637248587775775,
    1.189207115002721,
    1.215247359980469,
    1.241857812073484,
    1.2690509571917332,
    1.2968395546510096,
    1.3252366431597413,
    1.3542555469368927,
    1.383909881963832,
    std::f64::consts::SQRT_2,
    1.4451808069770467,
    1.4768261459394993,
    1.5091644275934228,
    1.5422108254079407,
    1.5759808451078865,
    1.6104903319492543,
    1.645755478153965,
    1.681792830507429,
    1.718619298122478,
    1.7562521603732995,
    1.7947090750031072,
    1.8340080864093424,
    1.8741676341103,
    1.9152065613971474,
    1.9571441241754002,
];

/// `exp(-z)` for `|z| <= FAST_RANGE`, without branches (see the module docs).
#[inline(always)]
fn exp_neg_fast(z: f64) -> f64 {
    let (t, q) = reduce(-z);
    scale(t, q)
}

/// [`exp_neg`] of four values, to the bit: the reduction and the polynomial in SIMD lanes
/// (the same [`reduce`] as the scalar form), the table lookup and `2^k` per lane, when all
/// four lie in the fast range; else [`exp_neg`] one by one.
#[inline]
pub(super) fn exp_neg_x4(z: [f64; 4]) -> [f64; 4] {
    if !z.iter().all(|z| z.abs() <= FAST_RANGE) {
        return z.map(exp_neg);
    }
    let (t, q) = reduce(wide::f64x4::from(z.map(|z| -z)));
    let (t, q) = (t.to_array(), q.to_array());
    std::array::from_fn(|i| scale(t[i], q[i]))
}

/// 1.5 * 2^52: adding it rounds to an integer, held in the low bits of the sum.
const SHIFTER: f64 = 6_755_399_441_055_744.0;

/// The reduction of `exp(x)` (`x = -z`, `|x| <= FAST_RANGE`): `t = x 32 / ln 2 + SHIFTER`,
/// whose low bits hold `n = round(32 x / ln 2)`, and `q = exp(r) - 1`, for `f64` or SIMD
/// lanes of `f64`: the same operations in the same order (no fused multiply-add), so each
/// lane rounds exactly as the scalar form.
#[inline(always)]
fn reduce<T>(x: T) -> (T, T)
where
    T: Copy
        + From<f64>
        + std::ops::Add<Output = T>
        + std::ops::Sub<Output = T>
        + std::ops::Mul<Output = T>
        + std::ops::Div<Output = T>,
{
    // 32 / ln 2, and ln 2 / 32 split as fdlibm's ln 2 (the high part has 21 trailing zero
    // bits, so that `n ln2_hi / 32` is exact for `|n| < 2^21`).
    const INV_STEP: f64 = 32.0 * std::f64::consts::LOG2_E;
    const STEP_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000) / 32.0;
    const STEP_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76) / 32.0;
    let k = T::from;
    let t = x * k(INV_STEP) + k(SHIFTER);
    let n = t - k(SHIFTER);
    let r = (x - n * k(STEP_HI)) - n * k(STEP_LO);
    // exp(r) - 1 to degree 6.
    let q = r
        * (k(1.0)
            + r * (k(0.5)
                + r * (k(1.0 / 6.0) + r * (k(1.0 / 24.0) + r * (k(1.0 / 120.0) + r / k(720.0))))));
    (t, q)
}

/// `exp(x) = 2^k 2^(j/32) (1 + q)` from [`reduce`]'s `t` (holding `n = 32 k + j`) and `q`.
#[inline(always)]
fn scale(t: f64, q: f64) -> f64 {
    // The integer n = 32 k + j is the difference of the bit patterns of t and the shifter.
    let n_bits = t.to_bits().wrapping_sub(SHIFTER.to_bits()) as i64;
    let two_j = TWO_TO_J_32[(n_bits & 31) as usize];
    let two_k = f64::from_bits(((n_bits >> 5) + 1023).cast_unsigned() << 52);
    (two_j + two_j * q) * two_k
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fast_weights_agree_with_libm_to_one_ulp() {
        // Every z on a fine grid over the fast range, and its ends.
        let zs: Vec<f64> = (-7_000_000..=7_000_000)
            .map(|i| f64::from(i) * 1e-4 + 1.234_567e-9)
            .filter(|z| z.abs() <= FAST_RANGE)
            .chain([0.0, FAST_RANGE, -FAST_RANGE, 25.0, 1e-300])
            .collect();
        let worst = zs
            .iter()
            .map(|&z| ((exp_neg(z) - (-z).exp()) / (-z).exp()).abs())
            .fold(0.0, f64::max);
        assert!(worst < 2.3e-16, "relative error {worst}");
    }

    #[test]
    fn weights_beyond_the_fast_range_are_libms() {
        let zs = [-800.0, 1.0, 745.0, 800.0].map(exp_neg);
        assert!(zs[0].is_infinite());
        assert!((zs[1] - (-1.0f64).exp()).abs() <= f64::EPSILON * zs[1]);
        assert!(zs[2] > 0.0);
        assert_eq!(zs[3].to_bits(), 0, "exp(-800) underflows to 0");
    }

    /// `exp_neg_x4` is `exp_neg` to the bit over the whole fast range and its ends, four
    /// irregularly spaced values at a time, and where a lane lies beyond the fast range.
    #[test]
    fn four_at_once_are_exp_neg_to_the_bit() {
        let check = |z: [f64; 4]| {
            let four = exp_neg_x4(z).map(f64::to_bits);
            assert_eq!(four, z.map(|z| exp_neg(z).to_bits()), "z = {z:?}");
        };
        for i in -1_000_000..=1_000_000 {
            let z = |k: f64| f64::from(i) * 7e-4 + k * 0.173 + 1.234_567e-9;
            check([z(0.0), z(1.0), z(-2.0), z(3.0)].map(|z| z.clamp(-FAST_RANGE, FAST_RANGE)));
        }
        check([0.0, -0.0, FAST_RANGE, -FAST_RANGE]);
        check([1.0, 2.0, 800.0, 3.0]);
        check([-800.0, 2.0, 1e-300, 745.0]);
    }
}
