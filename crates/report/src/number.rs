//! Numbers to a fixed count of significant digits without the formatting machinery: the
//! bytes of `format!("{x:.prec$e}")` (Rust's exact, correctly rounded decimal conversion) from
//! one 128-bit integer division, for the tables' [`NumberFormat::Significant`].
//!
//! A finite nonzero `x` is `m 2^e` exactly (`m < 2^53`); its `n` significant digits are the
//! integer nearest to `m 2^e 10^p` with `p = n - 1 - floor(log10 |x|)`, computed as the
//! quotient and remainder of two integers, so the rounding is decided exactly, as the
//! standard library decides it. Where that cannot be done in 128 bits (`|x|` beyond about
//! `1e-15..1e21` for 10 digits) and on an exact tie (the remainder exactly half: the
//! standard library's tie rule is not restated here), the caller formats `x` the standard
//! way. The four tables of `benches/data/en15302_e1_delta_r.toml` (13,225 numbers) took 28 M
//! instructions through `format!` and the csv writer, 5.5 M with this path and
//! `csv_out`. The test `agrees_with_the_standard_formatting` compares the two on three
//! million numbers over 41 decades, `every_digit_count_agrees` on 1 to 17 digits,
//! `powers_of_ten_their_neighbours_and_carries` on the powers of ten, their neighbours,
//! carries and zeros.
//!
//! The reports' tables write 10 digits, and that case has a copy of the code with the count
//! a constant (see [`push_significant`]); with the fraction compared as bits, the digits
//! eight at a time and the rare ranges' code apart, the 12,349 numbers of the EN 15302 E1
//! comparison scene (the one `../shared/peer/awrcc/compare.sh` runs) take 2.75 M
//! instructions instead of 3.98 M, and 199 instead of 319 a number in a loop over the same
//! numbers alone.
//!
//! [`NumberFormat::Significant`]: super::NumberFormat::Significant

use std::cmp::Ordering;

/// `10^i` for `i < 20` (all that fit 64 bits).
const POW10_U64: [u64; 20] = {
    let mut p = [1u64; 20];
    let mut i = 1;
    while i < 20 {
        p[i] = p[i - 1] * 10;
        i += 1;
    }
    p
};

/// `10^i` for `i < 39` (all that fit 128 bits).
const POW10: [u128; 39] = {
    let mut p = [1u128; 39];
    let mut i = 1;
    while i < 39 {
        p[i] = p[i - 1] * 10;
        i += 1;
    }
    p
};

/// `10^(i - 30)` as the nearest `f64` or close to it (exact from `1e0` to `1e22`), for the
/// first guess of a number's decimal exponent only: the integers decide.
const POW10_GUESS: [f64; 61] = {
    let mut p = [1.0f64; 61];
    let mut i = 31;
    while i < 61 {
        p[i] = p[i - 1] * 10.0;
        i += 1;
    }
    let mut i = 30;
    while i > 0 {
        p[i - 1] = p[i] / 10.0;
        i -= 1;
    }
    p
};

/// Appends `x` with `digits` significant digits (1 to 17) exactly as `format!("{x:.{}e}",
/// digits - 1)` writes it, and returns `true`; returns `false` having appended nothing where
/// the integer path does not apply (not finite, out of range, an exact tie).
pub(crate) fn push_significant(out: &mut Vec<u8>, x: f64, digits: u32) -> bool {
    let mut text = [0u8; TEXT];
    // The tables' count (`outputs::CSV_FORMAT`) as a constant: the digits' places, the
    // powers of ten and the loops are then fixed (319 -> 250 instructions a number).
    let len = if digits == 10 {
        significant(&mut text, x, 10)
    } else {
        significant(&mut text, x, digits)
    };
    let Some(len) = len else {
        return false;
    };
    out.extend_from_slice(&text[..len]);
    true
}

/// The room [`put_ten`] writes in: at most a sign, 17 digits, the point, `e`, a sign and 3
/// digits (26 bytes) fit, and the digits' places are constants within it.
pub(crate) const TEXT: usize = 33;

