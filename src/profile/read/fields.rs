//! Number and token parsing shared by the readers, with the error variants the readers report.

use super::error::{Field, ReadError};

/// A point read from a file, already in the side frame, with the line it came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RawPoint {
    /// Lateral coordinate, side frame, mm.
    pub lat: f64,
    /// Vertical coordinate, side frame, mm.
    pub vert: f64,
    /// 1-based line number in the file.
    pub line: usize,
}

/// Parses one number as written by C, Fortran (`1.0D+03`, `1000.`) or spreadsheet programs.
///
/// # Errors
///
/// [`ReadError::NonNumeric`] for text that is not a number, [`ReadError::NonFinite`] for
/// NaN and infinities (which Rust's parser would accept).
pub(crate) fn number(
    token: &str,
    origin: &str,
    line: usize,
    field: Field,
    expected: &'static str,
) -> Result<f64, ReadError> {
    let parsed = exact_decimal(token)
        .or_else(|| token.parse::<f64>().ok())
        .or_else(|| {
            // Fortran writes double-precision exponents with D; only try when that is the sole
            // difference, so that words like "dead" stay non-numeric.
            if token.contains(['d', 'D']) {
                token.replace(['d', 'D'], "e").parse::<f64>().ok()
            } else {
                None
            }
        });
    match parsed {
        Some(v) if v.is_finite() => Ok(v),
        Some(_) => Err(ReadError::NonFinite {
            origin: origin.to_owned(),
            line,
            field,
            value: token.to_owned(),
        }),
        None => Err(ReadError::NonNumeric {
            origin: origin.to_owned(),
            line,
            field,
            value: shorten(token),
            expected,
        }),
    }
}

/// The largest power of ten an `f64` holds exactly (5^22 < 2^53).
const MAX_EXACT_POWER_OF_TEN: usize = 22;

/// 10^0 to 10^22, each exact in an `f64`.
const POWERS_OF_TEN: [f64; MAX_EXACT_POWER_OF_TEN + 1] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The value of `token` when the whole of it is a decimal number that converts exactly by
/// Clinger's fast path, else `None` (and the caller asks `str::parse`).
///
/// The form is `[+-]digits[.digits][(e|E)[+-]digits]` with at least one digit before the
/// exponent, a subset of what `str::parse::<f64>` accepts. When the digits, without the
/// point, are an integer `m` of at most 2^53 (exact in an `f64`) and the decimal exponent
/// `e` is within ±22 (so 10^|e| is exact), `m * 10^e` or `m / 10^e` is one
/// IEEE operation on exact operands, rounded to nearest: the correctly rounded value, the
/// one `str::parse` gives, to the bit (W. D. Clinger, "How to read floating point numbers
/// accurately", PLDI 1990; the standard library's own first path). The test
/// `exact_decimals_are_the_standard_parse_to_the_bit` and the one after it compare the two
/// on every form.
///
/// Why: a profile file is two short decimals per line, which `number` gave to `str::parse`
/// for 264 instructions each on the EN 15302 reference files (`tests/data/en15302/`); this
/// takes some 180, and with [`short_decimal`] some 135 (callgrind).
pub(crate) fn exact_decimal(token: &str) -> Option<f64> {
    match decimal_prefix(token.as_bytes()) {
        Some((value, used)) if used == token.len() => Some(value),
        _ => None,
    }
}

/// [`exact_decimal`] of the longest prefix of `bytes` in its form, with the number of bytes
/// it takes, or `None` when the prefix holds no digit, ends in an exponent mark without
/// digits, or does not convert exactly by the fast path.
///
/// A number of at most seven digits before its point and seven after, without an exponent,
/// with eight bytes or more from the start of each run (every number of a profile file but
/// the last few), is read eight bytes at a time
/// ([`short_decimal`]); any other by [`any_decimal`].
// Inlined into the CSV reader's loop with `short_decimal` (the rare `any_decimal` not):
// 0.98 M -> 0.93 M instructions for the E1 scene's two profiles (callgrind).
#[inline(always)]
pub(crate) fn decimal_prefix(bytes: &[u8]) -> Option<(f64, usize)> {
    short_decimal(bytes).or_else(|| any_decimal(bytes))
}

