//! The diff a person reads: `Display` of a [`Comparison`] and of a [`FilesComparison`],
//! capped so that a large mismatch stays readable.

use std::fmt;

use super::super::table::{NumberFormat, format_number};
use super::{ColumnDiff, Comparison, FileOutcome, FilesComparison, NumericFailure};

/// At most this many columns are detailed by `Display for Comparison`; the rest are counted.
pub const SHOWN_COLUMNS: usize = 12;

fn num(x: f64) -> String {
    format_number(x, NumberFormat::Significant(10))
}

impl NumericFailure {
    fn describe(&self, key_name: Option<&str>) -> String {
        let key = match (key_name, self.key) {
            (Some(name), Some(k)) => {
                format!(" ({name} = {})", format_number(k, NumberFormat::Shortest))
            }
            _ => String::new(),
        };
        format!(
            "row {}{key}: expected {}, actual {}, |diff| {}, allowed {}",
            self.row,
            num(self.expected),
            num(self.actual),
            num(self.difference),
            num(self.allowance)
        )
    }
}

impl fmt::Display for Comparison {
    /// A readable diff, at most about 8 lines per column and [`SHOWN_COLUMNS`] columns.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_match() {
            return f.write_str("tables match within tolerance\n");
        }
        if !self.missing_columns.is_empty() {
            writeln!(f, "missing columns: {}", self.missing_columns.join(", "))?;
        }
        if !self.extra_columns.is_empty() {
            writeln!(f, "extra columns: {}", self.extra_columns.join(", "))?;
        }
        if let Some((e, a)) = self.row_counts {
            writeln!(
                f,
                "row count: expected {e}, actual {a} (common rows compared)"
            )?;
        }
        let key = self.key_column.as_deref();
        for (name, diff) in self.columns.iter().take(SHOWN_COLUMNS) {
            match diff {
                ColumnDiff::KindMismatch { expected, actual } => {
                    writeln!(f, "{name}: expected a {expected} column, found {actual}")?;
                }
                ColumnDiff::Numeric {
                    tolerance,
                    failing,
                    compared,
                    worst,
                    first,
                } => {
                    writeln!(
                        f,
                        "{name}: {failing} of {compared} rows outside tolerance ({tolerance})"
                    )?;
                    writeln!(f, "  worst {}", worst.describe(key))?;
                    for failure in first {
                        writeln!(f, "  {}", failure.describe(key))?;
                    }
                    if *failing > first.len() {
                        writeln!(f, "  ... {} more", failing - first.len())?;
                    }
                }
                ColumnDiff::Text {
                    failing,
                    compared,
                    first,
                } => {
                    writeln!(f, "{name}: {failing} of {compared} text cells differ")?;
                    for t in first {
                        writeln!(
                            f,
                            "  row {}: expected {:?}, actual {:?}",
                            t.row, t.expected, t.actual
                        )?;
                    }
                    if *failing > first.len() {
                        writeln!(f, "  ... {} more", failing - first.len())?;
                    }
                }
            }
        }
        if self.columns.len() > SHOWN_COLUMNS {
            writeln!(
                f,
                "... and {} more differing columns",
                self.columns.len() - SHOWN_COLUMNS
            )?;
        }
        Ok(())
    }
}

impl fmt::Display for FilesComparison {
    /// One block per file that does not match; a one-line summary when all match.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let failing = self.failing().count();
        if failing == 0 {
            return writeln!(f, "all {} files match within tolerance", self.files.len());
        }
        writeln!(f, "{failing} of {} files differ", self.files.len())?;
        for (name, outcome) in &self.files {
            match outcome {
                FileOutcome::Match => {}
                FileOutcome::Differs(c) => {
                    writeln!(f, "--- {name}")?;
                    for line in c.to_string().lines() {
                        writeln!(f, "  {line}")?;
                    }
                }
                FileOutcome::MissingExpected => {
                    writeln!(
                        f,
                        "--- {name}: no golden file (new output; review and accept it)"
                    )?;
                }
                FileOutcome::MissingActual => writeln!(f, "--- {name}: not produced")?,
                FileOutcome::InvalidExpected(e) => writeln!(f, "--- {name}: golden file: {e}")?,
                FileOutcome::InvalidActual(e) => writeln!(f, "--- {name}: produced file: {e}")?,
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::golden::{TolerancePolicy, compare};
    use crate::table::Table;

    fn one(name: &str, v: Vec<f64>) -> Table {
        Table::builder().numeric(name, v).build().unwrap()
    }

    #[test]
    fn display_is_capped() {
        let n = 1000;
        let golden = Table::builder()
            .numeric("a_mm", vec![0.0; n])
            .build()
            .unwrap();
        let actual = one("a_mm", (0..n).map(|i| i as f64).collect());
        let text = compare(&golden, &actual, &TolerancePolicy::default()).to_string();
        assert!(text.lines().count() <= 8, "{text}");
        assert!(text.contains("a_mm: 999 of 1000 rows outside tolerance"));
        assert!(text.contains("worst row 999"));
        assert!(text.contains("... 994 more"));
    }
}
