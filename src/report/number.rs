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
//! million numbers over 41 decades, `powers_of_ten_their_neighbours_and_carries` on the
//! powers of ten, their neighbours, carries and zeros.
//!
//! [`NumberFormat::Significant`]: super::NumberFormat::Significant

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
    if !x.is_finite() || !(1..=17).contains(&digits) {
        return false;
    }
    if x == 0.0 {
        // `0.000e0`, signed as the zero is.
        write(out, x.is_sign_negative(), 0, digits as usize, 0);
        return true;
    }
    let a = x.abs();
    let bits = a.to_bits();
    let biased = (bits >> 52) as i32;
    let fraction = bits & ((1u64 << 52) - 1);
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), biased - 1075)
    };
    let n = digits as usize;
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
        let Some((q, r, den)) = scaled(m, e, n as i32 - 1 - k) else {
            return false;
        };
        if q >= POW10[n] {
            k += 1;
            continue;
        }
        if q < POW10[n - 1] {
            k -= 1;
            continue;
        }
        let half = den - r;
        let q = match r.cmp(&half) {
            std::cmp::Ordering::Less => q,
            std::cmp::Ordering::Greater => q + 1,
            std::cmp::Ordering::Equal => return false,
        };
        // Rounding up may carry to 10^n: one digit more in the exponent.
        let (q, k) = if q == POW10[n] {
            (POW10[n - 1], k + 1)
        } else {
            (q, k)
        };
        // q < 10^17 fits 64 bits.
        write(out, x.is_sign_negative(), q as u64, n, k);
        return true;
    }
    false
}

/// The quotient and remainder of `m 2^e 10^p` as `num / den` in integers, with `den`;
/// `None` when a factor does not fit 128 bits.
fn scaled(m: u64, e: i32, p: i32) -> Option<(u128, u128, u128)> {
    let pow = |i: i32| POW10.get(usize::try_from(i).ok()?).copied();
    let (mut num, mut den) = if p >= 0 {
        let pow = pow(p)?;
        // While 10^p fits 64 bits (p <= 19) one widening multiply (m < 2^53: no overflow).
        let num = match u64::try_from(pow) {
            Ok(pow) => u128::from(m) * u128::from(pow),
            Err(_) => u128::from(m).checked_mul(pow)?,
        };
        (num, 1u128)
    } else {
        (u128::from(m), pow(-p)?)
    };
    if e >= 0 {
        let shift = u32::try_from(e).ok()?;
        if shift >= num.leading_zeros() {
            return None;
        }
        num <<= shift;
    } else {
        let shift = u32::try_from(-e).ok()?;
        // Keep 2 den below 2^128 (the half comparison takes den - r).
        if shift >= den.leading_zeros() {
            return None;
        }
        if den == 1 {
            // A power of two: shifts, no division (most table numbers).
            let mask = (1u128 << shift) - 1;
            return Some((num >> shift, num & mask, 1u128 << shift));
        }
        den <<= shift;
    }
    Some((num / den, num % den, den))
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

/// Writes the `n` digits of `q` as `d.ddd` (`d` alone for one digit), `e` and `k`.
fn write(out: &mut Vec<u8>, negative: bool, q: u64, n: usize, k: i32) {
    // The text is put together on the stack: at most a sign, 17 digits, the point, `e`, a
    // sign and 3 digits (26 bytes).
    let mut text = [0u8; 32];
    let mut len = usize::from(negative);
    text[0] = b'-';
    // The digits two at a time from the last (an odd count starts with a pair's second),
    // one place to the right; the first then moves left over the point.
    let mut q = q;
    let mut end = len + 1 + n;
    while end > len + 2 {
        text[end - 2..end].copy_from_slice(&PAIRS[(q % 100) as usize]);
        q /= 100;
        end -= 2;
    }
    if end > len + 1 {
        text[len + 1] = b'0' + q as u8;
    }
    text[len] = text[len + 1];
    if n > 1 {
        text[len + 1] = b'.';
        len += n + 1;
    } else {
        len += 1;
    }
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
    len += 1;
    // The whole array and then the length: a copy of known size, no call to `memcpy`.
    let start = out.len();
    out.extend_from_slice(&text);
    out.truncate(start + len);
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

    #[test]
    fn agrees_with_the_standard_formatting() {
        // Random numbers from 1e-20 to 1e20, both signs.
        let mut rng = crate::rng::SplitMix64::new(0x9e37_79b9_7f4a_7c15);
        let mut next = || rng.next_u64();
        let (mut fast, mut total) = (0, 0);
        for _ in 0..1_000_000 {
            let r = next();
            let decade = (r % 41) as i32 - 20;
            let mantissa = 1.0 + (r >> 11) as f64 / (1u64 << 53) as f64 * 9.0;
            let sign = if r & 1 == 0 { 1.0 } else { -1.0 };
            let x = sign * mantissa * 10f64.powi(decade);
            for digits in [10, 3, 17] {
                total += 1;
                fast += usize::from(check(x, digits));
            }
        }
        // The path covers the tables' range: all but the far decades.
        assert!(fast * 10 > total * 8, "{fast} of {total}");
    }

    #[test]
    fn few_digits_beyond_the_guess_table() {
        // With few digits the integer path reaches past the decades of `POW10_GUESS`
        // (1e-30 to 1e30), where the exponent's first guess comes from the binary exponent
        // alone.
        let mut rng = crate::rng::SplitMix64::new(0x005e_ed0f_d161_7500);
        let mut fast = 0;
        for _ in 0..200_000 {
            let r = rng.next_u64();
            let decade = (r % 81) as i32 - 40;
            let mantissa = 1.0 + (r >> 11) as f64 / (1u64 << 53) as f64 * 9.0;
            let x = mantissa * 10f64.powi(decade);
            for digits in [1, 2, 3] {
                fast += usize::from(check(x, digits));
            }
        }
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
