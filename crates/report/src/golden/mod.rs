//! Golden-file comparison: tables compared column by column with stated tolerances.
//!
//! A golden file is a CSV [`Table`] that a reviewer accepted. A test recomputes the table and
//! calls [`compare`] with a [`TolerancePolicy`] naming the tolerance of every column; the
//! resulting [`Comparison`] says whether they match and, through `Display`, prints a diff a
//! person can act on: per column the number of failing rows, the worst row (expected, actual,
//! difference, allowance) and the first few failing rows.
//!
//! Comment lines are not compared: they carry provenance (versions, dates) that may change
//! without the numbers changing.
//!
//! [`compare_files`] does the same for a set of files whose texts the caller has read, so the
//! comparison itself never touches the file system.

//!
//! The parts: [`Tolerance`] and [`TolerancePolicy`] (`tolerance.rs`), the comparison
//! (here), and the diff text of `Display` (`text.rs`).

mod text;
mod tolerance;

pub use text::SHOWN_COLUMNS;
pub use tolerance::{Tolerance, TolerancePolicy};

use super::table::{ColumnData, Table, TableError};
use std::borrow::Cow;

/// One numeric value outside its tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericFailure {
    /// Data row, counted from 0 after the header.
    pub row: usize,
    /// Value of the policy's key column in this row of the expected table, if there is one.
    pub key: Option<f64>,
    /// Golden value.
    pub expected: f64,
    /// Computed value.
    pub actual: f64,
    /// `|actual - expected|` (`NaN` when exactly one of them is `NaN`).
    pub difference: f64,
    /// The tolerance's allowance at `expected`.
    pub allowance: f64,
}

impl NumericFailure {
    /// How many allowances the difference spans; infinite for a NaN mismatch or a zero
    /// allowance.
    pub fn excess(&self) -> f64 {
        if self.difference.is_nan() {
            f64::INFINITY
        } else if self.allowance > 0.0 {
            self.difference / self.allowance
        } else {
            f64::INFINITY
        }
    }

    /// Order of badness: a NaN mismatch, then the larger excess, then the larger difference.
    fn is_worse_than(&self, other: &NumericFailure) -> bool {
        let key = |f: &NumericFailure| (f.difference.is_nan(), f.excess(), f.difference);
        let (a, b) = (key(self), key(other));
        a.0.cmp(&b.0)
            .then(a.1.total_cmp(&b.1))
            .then(a.2.total_cmp(&b.2))
            .is_gt()
    }
}

/// One text cell that differs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TextFailure {
    /// Data row, counted from 0 after the header.
    pub row: usize,
    /// Golden text.
    pub expected: String,
    /// Computed text.
    pub actual: String,
}

/// How many failures a [`ColumnDiff`] keeps in its `first` list.
pub const KEPT_FAILURES: usize = 5;

/// What differs in one column present in both tables.
#[derive(Debug, Clone, PartialEq)]
pub enum ColumnDiff {
    /// One table has numbers, the other text.
    KindMismatch {
        /// `"numeric"` or `"text"`.
        expected: &'static str,
        /// `"numeric"` or `"text"`.
        actual: &'static str,
    },
    /// Numbers outside tolerance.
    Numeric {
        /// The tolerance applied.
        tolerance: Tolerance,
        /// Number of failing rows.
        failing: usize,
        /// Number of rows compared (those both tables have).
        compared: usize,
        /// The worst failure: a NaN mismatch, else the largest [`NumericFailure::excess`], else
        /// the largest difference (the first one on ties).
        worst: NumericFailure,
        /// The first failures in row order, at most [`KEPT_FAILURES`].
        first: Vec<NumericFailure>,
    },
    /// Text cells that differ.
    Text {
        /// Number of failing rows.
        failing: usize,
        /// Number of rows compared (those both tables have).
        compared: usize,
        /// The first failures in row order, at most [`KEPT_FAILURES`].
        first: Vec<TextFailure>,
    },
}

/// The result of comparing an actual table with a golden one; see [`compare`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Comparison {
    /// Columns of the golden table that the actual one lacks.
    pub missing_columns: Vec<String>,
    /// Columns of the actual table that the golden one lacks.
    pub extra_columns: Vec<String>,
    /// `(expected, actual)` row counts, when they differ.
    pub row_counts: Option<(usize, usize)>,
    /// Differences in shared columns, in the golden table's column order.
    pub columns: Vec<(String, ColumnDiff)>,
    /// Name of the key column, for the report.
    pub key_column: Option<String>,
}

impl Comparison {
    /// `true` when nothing differs beyond tolerance.
    pub fn is_match(&self) -> bool {
        self.missing_columns.is_empty()
            && self.extra_columns.is_empty()
            && self.row_counts.is_none()
            && self.columns.is_empty()
    }
}