/// [`decimal_prefix`] of `[+-]digits[.digits]` with at most seven digits before the point
/// and seven after, eight bytes or more from the start of each run, and no exponent after
/// them; `None` for anything else (which [`any_decimal`] then reads).
///
/// The integer digits, and after a point the fraction's, are found and read as whole
/// runs: eight bytes as one `u64` (SWAR, [`digit_run`]); the two runs joined are the
/// integer [`any_decimal`] reads, divided by 10^(fraction digits) as it does. Why: [`any_decimal`], one digit
/// at a time and each step checked, took some 180 instructions a number of the two
/// 1001-point EN 15302 reference files (`tests/data/en15302/`, 0.72 M); this takes some
/// 135 (callgrind, the `report` of the E1 scene: 0.72 M -> 0.54 M).
#[inline(always)]
fn short_decimal(bytes: &[u8]) -> Option<(f64, usize)> {
    let (negative, start) = match bytes.first() {
        Some(b'-') => (true, 1),
        Some(b'+') => (false, 1),
        _ => (false, 0),
    };
    let (whole, whole_digits) = digit_run(bytes.get(start..)?)?;
    let after = start + whole_digits;
    let (part, fraction, end) = if bytes.get(after) == Some(&b'.') {
        let (part, fraction) = digit_run(bytes.get(after + 1..)?)?;
        (part, fraction, after + 1 + fraction)
    } else {
        (0, 0, after)
    };
    if whole_digits + fraction == 0 || matches!(bytes.get(end), Some(b'e' | b'E')) {
        return None;
    }
    // The mantissa `any_decimal` reads, at most 14 digits: exact in an `i64` and in an
    // `f64` (converted from `i64`, one instruction where `u64` takes a dozen); 10^fraction
    // is exact too, so one division rounds as `any_decimal`'s does (which multiplies by
    // 10^0 = 1 where this divides by it).
    let m = ((whole * POWERS_OF_TEN_U64[fraction] + part) as i64) as f64;
    let magnitude = m / POWERS_OF_TEN[fraction];
    Some((if negative { -magnitude } else { magnitude }, end))
}

/// Every byte of a `u64` equal to one.
const ONES: u64 = 0x0101_0101_0101_0101;

/// The value of the digits `bytes` starts with, and how many there are (0 to 7); `None`
/// when there are fewer than eight bytes or eight digits (the run's end not in sight).
fn digit_run(bytes: &[u8]) -> Option<(u64, usize)> {
    // Each byte XOR `0`: a digit's value for a digit, 10 or more for any other byte (XOR
    // is one to one).
    let values = u64::from_le_bytes(*bytes.first_chunk::<8>()?) ^ (ONES * u64::from(b'0'));
    // The top bit of each byte whose value is 10 or more: its low seven bits plus 118 reach
    // 128 from 10 on and stay within the byte (127 + 118 < 256); a top bit of its own counts.
    let others = (((values & (ONES * 0x7f)) + ONES * 118) | values) & (ONES * 0x80);
    // The first byte is the lowest: the run ends at the lowest marked byte.
    let run = others.trailing_zeros() / 8;
    if run == 8 {
        return None;
    }
    // The run moved to the top bytes, zeros below it (and nothing of it when it is empty):
    // an eight-digit number of its value.
    let value = eight_digits(values.checked_shl(64 - 8 * run).unwrap_or(0));
    Some((value, run as usize))
}

/// 10^0 to 10^7, the place value of a run of digits before one of 0 to 7 digits.
const POWERS_OF_TEN_U64: [u64; 8] = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000];

/// The value of eight decimal digits, one a byte, the first (most significant) in the
/// lowest byte as `u64::from_le_bytes` reads text: adjacent digits are joined into pairs,
/// pairs into fours, fours into the eight (each step multiplications by place values;
/// lanes never overflow into each other, the result being at most 99 999 999 < 2^32).
fn eight_digits(values: u64) -> u64 {
    const LOW_OF_FOURS: u64 = 0x0000_00ff_0000_00ff;
    // Place values of pairs: 100 and 1 for the low four's (the low half), 10^6 and 10^4
    // for the high four's (the high half, where the result is read).
    const FIRST: u64 = 100 + (1_000_000 << 32);
    const SECOND: u64 = 1 + (10_000 << 32);
    // Byte 2k holds 10 * digit 2k + digit 2k + 1 (the odd bytes hold what is not used).
    let pairs = values * 10 + (values >> 8);
    (pairs & LOW_OF_FOURS)
        .wrapping_mul(FIRST)
        .wrapping_add(((pairs >> 16) & LOW_OF_FOURS).wrapping_mul(SECOND))
        >> 32
}

