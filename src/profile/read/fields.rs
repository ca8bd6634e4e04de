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
    match value(token) {
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

/// Whether a token reads as a number (finite or not); used to tell data rows from header text.
pub(crate) fn is_number(token: &str) -> bool {
    value(token).is_some()
}

/// The value of `token` by `str::parse::<f64>` (correctly rounded, so the same bits as any
/// other correct reader of the file), or of the token with Fortran's `D` exponent read as
/// `e`; NaN and infinities included.
fn value(token: &str) -> Option<f64> {
    token.parse::<f64>().ok().or_else(|| {
        // Fortran writes double-precision exponents with D; only try when that is the sole
        // difference, so that words like "dead" stay non-numeric.
        if token.contains(['d', 'D']) {
            token.replace(['d', 'D'], "e").parse::<f64>().ok()
        } else {
            None
        }
    })
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
            ("1000.", 1000.0_f64),
            ("+1.000000000000000e+03", 1000.0),
            ("1.0D+03", 1000.0),
            ("-4.3704898E+01", -43.704898),
        ] {
            // Exact: the token and the literal are the same decimal, both correctly rounded.
            let got = parse(text).unwrap();
            assert_eq!(got.to_bits(), want.to_bits(), "{text}: {got}");
        }
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