/// Compares `actual` with the golden `expected`, column by column.
///
/// Columns are matched by name (order does not matter). Shared columns are compared over the
/// rows both tables have, so a row-count mismatch still shows the differences in the common
/// rows. Numeric columns use `policy.tolerance_for(name)`; text columns must be equal. Comment
/// lines are ignored.
///
/// # Examples
///
/// ```
/// use wheelrail_report::golden::{compare, Tolerance, TolerancePolicy};
/// use wheelrail_report::table::Table;
///
/// let golden = Table::builder().numeric("x_mm", vec![1.0, 2.0]).build()?;
/// let close = Table::builder().numeric("x_mm", vec![1.0, 2.0 + 5e-7]).build()?;
/// let far = Table::builder().numeric("x_mm", vec![1.0, 2.0 + 2e-6]).build()?;
/// let policy = TolerancePolicy::new(Tolerance::abs(1e-6));
/// assert!(compare(&golden, &close, &policy).is_match());
/// let diff = compare(&golden, &far, &policy);
/// assert!(!diff.is_match());
/// assert!(diff.to_string().contains("x_mm: 1 of 2 rows outside"));
/// # Ok::<(), wheelrail_report::table::TableError>(())
/// ```
pub fn compare(expected: &Table, actual: &Table, policy: &TolerancePolicy) -> Comparison {
    let mut out = Comparison {
        key_column: policy.key_column.clone(),
        ..Comparison::default()
    };
    out.missing_columns = expected
        .column_names()
        .filter(|n| actual.column(n).is_none())
        .map(str::to_owned)
        .collect();
    out.extra_columns = actual
        .column_names()
        .filter(|n| expected.column(n).is_none())
        .map(str::to_owned)
        .collect();
    if expected.n_rows() != actual.n_rows() {
        out.row_counts = Some((expected.n_rows(), actual.n_rows()));
    }
    let keys = policy
        .key_column
        .as_deref()
        .and_then(|k| expected.numeric(k));
    for e in expected.columns() {
        let Some(a) = actual.column(&e.name) else {
            continue;
        };
        let diff = match (&e.data, &a.data) {
            (ColumnData::Numeric(ev), ColumnData::Numeric(av)) => compare_numeric(
                ev,
                av,
                policy.tolerance_for(&e.name),
                |row| policy.tolerance_at(&e.name, keys.and_then(|k| k.get(row).copied())),
                keys,
            ),
            (ColumnData::Text(ev), ColumnData::Text(av)) => compare_text(ev, av),
            // A column without rows reads back as numeric whatever it held.
            (ed, ad) if ed.is_empty() || ad.is_empty() => None,
            (ed, ad) => Some(ColumnDiff::KindMismatch {
                expected: ed.kind(),
                actual: ad.kind(),
            }),
        };
        if let Some(diff) = diff {
            out.columns.push((e.name.clone(), diff));
        }
    }
    out
}

/// `tolerance` is the column's rule outside any region (reported), `at` the rule of a row.
fn compare_numeric(
    expected: &[f64],
    actual: &[f64],
    tolerance: Tolerance,
    at: impl Fn(usize) -> Tolerance,
    keys: Option<&[f64]>,
) -> Option<ColumnDiff> {
    let mut failing = 0;
    let mut worst: Option<NumericFailure> = None;
    let mut first = Vec::new();
    for (row, (&e, &a)) in expected.iter().zip(actual).enumerate() {
        let tolerance = at(row);
        if tolerance.accepts(e, a) {
            continue;
        }
        failing += 1;
        let failure = NumericFailure {
            row,
            key: keys.and_then(|k| k.get(row).copied()),
            expected: e,
            actual: a,
            difference: (a - e).abs(),
            allowance: tolerance.allowance(e),
        };
        if worst.as_ref().is_none_or(|w| failure.is_worse_than(w)) {
            worst = Some(failure.clone());
        }
        if first.len() < KEPT_FAILURES {
            first.push(failure);
        }
    }
    worst.map(|worst| ColumnDiff::Numeric {
        tolerance,
        failing,
        compared: expected.len().min(actual.len()),
        worst,
        first,
    })
}