/// [`decimal_prefix`] of any prefix, one digit at a time.
#[inline(never)]
fn any_decimal(bytes: &[u8]) -> Option<(f64, usize)> {
    /// Significant digits that fit in a `u64` whatever they are (10^19 < 2^64).
    const MAX_DIGITS: usize = 19;
    /// The largest integer up to which every integer is exact in an `f64`.
    const MAX_EXACT_INTEGER: u64 = 1 << 53;
    let mut at = 0;
    let negative = match bytes.first() {
        Some(b'-') => {
            at = 1;
            true
        }
        Some(b'+') => {
            at = 1;
            false
        }
        _ => false,
    };
    // Leading zeros are passed over: they are digits, but not significant ones.
    let first_digit = at;
    at = zeros(bytes, at);
    let mut mantissa: u64 = 0;
    let integer = at;
    at = digits(bytes, at, &mut mantissa);
    let mut significant = at - integer;
    let mut fraction = 0;
    let mut any_digit = at > first_digit;
    if bytes.get(at) == Some(&b'.') {
        at += 1;
        let point = at;
        if significant == 0 {
            at = zeros(bytes, at);
        }
        let digit = at;
        at = digits(bytes, at, &mut mantissa);
        significant += at - digit;
        fraction = at - point;
        any_digit |= at > point;
    }
    if !any_digit || significant > MAX_DIGITS {
        return None;
    }
    let mut exponent: i64 = 0;
    if let Some(b'e' | b'E') = bytes.get(at) {
        at += 1;
        let negative_exponent = match bytes.get(at) {
            Some(b'-') => {
                at += 1;
                true
            }
            Some(b'+') => {
                at += 1;
                false
            }
            _ => false,
        };
        let start = at;
        while let Some(&b @ b'0'..=b'9') = bytes.get(at) {
            // Saturating: any exponent this large leaves the fast path anyway.
            exponent = (exponent * 10 + i64::from(b - b'0')).min(1 << 20);
            at += 1;
        }
        if at == start {
            return None;
        }
        if negative_exponent {
            exponent = -exponent;
        }
    }
    if mantissa > MAX_EXACT_INTEGER {
        return None;
    }
    // `fraction` is at most the token's length, far below i64's range.
    let exponent = exponent - i64::try_from(fraction).ok()?;
    let power = POWERS_OF_TEN.get(usize::try_from(exponent.unsigned_abs()).ok()?)?;
    // Exact: the mantissa is at most 2^53.
    let m = mantissa as f64;
    let magnitude = if exponent < 0 { m / power } else { m * power };
    Some((if negative { -magnitude } else { magnitude }, at))
}

/// The end of the run of `0` starting at `at` in `bytes`.
fn zeros(bytes: &[u8], mut at: usize) -> usize {
    while bytes.get(at) == Some(&b'0') {
        at += 1;
    }
    at
}

/// The end of the run of decimal digits starting at `at` in `bytes`, their value appended
/// to `mantissa` (wrapping: the caller discards it when there are more than 19).
fn digits(bytes: &[u8], mut at: usize, mantissa: &mut u64) -> usize {
    while let Some(&b) = bytes.get(at) {
        let digit = b.wrapping_sub(b'0');
        if digit > 9 {
            break;
        }
        *mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(digit));
        at += 1;
    }
    at
}

/// Whether a token reads as a number (finite or not); used to tell data rows from header text.
pub(crate) fn is_number(token: &str) -> bool {
    token.parse::<f64>().is_ok()
        || (token.contains(['d', 'D']) && token.replace(['d', 'D'], "e").parse::<f64>().is_ok())
}

