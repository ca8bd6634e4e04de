//! The rolling radius difference function Δr(y): a table, checked, with its jumps and its
//! equilibrium.

use crate::rigid::resolved_delta_r;
use std::fmt;

/// `delta_r` with the values below 1e-9 mm (the rigid search's Δr resolution) set to 0.
fn resolved(mut delta_r: Vec<f64>) -> Vec<f64> {
    for v in &mut delta_r {
        *v = resolved_delta_r(*v);
    }
    delta_r
}

/// Why a Δr function cannot be used.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum DeltaRError {
    /// Fewer than 3 points.
    TooFewPoints {
        /// Points given.
        count: usize,
    },
    /// A value is NaN or infinite (index of the point).
    NonFinite {
        /// Index of the point.
        index: usize,
    },
    /// `y` decreases (or repeats more than once) at this point.
    NotIncreasing {
        /// Index of the point.
        index: usize,
    },
    /// Δr never changes sign from negative to positive: no equilibrium.
    NoSignChange,
    /// The `y` and Δr columns differ in length.
    LengthMismatch,
}

impl fmt::Display for DeltaRError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DeltaRError::TooFewPoints { count } => {
                write!(f, "{count} points; at least 3 are needed")
            }
            DeltaRError::NonFinite { index } => write!(f, "point {index} is not finite"),
            DeltaRError::NotIncreasing { index } => {
                write!(f, "y does not increase at point {index}")
            }
            DeltaRError::NoSignChange => write!(
                f,
                "delta_r never changes sign from negative to positive: no equilibrium position"
            ),
            DeltaRError::LengthMismatch => write!(f, "y and delta_r differ in length"),
        }
    }
}

impl std::error::Error for DeltaRError {}

/// Why a CSV text is not a Δr table ([`DeltaR::parse_csv`]): the file, the line where known,
/// and the problem.
#[derive(Debug, Clone, PartialEq)]
pub struct DeltaRCsvError {
    /// The file (or the name the text was given).
    pub origin: String,
    /// The 1-based line, where the problem has one.
    pub line: Option<usize>,
    /// What is wrong.
    pub problem: CsvProblem,
    /// Where the row separates its fields otherwise than the header: `(the row's
    /// separator, the header's)`, in words (`"semicolons"`).
    pub mixed: Option<(&'static str, &'static str)>,
}

/// What is wrong with a Δr table's text.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum CsvProblem {
    /// The first row is no header with the columns `y_mm` (or `y_ws_mm`) and `delta_r_mm`.
    NoHeader(String),
    /// A row has no value in a column (the column, the row).
    NoValue(&'static str, String),
    /// A value is not a number (the column, the text).
    NotANumber(&'static str, String),
    /// A value is not finite (the column, the text).
    NotFinite(&'static str, String),
    /// No header at all.
    Empty,
    /// `y` does not increase from the row before.
    NotIncreasing {
        /// The row's `y` (mm).
        y: f64,
        /// The line of the row before.
        previous_line: usize,
        /// Its `y` (mm).
        previous_y: f64,
    },
    /// A value is not finite.
    NonFinite,
    /// The table as a whole is no Δr function.
    Table(DeltaRError),
}

impl fmt::Display for DeltaRCsvError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{line}: ", self.origin)?,
            None => write!(f, "{}: ", self.origin)?,
        }
        match &self.problem {
            CsvProblem::NoHeader(line) => write!(
                f,
                "expected a header with columns `y_mm` (or `y_ws_mm`) and `delta_r_mm`, separated by commas, semicolons or tabs, found {line:?}"
            ),
            CsvProblem::NoValue(column, line) => {
                write!(f, "no value in column {column} in {line:?}")
            }
            CsvProblem::NotANumber(column, text) => write!(f, "{column} {text:?} is not a number"),
            CsvProblem::NotFinite(column, text) => write!(
                f,
                "{column} {text} is not finite (leave out rows the rigid search did not converge at)"
            ),
            CsvProblem::Empty => {
                f.write_str("empty: expected a header `y_mm,delta_r_mm` and at least 3 rows")
            }
            CsvProblem::NotIncreasing {
                y,
                previous_line,
                previous_y,
            } => write!(
                f,
                "y {y} does not increase (previous row, line {previous_line}: {previous_y})"
            ),
            CsvProblem::NonFinite => f.write_str("value not finite"),
            CsvProblem::Table(e) => write!(f, "{e}"),
        }?;
        match self.mixed {
            Some((row, header)) => write!(
                f,
                " (this row separates its fields by {row}, the header by {header}: a file takes one separator)"
            ),
            None => Ok(()),
        }
    }
}