fn compare_text(
    expected: &[Cow<'static, str>],
    actual: &[Cow<'static, str>],
) -> Option<ColumnDiff> {
    let mut failing = 0;
    let mut first = Vec::new();
    for (row, (e, a)) in expected.iter().zip(actual).enumerate() {
        if e != a {
            failing += 1;
            if first.len() < KEPT_FAILURES {
                first.push(TextFailure {
                    row,
                    expected: e.to_string(),
                    actual: a.to_string(),
                });
            }
        }
    }
    (failing > 0).then_some(ColumnDiff::Text {
        failing,
        compared: expected.len().min(actual.len()),
        first,
    })
}

/// The outcome for one file of [`compare_files`].
#[derive(Debug, Clone, PartialEq)]
pub enum FileOutcome {
    /// The tables match within tolerance.
    Match,
    /// The tables differ.
    Differs(Comparison),
    /// There is no golden text for a produced file (a new output: review and accept it).
    MissingExpected,
    /// A golden file was not produced.
    MissingActual,
    /// The golden text is not a valid table.
    InvalidExpected(TableError),
    /// The produced text is not a valid table.
    InvalidActual(TableError),
}

/// The outcomes of [`compare_files`], in the order given.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FilesComparison {
    /// `(file name, outcome)` pairs.
    pub files: Vec<(String, FileOutcome)>,
}

impl FilesComparison {
    /// `true` when every file matches.
    pub fn is_match(&self) -> bool {
        self.files.iter().all(|(_, o)| *o == FileOutcome::Match)
    }

    /// Names of the files that do not match.
    pub fn failing(&self) -> impl Iterator<Item = &str> {
        self.files
            .iter()
            .filter(|(_, o)| *o != FileOutcome::Match)
            .map(|(n, _)| n.as_str())
    }
}

/// Compares sets of CSV texts: each item is `(file name, golden text, produced text)`, a
/// `None` standing for a file that does not exist. The caller reads the files.
///
/// # Examples
///
/// ```
/// use wheelrail_report::golden::{compare_files, FileOutcome, TolerancePolicy};
///
/// let files = [
///     ("a.csv", Some("x_mm\n1\n"), Some("x_mm\n1\n")),
///     ("b.csv", None, Some("x_mm\n1\n")),
/// ];
/// let result = compare_files(&files, &TolerancePolicy::default());
/// assert!(!result.is_match());
/// assert_eq!(result.files[1].1, FileOutcome::MissingExpected);
/// assert_eq!(result.failing().collect::<Vec<_>>(), ["b.csv"]);
/// ```
pub fn compare_files(
    files: &[(&str, Option<&str>, Option<&str>)],
    policy: &TolerancePolicy,
) -> FilesComparison {
    let files = files
        .iter()
        .map(|&(name, expected, actual)| {
            let outcome = match (expected, actual) {
                (None, _) => FileOutcome::MissingExpected,
                (Some(_), None) => FileOutcome::MissingActual,
                (Some(e), Some(a)) => match (Table::parse_csv(e), Table::parse_csv(a)) {
                    (Err(e), _) => FileOutcome::InvalidExpected(e),
                    (_, Err(a)) => FileOutcome::InvalidActual(a),
                    (Ok(e), Ok(a)) => {
                        let c = compare(&e, &a, policy);
                        if c.is_match() {
                            FileOutcome::Match
                        } else {
                            FileOutcome::Differs(c)
                        }
                    }
                },
            };
            (name.to_owned(), outcome)
        })
        .collect();
    FilesComparison { files }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(name: &str, v: Vec<f64>) -> Table {
        Table::builder().numeric(name, v).build().unwrap()
    }

    #[test]
    fn just_within_passes_and_just_beyond_fails_abs() {
        // allowance = 1e-6; the perturbations are 0.1 % inside and outside it.
        let policy = TolerancePolicy::new(Tolerance::abs(1e-6));
        let golden = one("x_mm", vec![1.0, -3.0]);
        let within = one("x_mm", vec![1.0 + 0.999e-6, -3.0 - 0.999e-6]);
        let beyond = one("x_mm", vec![1.0 + 1.001e-6, -3.0]);
        assert!(compare(&golden, &within, &policy).is_match());
        assert!(!compare(&golden, &beyond, &policy).is_match());
    }

    #[test]
    fn just_within_passes_and_just_beyond_fails_rel() {
        // allowance = 1e-6 * |1000| = 1e-3, taken relative to the golden value.
        let policy = TolerancePolicy::new(Tolerance::rel(1e-6));
        let golden = one("p0_MPa", vec![1000.0]);
        assert!(compare(&golden, &one("p0_MPa", vec![1000.000999]), &policy).is_match());
        assert!(!compare(&golden, &one("p0_MPa", vec![1000.001001]), &policy).is_match());
        assert!(compare(&golden, &one("p0_MPa", vec![999.999001]), &policy).is_match());
        assert!(!compare(&golden, &one("p0_MPa", vec![999.998999]), &policy).is_match());
    }

    #[test]
    fn worst_is_largest_excess_and_nan_mismatch_is_worst() {
        let policy = TolerancePolicy::new(Tolerance::abs(1.0));
        let golden = one("a", vec![0.0, 0.0, 0.0, 0.0]);
        let actual = one("a", vec![2.0, 5.0, f64::NAN, 3.0]);
        let c = compare(&golden, &actual, &policy);
        let ColumnDiff::Numeric {
            failing,
            worst,
            first,
            ..
        } = &c.columns[0].1
        else {
            panic!("numeric diff expected")
        };
        assert_eq!(*failing, 4);
        assert_eq!(worst.row, 2);
        assert_eq!(first.len(), 4);
    }
}