/// Writes `x` with 10 significant digits at the start of `out` exactly as `format!("{x:.9e}")`
/// writes it and returns its length, or `None` (the bytes then are of no meaning) where the
/// integer path does not apply; for callers that inline it.
#[inline(always)]
pub(crate) fn put_ten(out: &mut [u8; TEXT], x: f64) -> Option<usize> {
    significant(out, x, 10)
}

#[inline(always)]
fn significant(out: &mut [u8; TEXT], x: f64, digits: u32) -> Option<usize> {
    if !(1..=17).contains(&digits) {
        return None;
    }
    let n = digits as usize;
    let bits = x.to_bits();
    let magnitude = bits & !(1u64 << 63);
    // `0.000e0` for a zero, signed as the zero is. One call of `write`: with a second one
    // for the zero the compiler called the vector's copy out of line (the scene's numbers
    // 3.34 M instructions, 3.04 M so). Not-a-number and the infinities are told apart in
    // `rounded` by the exponent it takes apart anyway.
    let (q, k) = if magnitude == 0 {
        (0, 0)
    } else {
        rounded(magnitude, n)?
    };
    Some(write(out, bits != magnitude, q, n, k))
}

/// The `n` significant digits of `a > 0` (given as its bits) as an integer `q` (`10^(n-1) <=
/// q < 10^n`) and the decimal exponent `k` of its first digit; `None` where the integer path
/// does not apply (`a` not finite included).
#[inline(always)]
fn rounded(bits: u64, n: usize) -> Option<(u64, i32)> {
    let a = f64::from_bits(bits);
    let biased = (bits >> 52) as i32;
    if biased == 0x7ff {
        return None;
    }
    let fraction = bits & ((1u64 << 52) - 1);
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), biased - 1075)
    };
    // floor(log10 a) is k or k + 1 for this k from the binary exponent (1233 / 4096 just
    // below log10 2), and mostly the k that a comparison with a power of ten in floating
    // point gives; a wrong guess shows in the quotient's length and is corrected.
    let e2 = e + 63 - m.leading_zeros() as i32;
    let mut k = (e2 * 1233) >> 12;
    if let Some(&next) = usize::try_from(k + 31)
        .ok()
        .and_then(|i| POW10_GUESS.get(i))
        && a >= next
    {
        k += 1;
    }
    for _ in 0..3 {
        let (q, rest) = scaled(m, e, n as i32 - 1 - k)?;
        if q >= POW10_U64[n] {
            k += 1;
            continue;
        }
        if q < POW10_U64[n - 1] {
            k -= 1;
            continue;
        }
        let q = match rest {
            Ordering::Less => q,
            Ordering::Greater => q + 1,
            Ordering::Equal => return None,
        };
        // Rounding up may carry to 10^n: one digit more in the exponent.
        return Some(if q == POW10_U64[n] {
            (POW10_U64[n - 1], k + 1)
        } else {
            (q, k)
        });
    }
    None
}

/// The integer part of `m 2^e 10^p` and how the fraction left compares with one half;
/// `None` when a factor does not fit 128 bits or the integer part not 64 bits (it is below
/// `10^18` for any exponent guess of [`rounded`]). A quotient of 64 bits is compared and
/// rounded in 64-bit registers: the tables of the EN 15302 E1 comparison scene took 3.25 M
/// instructions with a quotient of 128 bits, 3.14 M so.
#[inline(always)]
fn scaled(m: u64, e: i32, p: i32) -> Option<(u64, Ordering)> {
    // The tables' numbers (from 1e-10 to 1e10 for 10 digits): a power of ten of 64 bits
    // (p <= 19), one widening multiply (m < 2^53: no overflow), a division by a power of
    // two. The bits shifted out, moved to the top, are the fraction, and one half is the
    // top bit alone (no mask, no `den - r`: 250 -> 232 instructions a number). A negative
    // `p` wraps to an index past the table.
    if let (Some(&pow), Ok(shift @ 1..=127)) = (POW10_U64.get(p as usize), u32::try_from(-e)) {
        let num = u128::from(m) * u128::from(pow);
        let fraction = num << (128 - shift);
        let q = u64::try_from(num >> shift).ok()?;
        return Some((q, fraction.cmp(&(1u128 << 127))));
    }
    scaled_otherwise(m, e, p)
}