/// Splits a data row at white space and commas.
pub(crate) fn tokens(line: &str) -> impl Iterator<Item = &str> {
    line.split(|c: char| c.is_whitespace() || c == ',')
        .filter(|t| !t.is_empty())
}

/// Keeps error messages readable when a "number" is a whole paragraph of garbage.
fn shorten(token: &str) -> String {
    const MAX_CHARS: usize = 40;
    if token.chars().count() <= MAX_CHARS {
        token.to_owned()
    } else {
        let head: String = token.chars().take(MAX_CHARS).collect();
        format!("{head}...")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(t: &str) -> Result<f64, ReadError> {
        number(t, "t", 1, Field::Column(1), "a number")
    }

    #[test]
    fn accepts_c_and_fortran_forms() {
        for (text, want) in [
            ("1000.", 1000.0),
            ("+1.000000000000000e+03", 1000.0),
            ("1.0D+03", 1000.0),
            ("-4.3704898E+01", -43.704898),
        ] {
            let got = parse(text).unwrap();
            assert!((got - want).abs() < 1e-12, "{text}: {got}");
        }
    }

    /// `exact_decimal` of `token` is `str::parse`'s value to the bit whenever it has one;
    /// whether it had one.
    fn check_exact(token: &str) -> bool {
        let Some(fast) = exact_decimal(token) else {
            return false;
        };
        let parsed = token.parse::<f64>();
        assert_eq!(
            parsed.clone().map(f64::to_bits),
            Ok(fast.to_bits()),
            "{token:?}: {fast:e} against {parsed:?}"
        );
        true
    }

    /// `exact_decimal` is `str::parse` to the bit wherever it gives a value (here and in
    /// `random_decimals_read_as_the_standard_parse_reads_them`).
    #[test]
    fn exact_decimals_are_the_standard_parse_to_the_bit() {
        // Edges of the form and of the fast path's range: signed zeros, no digits before or
        // after the point, exponents without digits, 2^53 and above, 10^22 and above.
        for (token, fast) in [
            ("0", true),
            ("-0", true),
            ("-0.000", true),
            ("+0e-5", true),
            ("1.", true),
            (".5", true),
            ("-.5", true),
            ("+.5e1", true),
            ("1.e5", true),
            ("00000000000000000000000001.5", true),
            ("9007199254740992", true),
            ("9007199254740993", false),
            ("90071992547409920", false),
            ("1e22", true),
            ("1e23", false),
            ("1e-22", true),
            ("1e-23", false),
            ("123456789e-30", false),
            ("0.1234567890123456789", false),
            ("1e99999999999999999999999", false),
            ("", false),
            ("+", false),
            ("-", false),
            (".", false),
            ("-.", false),
            ("e5", false),
            ("1e", false),
            ("1e+", false),
            ("1.2.3", false),
            ("1,5", false),
            (" 1", false),
            ("1 ", false),
            ("1D3", false),
            ("inf", false),
            ("NaN", false),
            ("0x10", false),
        ] {
            assert_eq!(check_exact(token), fast, "{token:?}");
        }
    }

    #[test]
    fn random_decimals_read_as_the_standard_parse_reads_them() {
        // Random tokens of the form and near it: signs, up to 20 digits on either side of a
        // point, exponents of up to 3 digits, now and then a stray character.
        let mut rng = crate::rng::SplitMix64::new(29);
        let mut below = |n: u64| rng.next_u64() % n;
        let mut fast = 0;
        let rounds = 200_000;
        for _ in 0..rounds {
            let mut token = String::new();
            let pieces = [
                ["", "-", "+", ""][below(4) as usize],
                &"0123456789".repeat(2)[..below(21) as usize],
                ["", ".", ".", "x"][below(4) as usize],
            ];
            for piece in pieces {
                token += piece;
            }
            for _ in 0..below(21) {
                token.push(char::from(b'0' + below(10) as u8));
            }
            if below(2) == 0 {
                token += ["e", "E", "e-", "e+", "E-"][below(5) as usize];
                for _ in 0..below(4) {
                    token.push(char::from(b'0' + below(10) as u8));
                }
            }
            // Shuffle the digits' values so that the mantissas are not all the same.
            let token: String = token
                .chars()
                .map(|c| match c {
                    '0'..='9' if below(3) == 0 => char::from(b'0' + below(10) as u8),
                    c => c,
                })
                .collect();
            fast += usize::from(check_exact(&token));
        }
        // Both outcomes are exercised (18 % fast with this seed).
        assert!(fast > rounds / 10 && fast < rounds / 2, "{fast} fast");
        // Doubles as programs write them (shortest, fixed decimals, scientific), and integers
        // up to 2^53 over powers of ten: the roundings that are hard to get right.
        let mut fast = 0;
        for _ in 0..rounds {
            let x = f64::from_bits(below(1 << 62)) * if below(2) == 0 { -1.0 } else { 1.0 };
            let m = below((1 << 53) + 1);
            let e = below(45) as i32 - 22;
            for token in [
                format!("{x}"),
                format!("{x:.5}"),
                format!("{x:e}"),
                format!("{}", (x * 1e-300).clamp(-1e6, 1e6)),
                format!("{:.5}", (x * 1e-300).clamp(-1e6, 1e6)),
                format!("{m}e{e}"),
            ] {
                fast += usize::from(check_exact(&token));
            }
        }
        assert!(fast > rounds, "{fast} fast");
    }

    /// Numbers at the edges of the eight-byte reading ([`short_decimal`]): runs of 0 to 20
    /// digits, split at a point or not, signed or not, with leading zeros, with an exponent
    /// or not, followed by the bytes around the digits' (`/`, `:`, and `°` whose second byte
    /// is `0` + 128), a separator, more text within or past the eight bytes, or nothing.
    /// Each reads as one digit at a time ([`any_decimal`]) reads it, and where it is the
    /// whole token, as `str::parse` reads it, to the bit.
    #[test]
    fn numbers_read_eight_bytes_at_a_time_as_one_digit_at_a_time() {
        let mut rng = crate::rng::SplitMix64::new(8);
        let mut below = |n: u64| rng.next_u64() % n;
        let tails = [
            "",
            ",",
            "x",
            "/",
            ":",
            ".",
            "e",
            "E5",
            "\n",
            "\u{b0}",
            "\u{3000}",
            ".5",
            ",1234567",
            "\n-70.00000,9.51900\n",
        ];
        let mut short = 0;
        for len in 0..=20 {
            for _ in 0..100 {
                let run: String = (0..len)
                    .map(|_| char::from(b'0' + below(10) as u8))
                    .collect();
                let (whole, part) = run.split_at(below(len + 1) as usize);
                for sign in ["", "-", "+"] {
                    for zeros in ["", "0", "000000000"] {
                        for point in [".", ""] {
                            for exponent in ["", "e-3", "E+2"] {
                                let token = format!("{sign}{zeros}{whole}{point}{part}{exponent}");
                                if let Some((value, used)) = decimal_prefix(token.as_bytes()) {
                                    assert_eq!(used, token.len(), "{token:?}");
                                    assert_eq!(
                                        token.parse::<f64>().map(f64::to_bits),
                                        Ok(value.to_bits()),
                                        "{token:?}"
                                    );
                                }
                                for tail in tails {
                                    let text = format!("{token}{tail}");
                                    let bytes = text.as_bytes();
                                    let got = decimal_prefix(bytes);
                                    let want = any_decimal(bytes);
                                    assert_eq!(
                                        got.map(|(v, n)| (v.to_bits(), n)),
                                        want.map(|(v, n)| (v.to_bits(), n)),
                                        "{text:?}"
                                    );
                                    short += usize::from(short_decimal(bytes).is_some());
                                }
                            }
                        }
                    }
                }
            }
        }
        // Both paths are exercised.
        assert!(short > 10_000 && short < 500_000, "{short} short");
    }

    #[test]
    fn rejects_words_and_non_finite() {
        assert!(matches!(parse("abc"), Err(ReadError::NonNumeric { .. })));
        assert!(matches!(parse("dead"), Err(ReadError::NonNumeric { .. })));
        assert!(matches!(parse("NaN"), Err(ReadError::NonFinite { .. })));
        assert!(matches!(parse("-inf"), Err(ReadError::NonFinite { .. })));
        assert!(matches!(parse("1e999"), Err(ReadError::NonFinite { .. })));
    }
}
