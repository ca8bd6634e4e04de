//! Helpers for the words of error messages, shared by every module that checks an input: a
//! leaf of the module graph (it imports nothing of the crate), so that any module may use it.

use std::fmt;

/// A number in a message as a user would write it: the shortest text that reads back as the
/// same `f64`, in scientific notation when it is very large or very small (`1e308`, not 309
/// digits; `1e-300`, not 300 zeros).
#[derive(Debug, Clone, Copy)]
pub struct Number(pub f64);

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let magnitude = self.0.abs();
        if magnitude == 0.0 || !magnitude.is_finite() || (1e-4..1e16).contains(&magnitude) {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Number;

    #[test]
    fn numbers_read_as_written() {
        for (x, text) in [
            (1e308, "1e308"),
            (-1e-300, "-1e-300"),
            (70.0, "70"),
            (0.3, "0.3"),
            (1.5e-5, "1.5e-5"),
            (f64::INFINITY, "inf"),
            (0.0, "0"),
        ] {
            assert_eq!(Number(x).to_string(), text);
            assert_eq!(
                Number(x).to_string().parse::<f64>().unwrap().to_bits(),
                x.to_bits()
            );
        }
    }
}