/// [`scaled`] for the numbers beyond the tables' range, kept out of its way: inlined, the
/// shifts of these paths were worked out ahead for every number (220 -> 199 instructions a
/// number with them apart).
#[cold]
#[inline(never)]
fn scaled_otherwise(m: u64, e: i32, p: i32) -> Option<(u64, Ordering)> {
    let pow = |i: i32| POW10.get(usize::try_from(i).ok()?).copied();
    let (mut num, mut den) = if p >= 0 {
        (u128::from(m).checked_mul(pow(p)?)?, 1)
    } else {
        (u128::from(m), pow(-p)?)
    };
    if e >= 0 {
        let shift = e.unsigned_abs();
        if shift >= num.leading_zeros() {
            return None;
        }
        num <<= shift;
    } else {
        let shift = e.unsigned_abs();
        // Keep 2 den below 2^128 (the half comparison takes den - r).
        if shift >= den.leading_zeros() {
            return None;
        }
        den <<= shift;
    }
    let r = num % den;
    Some((u64::try_from(num / den).ok()?, r.cmp(&(den - r))))
}

/// `"00"` to `"99"`.
const PAIRS: [[u8; 2]; 100] = {
    let mut p = [[0u8; 2]; 100];
    let mut i = 0;
    while i < 100 {
        p[i] = [b'0' + (i / 10) as u8, b'0' + (i % 10) as u8];
        i += 1;
    }
    p
};