impl std::error::Error for DeltaRCsvError {}

/// A rolling radius difference function: Δr (mm) linear between points `(y, Δr)`, `y`
/// increasing. Two consecutive points at the same `y` are a jump of Δr there (a contact-point
/// jump): the first holds the value from the left, the second the value from the right.
/// A NaN value marks a point where Δr is unknown; the function ends there. A value smaller
/// than 1e-9 mm (the rigid search's Δr resolution) is 0: the rounding of two equal rolling radii
/// is no slope (the constant's docs say why it cannot hide one).
#[derive(Debug, Clone, PartialEq)]
pub struct DeltaR {
    pub(super) y: Vec<f64>,
    pub(super) dr: Vec<f64>,
}

impl DeltaR {
    /// A Δr function from a table with strictly increasing `y`, all values finite, at least
    /// 3 points and a change of sign (values below the rigid search's Δr resolution,
    /// 1e-9 mm, are 0).
    ///
    /// # Errors
    /// [`DeltaRError`] naming the offending point.
    pub fn new(y: Vec<f64>, delta_r: Vec<f64>) -> Result<DeltaR, DeltaRError> {
        if y.len() != delta_r.len() {
            return Err(DeltaRError::LengthMismatch);
        }
        if y.len() < 3 {
            return Err(DeltaRError::TooFewPoints { count: y.len() });
        }
        for (i, (a, b)) in y.iter().zip(&delta_r).enumerate() {
            if !(a.is_finite() && b.is_finite()) {
                return Err(DeltaRError::NonFinite { index: i });
            }
            if i > 0 && *a <= y[i - 1] {
                return Err(DeltaRError::NotIncreasing { index: i });
            }
        }
        let d = DeltaR {
            y,
            dr: resolved(delta_r),
        };
        if d.equilibrium().is_none() {
            return Err(DeltaRError::NoSignChange);
        }
        Ok(d)
    }

    /// A Δr function with jumps (a `y` given twice: values from the left, then from the
    /// right) and unknown values (NaN), as a rigid sweep gives it. `y` must not decrease and
    /// no `y` may appear three times; no sign change is required (the conicity then says
    /// [`ConicityStatus::NoEquilibrium`](super::ConicityStatus::NoEquilibrium)).
    ///
    /// # Errors
    /// [`DeltaRError::NotIncreasing`], [`DeltaRError::NonFinite`] for a non-finite `y`.
    pub fn with_jumps(y: Vec<f64>, delta_r: Vec<f64>) -> Result<DeltaR, DeltaRError> {
        if y.len() != delta_r.len() {
            return Err(DeltaRError::LengthMismatch);
        }
        for i in 0..y.len() {
            if !y[i].is_finite() {
                return Err(DeltaRError::NonFinite { index: i });
            }
            let repeats_twice = i >= 2 && y[i] <= y[i - 2];
            if i > 0 && (y[i] < y[i - 1] || repeats_twice) {
                return Err(DeltaRError::NotIncreasing { index: i });
            }
        }
        Ok(DeltaR {
            y,
            dr: resolved(delta_r),
        })
    }

