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
    let parsed = token.parse::<f64>().ok().or_else(|| {
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

    #[test]
    fn rejects_words_and_non_finite() {
        assert!(matches!(parse("abc"), Err(ReadError::NonNumeric { .. })));
        assert!(matches!(parse("dead"), Err(ReadError::NonNumeric { .. })));
        assert!(matches!(parse("NaN"), Err(ReadError::NonFinite { .. })));
        assert!(matches!(parse("-inf"), Err(ReadError::NonFinite { .. })));
        assert!(matches!(parse("1e999"), Err(ReadError::NonFinite { .. })));
    }
}