/// Writes a `-` for a negative number and the `n` digits of `q` as `d.ddd` (`d` alone for
/// one digit), `e` and `k` at the start of `out`; returns the length.
#[inline(always)]
fn write(out: &mut [u8; TEXT], negative: bool, q: u64, n: usize, k: i32) -> usize {
    // A `-` always, and the text after it only for a negative number (over it otherwise):
    // from there the digits' places do not depend on the sign (constants where `n` is).
    // Written in place by `Table::to_csv_with` (where it was put together on the stack,
    // copied out as 32 bytes from the sign or the first digit and truncated: the measure is
    // given there).
    out[0] = b'-';
    let first = usize::from(negative);
    let text: &mut [u8; 32] = out[first..].first_chunk_mut().expect("33 bytes");
    // The digits from the last, from index 1 on, eight at a time while eight are left
    // (one 64-bit division, then 32-bit ones: 232 -> 224 instructions a number for ten
    // digits against two at a time throughout), then two at a time (an odd count starts
    // with a pair's second); the first then moves left over the point.
    let mut q = q;
    let mut end = n + 1;
    while end >= 9 {
        let eight = (q % 100_000_000) as u32;
        q /= 100_000_000;
        let (high, low) = (eight / 10_000, eight % 10_000);
        for (i, four) in [high, low].into_iter().enumerate() {
            let at = end - 8 + 4 * i;
            text[at..at + 2].copy_from_slice(&PAIRS[(four / 100) as usize]);
            text[at + 2..at + 4].copy_from_slice(&PAIRS[(four % 100) as usize]);
        }
        end -= 8;
    }
    while end > 2 {
        text[end - 2..end].copy_from_slice(&PAIRS[(q % 100) as usize]);
        q /= 100;
        end -= 2;
    }
    if end > 1 {
        text[1] = b'0' + q as u8;
    }
    text[0] = text[1];
    let mut len = if n > 1 {
        text[1] = b'.';
        n + 1
    } else {
        1
    };
    text[len] = b'e';
    len += 1;
    if k < 0 {
        text[len] = b'-';
        len += 1;
    }
    // At most 3 digits (|k| <= 324).
    let k = k.unsigned_abs() as usize;
    if k >= 100 {
        text[len] = b'0' + (k / 100) as u8;
        len += 1;
    }
    if k >= 10 {
        text[len] = PAIRS[k % 100][0];
        len += 1;
    }
    text[len] = PAIRS[k % 100][1];
    first + len + 1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn standard(x: f64, digits: u32) -> String {
        let prec = digits as usize - 1;
        format!("{x:.prec$e}")
    }

    /// The fast path where it applies, else nothing to compare.
    fn check(x: f64, digits: u32) -> bool {
        let mut s = Vec::new();
        if push_significant(&mut s, x, digits) {
            let s = String::from_utf8(s).unwrap();
            assert_eq!(s, standard(x, digits), "{x:e} to {digits} digits");
            true
        } else {
            false
        }
    }

    /// A number from the random bits `r`: a mantissa from 1 to 10, a decade from `-decades`
    /// to `decades`, either sign.
    fn random_number(r: u64, decades: u64) -> f64 {
        let decade = (r % (2 * decades + 1)) as i32 - decades as i32;
        let mantissa = 1.0 + (r >> 11) as f64 / (1u64 << 53) as f64 * 9.0;
        let sign = if r & 1 == 0 { 1.0 } else { -1.0 };
        sign * mantissa * 10f64.powi(decade)
    }

    /// How many of `count` random numbers (seed `seed`, `random_number(_, decades)`) times
    /// `digits` the fast path wrote, each checked against the standard formatting.
    fn fast_and_agreeing(seed: u64, count: usize, decades: u64, digits: &[u32]) -> usize {
        let mut rng = wheelrail::rng::SplitMix64::new(seed);
        let mut fast = 0;
        for _ in 0..count {
            let x = random_number(rng.next_u64(), decades);
            for &d in digits {
                fast += usize::from(check(x, d));
            }
        }
        fast
    }

    #[test]
    fn agrees_with_the_standard_formatting() {
        // Random numbers from 1e-20 to 1e20, both signs.
        let mut rng = wheelrail::rng::SplitMix64::new(0x9e37_79b9_7f4a_7c15);
        let mut next = || rng.next_u64();
        let (mut fast, mut total) = (0, 0);
        for _ in 0..1_000_000 {
            let r = next();
            let x = random_number(r, 20);
            for digits in [10, 3, 17] {
                total += 1;
                fast += usize::from(check(x, digits));
            }
        }
        // The path covers the tables' range: all but the far decades.
        assert!(fast * 10 > total * 8, "{fast} of {total}");
    }

    #[test]
    fn every_digit_count_agrees() {
        // The digits eight, then two at a time: every count from 1 to 17 goes its own way
        // through them.
        let digits: Vec<u32> = (1..=17).collect();
        let fast = fast_and_agreeing(0x0123_4567_89ab_cdef, 50_000, 10, &digits);
        assert!(fast > 50_000 * 16, "{fast}");
    }

    #[test]
    fn few_digits_beyond_the_guess_table() {
        // With few digits the integer path reaches past the decades of `POW10_GUESS`
        // (1e-30 to 1e30), where the exponent's first guess comes from the binary exponent
        // alone.
        let fast = fast_and_agreeing(0x005e_ed0f_d161_7500, 200_000, 40, &[1, 2, 3]);
        assert!(fast > 400_000, "{fast}");
    }

    #[test]
    fn powers_of_ten_their_neighbours_and_carries() {
        for k in -15..=20 {
            let p = 10f64.powi(k);
            for x in [
                p,
                p.next_up(),
                p.next_down(),
                9.999_999_999_5 * p,
                9.999_999_999_4 * p,
            ] {
                for digits in 1..=17 {
                    check(x, digits);
                }
            }
        }
        assert!(check(9.999_999_999_9, 10));
        for digits in 1..=17 {
            assert!(check(0.0, digits) && check(-0.0, digits));
        }
        assert!(check(0.1 + 0.2, 17));
        assert!(check(-1.5e-7, 10));
    }

    #[test]
    fn exact_ties_and_out_of_range_numbers_fall_back() {
        let mut s = Vec::new();
        // 1234567890.5 to 10 digits is an exact tie.
        assert!(!push_significant(&mut s, 1_234_567_890.5, 10));
        assert!(!push_significant(&mut s, f64::NAN, 10));
        assert!(!push_significant(&mut s, 1e300, 10));
        assert!(!push_significant(&mut s, 5e-324, 10));
        assert!(s.is_empty());
    }
}