    /// Parses a CSV table holding the columns `y_mm` (or `y_ws_mm`, as in `rigid.csv`) and
    /// `delta_r_mm`, found by their header names; `#` comments and blank lines are skipped,
    /// other columns ignored. Fields are separated by commas, semicolons or tabs, as the
    /// header's are (the crate's `delimited` module); with semicolons or tabs a number may
    /// have a decimal comma.
    ///
    /// # Errors
    /// [`DeltaRCsvError`], naming `origin` and the line (and the separators, where a row
    /// holds another than its header).
    pub fn parse_csv(text: &str, origin: &str) -> Result<DeltaR, DeltaRCsvError> {
        let separator = crate::delimited::Separator::of_text(text);
        let mut y = Vec::new();
        let mut dr = Vec::new();
        let mut lines = Vec::new();
        let mut columns: Option<(usize, usize)> = None;
        let error = |line, problem| DeltaRCsvError {
            origin: origin.to_string(),
            line,
            problem,
            mixed: None,
        };
        for (k, raw) in text.lines().enumerate() {
            let line_no = k + 1;
            let line = raw.trim_matches(|c: char| c.is_whitespace() && c != separator.char());
            if line.trim().is_empty() || line.starts_with('#') {
                continue;
            }
            let cells: Vec<&str> = line.split(separator.char()).map(str::trim).collect();
            let Some((cy, cd)) = columns else {
                let find = |names: &[&str]| cells.iter().position(|c| names.contains(c));
                match (find(&["y_mm", "y_ws_mm"]), find(&["delta_r_mm"])) {
                    (Some(cy), Some(cd)) => columns = Some((cy, cd)),
                    _ => return Err(error(Some(line_no), CsvProblem::NoHeader(line.into()))),
                }
                continue;
            };
            let mixed = separator
                .other_in(line)
                .map(|found| (found.plural(), separator.plural()));
            let cell = |i: usize, column: &'static str| -> Result<f64, DeltaRCsvError> {
                let at = |problem| error(Some(line_no), problem);
                let text = cells.get(i).ok_or_else(|| DeltaRCsvError {
                    mixed,
                    ..at(CsvProblem::NoValue(column, line.into()))
                })?;
                let v: f64 = separator
                    .number_text(text)
                    .parse()
                    .map_err(|_| DeltaRCsvError {
                        mixed,
                        ..at(CsvProblem::NotANumber(column, text.to_string()))
                    })?;
                if v.is_finite() {
                    Ok(v)
                } else {
                    Err(at(CsvProblem::NotFinite(column, text.to_string())))
                }
            };
            y.push(cell(cy, "y")?);
            dr.push(cell(cd, "delta_r_mm")?);
            lines.push(line_no);
        }
        if columns.is_none() {
            return Err(error(None, CsvProblem::Empty));
        }
        DeltaR::new(y.clone(), dr).map_err(|e| match e {
            DeltaRError::NotIncreasing { index } => error(
                Some(lines[index]),
                CsvProblem::NotIncreasing {
                    y: y[index],
                    previous_line: lines[index - 1],
                    previous_y: y[index - 1],
                },
            ),
            DeltaRError::NonFinite { index } => error(Some(lines[index]), CsvProblem::NonFinite),
            other => error(None, CsvProblem::Table(other)),
        })
    }

    /// The points `(y, Δr)` (mm).
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.y.iter().copied().zip(self.dr.iter().copied())
    }

    /// Δr at `y` by linear interpolation (the value from the right at a jump); `None`
    /// outside the points or where a neighbouring value is unknown.
    pub fn at(&self, y: f64) -> Option<f64> {
        let n = self.y.len();
        if n == 0 || !(y >= self.y[0] && y <= self.y[n - 1]) {
            return None;
        }
        // The last point with y_i <= y (at a jump, the one holding the right value).
        let i = self.y.partition_point(|&v| v <= y).max(1) - 1;
        if i + 1 == n {
            return self.dr[i].is_finite().then_some(self.dr[i]);
        }
        let (y0, y1, d0, d1) = (self.y[i], self.y[i + 1], self.dr[i], self.dr[i + 1]);
        let v = if y1 > y0 {
            d0 + (d1 - d0) * (y - y0) / (y1 - y0)
        } else {
            d1
        };
        v.is_finite().then_some(v)
    }

    /// The equilibrium: the stable zero crossing of Δr (from negative to positive) nearest
    /// to `y = 0`, as the band `[from, to]` where Δr = 0 (`from == to` for a crossing point);
    /// of two equally near, the one at positive `y` (a symmetric wheelset's two equilibria
    /// off the centre are mirror images, with the same conicity). `None` when Δr has no
    /// stable crossing.
    pub fn equilibrium(&self) -> Option<(f64, f64)> {
        let (y, d) = (&self.y, &self.dr);
        let n = y.len();
        let mut best: Option<(f64, f64)> = None;
        let mut consider = |band: (f64, f64)| {
            let mid = 0.5 * (band.0 + band.1);
            let nearer = |b: (f64, f64)| {
                let other = 0.5 * (b.0 + b.1);
                match mid.abs().total_cmp(&other.abs()) {
                    std::cmp::Ordering::Less => true,
                    std::cmp::Ordering::Equal => mid > other,
                    std::cmp::Ordering::Greater => false,
                }
            };
            if best.is_none_or(nearer) {
                best = Some(band);
            }
        };
        let mut i = 0;
        while i < n {
            if d[i] == 0.0 {
                // A run of zeros: stable when entered from below and left upwards.
                let mut j = i;
                while j + 1 < n && d[j + 1] == 0.0 {
                    j += 1;
                }
                let below = i > 0 && d[i - 1] < 0.0;
                let above = j + 1 < n && d[j + 1] > 0.0;
                if below && above {
                    consider((y[i], y[j]));
                }
                i = j + 1;
                continue;
            }
            if i + 1 < n && d[i] < 0.0 && d[i + 1] > 0.0 {
                let crossing = if y[i + 1] > y[i] {
                    y[i] + (y[i + 1] - y[i]) * (-d[i] / (d[i + 1] - d[i]))
                } else {
                    y[i]
                };
                consider((crossing, crossing));
            }
            i += 1;
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::DeltaR;

    /// An odd Δr falling through 0 (unstable) between two stable crossings at ±2 mm, as a
    /// symmetric wheelset may give it: of the two equally near equilibria, the positive one.
    #[test]
    fn of_two_equally_near_equilibria_the_positive_one() {
        let y: Vec<f64> = (-4..=4).map(f64::from).collect();
        // Δr = y (y^2 - 4) / 4: zeros at 0 (falling) and ±2 (rising).
        let dr: Vec<f64> = y.iter().map(|&y| y * (y * y - 4.0) / 4.0).collect();
        let d = DeltaR::new(y.clone(), dr.clone()).unwrap();
        assert_eq!(d.equilibrium(), Some((2.0, 2.0)));
        // A crossing nearer the centre still wins, on either side: the zero at -2 moved
        // to -1.5.
        let mut nearer = y;
        nearer[2] = -1.5;
        let d = DeltaR::new(nearer, dr).unwrap();
        assert_eq!(d.equilibrium(), Some((-1.5, -1.5)));
    }

    /// A Δr table exported with semicolons or tabs (decimal commas or points) reads as the
    /// one with commas; a row with another separator than its header is named so.
    #[test]
    fn semicolons_and_tabs_read_as_commas() {
        let commas = "# rigid\ny_mm,delta_r_mm\n-1,-0.25\n0,0\n1.5,0.375\n";
        let want = DeltaR::parse_csv(commas, "c.csv").unwrap();
        for text in [
            "# rigid\ny_mm;delta_r_mm\n-1;-0,25\n0;0\n1,5;0.375\n",
            "# rigid\r\ny_mm\tdelta_r_mm\r\n-1\t-0,25\r\n0\t0\r\n1.5\t0.375\r\n",
        ] {
            let got = DeltaR::parse_csv(text, "e.csv").unwrap();
            assert_eq!(
                got.points().collect::<Vec<_>>(),
                want.points().collect::<Vec<_>>(),
                "{text:?}"
            );
        }
        let e = DeltaR::parse_csv("y_mm;delta_r_mm\n-1;0\n0.5,0.1\n", "e.csv")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("e.csv:3:")
                && e.contains("this row separates its fields by commas, the header by semicolons"),
            "{e}"
        );
        let e = DeltaR::parse_csv("y_mm,delta_r_mm\n-1;0\n", "e.csv")
            .unwrap_err()
            .to_string();
        assert!(e.contains("by semicolons, the header by commas"), "{e}");
    }
}
